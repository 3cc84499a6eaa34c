"""Planar pose helpers shared by featloc's analysis scripts
(match-errors.py, odometry-step-errors.py, carmen-*.py)."""
import gzip
import math


def read_poses(path):
    """Rows (t, x, y, yaw) of a trajectory file, in time order: 't x y yaw ...'
    (MRPT's .GT.txt, poses_cov.txt) or TUM 't x y z qx qy qz qw' (yaw from
    the quaternion). '#' and '%' lines are comments."""
    rows = []
    for line in open(path):
        f = line.replace(",", " ").split()
        if not f or f[0][0] in "#%":
            continue
        if len(f) == 8:
            qx, qy, qz, qw = map(float, f[4:8])
            yaw = math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
            rows.append((float(f[0]), float(f[1]), float(f[2]), yaw))
        else:
            rows.append(tuple(float(v) for v in f[:4]))
    rows.sort()
    return rows


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def relative(a, b):
    """Pose b (x, y, yaw) in the frame of pose a."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    c, s = math.cos(a[2]), math.sin(a[2])
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2]))


def read_carmen_reference(path):
    """(x, y, theta) of every FLASER message of a CARMEN log (.log or
    .log.gz), in order: a corrected log's reference poses."""
    opener = gzip.open if path.endswith(".gz") else open
    out = []
    with opener(path, "rt", errors="replace") as f:
        for line in f:
            t = line.split()
            if t and t[0] == "FLASER":
                n = int(t[1])
                out.append(tuple(float(v) for v in t[2 + n:5 + n]))
    return out
