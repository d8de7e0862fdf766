"""Record the golden gradebooks: the verdicts that speed work must not move.

Two classes: the bundled sample class (``tests/golden/sample_class_grades.csv``)
and the benchmark's class of ``BENCHMARK_STUDENTS`` students
(``tests/golden/benchmark_class_grades.csv``, built by
``support.benchmark_class`` as ``benchmarks/grading_speed.py`` builds it).

Usage, from the project root::

    .venv/bin/python -m tests.record_golden       # grades both classes, writes both files

Each file holds, per student, the points of every exercise and the notebook
point of every lesson (nothing else: timing, problems and wording may change).
``tests/test_sample_class.py`` and ``tests/test_speed_verdicts.py`` grade the
classes with the current grader and require exactly these points. Re-record
only when verdicts are *meant* to change (a new hidden check, a changed
mistake or master), and look at the diff of the files when you do; never
re-record to make a speed change pass.
"""

import csv
import io
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden" / "sample_class_grades.csv"
BENCHMARK_GOLDEN = ROOT / "tests" / "golden" / "benchmark_class_grades.csv"
BENCHMARK_STUDENTS = 8


def grade_sample_class(out, klass=None):
    """Grade the sample class, or the class in folder ``klass`` (full pipeline, nbval included) into
    ``out``; return grades.csv's path."""
    command = [
        sys.executable,
        "-m",
        "autograder",
        "grade",
        *([str(klass)] if klass else []),
        "--out",
        str(out),
        "--force",
    ]
    result = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=1800)
    if result.returncode != 0:
        raise RuntimeError("grading the sample class failed:\n" + result.stdout[-2000:] + result.stderr[-2000:])
    return Path(out) / "grades.csv"


def verdict_columns():
    """The gradebook columns that hold verdicts: one per exercise, then ``notebook_NN`` per lesson."""
    sys.path.insert(0, str(ROOT))
    from autograder.lessons.paths import this_course

    catalog = this_course().catalog
    return [e.name for e in catalog.exercises] + [f"notebook_{lesson.number}" for lesson in catalog.graded_lessons]


def verdicts(grades_csv):
    """``(columns, {student_id: {column: points}})``: the exercise and notebook columns of a gradebook."""
    with open(grades_csv, newline="", encoding="utf-8") as handle:
        reader = csv.DictReader(handle)
        header = list(reader.fieldnames)
        rows = list(reader)
    columns = [c for c in verdict_columns() if c in header]  # the gradebook has notebook_NN only with nbval
    return columns, {row["student_id"]: {c: row[c] for c in columns} for row in rows}


def golden_text(columns, table):
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["student_id"] + columns)
    for student in sorted(table):
        writer.writerow([student] + [table[student][c] for c in columns])
    return buffer.getvalue()


def read_golden(path=GOLDEN):
    with open(path, newline="", encoding="utf-8") as handle:
        reader = csv.DictReader(handle)
        columns = reader.fieldnames[1:]
        return columns, {row["student_id"]: {c: row[c] for c in columns} for row in reader}


def differences(expected, actual):
    """Lines saying where two ``verdicts`` tables differ (points compared as numbers)."""
    (want_columns, want), (got_columns, got) = expected, actual
    lines = []
    if want_columns != got_columns:
        lines.append(f"columns differ: {want_columns} != {got_columns}")
    for student in sorted(set(want) | set(got)):
        if student not in got or student not in want:
            lines.append(f"{student}: only in the {'golden file' if student in want else 'new gradebook'}")
            continue
        for column in want_columns:
            a, b = want[student].get(column, ""), got[student].get(column, "")
            try:
                same = float(a or "nan") == float(b or "nan") or a == b
            except ValueError:
                same = a == b
            if not same:
                lines.append(f"{student}, {column}: golden {a!r}, now {b!r}")
    return lines


def grade_benchmark_class(work):
    """Build the benchmark's class in ``work/class`` and grade it into ``work/out``; return grades.csv's path."""
    sys.path.insert(0, str(ROOT / "tests"))
    from support import benchmark_class

    benchmark_class(Path(work) / "class", BENCHMARK_STUDENTS)
    return grade_sample_class(Path(work) / "out", klass=Path(work) / "class")


def main():
    GOLDEN.parent.mkdir(parents=True, exist_ok=True)
    for path, grade_it in ((GOLDEN, grade_sample_class), (BENCHMARK_GOLDEN, grade_benchmark_class)):
        with tempfile.TemporaryDirectory(prefix="golden-") as work:
            columns, table = verdicts(grade_it(work))
        path.write_text(golden_text(columns, table), encoding="utf-8")
        print(f"wrote {path.relative_to(ROOT)}: {len(table)} students, {len(columns)} columns")


if __name__ == "__main__":
    main()
