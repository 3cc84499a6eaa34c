#!/usr/bin/env python3
"""A corrected CARMEN log's reference poses as a ground-truth file that
scripts/match-errors.py reads ('t x y yaw' rows), timed as featloc-run
timed its scans.

Usage: scripts/carmen-reference.py LOG POSES_COV > GT
  LOG: the CARMEN log (.log or .log.gz); its FLASER x y theta are the reference
  POSES_COV: poses_cov.txt of any featloc-run of LOG (one row per FLASER, in
    order), which gives each scan's time"""
import gzip
import sys

from planar_poses import read_poses

opener = gzip.open if sys.argv[1].endswith(".gz") else open
ref = []
with opener(sys.argv[1], "rt", errors="replace") as f:
    for line in f:
        t = line.split()
        if t and t[0] == "FLASER":
            n = int(t[1])
            ref.append(t[2 + n:5 + n])
rows = read_poses(sys.argv[2])
if len(rows) != len(ref):
    sys.exit("%d FLASER messages but %d poses" % (len(ref), len(rows)))
print("% t x y yaw: reference poses of " + sys.argv[1].split("/")[-1])
for r, p in zip(rows, ref):
    print("%.9f %s %s %s" % (r[0], p[0], p[1], p[2]))
