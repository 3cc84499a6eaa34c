#!/usr/bin/env python3
"""A corrected CARMEN log's reference poses as a ground-truth file that
scripts/match-errors.py reads ('t x y yaw' rows), timed as featloc-run
timed its scans.

Usage: scripts/carmen-reference.py LOG POSES_COV > GT
  LOG: the CARMEN log (.log or .log.gz); its FLASER x y theta are the reference
  POSES_COV: poses_cov.txt of any featloc-run of LOG (one row per FLASER, in
    order), which gives each scan's time"""
import sys

from planar_poses import read_carmen_reference, read_poses

ref = read_carmen_reference(sys.argv[1])
rows = read_poses(sys.argv[2])
if len(rows) != len(ref):
    sys.exit("%d FLASER messages but %d poses" % (len(ref), len(rows)))
print("% t x y yaw: reference poses of " + sys.argv[1].split("/")[-1])
for r, p in zip(rows, ref):
    print("%.9f %r %r %r" % (r[0], p[0], p[1], p[2]))
