#!/usr/bin/env bash
# featloc-live against featloc-sim's device emulator (a Hokuyo UTM-30LX at
# 40 Hz in SCIP 2.0 and odometry at 100 Hz, office world), for SECONDS
# (default 20), then featloc-run replays the recording. Prints the live
# run's pose latency and ATE and the replay's ATE (doc/benchmarks.md,
# "Live run against the emulator"). Needs a build (scripts/test.sh).
# LIDAR=hokuyo (default) | sick | both: the laser(s) served and run (the SICK
# LMS1xx at 25 Hz, MRPT's CLMS100Eth taking ~15 s to set it up; with both,
# featloc matches the Hokuyo's scans and records both).
# WORLD=FILE serves another world (default worlds/office.ini); EMULATOR_ARGS
# adds featloc-sim options (e.g. "--odometry-port 0": a robot without
# odometry, with --set Live:sensors=LASER).
# STEREO=1: Moon et al.'s stereo landmarks live (configs/live-stereo-emulator.ini,
# default world worlds/moon-lab.ini: 2 m in about 6 s, so SECONDS <= 6): the
# emulator also writes its stereo camera's recording, MRPT's CCameraSensor
# (grabber_type = rawlog) replays it, the EKF fuses laser, odometry and the
# vertical-line landmarks.
# LIVE_CPU=N pins featloc-live (all its threads) to core N with taskset,
# the emulator running on the other cores: "keeps up on one core".
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="$ROOT/build/bin"
SECS="${1:-20}"
shift $(( $# > 0 ? 1 : 0 ))  # the rest: featloc-live options (--set ...), for the replay too
OUT="${OUT:-/tmp/featloc-live-demo}"
rm -rf "$OUT" && mkdir -p "$OUT"
case "${LIDAR:-hokuyo}" in
  hokuyo) EMU_LIDAR=(--set Laser:rate=40); LIVE_LIDAR=() ;;
  sick) EMU_LIDAR=(--laser-port 0 --sick-port 2111 --set Laser:rate=25)
        LIVE_LIDAR=(--set "Live:sensors=SICK ODOMETRY" --set Input:laser_label=SICK) ;;
  both) EMU_LIDAR=(--sick-port 2111 --set Laser:rate=25)
        LIVE_LIDAR=(--set "Live:sensors=LASER SICK ODOMETRY") ;;
  *) echo "LIDAR must be hokuyo, sick or both" >&2; exit 2 ;;
esac
CONFIG="$ROOT/configs/live-emulator.ini"
DEFAULT_WORLD="$ROOT/worlds/office.ini"
LIVE_CAMERA=()
if [ -n "${STEREO:-}" ]; then
  CONFIG="$ROOT/configs/live-stereo-emulator.ini"
  DEFAULT_WORLD="$ROOT/worlds/moon-lab.ini"
  LIVE_CAMERA=(--set CAMERA:rawlog_file="$OUT/emu.camera.rawlog")
fi
"$BIN/featloc-sim" "${WORLD:-$DEFAULT_WORLD}" --out "$OUT/emu" --serve -q \
  --set Laser:preset=hokuyo_utm30lx "${EMU_LIDAR[@]}" --set Odometry:rate=100 \
  --set Simulation:duration=$((SECS + 30)) ${EMULATOR_ARGS:-} > "$OUT/emulator.txt" 2>&1 &
emu=$!
trap 'kill -TERM $emu 2>/dev/null || true' EXIT
# featloc-sim simulates the log before it opens its ports: wait for its
# devices (up to 60 s), not a fixed time.
for _ in $(seq 600); do
  grep -q 'waiting for the drivers to connect' "$OUT/emulator.txt" 2>/dev/null && break
  kill -0 $emu 2>/dev/null || { cat "$OUT/emulator.txt" >&2; exit 1; }
  sleep 0.1
done
PIN=()
if [ -n "${LIVE_CPU:-}" ]; then
  PIN=(taskset -c "$LIVE_CPU")
  taskset -pc "$(( LIVE_CPU == 0 ? 1 : 0 ))" $emu > /dev/null  # the emulator elsewhere
fi
"${PIN[@]}" "$BIN/featloc-live" "$CONFIG" --out "$OUT/live" --duration "$SECS" \
  --set Evaluation:ground_truth="$OUT/emu.served.gt.txt" --set Live:status_period=5 \
  "${LIVE_LIDAR[@]}" "${LIVE_CAMERA[@]}" "$@"
kill -TERM $emu; wait $emu || true; trap - EXIT
"$BIN/featloc-run" "$CONFIG" "$OUT/live/live.rawlog" -q \
  --out "$OUT/replay" --set Evaluation:ground_truth="$OUT/emu.served.gt.txt" "${LIVE_LIDAR[@]}" \
  "${LIVE_CAMERA[@]}" "$@" \
  > "$OUT/replay.txt"
echo "--- replay of live.rawlog with featloc-run:"
grep -E "ATE translation|matches:" "$OUT/replay.txt"
if diff -q <(grep -v '^#' "$OUT/live/trajectory.tum") <(grep -v '^#' "$OUT/replay/trajectory.tum") > /dev/null; then
  echo "replay poses: identical to the live run's"
else
  echo "replay poses: DIFFER from the live run's"; exit 1
fi
