#!/usr/bin/env bash
# Reproduces "A range lattice's run kept on its level is one error" in
# doc/benchmarks.md (issue 15, eighteenth session): IDC's and CF-IDC's
# covariance before the change (commit e4e4164, built in a git worktree
# under OUT) and after (this tree), in whole EKF runs on the logs with
# MRPT's 0.16 m range lattice: the bundled log and featloc-sim's held-out
# corridor with people, room with doors and cart, and hall with people
# (Laser:range_step = 0.16, seeds 1-3; the hall seed 1). The estimates of
# every pair are the same up to the guess gate's use of the covariance
# (scripts/bench-range-lattice.sh gives the pair tables and their NEES);
# the EKF weighs each match by it. Per run: ATE rmse [mm] before -> after,
# the after run against the before run step by step (featloc-eval
# --paired-with: mean RPE difference [mm], 95% interval) and the run's
# NEES mean before -> after.
# Usage: scripts/bench-lattice-shared-errors.sh [OUTDIR]   (about 6 min with the old build cached by ccache, 12 without)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-lattice-shared-errors "$@"

BEFORE=e4e4164
OLD="$OUT/before-$BEFORE"
if [ ! -x "$OLD/build/bin/featloc-run" ]; then
  [ -d "$OLD" ] || git -C "$ROOT" worktree add -f --detach "$OLD" "$BEFORE" > /dev/null
  cmake -S "$OLD" -B "$OLD/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache > /dev/null
  cmake --build "$OLD/build" -j "$(nproc)" --target featloc-run > "$OUT/before-build.log"
fi

cases=("bundled:$ROOT/rawlogs/mrpt-simul/simul.rawlog:$ROOT/rawlogs/mrpt-simul/simul.gt.txt")
for w in corridor-people room-moving-objects; do
  for seed in 1 2 3; do
    sim_lattice "$w" "$w-lattice-seed$seed" --seed "$seed"
    cases+=("$w-lattice-seed$seed:$OUT/$w-lattice-seed$seed.rawlog:$OUT/$w-lattice-seed$seed.gt.txt")
  done
done
sim_lattice hall-people hall-people-lattice-seed1 --seed 1
cases+=("hall-people-lattice-seed1:$OUT/hall-people-lattice-seed1.rawlog:$OUT/hall-people-lattice-seed1.gt.txt")

machine_line
echo
echo "### EKF whole runs, before -> after"
echo
echo "| log | matcher | ATE rmse [mm] | step by step, after - before: RPE difference [mm] (95%) | NEES mean |"
echo "|---|---|---|---|---|"
for cls in IdcMatcher CfIdcMatcher; do
  for c in "${cases[@]}"; do
    IFS=: read -r name input gt <<< "$c"
    for way in before after; do
      bin="$BIN/featloc-run" cfg="$ROOT/config.ini"
      [ "$way" = before ] && bin="$OLD/build/bin/featloc-run" cfg="$OLD/config.ini"
      "$bin" "$cfg" "$input" -q --out "$OUT/$name-$cls-$way" --set Output:write_scene=false \
        --set Output:write_rawlog=false --set "Evaluation:ground_truth=$gt" --set Pipeline:estimator=ekf \
        --set "ScanMatcher:class=featloc::$cls" > "$OUT/$name-$cls-$way.txt" 2>&1
    done
    ate() { jq -r '.evaluation.ate_m.rmse * 1000 | round' "$OUT/$name-$cls-$1/summary.json"; }
    nees() { jq -r '.evaluation.nees.mean * 100 | round / 100' "$OUT/$name-$cls-$1/summary.json"; }
    step=$("$BIN/featloc-eval" "$gt" "$OUT/$name-$cls-after/poses_cov.txt" \
      --paired-with "$OUT/$name-$cls-before/poses_cov.txt" -j |
      jq -r '.paired | "\(.rpe_trans_mean_diff_m * 1e5 | round / 100) (\(.ci95_m[0] * 1e5 | round / 100), \(.ci95_m[1] * 1e5 | round / 100))"')
    echo "| $name | ${cls%Matcher} | $(ate before) -> $(ate after) | $step | $(nees before) -> $(nees after) |"
  done
done
echo
echo "(raw outputs in $OUT)"
