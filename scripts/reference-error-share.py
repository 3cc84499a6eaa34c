#!/usr/bin/env python3
"""How much of a matcher's error against a real log's reference poses is the
reference's own, and is each matcher's covariance consistent with the rest
(issue 15, item 5)?

Input: featloc-bench --pairs FILE (one or more files), with three or more
matchers run on the same pairs. For matcher A on a pair,

  e_A = estimate_A - reference = n_A - r

where n_A is A's own error (against the unknown truth) and r the reference
poses' error there, the same for every matcher. Differences between
matchers cancel r:

  d_AB = e_A - e_B = n_A - n_B.

Per data set and matcher A, with B and C the first two other matchers, over
the pairs all three used (neither failed nor flagged ambiguous):

- the NEES against the reference, as featloc-bench computes it;
- the three-cornered hat (the clock-stability estimate of each of three
  instruments' own variance from their pairwise differences, assuming their
  own errors independent): var n_A = (var d_AB + var d_AC - var d_BC) / 2
  per axis, against the variance A's covariance reports (mean of P_A's
  diagonal): their ratio is 1 for a consistent covariance, above 1 for an
  over-confident one. Matchers whose errors share a cause (IDC and CF-IDC)
  break the assumption and come out too small;
- the shared error (the reference's, and whatever in the scans misleads
  every matcher alike): the cross-covariance of e_B and e_C (symmetrised,
  negative eigenvalues set to 0), its axes' standard deviations;
- the difference NEES of A against each other matcher B over the pairs both
  used, d_AB^T (P_A + P_B)^-1 d_AB: 3 when both covariances are consistent
  and their own errors independent (less when they share errors), so a mean
  far above 3 says that A or B is over-confident whatever the reference's
  quality.

Usage: scripts/reference-error-share.py PAIRS.tsv [PAIRS.tsv ...]
"""
import math
import sys
from collections import defaultdict


def read(paths):
    """{data: {matcher: {pair: (status, err[3], cov[3][3])}}}, matchers in file order."""
    out = defaultdict(dict)
    order = defaultdict(list)
    for path in paths:
        with open(path) as f:
            for n, line in enumerate(f, 1):
                if line.startswith("#") or not line.strip():
                    continue
                c = line.rstrip("\n").split("\t")
                if len(c) != 14:
                    sys.exit(f"{path}:{n}: {len(c)} columns, expected 14 (featloc-bench --pairs)")
                data, matcher, pair, status = c[0], c[1], int(c[2]), c[3]
                v = [float(x) for x in c[4:13]]
                e = v[0:3]
                xx, xy, xw, yy, yw, ww = v[3:9]
                cov = [[xx, xy, xw], [xy, yy, yw], [xw, yw, ww]]
                if matcher not in out[data]:
                    out[data][matcher] = {}
                    order[data].append(matcher)
                out[data][matcher][pair] = (status, e, cov)
    return out, order


def inv3(m):
    a, b, c = m[0]
    d, e, f = m[1]
    g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    if det == 0 or not math.isfinite(det):
        return None
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]


def quad(e, m):
    return sum(e[p] * m[p][q] * e[q] for p in range(3) for q in range(3))


def eigen_sym(m):
    """Eigenvalues and eigenvectors (columns of V) of the symmetric part of
    a 3x3 matrix, by Jacobi rotations."""
    a = [[(m[p][q] + m[q][p]) / 2 for q in range(3)] for p in range(3)]
    v = [[1.0 if p == q else 0.0 for q in range(3)] for p in range(3)]
    for _ in range(50):
        off = max(abs(a[p][q]) for p in range(3) for q in range(3) if p != q)
        if off < 1e-30:
            break
        for p in range(3):
            for q in range(p + 1, 3):
                if abs(a[p][q]) < 1e-300:
                    continue
                theta = (a[q][q] - a[p][p]) / (2 * a[p][q])
                t = (1 if theta >= 0 else -1) / (abs(theta) + math.sqrt(theta * theta + 1))
                c = 1 / math.sqrt(t * t + 1)
                s = t * c
                for k in range(3):
                    akp, akq = a[k][p], a[k][q]
                    a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
                for k in range(3):
                    apk, aqk = a[p][k], a[q][k]
                    a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
                for k in range(3):
                    vkp, vkq = v[k][p], v[k][q]
                    v[k][p], v[k][q] = c * vkp - s * vkq, s * vkp + c * vkq
    return [a[k][k] for k in range(3)], v


def psd(m):
    """Symmetric part with negative eigenvalues set to zero."""
    lam, v = eigen_sym(m)
    lam = [max(0.0, x) for x in lam]
    return [[sum(v[p][k] * lam[k] * v[q][k] for k in range(3)) for q in range(3)] for p in range(3)]


def cross_cov(eb, ec):
    n = len(eb)
    mb = [sum(x[k] for x in eb) / n for k in range(3)]
    mc = [sum(x[k] for x in ec) / n for k in range(3)]
    return [[sum((eb[i][p] - mb[p]) * (ec[i][q] - mc[q]) for i in range(n)) / (n - 1)
             for q in range(3)] for p in range(3)]


def var(xs):
    n = len(xs)
    m = sum(xs) / n
    return sum((x - m) ** 2 for x in xs) / (n - 1)


def mean(xs):
    return sum(xs) / len(xs)


def summary(xs, bound=7.81):  # chi2, 3 dof, 95%
    if not xs:
        return "-"
    return f"{mean(xs):.2f} / {100 * sum(x <= bound for x in xs) / len(xs):.0f}%"


def nees(e, P):
    pi = inv3(P)
    return None if pi is None else quad(e, pi)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    data, order = read(sys.argv[1:])
    axes = ("x", "y", "yaw")
    print("Own errors (three-cornered hat) against the covariances, and the shared error")
    print()
    print("| data | matcher | with | pairs | NEES against the reference: mean / in 95% | "
          "own sd: x, y [mm], yaw [deg] | reported sd: x, y [mm], yaw [deg] | own / reported | "
          "shared sd: x, y [mm], yaw [deg] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, matchers in data.items():
        names = order[name]
        if len(names) < 3:
            sys.exit(f"{name}: {len(names)} matchers; three or more are needed")
        for a in names:
            b, c = [m for m in names if m != a][:2]
            used = [k for k in matchers[a] if all(
                k in matchers[m] and matchers[m][k][0] == "used" for m in (a, b, c))]
            raw = [v for v in (nees(e, P) for st, e, P in matchers[a].values() if st != "failed")
                   if v is not None]
            if len(used) < 10:
                print(f"| {name} | {a} | {b}, {c} | {len(used)} (too few) | {summary(raw)} | | | | |")
                continue
            ea = [matchers[a][k][1] for k in used]
            eb = [matchers[b][k][1] for k in used]
            ec = [matchers[c][k][1] for k in used]
            own, reported = [], []
            for i in range(3):
                vab = var([x[i] - y[i] for x, y in zip(ea, eb)])
                vac = var([x[i] - y[i] for x, y in zip(ea, ec)])
                vbc = var([x[i] - y[i] for x, y in zip(eb, ec)])
                own.append((vab + vac - vbc) / 2)
                reported.append(mean([matchers[a][k][2][i][i] for k in used]))
            R = psd(cross_cov(eb, ec))
            scale = (1e3, 1e3, math.degrees(1))

            def sds(vs):
                return ", ".join("-" if v < 0 else f"{math.sqrt(v) * f:.{1 if i < 2 else 3}f}"
                                 for i, (v, f) in enumerate(zip(vs, scale)))
            ratios = ", ".join("-" if o < 0 or r <= 0 else f"{math.sqrt(o / r):.1f}"
                               for o, r in zip(own, reported))
            print(f"| {name} | {a} | {b}, {c} | {len(used)} | {summary(raw)} | {sds(own)} | "
                  f"{sds(reported)} | {ratios} | {sds([R[i][i] for i in range(3)])} |")
    print()
    print("Difference NEES: d^T (P_A + P_B)^-1 d, d = e_A - e_B, over the pairs both used "
          "(3 if both covariances are consistent and their own errors independent)")
    print()
    print("| data | A | B | pairs | mean / in 95% |")
    print("|---|---|---|---|---|")
    for name, matchers in data.items():
        names = order[name]
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                vals = []
                for k, (st, e, P) in matchers[a].items():
                    if st != "used" or k not in matchers[b] or matchers[b][k][0] != "used":
                        continue
                    _, f, Q = matchers[b][k]
                    v = nees([x - y for x, y in zip(e, f)],
                             [[P[p][q] + Q[p][q] for q in range(3)] for p in range(3)])
                    if v is not None:
                        vals.append(v)
                print(f"| {name} | {a} | {b} | {len(vals)} | {summary(vals)} |")


if __name__ == "__main__":
    main()
