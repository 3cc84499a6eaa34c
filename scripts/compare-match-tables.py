#!/usr/bin/env python3
"""Compares two featloc-run results folders' matches.txt against ground truth.

For the keyframe pairs both runs matched and whose estimates differ by more
than --min-diff metres, prints how far each run's estimate is from the
ground-truth relative motion (robot frame). Then, per run, the errors of its
keyframe links (the matches whose current scan became the next keyframe,
the ones a matcher chain composes): rms and summed along-track (x) and yaw
errors, and the random walk's spread of that sum (rms x sqrt(links)); and
the paired difference B - A of the along-track error over every common
match. Used in doc/benchmarks.md ("Wide basin") to see where a change moves
the matches, and whether a whole-run difference is more than one draw.

Usage: scripts/compare-match-tables.py RUN_A RUN_B GROUND_TRUTH [--min-diff M]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bisect  # noqa: E402

from planar_poses import read_poses, relative, wrap  # noqa: E402


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

    def err(key, est):
        p0, p1 = pose_at(float(key[1])), pose_at(float(key[0]))
        if p0 is None or p1 is None:
            return None
        tr = relative(p0, p1)
        return est[0] - tr[0], wrap(est[2] - tr[2])
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
    for name, rows in (("A", ra), ("B", rb)):
        refs = {key[1] for key in rows}
        links = [e for e in (err(k, v) for k, v in rows.items() if k[0] in refs) if e]
        if not links:
            continue
        n = len(links)
        rx = math.sqrt(sum(e[0] ** 2 for e in links) / n)
        rw = math.sqrt(sum(e[1] ** 2 for e in links) / n)
        print("%s: %d keyframe links: along-track rms %.1f mm, sum %.3f m (random walk %.3f m); "
              "yaw rms %.3f deg, sum %.2f deg (random walk %.2f deg)"
              % (name, n, 1e3 * rx, sum(e[0] for e in links), rx * math.sqrt(n),
                 math.degrees(rw), math.degrees(sum(e[1] for e in links)), math.degrees(rw) * math.sqrt(n)))
    d = []
    for key in ra:
        if key in rb:
            x, y = err(key, ra[key]), err(key, rb[key])
            if x and y:
                d.append(y[0] - x[0])
    if len(d) > 1:
        m = sum(d) / len(d)
        sd = math.sqrt(sum((v - m) ** 2 for v in d) / (len(d) - 1))
        print("paired along-track error B - A over %d common matches: %.2f +- %.2f mm (mean +- its standard error)"
              % (len(d), 1e3 * m, 1e3 * sd / math.sqrt(len(d))))


if __name__ == "__main__":
    main()
