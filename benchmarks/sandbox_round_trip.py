"""Benchmark: one call's round trip into a student's sandbox, with the sandbox kept on one CPU and without.

The notebook stage replays thousands of small calls per lesson (lesson 09's master makes about 23,000), one
hand-over from the feeder to the runner and back per call. This starts a sandbox holding a one-line function,
makes batches of calls, and prints the cost per call for a sandbox left to the scheduler and for one whose
processes keep to one CPU (as a grading slot's do, ``autograder/sandbox/cpus.py``), alternating the two so
that both see the same machine. Run it on a quiet machine with at least 2 CPUs.

Usage::

    .venv/bin/python benchmarks/sandbox_round_trip.py               # 5 rounds of 4,000 calls
    .venv/bin/python benchmarks/sandbox_round_trip.py --calls 1000 --rounds 3
"""

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "autograder" / "sandbox" / "child"))

import wire  # noqa: E402

from autograder.grading.options import GradingOptions  # noqa: E402
from autograder.lessons.paths import this_course  # noqa: E402
from autograder.sandbox import cpus  # noqa: E402
from autograder.sandbox.session import LessonProgram, StudentSandbox  # noqa: E402

PROGRAM = LessonProgram(setup="", cells=[("echo", "def echo(x):\n    return x\n")])


def per_call(calls: int, cpu: int | None) -> float:
    """Seconds per call of a batch of ``calls`` calls to a fresh sandbox (kept to ``cpu`` unless None)."""
    call = wire.dumps({"lesson": "01", "name": "echo", "args": [[0.5, 0.25, 0.125]], "kwargs": {}, "timeout": None})
    with cpus.pinned(cpu):
        box = StudentSandbox({"01": PROGRAM}, this_course().support, limits=GradingOptions().limits)
        box.call_batch([call], [None])  # started and loaded, outside the timing
    with box:
        started = time.perf_counter()
        replies = box.call_batch([call] * calls, [None] * calls, budget=1000.0)
        seconds = time.perf_counter() - started
    if replies is None or len(replies) != calls or not all(r.get("ok") for r in replies):
        raise RuntimeError("the sandbox did not answer every call")
    return seconds / calls


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--calls", type=int, default=4000, help="calls per batch")
    parser.add_argument("--rounds", type=int, default=5, help="batches of each kind, alternating")
    args = parser.parse_args()
    cpu = cpus.cpu_of_slot(0, jobs=2)
    if cpu is None:
        print("one CPU only: nothing to compare")
        return
    free, kept = [], []
    for _ in range(args.rounds):
        free.append(per_call(args.calls, None))
        kept.append(per_call(args.calls, cpu))
    print(f"{len(os.sched_getaffinity(0))} CPUs; {args.rounds} rounds of {args.calls} calls; microseconds per call")
    print("                        min   median      max")
    for label, values in (("left to the scheduler", free), (f"kept on CPU {cpu}", kept)):
        low, mid, high = (1e6 * v for v in (min(values), statistics.median(values), max(values)))
        print(f"{label:<22} {low:6.0f}   {mid:6.0f}   {high:6.0f}")
    print(f"ratio kept / free (medians): {statistics.median(kept) / statistics.median(free):.2f}")


if __name__ == "__main__":
    started = time.monotonic()
    main()
    print(f"({time.monotonic() - started:.0f} s)")
