"""How long the similarity stage takes: 300 students × every exercise, and its cost within a default grade.

Usage: ``python benchmarks/similarity_speed.py [--students 300] [--sample] [--jobs N]``.

The stage alone: the class is written as notebooks, each student handing in the reference answer of every
exercise with their own variable names, so no two texts are the same (nothing is shared between students)
and every answer is long enough to compare: the stage's worst case. Printed: wall seconds and CPU seconds
apart (this process and its forked workers). On a shared machine the wall time follows the load; the CPU
seconds are what the stage costs, and its wall time on an idle machine is about CPU seconds / cores.

``--sample`` also grades the sample class twice, by default and with ``--no-similarity``, and prints for
each run its wall and CPU seconds (the ``grade`` process and every process it waited for), the similarity
stage's own seconds as ``grade`` reports them, and the stage's share of the default run. The README's figures come from this script.
"""

import argparse
import copy
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's autograder, not an installed one

from autograder.authoring.sample_class import rename_locals  # noqa: E402
from autograder.lessons import cells  # noqa: E402
from autograder.lessons.notebook_files import canonical_text, read_master  # noqa: E402
from autograder.lessons.paths import this_course  # noqa: E402
from autograder.lessons.reference import answer_sources  # noqa: E402
from autograder.similarity.stage import similarity_of_class  # noqa: E402

THIS_COURSE = this_course()
STAGE_LINE = re.compile(r"similar answers: .*\((?P<wall>[\d.]+) s, (?P<cpu>[\d.]+) s of CPU")


def write_big_class(folder, students):
    """``students`` folders under ``folder``, each with every graded lesson answered by the reference with
    the student's own local names."""
    references = answer_sources(THIS_COURSE.solutions)
    for lesson in THIS_COURSE.catalog.graded_lessons:
        released = read_master(THIS_COURSE.released / lesson.filename)
        for number in range(students):
            nb = copy.deepcopy(released)
            for cell in nb.cells:
                if cells.is_answer_cell(cell):
                    cell.source = rename_locals(references[cells.grade_id(cell)], prefix=f"s{number}_")
            (folder / f"student{number:03d}").mkdir(parents=True, exist_ok=True)
            (folder / f"student{number:03d}" / lesson.filename).write_text(canonical_text(nb), encoding="utf-8")


def cpu_seconds():
    """CPU seconds of this process and of its finished children (the stage's forked workers, a ``grade``)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def time_stage(students, jobs):
    """Print the stage's wall and CPU seconds on a class of ``students``."""
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work) / "class"
        write_big_class(folder, students)
        started, cpu = time.perf_counter(), cpu_seconds()
        findings = similarity_of_class(folder, THIS_COURSE, jobs=jobs)
        seconds, cpu = time.perf_counter() - started, cpu_seconds() - cpu
    print(
        f"stage, {students} students x {len(findings.compared)} exercises "
        f"({sum(findings.compared.values())} answers compared, {jobs or os.cpu_count()} processes): "
        f"{seconds:.1f} s wall, {cpu:.1f} s CPU (load average {os.getloadavg()[0]:.1f})",
        flush=True,
    )


def time_grade(extra):
    """``(wall, CPU, stage wall, stage CPU)`` seconds of a default ``grade`` of the sample class plus ``extra``
    options (stage figures NaN when the stage did not run)."""
    with tempfile.TemporaryDirectory() as work:
        started, cpu = time.perf_counter(), cpu_seconds()
        result = subprocess.run(
            [sys.executable, "-m", "autograder", "grade", "--out", str(Path(work) / "out"), *extra],
            cwd=ROOT,
            capture_output=True,
            text=True,
        )
        wall, cpu = time.perf_counter() - started, cpu_seconds() - cpu
    if result.returncode != 0:
        raise SystemExit(f"grade {' '.join(extra)} failed:\n{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    stage = STAGE_LINE.search(result.stdout)
    if stage is None and not extra:
        raise SystemExit(f"grade printed no similarity line:\n{result.stdout[-2000:]}")
    stage_wall, stage_cpu = (float(stage["wall"]), float(stage["cpu"])) if stage else (float("nan"),) * 2
    return wall, cpu, stage_wall, stage_cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--students", type=int, default=300, help="class size for the stage alone (0: skip)")
    parser.add_argument("--jobs", type=int, default=None, help="processes for the stage (default: the cores)")
    parser.add_argument("--sample", action="store_true", help="also time default grades of the sample class")
    args = parser.parse_args()
    if args.students:
        time_stage(args.students, args.jobs)
    if args.sample:
        wall, cpu, stage_wall, stage_cpu = time_grade([])
        bare_wall, bare_cpu, _, _ = time_grade(["--no-similarity"])
        print(
            f"grade of the sample class: {wall:.1f} s wall, {cpu:.1f} s CPU; with --no-similarity: "
            f"{bare_wall:.1f} s wall, {bare_cpu:.1f} s CPU (load average {os.getloadavg()[0]:.1f})"
        )
        print(
            f"similarity stage within it: {stage_wall:.1f} s wall = {100 * stage_wall / wall:.1f}% of the run, "
            f"{stage_cpu:.1f} s CPU = {100 * stage_cpu / cpu:.1f}% of the run's CPU "
            f"(the two runs differ by {cpu - bare_cpu:+.1f} s CPU)"
        )


if __name__ == "__main__":
    main()
