#!/usr/bin/env python3
"""Per-step odometry error of a log against its ground truth, with the
step's duration: what OdometrySamplingOffset models (doc/benchmarks.md,
"Odometry read off the scan's instant").

Usage: scripts/odometry-step-errors.py POSES_COV GROUND_TRUTH [N]
  POSES_COV: poses_cov.txt of `featloc-run ... --set Pipeline:estimator=odometry`
  GROUND_TRUTH: 't x y yaw' rows (MRPT .GT.txt)
Prints the N largest per-step errors (default 6) with the step before and
after, and the error quantiles."""
import bisect
import math
import sys

from planar_poses import read_poses, relative


odo, gt = read_poses(sys.argv[1]), read_poses(sys.argv[2])
n = int(sys.argv[3]) if len(sys.argv) > 3 else 6
gtt = [g[0] for g in gt]


def gt_at(t):
    i = min(bisect.bisect_left(gtt, t - 1e-4), len(gt) - 1)
    return gt[i][1:4]


steps = []
for k in range(1, len(odo)):
    o = relative(odo[k - 1][1:4], odo[k][1:4])
    g = relative(gt_at(odo[k - 1][0]), gt_at(odo[k][0]))
    steps.append((k, odo[k][0] - odo[k - 1][0], math.hypot(*o[:2]), math.hypot(*g[:2]),
                  math.hypot(o[0] - g[0], o[1] - g[1]), math.degrees(o[2]), math.degrees(g[2])))
errs = sorted(s[4] for s in steps)
q = lambda p: errs[min(len(errs) - 1, int(p * len(errs)))]
print("steps %d: error median %.4f m, p95 %.4f m, max %.4f m; step length median %.4f m" % (
    len(steps), q(0.5), q(0.95), errs[-1], sorted(s[3] for s in steps)[len(steps) // 2]))
print("step  dt[s]  odometry[m]  truth[m]  error[m]  odometry[deg]  truth[deg]   (largest errors, with the steps around them)")
for k, *_ in sorted(steps, key=lambda s: -s[4])[:n]:
    for s in steps[max(0, k - 2):k + 1]:
        print("%4d  %5.3f  %10.3f  %8.3f  %8.3f  %12.2f  %10.2f" % s)
    print()
