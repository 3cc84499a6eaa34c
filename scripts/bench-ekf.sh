#!/usr/bin/env bash
# Reproduces the EKF figures of doc/benchmarks.md: a Monte Carlo run over
# simulator seeds (every seed redraws odometry errors, range noise and, in
# the lab, the exploration path) of the shipped office, lab and
# corridor-with-people worlds, each with its realistic odometry drift.
# featloc-run estimates every log three ways (odometry, matcher, ekf) with
# each matcher; reported per scene and matcher:
#  - mean ATE (m, RMSE after SE(2) alignment) over the seeds, and on how
#    many seeds the EKF beat both odometry and the matcher alone;
#  - the EKF's consistency as in Bar-Shalom's Monte Carlo test: the NEES
#    (3 dof, anchored at the first pose) averaged over the M runs at every
#    scan, its mean over time, and the share of scans where that average is
#    inside the two-sided 95% band of chi2(3M)/M;
#  - matches the EKF did not use (failed or gated);
#  - the estimator's own time per step (matcher excluded) and the
#    real-time factor at 10 Hz scans.
# Then the lab with eight beacons (no identities), EKF with and without.
# Usage: scripts/bench-ekf.sh [OUTDIR] [SEEDS (default 5)] [MATCHERS (default
#   "IcpMatcher IdcMatcher"; CfIdcMatcher and PcmFeatureMatcher also work)]
# Takes about 15 minutes on 2 cores with the defaults.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-ekf "$@"
M="${2:-5}"
MATCHERS="${3:-IcpMatcher IdcMatcher}"
SCENES="office lab corridor-people"
BEACONS="[1 1; 7 5; 13 9; 2 8; 10 2; 5 8.5; 12 4; 3.5 5]"

# Two-sided 95% band of the mean of M chi2(3) draws (Wilson-Hilferty).
band() { awk -v k=$((3 * M)) -v m="$M" -v z="$1" 'BEGIN{a=2/(9*k); printf "%.3f", k*(1-a+z*sqrt(a))^3/m}'; }
LO=$(band -1.959964); HI=$(band 1.959964)

run() { # rawlog gt out estimator matcher [extra...]
  local log="$1" gt="$2" out="$3" est="$4" m="$5"; shift 5
  "$BIN/featloc-run" "$ROOT/config.ini" "$log" --out "$out" -q \
    --set Pipeline:estimator="$est" --set ScanMatcher:class=featloc::"$m" \
    --set Evaluation:ground_truth="$gt" --set Output:write_rawlog=false \
    --set Output:write_scene=false "$@" >/dev/null
}
jqv() { jq -r "$1" "$2"; }
# FORMAT nees.txt...: the NEES at every scan averaged over the runs (scans
# every run has), printed as FORMAT with its mean over time and the share
# of scans inside [LO, HI].
mc_nees() {
  local format="$1"; shift
  awk -v lo="$LO" -v hi="$HI" -v fmt="$format" 'FNR==1{f++} !/^#/{k=FNR; s[k]+=$2; c[k]++}
    END{for (k in s) if (c[k]==f) {n++; a=s[k]/f; t+=a; if (a>=lo && a<=hi) w++}
        printf fmt, t/n, 100*w/n}' "$@"
}
mean() { awk '{s+=$1; n++} END{printf "%.9g", s/n}'; }

machine_line
echo "seeds 1..$M; NEES band for the mean of $M runs: [$LO, $HI]"
echo
for scene in $SCENES; do
  for s in $(seq 1 "$M"); do
    "$BIN/featloc-sim" "$ROOT/worlds/$scene.ini" --out "$OUT/$scene-s$s" --seed "$s" -q >/dev/null
  done
done

echo "| scene | matcher | ATE odometry | ATE matcher | ATE ekf | ekf best on | MC NEES mean | in 95% band | matches not used | ekf us/step | x real time (10 Hz) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for scene in $SCENES; do
  for m in $MATCHERS; do
    : >"$OUT/ate.txt"; nees=""; unused=0; attempted=0; us=""; wins=0
    for s in $(seq 1 "$M"); do
      base="$OUT/$scene-s$s"
      for est in odometry matcher ekf; do
        [ "$est" = odometry ] && [ -f "$base-odometry/summary.json" ] && continue
        d="$base-$est"; [ "$est" != odometry ] && d="$base-$m-$est"
        run "$base.rawlog" "$base.gt.txt" "$d" "$est" "$m"
      done
      ao=$(jqv .evaluation.ate_m.rmse "$base-odometry/summary.json")
      am=$(jqv .evaluation.ate_m.rmse "$base-$m-matcher/summary.json")
      ae=$(jqv .evaluation.ate_m.rmse "$base-$m-ekf/summary.json")
      echo "$ao $am $ae" >>"$OUT/ate.txt"
      wins=$((wins + $(awk -v o="$ao" -v m="$am" -v e="$ae" 'BEGIN{print (e<o && e<m) ? 1 : 0}')))
      nees="$nees $base-$m-ekf/nees.txt"
      unused=$((unused + $(jqv .counts.fallbacks_to_odometry "$base-$m-ekf/summary.json")))
      attempted=$((attempted + $(jqv .counts.matches "$base-$m-ekf/summary.json")))
      us="$us $(jqv .estimator_time_s.mean "$base-$m-ekf/summary.json")"
    done
    ates=$(awk '{o+=$1; m+=$2; e+=$3; n++} END{printf "%.4f | %.4f | %.4f", o/n, m/n, e/n}' "$OUT/ate.txt")
    # NEES at every scan averaged over the runs (only scans every run has).
    nees_stats=$(mc_nees "%.2f | %.0f%%" $nees)
    tus=$(echo $us | tr ' ' '\n' | mean)
    rt=$(awk -v t="$tus" 'BEGIN{printf "%.0f", 0.1/t}')
    echo "| $scene | $m | $ates | $wins/$M | $nees_stats | $unused of $attempted | $(awk -v t="$tus" 'BEGIN{printf "%.1f", t*1e6}') | $rt |"
  done
done

echo
echo "Lab with 8 beacons (range 8 m, 3 cm / 1 deg noise, no identities), IdcMatcher:"
echo "| seed | ATE ekf without beacons | ATE ekf with beacons | landmarks mapped | MC NEES with beacons |"
echo "|---|---|---|---|---|"
nees=""
for s in $(seq 1 "$M"); do
  base="$OUT/lab-s$s"
  "$BIN/featloc-sim" "$ROOT/worlds/lab.ini" --out "$base-b" --seed "$s" -q --set "Beacons:points=$BEACONS" >/dev/null
  [ -f "$base-IdcMatcher-ekf/summary.json" ] || run "$base.rawlog" "$base.gt.txt" "$base-IdcMatcher-ekf" ekf IdcMatcher
  run "$base-b.rawlog" "$base-b.gt.txt" "$base-b-ekf" ekf IdcMatcher
  nees="$nees $base-b-ekf/nees.txt"
  echo "| $s | $(fmt "$(jqv .evaluation.ate_m.rmse "$base-IdcMatcher-ekf/summary.json")" 4) | $(fmt "$(jqv .evaluation.ate_m.rmse "$base-b-ekf/summary.json")" 4) | $(jqv .counts.landmarks_in_map "$base-b-ekf/summary.json") | |"
done
echo "| all | | | | $(mc_nees "%.2f (%.0f%% in band)" $nees) |"
echo
echo "results in $OUT"
