"""Benchmark: our grader against stock ``nbgrader autograde``, on one machine, in one run.

Builds a class of N students for every lesson (half the reference answers,
half untouched stubs or typical mistakes), grades it with stock nbgrader
(``generate_assignment`` + ``autograde``, one assignment per lesson) and with
``python -m autograder grade`` (full, then ``--no-nbval``), and prints wall
times, the ratios, seconds per student at N and at a larger N, CPU seconds
per student (the whole machine's busy time during the run / N: run it on a
quiet machine), and the grader's peak memory (resident memory of its whole
process tree, sampled). Then the same comparison, with both graders, on the
bundled sample class (11 students: mistakes, cheats, code that hangs or
crashes, a damaged notebook; what ``python -m autograder grade`` grades by
default).

Usage::

    .venv/bin/python benchmarks/grading_speed.py                 # N = 20 and 100 (about 35 min on 2 cores)
    .venv/bin/python benchmarks/grading_speed.py --students 6 --large 12   # a quick look

Targets (issue 17; N = 20): full grading ≤ 0.25 × nbgrader's wall time;
``--no-nbval`` ≤ 0.04 ×; seconds per student about the same at N = 20 and
N = 100; ``--no-nbval`` ≤ 0.5 s per student per core (the CPU seconds per
student); peak memory stated. The canary (graded once per grader version and
options, then cached) is warmed before the timed runs, as nbgrader's
``generate_assignment`` is left out of its time.
"""

import argparse
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

from autograder.authoring.sample_class import build_sample_class  # noqa: E402
from autograder.integrations.nbgrader_course import assignment_name, build_course, run_nbgrader, submit  # noqa: E402
from process_memory import PeakMemory  # noqa: E402
from support import benchmark_class  # noqa: E402
from support import THIS_COURSE  # noqa: E402


def machine_cpu_seconds():
    """CPU time the whole machine has spent busy so far (/proc/stat): on a quiet machine, the grader's."""
    with open("/proc/stat", encoding="ascii") as stat:
        ticks = [int(x) for x in stat.readline().split()[1:]]
    return (sum(ticks) - ticks[3] - ticks[4]) / os.sysconf("SC_CLK_TCK")  # all but idle and iowait


def timed(command, cwd, measure_memory=False, env=None):
    """(wall seconds, peak resident bytes of the process tree, machine CPU seconds) of ``command``."""
    started, cpu_started = time.monotonic(), machine_cpu_seconds()
    process = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    peak = 0
    if measure_memory:
        with PeakMemory(process.pid) as memory:
            output, _ = process.communicate()
        peak = memory.peak
    else:
        output, _ = process.communicate()
    if process.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{output[-3000:]}")
    return time.monotonic() - started, peak, machine_cpu_seconds() - cpu_started


def run_nbgrader_baseline(students, course_dir, check=True):
    """Wall time of stock nbgrader autograding every lesson for every student (generating is not timed).

    ``check=False``: a class with damaged notebooks, on which nbgrader reports errors but grades the rest.
    """
    course = build_course(course_dir, THIS_COURSE.solutions)
    lessons = THIS_COURSE.catalog.graded_lessons
    for lesson in lessons:
        run_nbgrader(course, "generate_assignment", assignment_name(lesson), "--force")
    for folder in students:
        for lesson in lessons:
            if (folder / lesson.filename).exists():
                submit(course, folder.name, lesson, folder / lesson.filename)
    started = time.monotonic()
    for lesson in lessons:
        run_nbgrader(course, "autograde", assignment_name(lesson), "--force", check=check)
    return time.monotonic() - started


def run_ours(class_dir, out, extra=(), cold=False):
    """``timed`` of our grader on ``class_dir``; ``cold``: with an empty cache folder of its own (beside ``out``)."""
    command = [sys.executable, "-m", "autograder", "grade", str(class_dir), "--out", str(out), "--force", *extra]
    if not cold:
        return timed(command, ROOT, measure_memory=True)
    cache = Path(f"{out}-cache")
    shutil.rmtree(cache, ignore_errors=True)
    return timed(command, ROOT, measure_memory=True, env={**os.environ, "AUTOGRADER_CACHE": str(cache)})


def warm_canary(work):
    """Grade a one-student class in both modes, untimed: the canary is cached from then on."""
    benchmark_class(work / "class_warm", 1)
    for extra in ((), ("--no-nbval",)):
        timed(
            [
                sys.executable,
                "-m",
                "autograder",
                "grade",
                str(work / "class_warm"),
                "--out",
                str(work / "ours_warm"),
                "--force",
                *extra,
            ],
            ROOT,
        )


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--students", type=int, default=20, help="class size compared with nbgrader")
    parser.add_argument("--large", type=int, default=100, help="larger class for the per-student cost")
    parser.add_argument("--work", default=str(ROOT / "benchmark-output"), help="scratch folder")
    parser.add_argument(
        "--nbgrader-seconds",
        type=float,
        default=0.0,
        help="use this measured wall time of stock nbgrader on the same class instead of running it again",
    )
    parser.add_argument("--no-sample", action="store_true", help="leave out the sample class's comparison")
    parser.add_argument(
        "--cold",
        action="store_true",
        help="grade as on a machine that never graded this course: each of our timed runs starts with an empty "
        "cache folder (no passing canary, no recorded transcripts)",
    )
    args = parser.parse_args()
    work = Path(args.work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    lessons = THIS_COURSE.catalog.graded_lessons
    print(f"{os.cpu_count()} cores; {len(lessons)} lessons; N = {args.students} and {args.large}")

    students = benchmark_class(work / "class_small", args.students)
    print(f"built {len(students)} students × {len(lessons)} notebooks")
    nbgrader_seconds = args.nbgrader_seconds or run_nbgrader_baseline(students, work / "nbgrader_course")
    if not args.cold:
        warm_canary(work)
    print(f"stock nbgrader autograde:       {nbgrader_seconds:8.1f} s")
    full_seconds, full_memory, full_cpu = run_ours(work / "class_small", work / "ours_full", cold=args.cold)
    print(f"ours, full (suite + nbval):     {full_seconds:8.1f} s   peak memory {full_memory / 2**20:6.0f} MiB")
    fast_seconds, fast_memory, fast_cpu = run_ours(
        work / "class_small", work / "ours_fast", ["--no-nbval"], cold=args.cold
    )
    print(f"ours, --no-nbval:               {fast_seconds:8.1f} s   peak memory {fast_memory / 2**20:6.0f} MiB")

    if args.large:
        large = benchmark_class(work / "class_large", args.large)
        large_full, large_full_memory, large_full_cpu = run_ours(work / "class_large", work / "ours_large_full")
        large_fast, large_fast_memory, large_fast_cpu = run_ours(
            work / "class_large", work / "ours_large_fast", ["--no-nbval"]
        )
    else:  # --large 0: the class of N only
        large, large_full, large_full_memory, large_full_cpu = students, full_seconds, full_memory, full_cpu
        large_fast, large_fast_memory, large_fast_cpu = fast_seconds, fast_memory, fast_cpu

    print()
    print(f"ratio full / nbgrader:          {full_seconds / nbgrader_seconds:6.3f}   (target ≤ 0.25)")
    print(f"ratio --no-nbval / nbgrader:    {fast_seconds / nbgrader_seconds:6.3f}   (target ≤ 0.04)")
    print()
    print(f"seconds per student             N = {len(students):<4d}  N = {len(large):<4d}")
    print(f"  nbgrader                      {nbgrader_seconds / len(students):7.2f}")
    print(f"  ours, full                    {full_seconds / len(students):7.2f}  {large_full / len(large):7.2f}")
    print(f"  ours, --no-nbval              {fast_seconds / len(students):7.2f}  {large_fast / len(large):7.2f}")
    print(
        "CPU seconds per student (busy time of the whole machine / N; the target of issue 17 item 4 is "
        "≤ 0.5 for --no-nbval)"
    )
    print(f"  ours, full                    {full_cpu / len(students):7.2f}  {large_full_cpu / len(large):7.2f}")
    print(f"  ours, --no-nbval              {fast_cpu / len(students):7.2f}  {large_fast_cpu / len(large):7.2f}")
    print(
        f"peak memory of the grader, whole process tree: N = {len(students)} full {full_memory / 2**20:.0f} MiB, "
        f"--no-nbval {fast_memory / 2**20:.0f} MiB; N = {len(large)} full {large_full_memory / 2**20:.0f} MiB, "
        f"--no-nbval {large_fast_memory / 2**20:.0f} MiB"
    )

    if args.no_sample:
        print(f"machine: {os.cpu_count()} cores")
        return
    ids = build_sample_class(work / "class_sample", THIS_COURSE)
    sample_nbgrader = run_nbgrader_baseline(
        [work / "class_sample" / i for i in ids], work / "nbgrader_sample", check=False
    )
    sample_full, _, _ = run_ours(work / "class_sample", work / "ours_sample_full")
    sample_fast, _, _ = run_ours(work / "class_sample", work / "ours_sample_fast", ["--no-nbval"])
    print()
    print(f"the sample class ({len(ids)} students: mistakes, cheats, hangs, a damaged notebook):")
    print(f"  stock nbgrader autograde:     {sample_nbgrader:8.1f} s")
    print(
        f"  ours, full:                   {sample_full:8.1f} s   ratio {sample_full / sample_nbgrader:6.3f}"
        "   (target ≤ 0.25)"
    )
    print(
        f"  ours, --no-nbval:             {sample_fast:8.1f} s   ratio {sample_fast / sample_nbgrader:6.3f}"
        "   (target ≤ 0.04)"
    )
    print(f"machine: {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
