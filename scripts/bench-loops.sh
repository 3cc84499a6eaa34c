#!/usr/bin/env bash
# Issue 17: the EKF against the matcher alone on MRPT's Malaga 2006 log,
# which has no ground truth, measured at its loop. featloc-bench
# --loop-relations finds where a trajectory comes back to a place it passed
# (poses within 1 m and 30 deg, 50 or more scans apart) and matches the two
# scans directly (IcpMatcher with the wide-basin coarse search, from that
# trajectory's motion); featloc-eval measures each estimate against these
# relations (Kuemmerle et al. 2009). The relations are built twice, from
# the matcher's and from the EKF's trajectory, to show they do not depend
# on the trajectory that proposed them.
# Issue 15 (Malaga is one of its real logs, with the Radish ones): every
# matcher as config.ini has it, matcher chain and EKF, against the same
# relations and against relations that IdcMatcher made instead of MRPT's
# ICP (so that the reference does not favour one matcher); and each run's
# failed matches.
# Usage: scripts/bench-loops.sh [OUTDIR]      (about 2 minutes)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
bench_init loops "$@"
MALAGA="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
machine_line

run() { # name, featloc-run --set arguments...
  local name="$1"; shift
  "$BIN/featloc-run" "$ROOT/config.ini" "$MALAGA" -q --out "$OUT/$name" \
    --set Evaluation:ground_truth= "$@" >/dev/null
}
run odometry --set Pipeline:estimator=odometry
run matcher --set Pipeline:estimator=matcher
run ekf --set Pipeline:estimator=ekf
run ekf-covariance-check --set Pipeline:estimator=ekf --set Odometry:covariance_check=true
# The odometry direction offset learnt in the EKF (prior 2 deg by default):
# off, and at a wider prior. The log's odometry steps point 2.6 deg off the
# matcher's.
run ekf-direction-off --set Pipeline:estimator=ekf --set Ekf:odometry_direction_sigma_DEG=0
run ekf-direction-5deg --set Pipeline:estimator=ekf --set Ekf:odometry_direction_sigma_DEG=5

relations() { # trajectory run, reference matcher class, relations file
  "$BIN/featloc-bench" "$ROOT/config.ini" "$MALAGA" -q --reference-matcher "$2" \
    --set "ScanMatcher.${2#featloc::}:coarse_search=true" --loop-relations "$OUT/$1/poses_cov.txt" \
    --write-relations "$3"
}
# Prints "relations | translation error mean / median / max [m] | rotation
# error mean / median / max [deg]" of run $2's estimate against relations $1.
# featloc-eval's JSON is kept as OUT/eval-RELATIONS-RUN.json.
against() { # relations file, run
  local json="$OUT/eval-$(basename "$1" .txt)-$2.json"
  "$BIN/featloc-eval" "$1" "$OUT/$2/poses_cov.txt" --reference-format relations -j > "$json"
  python3 - "$json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
t, r = j["relation_translation_m"], j["relation_rotation"]  # m, deg
print("%d | %.3f / %.3f / %.3f | %.2f / %.2f / %.2f" % (j["relations_matched"],
    t["mean"], t["median"], t["max"], r["mean"], r["median"], r["max"]))
PY
}

for from in matcher ekf; do
  relations "$from" featloc::IcpMatcher "$OUT/loops-from-$from.txt"
done
echo
echo "| relations from | estimate | relations | translation error mean / median / max [m] | rotation error mean / median / max [deg] |"
echo "|---|---|---|---|---|"
for from in matcher ekf; do
  for est in odometry matcher ekf ekf-covariance-check ekf-direction-off ekf-direction-5deg; do
    echo "| $from's | $est | $(against "$OUT/loops-from-$from.txt" "$est") |"
  done
done

echo
echo "### Every matcher as config.ini has it (issue 15)"
echo
relations matcher featloc::IdcMatcher "$OUT/loops-idc-from-matcher.txt"
echo "| matcher | estimator | failed matches (of 224) | relations by MRPT's ICP | translation error mean / median / max [m] | rotation error mean / median / max [deg] | relations by IdcMatcher | translation error [m] | rotation error [deg] |"
echo "|---|---|---|---|---|---|---|---|---|"
for cls in IcpMatcher PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
  for est in matcher ekf; do
    run "$est-$cls" --set "Pipeline:estimator=$est" --set "ScanMatcher:class=featloc::$cls"
    failed=$(jq -r '.counts.match_failures' "$OUT/$est-$cls/summary.json")
    echo "| $cls | $est | $failed | $(against "$OUT/loops-from-matcher.txt" "$est-$cls") | $(against "$OUT/loops-idc-from-matcher.txt" "$est-$cls") |"
  done
done
