#!/usr/bin/env python3
"""How a CARMEN log's whole runs and scan pairs turn against the log's
corrected poses, step by step: the signed heading error per step, its mean
with a 95% interval, and where it leads (doc/benchmarks.md, "Issue 15,
seventeenth session": why the EKF's ATE on some Radish logs moves the way
it does).

Usage:
  scripts/heading-bias.py LOG RUN_DIR...
    RUN_DIR: a featloc-run of LOG (its poses_cov.txt, one row per FLASER);
    prints per run the mean signed heading error per step [deg] with its 95%
    interval and the sum over the log [deg]; and each run against the
    first, step by step (the reference cancels): the mean difference of
    their turns with its 95% interval, the sum, and the sum in units of
    sd x sqrt(steps), the spread a sum of independent step differences of
    that sd would have with no systematic difference at all.
  scripts/heading-bias.py LOG --pairs PAIRS.tsv
    PAIRS.tsv: `featloc-bench LOG --pairs PAIRS.tsv` (scan k against k - 1);
    prints per matcher, over the pairs it used (failures and errors above
    2 deg left out: a wrong minimum is not a bias), the mean signed heading
    error with its 95% interval, and the least-squares line error = a + b x
    rotation (b: how much of each turn the matcher adds); and, over the used
    pairs under 10 cm that moved at least 0.2 m, the mean error across the
    reference's direction of travel (+: to the left) with its 95% interval,
    and that as an angle of the mean step."""
import math
import sys

from planar_poses import read_carmen_reference, read_poses, relative, wrap


def mean_interval(v):
    n = len(v)
    m = sum(v) / n
    sd = math.sqrt(sum((x - m) ** 2 for x in v) / (n - 1)) if n > 1 else 0.0
    return m, 1.96 * sd / math.sqrt(n) if n > 1 else 0.0


def line_fit(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    b = sum((a - mx) * (c - my) for a, c in zip(x, y)) / sxx if sxx > 0 else 0.0
    res = [c - my - b * (a - mx) for a, c in zip(x, y)]
    s2 = sum(r * r for r in res) / (n - 2) if n > 2 else 0.0
    return my - b * mx, b, 1.96 * math.sqrt(s2 / sxx) if sxx > 0 else 0.0


def runs(log, dirs):
    ref = read_carmen_reference(log)
    turns = [relative(ref[k - 1], ref[k])[2] for k in range(1, len(ref))]
    print("%s: %d steps, the reference turns %+.1f deg in all" % (
        log.split("/")[-1], len(turns), math.degrees(sum(turns))))
    print("| run | heading error per step, mean [deg] (95% interval) | sum over the log [deg] |")
    print("|---|---|---|")
    own = []
    for d in dirs:
        est = [r[1:4] for r in read_poses(d.rstrip("/") + "/poses_cov.txt")]
        if len(est) != len(ref):
            sys.exit("%s: %d poses, but %s has %d FLASER messages" % (d, len(est), log, len(ref)))
        own.append([relative(est[k - 1], est[k])[2] for k in range(1, len(ref))])
        err = [wrap(t - r) for t, r in zip(own[-1], turns)]
        m, h = mean_interval(err)
        print("| %s | %+.4f (%+.4f, %+.4f) | %+.2f |" % (
            name(d), math.degrees(m), math.degrees(m - h), math.degrees(m + h),
            math.degrees(sum(err))))
    if len(dirs) < 2:
        return
    print()
    print("| run | against | turn difference per step, mean [deg] (95% interval) | sd [deg] "
          "| sum [deg] | sum / (sd sqrt(steps)) |")
    print("|---|---|---|---|---|---|")
    for d, turned in zip(dirs[1:], own[1:]):
        diff = [wrap(a - b) for a, b in zip(turned, own[0])]
        m, h = mean_interval(diff)
        sd = h / 1.96 * math.sqrt(len(diff))
        print("| %s | %s | %+.4f (%+.4f, %+.4f) | %.3f | %+.2f | %+.1f |" % (
            name(d), name(dirs[0]), math.degrees(m), math.degrees(m - h), math.degrees(m + h),
            math.degrees(sd), math.degrees(sum(diff)),
            sum(diff) / (sd * math.sqrt(len(diff))) if sd > 0 else 0.0))


def name(d):
    return d.rstrip("/").split("/")[-1]


def pairs(log, path):
    ref = read_carmen_reference(log)
    motions = [relative(ref[k - 1], ref[k]) for k in range(1, len(ref))]
    turns = [m[2] for m in motions]
    rows, lateral = {}, {}
    for line in open(path):
        if line.startswith("#"):
            continue
        f = line.rstrip("\n").split("\t")
        if f[3] == "failed":
            continue
        k, ex, ey, ew = int(f[2]), float(f[4]), float(f[5]), float(f[6])
        if abs(ew) < math.radians(2):
            rows.setdefault(f[1], []).append((turns[k], ew))
        mx, my, _ = motions[k]
        step = math.hypot(mx, my)
        if math.hypot(ex, ey) < 0.1 and step >= 0.2:
            lateral.setdefault(f[1], []).append(((-my * ex + mx * ey) / step, step))
    print("%s, pairs: the heading error of each matcher's used matches under 2 deg" % log.split("/")[-1])
    print("| matcher | pairs | mean [deg] (95% interval) | error = a + b x turn: a [deg] | b (95% interval) |")
    print("|---|---|---|---|---|")
    for name, v in rows.items():
        m, h = mean_interval([e for _, e in v])
        a, b, hb = line_fit([t for t, _ in v], [e for _, e in v])
        print("| %s | %d | %+.4f (%+.4f, %+.4f) | %+.4f | %+.4f (%+.4f, %+.4f) |" % (
            name, len(v), math.degrees(m), math.degrees(m - h), math.degrees(m + h),
            math.degrees(a), b, b - hb, b + hb))
    print()
    print("| matcher | pairs | error across the direction of travel, mean [mm] (95% interval) "
          "| as an angle of the mean step [deg] |")
    print("|---|---|---|---|")
    for name, v in lateral.items():
        m, h = mean_interval([e for e, _ in v])
        mean_step = sum(s for _, s in v) / len(v)
        print("| %s | %d | %+.1f (%+.1f, %+.1f) | %+.2f |" % (
            name, len(v), 1000 * m, 1000 * (m - h), 1000 * (m + h), math.degrees(m / mean_step)))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    if sys.argv[2] == "--pairs":
        pairs(sys.argv[1], sys.argv[3])
    else:
        runs(sys.argv[1], sys.argv[2:])
