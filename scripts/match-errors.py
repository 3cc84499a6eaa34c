#!/usr/bin/env python3
"""Errors of a run's scan matches against ground truth, from matches.txt.

Usage: scripts/match-errors.py RESULTS/matches.txt GT [--all | --print-signed]

For every match that did not succeed (status failed or gate) -- or every
match with --all -- prints the converged estimate's error and the initial
guess's (odometry's) error against the ground truth's relative motion
between the reference scan's time and the current scan's, so that a guess
gate's rejection can be told right (the estimate is wrong) or wrong (the
estimate is right and the guess is not). With --all it ends with the
successful matches' signed errors (mean and standard deviation: a bias
shows in the mean) beside the standard deviation their covariances
predict. --print-signed prints only the successful matches' signed
errors, one "x y [m] yaw [deg]" row each (scripts/bench-match-bias.sh).
GT: 't x y yaw' rows (MRPT's .GT.txt) or TUM; nearest row within 10 ms.
"""
import bisect
import math
import sys

from planar_poses import read_poses, relative, wrap


def nearest(rows, times, t):
    i = bisect.bisect_left(times, t)
    best = min((j for j in (i - 1, i) if 0 <= j < len(rows)), key=lambda j: abs(times[j] - t))
    return rows[best] if abs(times[best] - t) <= 0.01 else None


def error(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1]), math.degrees(wrap(p[2] - q[2]))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    gt = read_poses(sys.argv[2])
    times = [r[0] for r in gt]
    only_signed = "--print-signed" in sys.argv
    every = "--all" in sys.argv or only_signed
    if not only_signed:
        print("t ref_t status used | estimate error m deg | guess error m deg | reason")
    counts = {}
    signed = []  # successful matches: (error x, y [m], yaw [rad]), predicted sigmas
    for line in open(sys.argv[1]):
        if line.startswith("#"):
            continue
        f = line.split()
        t, ref_t, status, used = float(f[0]), float(f[1]), f[2], f[3]
        if status == "ok" and not every:
            continue
        a, b = nearest(gt, times, ref_t), nearest(gt, times, t)
        if not a or not b:
            print(f"{t:.3f} {ref_t:.3f} {status} {used} | no ground truth at these times")
            continue
        truth = relative(a[1:4], b[1:4])
        guess = tuple(map(float, f[9:12]))
        est = tuple(map(float, f[12:15]))
        ee, ge = error(est, truth), error(guess, truth)
        if status in ("ok", "overruled"):
            cov = list(map(float, f[15:21]))  # c_xx c_xy c_xyaw c_yy c_yyaw c_yawyaw
            signed.append(((est[0] - truth[0], est[1] - truth[1], wrap(est[2] - truth[2])),
                           (math.sqrt(cov[0]), math.sqrt(cov[3]), math.sqrt(cov[5]))))
        right = ee[0] <= 0.05 and abs(ee[1]) <= 1.0
        counts[(status, right)] = counts.get((status, right), 0) + 1
        if only_signed:
            continue
        print(f"{t:.3f} {ref_t:.3f} {status} {used} | {ee[0]:.3f} {ee[1]:+.2f} | "
              f"{ge[0]:.3f} {ge[1]:+.2f} | {' '.join(f[33:])[:90]}")
    if only_signed:
        for (ex, ey, ew), _ in signed:
            print(f"{ex:.6f} {ey:.6f} {math.degrees(ew):.6f}")
        return
    for (status, right), n in sorted(counts.items()):
        print(f"# {status}: {n} with the estimate {'within' if right else 'outside'} 0.05 m / 1 deg of the truth")
    if every and signed:
        n = len(signed)
        for k, (name, scale, unit) in enumerate((("x", 1e3, "mm"), ("y", 1e3, "mm"), ("yaw", math.degrees(1), "deg"))):
            e = [v[0][k] * scale for v in signed]
            mean = sum(e) / n
            sd = math.sqrt(sum((x - mean) ** 2 for x in e) / n)
            predicted = math.sqrt(sum((v[1][k] * scale) ** 2 for v in signed) / n)
            print(f"# successful matches ({n}), {name} error: mean {mean:+.4f} {unit}, sd {sd:.4f} {unit}; "
                  f"the covariances' sigma (rms) {predicted:.4f} {unit}")


if __name__ == "__main__":
    main()
