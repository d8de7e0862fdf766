"""How long the similarity stage takes: 300 students × every exercise, and its share of a default grade.

Usage: ``python benchmarks/similarity_speed.py [--students 300] [--sample]``. The class is written as
notebooks: each student hands in the reference answer of every exercise with their own variable names
(so nothing is cached between students), which is the stage's worst case (every answer long enough to
compare). ``--sample`` also grades the sample class with the default ``grade`` and prints the similarity
stage's seconds and share of the whole run.
"""

import argparse
import copy
import resource
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from autograder.authoring.sample_class import rename_locals
from autograder.lessons import cells
from autograder.lessons.catalog import load_catalog
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.paths import COURSE, PROJECT_ROOT
from autograder.lessons.reference import answer_sources
from autograder.similarity.stage import similarity_of_class


def write_big_class(folder, students):
    references = answer_sources()
    for lesson in load_catalog().graded_lessons:
        released = read_master(COURSE / lesson.filename)
        for number in range(students):
            nb = copy.deepcopy(released)
            for cell in nb.cells:
                if cells.is_answer_cell(cell):
                    cell.source = rename_locals(references[cells.grade_id(cell)], prefix=f"s{number}_")
            (folder / f"student{number:03d}").mkdir(parents=True, exist_ok=True)
            (folder / f"student{number:03d}" / lesson.filename).write_text(canonical_text(nb), encoding="utf-8")


def _cpu_seconds():
    """CPU seconds of this process and of its finished children (the stage's forked workers)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--students", type=int, default=300)
    parser.add_argument("--sample", action="store_true", help="also time a default grade of the sample class")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work) / "class"
        write_big_class(folder, args.students)
        started, cpu = time.perf_counter(), _cpu_seconds()
        findings = similarity_of_class(folder)
        seconds, cpu = time.perf_counter() - started, _cpu_seconds() - cpu
        print(f"{args.students} students x {len(findings.compared)} exercises: "
              f"{sum(findings.compared.values())} answers compared in {seconds:.1f} s "
              f"({cpu:.1f} s of CPU, this process and its workers; load average {os.getloadavg()[0]:.1f})")
        if args.sample:
            out = Path(work) / "out"
            started = time.perf_counter()
            result = subprocess.run([sys.executable, "-m", "autograder", "grade", "--out", str(out)],
                                    cwd=PROJECT_ROOT, capture_output=True, text=True)
            total = time.perf_counter() - started
            line = [x for x in result.stdout.splitlines() if x.startswith("similar answers:")]
            print(f"default grade of the sample class: {total:.1f} s; {line[0] if line else result.stderr[-500:]}")
            stage = float(line[0].split("(")[1].split(" s")[0]) if line else float("nan")
            print(f"similarity stage: {stage:.1f} s = {100 * stage / total:.1f}% of the run")


if __name__ == "__main__":
    main()
