#!/usr/bin/env python3
"""Issue 16: replays the rawlog inputs that libFuzzer counted as out of
memory (an allocation over 1 GiB under ASan, where featloc's allocation
ceiling is off) through the release featloc-run, where the ceiling is on,
and reports their exit codes, the messages and the largest peak RSS.

Usage: scripts/replay-fuzz-ooms.py [FUZZ_OUT_DIR] [FEATLOC_RUN]
(defaults: fuzz-out/fuzz_rawlog_reader, build/bin/featloc-run)."""
import glob
import os
import resource
import shutil
import subprocess
import sys
import tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
found = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "fuzz-out", "fuzz_rawlog_reader")
run = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "build", "bin", "featloc-run")
files = sorted(glob.glob(os.path.join(found, "oom-*")))
if not files:
    sys.exit("no oom-* inputs in " + found)

MEASURE = """
import resource, subprocess, sys
p = subprocess.run(sys.argv[1:], capture_output=True, text=True)
last = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
print(p.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss // 1024)
print(last)
"""
work = tempfile.mkdtemp(prefix="featloc-ooms-")
codes, kinds, worst = {}, {}, 0
for i, f in enumerate(files):
    data = open(f, "rb").read()
    # As the fuzz body: byte 0 odd means a .gz file.
    name = os.path.join(work, "in%d" % i + (".rawlog.gz" if data and data[0] & 1 else ".rawlog"))
    open(name, "wb").write(data)
    out = subprocess.run([sys.executable, "-c", MEASURE, run, os.path.join(root, "config.ini"), name,
                          "-q", "--out", os.path.join(work, "out"), "--set", "Evaluation:ground_truth="],
                         capture_output=True, text=True).stdout.splitlines()
    code, mb = out[0].split()
    codes[code] = codes.get(code, 0) + 1
    worst = max(worst, int(mb))
    message = out[1] if len(out) > 1 else ""
    kind = "asks for more than 1024 MiB" if "asks for more than" in message else \
        "another input error (the run stops at an earlier fault)" if code == "1" else message[:100]
    kinds[kind] = kinds.get(kind, 0) + 1
    os.remove(name)
    shutil.rmtree(os.path.join(work, "out"), ignore_errors=True)
shutil.rmtree(work, ignore_errors=True)
print("%d inputs; exit codes %s; largest peak RSS %d MB" %
      (len(files), ", ".join("%s: %d" % kv for kv in sorted(codes.items())), worst))
for kind, n in sorted(kinds.items(), key=lambda kv: -kv[1]):
    print("  %4d  %s" % (n, kind))
