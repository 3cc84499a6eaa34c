#!/usr/bin/env python3
"""How a CARMEN log's odometry, as featloc-run reads it, moves against the
log's corrected poses, step by step (doc/benchmarks.md, "Gates and odometry
covariance": the Radish logs' wheel odometry).

Usage: scripts/carmen-odometry-errors.py LOG POSES_COV
  LOG: the CARMEN log (.log or .log.gz); its FLASER x y theta are the reference
  POSES_COV: poses_cov.txt of `featloc-run config.ini LOG --set
    Pipeline:estimator=odometry` (one row per FLASER, in order)
Prints, over the steps where both moved at least 0.1 m, the angle between the
odometry's direction of travel and the reference's (median, quartiles), and
over all steps the error of the odometry's turn (p10, median, p90), in deg."""
import math
import sys

from planar_poses import read_carmen_reference, read_poses, relative

ref = read_carmen_reference(sys.argv[1])
odo = [r[1:4] for r in read_poses(sys.argv[2])]
if len(ref) != len(odo):
    sys.exit("%d FLASER messages but %d poses" % (len(ref), len(odo)))
direction, turn = [], []
for k in range(1, len(ref)):
    r, o = relative(ref[k - 1], ref[k]), relative(odo[k - 1], odo[k])
    turn.append(math.degrees(math.atan2(math.sin(o[2] - r[2]), math.cos(o[2] - r[2]))))
    if math.hypot(r[0], r[1]) >= 0.1 and math.hypot(o[0], o[1]) >= 0.1:
        direction.append(math.degrees(math.atan2(o[0] * r[1] - o[1] * r[0], o[0] * r[0] + o[1] * r[1])))
q = lambda v, p: sorted(v)[min(len(v) - 1, int(p * len(v)))]
print("%s: %d steps; direction of travel, odometry against reference [deg] (%d steps): median %.2f, "
      "quartiles %.2f / %.2f; turn error [deg]: p10 %.2f, median %.2f, p90 %.2f" % (
          sys.argv[1].split("/")[-1], len(ref) - 1, len(direction), q(direction, 0.5),
          q(direction, 0.25), q(direction, 0.75), q(turn, 0.1), q(turn, 0.5), q(turn, 0.9)))
