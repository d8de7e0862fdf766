"""Benchmark: what a class of hostile students costs the grader, in time and memory.

Builds the class of ``tests/hostile_class.py`` (every student hostile in a
different way, beside three honest ones) and the honest students alone,
grades both with ``python -m autograder grade`` (lesson 01, the notebook
stage included), as root and as an ordinary user (``nobody``; only the
latter when not run as root), and prints for each run: the wall time, the
largest resident memory of any one process of the grader (its high-water
mark; the sandboxes it starts are not the grader), the peak of the grader's
processes together, and the peak of the whole process tree (sandboxes
included). Every figure is sampled from ``/proc`` every 0.1 s.

Usage::

    .venv/bin/python benchmarks/hostile_class.py               # about 8 minutes on 2 busy cores
    .venv/bin/python benchmarks/hostile_class.py --modes root
"""

import argparse
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

import ordinary_user  # noqa: E402
from hostile_class import CASES, build_class, build_honest, commands, unlock  # noqa: E402
from process_memory import PeakMemory, is_grader  # noqa: E402


def measured(command, env):
    """(wall seconds, largest grader process, grader processes together, whole tree) of one run."""
    started = time.monotonic()
    process = subprocess.Popen(command, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    with PeakMemory(process.pid, interval=0.1, only=is_grader) as grader, PeakMemory(process.pid, 0.1) as tree:
        output, _ = process.communicate()
    if process.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{output.decode('utf-8', 'replace')[-3000:]}")
    return time.monotonic() - started, grader.largest, grader.peak, tree.peak


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    modes = ["root", "ordinary user"] if ordinary_user.running_as_root() else ["ordinary user"]
    parser.add_argument("--modes", nargs="+", default=modes, choices=["root", "ordinary user"])
    args = parser.parse_args()
    base = Path(tempfile.mkdtemp(prefix="hostile-bench-", dir="/tmp"))
    base.chmod(0o755)
    try:
        build_honest(base / "honest")
        shutil.copytree(base / "honest", base / "class", symlinks=True)
        built = build_class(base / "class")
        students = 3 + sum(1 for student in built.values() if student is not None)
        print(
            f"hostile class: {len(CASES)} cases, {students} students (3 honest), "
            f"{len(built) - students + 3} entries that are not students"
        )
        mib = 2**20
        for mode in args.modes:
            for label, folder in (("honest students alone", "honest"), ("hostile class", "class")):
                command, _, env = commands(base, base / folder, base / f"out-{mode}-{folder}", mode)
                seconds, largest, together, tree = measured(command, env)
                print(
                    f"{mode:>13}, {label:>21}: {seconds:6.1f} s; largest grader process {largest / mib:5.0f} MiB, "
                    f"grader processes together {together / mib:5.0f} MiB, with sandboxes {tree / mib:5.0f} MiB"
                )
    finally:
        unlock(base)
        shutil.rmtree(base, ignore_errors=True)


if __name__ == "__main__":
    main()
