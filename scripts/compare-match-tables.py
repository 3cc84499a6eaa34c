#!/usr/bin/env python3
"""Compares two featloc-run results folders' matches.txt against ground truth.

For the keyframe pairs both runs matched and whose estimates differ by more
than --min-diff metres, prints how far each run's estimate is from the
ground-truth relative motion (robot frame). Used in doc/benchmarks.md ("Wide
basin") to see where a change moves the matches.

Usage: scripts/compare-match-tables.py RUN_A RUN_B GROUND_TRUTH [--min-diff M]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bisect  # noqa: E402

from planar_poses import read_poses, relative  # noqa: E402


def load(folder):
    rows = {}
    with open(os.path.join(folder, "matches.txt")) as f:
        for line in f:
            if line.startswith("#"):
                continue
            c = line.split()
            rows[(c[0], c[1])] = (float(c[12]), float(c[13]), float(c[14]))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run_a")
    ap.add_argument("run_b")
    ap.add_argument("ground_truth")
    ap.add_argument("--min-diff", type=float, default=0.05)
    a = ap.parse_args()
    gt = read_poses(a.ground_truth)
    times = [r[0] for r in gt]

    def pose_at(t):
        """The ground-truth pose within 1 ms of t (None if none)."""
        i = bisect.bisect_left(times, t - 1e-3)
        return gt[i][1:] if i < len(gt) and abs(gt[i][0] - t) <= 1e-3 else None

    ra, rb = load(a.run_a), load(a.run_b)
    ea, eb = [], []
    for key in ra:
        if key not in rb:
            continue
        x, y = ra[key], rb[key]
        if math.hypot(x[0] - y[0], x[1] - y[1]) < a.min_diff:
            continue
        p0, p1 = pose_at(float(key[1])), pose_at(float(key[0]))
        if p0 is None or p1 is None:
            continue
        tr = relative(p0, p1)
        ea.append(math.hypot(x[0] - tr[0], x[1] - tr[1]))
        eb.append(math.hypot(y[0] - tr[0], y[1] - tr[1]))
    print("common pairs %d, differing by > %.2f m: %d" % (len([k for k in ra if k in rb]), a.min_diff, len(ea)))
    if ea:
        print("mean error there: A %.3f m, B %.3f m; B closer in %d of %d"
              % (sum(ea) / len(ea), sum(eb) / len(eb), sum(1 for i in range(len(ea)) if eb[i] < ea[i]), len(ea)))


if __name__ == "__main__":
    main()
