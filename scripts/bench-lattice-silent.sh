#!/usr/bin/env bash
# Issue 15: where the silent gross errors on MRPT's 0.16 m range lattice
# come from (doc/benchmarks.md, "Issue 15, twenty-fifth session").
#  - The simulated office and lab on the lattice with 1 cm noise
#    (calibration scenes), the held-out corridor with people on the lattice
#    and its frozen twin (the same log without its people).
#  - Each from Borges & Aldon's +-0.3 m / +-10 deg and from the true motion
#    (+-1 mm / +-0.05 deg): PCM, IDC and CF-IDC with MRPT's ICP in the same
#    runs.
#  - Then, per data set and matcher, the silent gross pairs (> 10 cm or
#    > 2 deg, not flagged): their median error along the robot's x (the
#    direction of travel) and y, and how many of them put the estimated
#    forward motion within 5 cm of zero (the truth moved 8-15 cm).
# Usage: scripts/bench-lattice-silent.sh [OUTDIR]   (about 1 min on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_init bench-lattice-silent "$@"

M="PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
COMMON="--seed 1 -q --paired-with none"
HEADER=--header

# The silent gross pairs of one --pairs file, against the log's
# ground-truth poses GT (one line per scan: t x y z qx qy qz qw; pair k is
# scans k and k + 1).
silent_pairs() { # name, pairs.tsv, gt
  awk -F'\t' -v name="$1" '
    FNR == NR {
      if ($0 !~ /^#/ && split($0, g, " ") >= 8) { n++; X[n] = g[2]; Y[n] = g[3]; W[n] = 2 * atan2(g[7], g[8]) }
      next
    }
    /^#/ { next }
    $4 == "used" {
      ex = $5; ey = $6; et = sqrt(ex * ex + ey * ey); ew = $7 * 57.29578; if (ew < 0) ew = -ew
      if (et <= 0.1 && ew <= 2) next
      i = $3 + 1
      fwd = cos(W[i]) * (X[i + 1] - X[i]) + sin(W[i]) * (Y[i + 1] - Y[i])
      m = $2; count[m]++
      ax[m, count[m]] = ex < 0 ? -ex : ex; ay[m, count[m]] = ey < 0 ? -ey : ey
      e = fwd + ex; if (e < 0) e = -e
      if (e < 0.05) still[m]++
      if (!(m in seen)) { seen[m] = 1; order[++nm] = m }
    }
    function median(a, m, k,   v, i, j, t) {
      for (i = 1; i <= k; i++) v[i] = a[m, i]
      for (i = 2; i <= k; i++) for (j = i; j > 1 && v[j - 1] > v[j]; j--) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
      return k % 2 ? v[(k + 1) / 2] : (v[k / 2] + v[k / 2 + 1]) / 2
    }
    END {
      for (j = 1; j <= nm; j++) {
        m = order[j]; k = count[m]
        printf "| %s | %s | %d | %.0f | %.0f | %d of %d |\n", name, m, k, 1000 * median(ax, m, k), 1000 * median(ay, m, k), still[m], k
      }
    }' "$3" "$2"
}

machine_line
sim_calibration_lattices
sim_lattice corridor-people corridor-people-lattice
sim_lattice corridor-people corridor-people-lattice-frozen --frozen
DATA=("office-1cm-lattice:sim office (1 cm), lattice" "lab-1cm-lattice:sim lab (1 cm), lattice"
  "corridor-people-lattice:corridor with people, lattice"
  "corridor-people-lattice-frozen:corridor without its people (frozen), lattice")
for protocol in "0.3 10:+-0.3 m / 10 deg" "0.001 0.05:from the true motion, +-1 mm / 0.05 deg"; do
  read -r xy yaw <<< "${protocol%%:*}"
  echo
  echo "### ${protocol#*:}"
  echo
  HEADER=--header
  for d in "${DATA[@]}"; do
    log="${d%%:*}" name="${d#*:}"
    bench_main_table "" "$name" "$OUT/$log.rawlog" -g "$OUT/$log.gt.txt" \
      --perturb-xy "$xy" --perturb-yaw-deg "$yaw" --pairs "$OUT/$log-$xy.pairs.tsv"
  done
  echo
  echo "Silent gross pairs: median |error| along the robot's x (travel) and y [mm]; estimated forward motion within 5 cm of zero"
  echo
  echo "| data | matcher | silent gross pairs | median x err | median y err | at zero motion |"
  echo "|---|---|---|---|---|---|"
  for d in "${DATA[@]}"; do
    log="${d%%:*}" name="${d#*:}"
    silent_pairs "$name" "$OUT/$log-$xy.pairs.tsv" "$OUT/$log.gt.txt"
  done
done
