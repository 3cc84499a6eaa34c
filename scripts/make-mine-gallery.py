#!/usr/bin/env python3
"""Writes worlds/mine-gallery.ini: a mine's galleries with rough rock walls.

Real walls are not the simulator's straight segments: rock, rubble and
shotcrete bulge and dip at every scale. This world's free space is one
outline (a main gallery, two cross-cuts, a chamber round a pillar of rock)
whose edges are cut every 0.2 m and pushed off their line by a slow
undulation (two sines, 2.5-8 m long, up to 15 cm) plus uneven rock (uniform
+-4 cm per vertex). The roughening is drawn from a fixed seed, so the file is
the same every time; it is generated once and committed, with nothing tuned
on it (issue 15, thirty-third session).

Usage: scripts/make-mine-gallery.py > worlds/mine-gallery.ini
"""
import math
import random

rng = random.Random(20261204)

# The free space, counter-clockwise (x east, y north) [m]: the main
# gallery (3.2 m wide, 40 m), a cross-cut north at x = 14 and one south
# at x = 28 (2.6 m wide), the chamber at the east end (8 m x 8 m).
OUTLINE = [(0, -1.6), (26.7, -1.6), (26.7, -10), (29.3, -10), (29.3, -1.6), (40, -1.6),
           (40, -4), (48, -4), (48, 4), (40, 4), (40, 1.6), (15.3, 1.6), (15.3, 12),
           (12.7, 12), (12.7, 1.6), (0, 1.6)]
# The pillar of rock left standing in the chamber, counter-clockwise.
PILLAR = [(43.0, -1.0), (45.0, -1.1), (45.1, 0.9), (43.1, 1.0)]
STEP = 0.2  # [m] vertex spacing along an edge
ROCK = 0.04  # [m] uniform half-width of each vertex's offset
WAVE = 0.15  # [m] largest amplitude of the slow undulation


def rough(points, closed, sign):
    """Each edge cut every STEP, each inner vertex pushed along the edge's
    normal; the offsets taper to 0 at the corners so that edges still meet.
    sign: +1 pushes into the rock for a counter-clockwise outline."""
    out = []
    n = len(points)
    edges = n if closed else n - 1
    for e in range(edges):
        (x0, y0), (x1, y1) = points[e], points[(e + 1) % n]
        length = math.hypot(x1 - x0, y1 - y0)
        k = max(1, int(round(length / STEP)))
        nx, ny = (y1 - y0) / length * sign, -(x1 - x0) / length * sign
        waves = [(rng.uniform(2.5, 8.0), rng.uniform(0, 2 * math.pi), rng.uniform(0.3, 1.0))
                 for _ in range(2)]
        out.append((x0, y0))
        for i in range(1, k):
            s = i / k
            d = s * length
            taper = min(1.0, d / 0.6, (length - d) / 0.6)
            slow = sum(a * WAVE / 2 * math.sin(2 * math.pi * d / w + p) for w, p, a in waves)
            off = taper * (slow + rng.uniform(-ROCK, ROCK))
            out.append((x0 + s * (x1 - x0) + off * nx, y0 + s * (y1 - y0) + off * ny))
    if not closed:
        out.append(points[-1])
    return out


def points_text(pts):
    return "; ".join("%.3f %.3f" % p for p in pts)


wall = rough(OUTLINE, True, +1)
pillar = rough(PILLAR, True, +1)

print("""# featloc-sim world: a mine's galleries with rough rock walls: a main
# gallery 3.2 m wide and 40 m long, a cross-cut north at x = 14 m and one
# south at x = 28 m (2.6 m wide), a chamber 8 m across at the east end with
# a pillar of rock left standing in it, timber props in pairs along part of
# the main gallery; a miner walking and a mine car pushed along the
# gallery. Every wall is rock: cut every 0.2 m and pushed off its line by a
# slow undulation (up to 15 cm over 2.5-8 m) and uneven rock (+-4 cm per
# vertex), so no wall is straight at any scale and a local line is only
# ever an approximation of it.
# Made on 2026-12-04 by scripts/make-mine-gallery.py (fixed seed) as a
# held-out scene for issue 15 (doc/benchmarks.md, "Issue 15, thirty-third
# session"): written before any matcher ran on it, nothing tuned on it.
# `--frozen` gives its static twin.
# The laser is a Hokuyo UTM-30LX (1081 beams over 270 deg, 30 m, 1.5 cm
# noise), 10 Hz, the robot at 0.6 m/s.
# Format: doc/simulator.md. Generate: featloc-sim worlds/mine-gallery.ini --out OUT

[Simulation]
t0        = 1700012000   // [s]
seed      = 81
format    = 1

[Laser]
preset    = hokuyo_utm30lx
rate      = 10           // [Hz]
sensor_pose = [0.25 0 0] // [m m deg]

[Odometry]
mode      = model
model     = gaussian
sigma_xy_min        = 0.002
sigma_xy_per_m      = 0.02
sigma_xy_per_deg    = 0.0005
sigma_yaw_min_DEG   = 0.05
sigma_yaw_per_m_DEG = 0.5
sigma_yaw_per_deg   = 0.02

[Robot]
path      = waypoints
speed     = 0.6          // [m/s]
waypoints = [2.000 0.000; 14.000 0.000; 14.000 10.000; 14.000 0.000; 28.000 0.000; 28.000 -8.000; 28.000 0.000; 41.500 0.000; 44.000 -2.500; 46.500 0.000; 44.000 2.500; 41.500 0.000; 20.000 0.000]
""")
print("[Wall.rock]")
print("polyline = [%s]" % points_text(wall))
print("closed   = true")
print("texture  = concrete")
print()
print("[Obstacle.pillar]")
print("polygon = [%s]" % points_text(pillar))
print("texture = concrete")
for i, x in enumerate([18.0, 21.0, 24.0, 32.0, 35.0]):
    for side, y in (("n", 1.25), ("s", -1.25)):
        print()
        print("[Obstacle.prop_%d_%s]" % (i, side))
        print("polygon = [%.2f %.2f; %.2f %.2f; %.2f %.2f; %.2f %.2f]" %
              (x - 0.1, y - 0.1, x + 0.1, y - 0.1, x + 0.1, y + 0.1, x - 0.1, y + 0.1))
        print("texture = wood")
print("""
[Agent.miner]
shape      = legs
waypoints  = [38.000 0.400; 4.000 0.400]
speed      = 0.9         // [m/s]
pause      = 4           // [s] at each waypoint
mode       = pingpong
start_time = 5           // [s]

[Agent.mine_car]
shape      = cart
cart_size  = [1.5 0.7]   // [m]
waypoints  = [30.000 -0.650; 6.000 -0.650]
speed      = 0.5         // [m/s]
pause      = 10          // [s] at each waypoint
mode       = pingpong
start_time = 20          // [s]""")
