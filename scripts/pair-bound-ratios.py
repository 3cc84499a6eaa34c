#!/usr/bin/env python3
"""Each matcher's errors and covariances against each pair's Cramer-Rao
bound, axis by axis (issue 15, items 5 and 6): where a matcher is far from
the bound, or over-confident, which direction is it?

Input: featloc-bench --pairs PAIRS.tsv and --pair-bounds BOUNDS.tsv of the
same run (--world). Over the pairs a matcher used and got right (status
"used", within 10 cm and 2 deg: the ones whose covariance claims to
describe them), per data set and matcher:

- NEES e^T P^-1 e against the matcher's own covariance P (3 if consistent),
  and its mean split along P's eigenvectors (yaw in radians taken as
  metres), least certain first (1, 1, 1 if consistent): which of the
  claimed directions the over-confidence is in (the last is mostly the
  heading);
- e^T B^-1 e against the bound B (3 for an efficient matcher; more is how
  far from the bound, in the bound's own metric);
- per axis (x, y along the reference's robot frame, yaw): the RMS error over
  the RMS bound sigma, and the median of the claimed sigma over the bound's;
- the share of pairs whose covariance claims more than the bound allows
  along some direction (the smallest eigenvalue of B^-1 P under 0.9): such
  a covariance is over-confident whatever the matcher does.

Usage: scripts/pair-bound-ratios.py PAIRS.tsv BOUNDS.tsv
"""
import importlib.util
import math
import os
import statistics
import sys

_spec = importlib.util.spec_from_file_location(
    "reference_error_share", os.path.join(os.path.dirname(__file__), "reference-error-share.py"))
_share = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_share)
inv3, quad, read_pairs, eigen_sym = _share.inv3, _share.quad, _share.read, _share.eigen_sym

GROSS_T, GROSS_W = 0.10, math.radians(2)


def read_bounds(path):
    """{data: {pair: B (3x3) or None}} from featloc-bench --pair-bounds."""
    out = {}
    with open(path) as f:
        for n, line in enumerate(f, 1):
            if line.startswith("#") or not line.strip():
                continue
            c = line.rstrip("\n").split("\t")
            if len(c) != 15:
                sys.exit(f"{path}:{n}: {len(c)} columns, expected 15 (featloc-bench --pair-bounds)")
            xx, xy, xw, yy, yw, ww = (float(x) for x in c[7:13])
            B = [[xx, xy, xw], [xy, yy, yw], [xw, yw, ww]]
            out.setdefault(c[0], {})[int(c[1])] = None if math.isnan(xx) else B
    return out


def smallest_generalized_eigenvalue(P, B):
    """Smallest eigenvalue of B^-1 P (B, P symmetric positive): that of W P W
    with W = B^-1/2, which eigen_sym gives."""
    lam, V = eigen_sym(B)
    W = [[sum(V[p][k] * V[q][k] / math.sqrt(lam[k]) for k in range(3)) for q in range(3)]
         for p in range(3)]
    WP = [[sum(W[p][k] * P[k][q] for k in range(3)) for q in range(3)] for p in range(3)]
    WPW = [[sum(WP[p][k] * W[k][q] for k in range(3)) for q in range(3)] for p in range(3)]
    return min(eigen_sym(WPW)[0])


def summary(xs):
    return f"{statistics.mean(xs):.2f} / {statistics.median(xs):.2f}" if xs else "-"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    pairs, order = read_pairs([sys.argv[1]])
    bounds = read_bounds(sys.argv[2])
    print("| data | matcher | pairs used and right | NEES mean / median "
          "| NEES along P's axes, least certain first | e^T B^-1 e mean / median "
          "| RMS error / RMS bound sigma: x, y, yaw | median claimed sigma / bound sigma: x, y, yaw "
          "| covariance under the bound |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in order:
        if name not in bounds:
            sys.exit(f"{sys.argv[2]} has no pair of '{name}' (another run's --pair-bounds?)")
        for m in order[name]:
            nees, eff, under, split = [], [], 0, [0.0] * 3
            err2, bound2, claimed = [0.0] * 3, [0.0] * 3, [[], [], []]
            for k, (status, e, P) in pairs[name][m].items():
                B = bounds[name].get(k)
                if B is None or status != "used":
                    continue
                if math.hypot(e[0], e[1]) > GROSS_T or abs(e[2]) > GROSS_W:
                    continue
                Pi, Bi = inv3(P), inv3(B)
                if Pi is None or Bi is None:
                    continue
                nees.append(quad(e, Pi))
                lam, V = eigen_sym(P)
                least_certain_first = sorted(range(3), key=lambda i: -lam[i])
                for rank, i in enumerate(least_certain_first):
                    d = sum(e[r] * V[r][i] for r in range(3))
                    split[rank] += d * d / lam[i] if lam[i] > 0 else 0.0
                eff.append(quad(e, Bi))
                for a in range(3):
                    err2[a] += e[a] ** 2
                    bound2[a] += B[a][a]
                    claimed[a].append(math.sqrt(max(0.0, P[a][a]) / B[a][a]))
                if smallest_generalized_eigenvalue(P, B) < 0.9:
                    under += 1
            n = len(nees)
            if n == 0:
                print(f"| {name} | {m} | 0 | - | - | - | - | - | - |")
                continue
            rms = ", ".join(f"{math.sqrt(err2[a] / bound2[a]):.2f}" for a in range(3))
            cl = ", ".join(f"{statistics.median(claimed[a]):.2f}" for a in range(3))
            axes = ", ".join(f"{split[k] / n:.2f}" for k in range(3))
            print(f"| {name} | {m} | {n} | {summary(nees)} | {axes} | {summary(eff)} | {rms} | {cl} "
                  f"| {100 * under / n:.1f}% |")


if __name__ == "__main__":
    main()
