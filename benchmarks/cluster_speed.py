"""Benchmark: local grading (``--jobs 2``) against a local Dask cluster (``--cluster local:2``), same class,
one run.

Builds a class of N students (every lesson; half the reference answers, half stubs or typical mistakes, as
benchmarks/grading_speed.py does), warms the driver's canary, then grades the class twice from scratch:
with the forked pool of one machine, and as Dask tasks on a ``LocalCluster`` of 2 worker processes on
loopback. Prints, for each: the wall time of the whole command, the grading time (the command's own "graded
N student(s) in S s", which leaves out Python's start-up), seconds per student, and for the cluster its
start-up (starting the workers and checking each of them: sandbox, grader, canary) apart. The overhead of
the cluster is stated as start-up (paid once per run, whatever the class size) plus the per-student
difference (shipping the submission and the results as bytes, a fork per task on the worker).

Usage::

    .venv/bin/python benchmarks/cluster_speed.py                        # N = 8, full pipeline
    .venv/bin/python benchmarks/cluster_speed.py --students 6 --no-nbval  # a quick look
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))

from grading_speed import build_class  # noqa: E402


def grade(class_dir, out, extra):
    """Run ``grade``; return (wall seconds, grading seconds, cluster start-up seconds or 0, output)."""
    command = [sys.executable, "-m", "autograder", "grade", str(class_dir), "--out", str(out), "--force", *extra]
    started = time.monotonic()
    run = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    wall = time.monotonic() - started
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}")
    graded = re.search(r"graded (\d+) student\(s\).* in ([0-9.]+) s", run.stdout)
    ready = re.search(r"cluster: \d+ worker\(s\) ready .* in ([0-9.]+) s", run.stdout)
    return wall, float(graded.group(2)), float(ready.group(1)) if ready else 0.0, run.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--students", type=int, default=8, help="class size")
    parser.add_argument("--no-nbval", action="store_true", help="skip the notebook stage in both runs")
    parser.add_argument("--work", default=str(ROOT / "benchmark-output" / "cluster"), help="scratch folder")
    args = parser.parse_args()
    work = Path(args.work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    extra = ["--no-nbval"] if args.no_nbval else []
    students = build_class(work / "class", args.students)
    build_class(work / "class_warm", 1)
    grade(work / "class_warm", work / "warm", extra)  # the driver's canary is cached from here on
    mode = "hidden suite only (--no-nbval)" if args.no_nbval else "hidden suite + notebook stage"
    print(f"{os.cpu_count()} cores; N = {len(students)} students, every lesson; {mode}")

    local_wall, local_grading, _, _ = grade(work / "class", work / "local", extra + ["--jobs", "2"])
    cluster_wall, cluster_grading, startup, _ = grade(
        work / "class", work / "cluster", extra + ["--cluster", "local:2"]
    )
    n = len(students)
    print()
    print(f"{'':34}{'wall':>9}{'grading':>10}{'s/student':>11}{'start-up':>10}")
    print(f"{'local, --jobs 2':34}{local_wall:8.1f}s{local_grading:9.1f}s{local_grading / n:10.2f}s{'':>10}")
    print(
        f"{'Dask, --cluster local:2':34}{cluster_wall:8.1f}s{cluster_grading:9.1f}s"
        f"{cluster_grading / n:10.2f}s{startup:9.1f}s"
    )
    print()
    per_student = (cluster_grading - local_grading) / n
    print(
        f"overhead of the cluster: {cluster_wall - local_wall:+.1f} s of wall time in all = "
        f"{startup:.1f} s start-up (workers started and checked, canary on each; once per run) "
        f"{'+' if per_student >= 0 else '-'} {abs(per_student):.2f} s per student "
        f"({100 * per_student / (local_grading / n):+.0f} % of the local cost per student)"
    )


if __name__ == "__main__":
    main()
