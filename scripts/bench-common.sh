# Sourced by the scripts/bench-*.sh scripts: sets up and builds featloc, then
# defines ROOT, BIN and OUT (the first argument, or a fresh temporary folder
# named after $1 of bench_init) and the helpers every benchmark prints with.
# Usage (after set -euo pipefail): source "$(dirname "$0")/bench-common.sh"; bench_init NAME "$@"
bench_init() { # name, script arguments...
  local name="$1"; shift
  ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  "$ROOT/scripts/setup.sh" >/dev/null
  "$ROOT/scripts/build.sh" >/dev/null
  BIN="${FEATLOC_BUILD_DIR:-$ROOT/build}/bin"
  OUT="${1:-$(mktemp -d "/tmp/featloc-$name-XXXXXX")}"
  mkdir -p "$OUT"
  # The real CARMEN logs (Radish) the benches and the functions below read.
  LASER2D="${FEATLOC_LASER2D:-$ROOT/../shared/data/laser2d}"
}
fmt() { printf "%.${2:-3}f" "$1"; }
machine_line() {
  echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), $(date -u +%Y-%m-%d)"
}
# The Radish logs held out from calibration: every *-corrected.log.gz in
# $LASER2D but orebro's (the calibration log), one path per line.
held_out_radish_logs() {
  local f
  for f in "$LASER2D"/*-corrected.log.gz; do
    [ "$(basename "$f")" = orebro-corrected.log.gz ] || echo "$f"
  done
}
# The calibration scenes of issue 15's benches, each through the caller's
# `bench NAME DATA ARGS...`, Borges & Aldon's protocol: the simulated office
# and lab at 1 cm noise, and the real orebro log in $LASER2D.
bench_calibration_scenes() {
  local scene
  for scene in office lab; do
    sim_1cm "$scene"
    bench "sim $scene (1 cm)" "$OUT/$scene-1cm.rawlog" -g "$OUT/$scene-1cm.gt.txt" \
      --perturb-xy 0.3 --perturb-yaw-deg 10
  done
  if [ -d "$LASER2D" ]; then
    bench "orebro" "$LASER2D/orebro-corrected.log.gz" --perturb-xy 0.3 --perturb-yaw-deg 10
  fi
}
# The calibration scenes on MRPT's 0.16 m range lattice: the simulated
# office and lab at 1 cm noise, as $OUT/{office,lab}-1cm-lattice.rawlog
# (+ .gt.txt), made once per OUT.
sim_calibration_lattices() {
  local scene
  for scene in office lab; do
    sim_lattice "$scene" "$scene-1cm-lattice" --set Laser:range_noise=0.01
  done
}
# Those two through the caller's `bench NAME DATA ARGS...` as "sim SCENE
# (1 cm)LABEL", further arguments to each (the protocol's).
bench_calibration_lattices() { # label, bench args...
  local scene label="$1"
  shift
  sim_calibration_lattices
  for scene in office lab; do
    bench "sim $scene (1 cm)$label" "$OUT/$scene-1cm-lattice.rawlog" \
      -g "$OUT/$scene-1cm-lattice.gt.txt" "$@"
  done
}
# The data sets of the benches of PCM's line extraction, through the
# caller's `bench NAME DATA ARGS...` (its main table and, with --world, the
# Cramer-Rao table; HEADER set before each table): the static scenes at 1 cm
# against the bound (the office and lab, calibration; the three held-out
# worlds frozen), then the held-out ones (the people and the room, the three
# held-out worlds as written and on MRPT's 0.16 m lattice, the corridor with
# people on the lattice, the bundled log, orebro and the other Radish
# logs); then the corridor seeds the whole runs use.
bench_extraction_scenes() {
  local w f
  echo
  echo "### Static, 1 cm noise, against the Cramer-Rao bound"
  echo
  HEADER=--header
  for w in office lab; do
    sim_1cm "$w"
    bench "sim $w (1 cm)" "$OUT/$w-1cm.rawlog" -g "$OUT/$w-1cm.gt.txt" --world "$ROOT/worlds/$w.ini"
  done
  for w in apartment warehouse-aisles parking-garage; do
    sim_world "$w" "$w-frozen-1cm" --frozen --set Laser:range_noise=0.01
    bench "$w frozen (1 cm)" "$OUT/$w-frozen-1cm.rawlog" -g "$OUT/$w-frozen-1cm.gt.txt" \
      --world "$ROOT/worlds/$w.ini" --frozen
  done
  echo
  echo "### Held out: people, carts, lattices, real logs"
  echo
  HEADER=--header
  for w in corridor-people hall-people room-moving-objects apartment warehouse-aisles parking-garage; do
    sim_world "$w" "$w"
    bench "$w" "$OUT/$w.rawlog" -g "$OUT/$w.gt.txt"
  done
  for w in apartment warehouse-aisles parking-garage corridor-people; do
    sim_lattice "$w" "$w-lattice"
    bench "$w, lattice" "$OUT/$w-lattice.rawlog" -g "$OUT/$w-lattice.gt.txt"
  done
  bench "bundled (MRPT's simulator, lattice)" "$ROOT/rawlogs/mrpt-simul/simul.rawlog" \
    -g "$ROOT/rawlogs/mrpt-simul/simul.gt.txt"
  if [ -d "$LASER2D" ]; then
    bench orebro "$LASER2D/orebro-corrected.log.gz"
    for f in $(held_out_radish_logs); do bench "$(basename "$f" -corrected.log.gz)" "$f"; done
  fi
  sim_corridor_seeds
}
# bench_extraction_scenes, then the two data sets it leaves out: the
# workshop as written, and the calibration scenes on the lattice (as "sim
# SCENE (1 cm), lattice"), under "### Held out from the change: ...".
bench_extraction_scenes_and_the_rest() {
  bench_extraction_scenes
  echo
  echo "### Held out from the change: the workshop, the calibration scenes on the lattice"
  echo
  HEADER=--header
  sim_world_and_bench workshop-moving-objects workshop-moving-objects
  bench_calibration_lattices ", lattice"
}
# A matcher's time per office pair ($OUT/office-1cm.rawlog, from sim_1cm)
# alone with MRPT's ICP, one way and the other (the other with the
# caller's OFF array of --set options), three runs in turn, each as
# "LABEL (WAY)": featloc-bench's main table.
office_time_two_ways() { # label, class, way A, way B
  local label="$1" class="$2" a="$3" b="$4" run way extra
  HEADER=--header
  for run in 1 2 3; do
    for way in "$a" "$b"; do
      extra=()
      [ "$way" = "$a" ] || extra=("${OFF[@]}")
      # shellcheck disable=SC2086
      "$BIN/featloc-bench" "$ROOT/config.ini" "$OUT/office-1cm.rawlog" -g "$OUT/office-1cm.gt.txt" \
        $COMMON $HEADER -m "$label ($way)=$class,IcpMatcher (MRPT)=featloc::IcpMatcher" \
        --name "sim office (1 cm), run $run" "${extra[@]}" | main_table
      HEADER=
    done
  done
}
# Issue 15's two per-pair tables: the calibration scenes, then the held-out
# ones, each through the caller's `bench` (HEADER set again for the second
# table), under "### [PREFIX]Calibration scenes" and "### [PREFIX]Held out".
bench_calibration_and_held_out() { # [title prefix]
  echo
  echo "### ${1:-}Calibration scenes"
  echo
  bench_calibration_scenes
  echo
  echo "### ${1:-}Held out"
  echo
  HEADER=--header
  bench_held_out_scenes
}
# The held-out scenes of issue 15's PCM benches, each through the caller's
# `bench NAME DATA ARGS...`, Borges & Aldon's protocol: the corridor with
# people (+-0.3 m / 10 deg and +-0.5 m / 15 deg), the hall with people, the
# room with doors and a cart (Cramer-Rao bound and moved points with
# --world), and the held-out Radish logs in $LASER2D.
bench_held_out_scenes() {
  local world
  for world in corridor-people hall-people room-moving-objects; do
    "$BIN/featloc-sim" "$ROOT/worlds/$world.ini" --out "$OUT/$world" -q > /dev/null
    bench "$world +-0.3/10" "$OUT/$world.rawlog" -g "$OUT/$world.gt.txt" \
      --perturb-xy 0.3 --perturb-yaw-deg 10 --world "$ROOT/worlds/$world.ini"
  done
  bench "corridor-people +-0.5/15" "$OUT/corridor-people.rawlog" -g "$OUT/corridor-people.gt.txt" \
    --perturb-xy 0.5 --perturb-yaw-deg 15 --world "$ROOT/worlds/corridor-people.ini"
  bench_held_out_radish_logs
}
# The held-out Radish logs through the caller's `bench NAME DATA ARGS...`,
# Borges & Aldon's protocol, each named after its log (plus SUFFIX).
bench_held_out_radish_logs() { # [suffix]
  local f
  if [ -d "$LASER2D" ]; then
    for f in $(held_out_radish_logs); do
      bench "$(basename "$f" -corrected.log.gz)${1:-}" "$f" --perturb-xy 0.3 --perturb-yaw-deg 10
    done
  else
    echo "(no real logs: $LASER2D not found)"
  fi
}
# Where a bench table named NAME keeps its files: $OUT/NAME with " /+()"
# turned into "_", without extension.
bench_file() { echo "$OUT/$(echo "$1" | tr " /+()" "_____")"; }
# One featloc-bench run of the caller's $M on DATA, with its $COMMON options
# and $HEADER, its JSON as "$(bench_file NAME).json". The caller clears
# HEADER after the first table (bench_main_table does; not here: piped, this
# runs in a subshell).
bench_run() { # name, data, extra args...
  local name="$1" data="$2"
  shift 2
  # shellcheck disable=SC2086
  "$BIN/featloc-bench" "$ROOT/config.ini" "$data" $COMMON -m "$M" $HEADER \
    --name "$name" "$@" -j "$(bench_file "$name").json"
}
# bench_run's main table (main_table NOTES), then HEADER cleared: the
# `bench` of the benches that print nothing else per data set.
bench_main_table() { # notes, name, data, extra args...
  local notes="$1"
  shift
  bench_run "$@" | main_table "$notes"
  HEADER=
}
# Keeps featloc-bench's main table (its header and rows; not --world's
# Cramer-Rao and moved-points tables) and the note lines that match the
# awk regex NOTES.
main_table() { # [notes]
  awk -F'|' -v notes="${1:-}" \
    '/^\| data \| matcher \| pairs \| flagged/ || (NF == 14 && !/pairs with a bound/) || (notes != "" && $0 ~ notes)'
}
# featloc-sim's log of worlds/SCENE.ini with 1 cm range noise, as
# $OUT/SCENE-1cm.rawlog (+ .gt.txt): the static calibration scenes; with a
# SEED, that seed's path as $OUT/SCENE-seedSEED.rawlog (whole runs).
sim_1cm() { # scene [seed]
  if [ $# -gt 1 ]; then
    "$BIN/featloc-sim" "$ROOT/worlds/$1.ini" --out "$OUT/$1-seed$2" --seed "$2" -q \
      --set Laser:range_noise=0.01 > /dev/null
  else
    "$BIN/featloc-sim" "$ROOT/worlds/$1.ini" --out "$OUT/$1-1cm" -q --set Laser:range_noise=0.01 > /dev/null
  fi
}
# featloc-sim's log of worlds/WORLD.ini as $OUT/NAME.rawlog (+ .gt.txt),
# made once per OUT; further arguments go to featloc-sim.
sim_world() { # world, name, featloc-sim args...
  [ -f "$OUT/$2.rawlog" ] ||
    "$BIN/featloc-sim" "$ROOT/worlds/$1.ini" --out "$OUT/$2" -q "${@:3}" > /dev/null
}
# sim_world, then the caller's `bench NAME DATA -g GT` on that log.
sim_world_and_bench() { # world, name, featloc-sim args...
  sim_world "$@"
  bench "$2" "$OUT/$2.rawlog" -g "$OUT/$2.gt.txt"
}
# The same with MRPT's simulator's 0.16 m range lattice (Laser:range_step,
# before the noise).
sim_lattice() { # world, name, featloc-sim args...
  sim_world "$1" "$2" --set Laser:range_step=0.16 "${@:3}"
}
# One featloc-run as config.ini has it but for the --set arguments, into
# $OUT/NAME (its console output in $OUT/NAME.txt), without the rawlog and
# 3-D scene outputs; fails if featloc-run does.
bench_featloc_run() { # name, input (empty: config.ini's), ground truth (empty: config.ini's or the log's), --set args...
  local name="$1" input="$2" gt="$3"
  shift 3
  local args=("$ROOT/config.ini")
  [ -n "$input" ] && args+=("$input")
  [ -n "$gt" ] && args+=(--set "Evaluation:ground_truth=$gt")
  "$BIN/featloc-run" "${args[@]}" -q --out "$OUT/$name" --set Output:write_scene=false \
    --set Output:write_rawlog=false "$@" > "$OUT/$name.txt" 2>&1
}
# featloc-sim's held-out corridor with people walking, seeds 1-6, as
# $OUT/corridor-people-seedSEED.rawlog (+ .gt.txt): the whole-run logs of
# issue 15's benches (made once per OUT).
sim_corridor_seeds() {
  local seed
  for seed in 1 2 3 4 5 6; do
    [ -f "$OUT/corridor-people-seed$seed.rawlog" ] ||
      "$BIN/featloc-sim" "$ROOT/worlds/corridor-people.ini" --out "$OUT/corridor-people-seed$seed" \
        --seed "$seed" -q > /dev/null
  done
}
# The setting of issue 15's benches of one switch (bench-line-bow.sh,
# bench-face-lines.sh, bench-round-things.sh): PCM, IDC and CF-IDC as
# config.ini has them and MRPT's ICP (M), Borges & Aldon's protocol, seed 1
# (COMMON), the switch KEY set to 0 in [ScanMatcher.IdcMatcher] and
# [ScanMatcher.CfIdcMatcher] as the other way (OFF, named OFF_NAME), and
# `bench` as switch_bench.
switch_setup() { # key, name of the other way[, the key's value that way (0)]
  M="PCM=featloc::PcmFeatureMatcher,IDC=featloc::IdcMatcher,CF-IDC=featloc::CfIdcMatcher"
  M="$M,IcpMatcher (MRPT)=featloc::IcpMatcher"
  COMMON="--seed 1 -q --paired-with none --perturb-xy 0.3 --perturb-yaw-deg 10"
  OFF=(--set "ScanMatcher.IdcMatcher:$1=${3:-0}" --set "ScanMatcher.CfIdcMatcher:$1=${3:-0}")
  OFF_NAME="$2"
  HEADER=--header
  BOUNDED=()
  bench() { switch_bench "$@"; }
}
# Issue 15's benches of one switch (bench-line-bow.sh, bench-face-lines.sh, bench-round-things.sh):
# each data set run as config.ini has it ("NAME") and with the caller's OFF
# array of --set options ("NAME, $OFF_NAME"); with --world also the
# Cramer-Rao table of each and every pair's outcome and bound, the names
# kept in BOUNDED for switch_bound_ratios. The caller's `bench` calls it.
switch_bench() { # name, data, extra args...
  local name="$1" data="$2" notes="fallback .* made"
  shift 2
  if [[ " $* " == *" --world "* ]]; then
    local f
    f="$(bench_file "$name")"
    bench_run "$name" "$data" "$@" --pairs "$f.pairs.tsv" --pair-bounds "$f.bounds.tsv" |
      awk -F'|' '/^\| data \| matcher \| pairs/ || NF == 14 || NF == 9'
    HEADER=
    f="$(bench_file "$name, $OFF_NAME")"
    bench_run "$name, $OFF_NAME" "$data" "$@" "${OFF[@]}" --pairs "$f.pairs.tsv" \
      --pair-bounds "$f.bounds.tsv" | awk -F'|' 'NF == 14 || NF == 9'
    BOUNDED+=("$name" "$name, $OFF_NAME")
  else
    bench_main_table "$notes" "$name" "$data" "$@"
    bench_main_table "$notes" "$name, $OFF_NAME" "$data" "$@" "${OFF[@]}"
  fi
}
# A world's static twin through the caller's `bench`, against the bound.
switch_frozen_world() { # world, name, featloc-sim args...
  sim_world "$1" "$2" --frozen "${@:3}"
  bench "$2" "$OUT/$2.rawlog" -g "$OUT/$2.gt.txt" --world "$ROOT/worlds/$1.ini" --frozen
}
# scripts/pair-bound-ratios.py on every run switch_bench kept in BOUNDED,
# one table.
switch_bound_ratios() {
  local name f header=1
  for name in "${BOUNDED[@]}"; do
    f="$(bench_file "$name")"
    [ -f "$f.bounds.tsv" ] || continue
    python3 "$ROOT/scripts/pair-bound-ratios.py" "$f.pairs.tsv" "$f.bounds.tsv" |
      if [ -n "$header" ]; then cat; else tail -n +3; fi
    header=
  done
}
# The curved worlds written for issue 15 (rotunda, ring-corridor, orchard,
# mine-gallery, in the order given) as written, then their static twins
# against the bound (the rotunda and the orchard at 1 cm, the ring and the
# mine at their Hokuyo's 1.5 cm), the data sets of
# bench_extraction_scenes_and_the_rest, and switch_bound_ratios' table:
# through the caller's `bench` (switch_bench).
switch_curved_worlds_and_the_rest() { # worlds...
  local w
  for w in "$@"; do sim_world_and_bench "$w" "${w//-/ }"; done
  echo
  HEADER=--header
  for w in "$@"; do
    if [ "$w" = ring-corridor ] || [ "$w" = mine-gallery ]; then
      switch_frozen_world "$w" "${w//-/ } frozen"
    else
      switch_frozen_world "$w" "$w frozen (1 cm)" --set Laser:range_noise=0.01
    fi
  done
  bench_extraction_scenes_and_the_rest
  echo
  echo "### Against each pair's Cramer-Rao bound: the right matches (used, within 10 cm and 2 deg)"
  echo
  switch_bound_ratios
}
# Whole runs (featloc-run as config.ini has it, tagged ON, and with OFF,
# tagged OFF_TAG) of each featloc matcher as the matcher chain and in the
# EKF, on each case LOG:INPUT:GT (bench_featloc_run's input and ground
# truth): one table row per log, estimator and matcher, the OFF run first.
switch_whole_runs() { # on tag, off tag, cases...
  local on="$1" off="$2" c log input gt est m name
  shift 2
  for c in "$@"; do
    IFS=: read -r log input gt <<< "$c"
    for est in matcher ekf; do
      for m in PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
        name="whole-${log// /-}-$est-$m"
        bench_featloc_run "$name-$on" "$input" "$gt" --set "Pipeline:estimator=$est" \
          --set "ScanMatcher:class=featloc::$m"
        bench_featloc_run "$name-$off" "$input" "$gt" --set "Pipeline:estimator=$est" \
          --set "ScanMatcher:class=featloc::$m" "${OFF[@]}"
        echo "| $log | $m | $est | $(run_counts "$name-$off") | $(run_counts "$name-$on") | $(runs_paired "$gt" "$OUT/$name-$on" "$OUT/$name-$off") |"
      done
    done
  done
}
# Whole runs of one configuration two ways, A and B (featloc-run with the
# --set options of each, estimator EST), on the bundled log, the corridor
# with people (seeds SEEDS; sim_corridor_seeds first) and the held-out
# Radish logs (references: scripts/carmen-reference.py): one table row per
# log, "| log | EST | A | B | B against A |": ATE rmse [mm] / failed matches
# / the fallback's matches of each, then B compared with A step by step
# (featloc-eval B --paired-with A: mean RPE difference [mm] with its 95%
# interval; the steps only one gets off by > 10 cm or 2 deg, McNemar's p).
# Runs in $OUT/LOG-EST-A and $OUT/LOG-EST-B; further arguments go to both.
# A "--set of" may hold several Section:key=value, separated by spaces.
whole_runs_two_ways() { # est, seeds, label A, --set of A, label B, --set of B, featloc-run args...
  local est="$1" seeds="$2" a="$3" b="$5" cases=() c name input gt ref s f kv words set_a=() set_b=()
  # Split at spaces with read, not by an unquoted expansion: a value with
  # [ ] or * would be matched against the files of the working directory.
  read -r -a words <<< "$4"
  for kv in "${words[@]}"; do set_a+=(--set "$kv"); done
  read -r -a words <<< "$6"
  for kv in "${words[@]}"; do set_b+=(--set "$kv"); done
  shift 6
  cases=("bundled::$ROOT/rawlogs/mrpt-simul/simul.gt.txt")
  for s in $seeds; do cases+=("corridor-seed$s:$OUT/corridor-people-seed$s.rawlog:$OUT/corridor-people-seed$s.gt.txt"); done
  for f in $(held_out_radish_logs); do cases+=("$(basename "$f" -corrected.log.gz):$f:"); done
  for c in "${cases[@]}"; do
    IFS=: read -r name input gt <<< "$c"
    bench_featloc_run "$name-$est-$a" "$input" "$gt" --set "Pipeline:estimator=$est" "$@" "${set_a[@]}"
    bench_featloc_run "$name-$est-$b" "$input" "$gt" --set "Pipeline:estimator=$est" "$@" "${set_b[@]}"
    ref="$gt"
    if [ -z "$ref" ]; then
      ref="$OUT/$name.reference.txt"
      python3 "$ROOT/scripts/carmen-reference.py" "$input" "$OUT/$name-$est-$b/poses_cov.txt" > "$ref"
    fi
    echo "| $name | $est | $(run_counts "$name-$est-$a") | $(run_counts "$name-$est-$b") | $(runs_paired "$ref" "$OUT/$name-$est-$b" "$OUT/$name-$est-$a") |"
  done
}
# whole_runs_two_ways for PCM, IDC and CF-IDC, each as the matcher, with
# estimator = matcher and then ekf: KEY = A against KEY = B, set in the
# matcher's own section and in [ScanMatcher.IdcMatcher], which PCM's and
# CF-IDC's fallback reads (PCM_OWN = no: not in PCM's own section, whose
# matching has no such key). One table per matcher and estimator, headed
# with the labels; runs in $OUT/LOG-EST-MATCHER-LABEL.
featloc_matchers_two_ways() { # key, value A, label A, value B, label B, seeds, PCM_OWN (yes|no)
  local key="$1" va="$2" la="$3" vb="$4" lb="$5" seeds="$6" pcm_own="$7" est m own_a own_b
  for est in matcher ekf; do
    for m in PcmFeatureMatcher IdcMatcher CfIdcMatcher; do
      echo
      echo "### Whole runs, $m, estimator = $est: ATE rmse [mm] / failed matches / fallback matches, $key $va | $vb"
      echo
      echo "| log | estimator | $la | $lb | $lb against $la: mean RPE difference [mm] (95%); steps off only $lb / only $la, McNemar |"
      echo "|---|---|---|---|---|"
      own_a="ScanMatcher.$m:$key=$va" own_b="ScanMatcher.$m:$key=$vb"
      if [ "$m" = PcmFeatureMatcher ] && [ "$pcm_own" = no ]; then own_a="" own_b=""; fi
      # IDC's own section is the fallback's: set once.
      if [ "$m" != IdcMatcher ]; then
        own_a="$own_a ScanMatcher.IdcMatcher:$key=$va" own_b="$own_b ScanMatcher.IdcMatcher:$key=$vb"
      fi
      whole_runs_two_ways "$est" "$seeds" "$m-$la" "$own_a" "$m-$lb" "$own_b" \
        --set "ScanMatcher:class=featloc::$m"
    done
  done
}
# A bench_featloc_run's time per match (mean / median) and ATE rmse, as a
# table cell: "M / m ms, A mm".
match_time_and_ate() { # name: of $OUT/NAME
  jq -r '"\(.match_time_s.mean * 1e5 | round / 100) / \(.match_time_s.median * 1e5 | round / 100) ms, \(.evaluation.ate_m.rmse * 1000 | round) mm"' "$OUT/$1/summary.json"
}
# "ATE [mm] / failed matches / fallback matches" of the run $OUT/NAME.
run_counts() { jq -r '"\((.evaluation.ate_m.rmse // -0.001) * 1000 | round) / \(.counts.match_failures) / \(.counts.fallback_matcher_matches)"' "$OUT/$1/summary.json"; }
# Run B against run A step by step (featloc-eval REFERENCE B --paired-with A).
runs_paired() { # reference, run B, run A
  "$BIN/featloc-eval" "$1" "$2/poses_cov.txt" --paired-with "$3/poses_cov.txt" -j |
    jq -r '.paired | "\(.rpe_trans_mean_diff_m * 1e5 | round / 100) (\(.ci95_m[0] * 1e5 | round / 100), \(.ci95_m[1] * 1e5 | round / 100)); \(.off_only_this) / \(.off_only_other), p = \(.mcnemar_p * 1000 | round / 1000)"'
}
# A benchmark's laser matcher: MATCHER from its second argument (else the
# default given), and MATCHER_SETS, --set options for its arguments 3..
# (KEY=VALUE in that matcher's section).
matcher_args() { # default-matcher, script arguments...
  local default="$1" kv
  shift
  MATCHER="${2:-$default}"
  MATCHER_SETS=()
  for kv in "${@:3}"; do MATCHER_SETS+=(--set "ScanMatcher.${MATCHER#featloc::}:$kv"); done
}
# The rows of featloc-bench's paired table (--paired-with) in FILE, as
# "| data | LABEL | matcher | difference | split |" (LABEL: a seed, a protocol).
paired_rows() { # label, featloc-bench output file
  awk -v label="$1" '/paired with/ {on = 1; next}
    on && /^\| / && !/^\|---/ { sub(/^\| /, ""); sub(/ \|$/, ""); n = split($0, c, / \| /);
      if (n == 5) printf "| %s | %s | %s | %s | %s |\n", c[1], label, c[2], c[4], c[5] }' "$2"
}
# paired_rows lines of one data set on stdin (LABEL: the seed) -> one row
# per matcher, "| NAME | matcher | cell | cell ... |", a cell per label in
# order: "difference (interval); only this / only the other, p = P".
paired_by_seed() { # name
  awk -F' [|] ' -v name="$1" '{ m = $3; if (!(m in cells)) order[++n] = m
      cells[m] = cells[m] " | " $4 "; " substr($5, 1, length($5) - 2) }
    END { for (i = 1; i <= n; i++) printf "| %s | %s%s |\n", name, order[i], cells[order[i]] }'
}
