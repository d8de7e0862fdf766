"""The nbval stage: do the student's answers run inside the reference notebook?

For every lesson we take the master from ``solutions/`` (with its recorded
demonstration outputs), put the student's answer cells in place of the
reference answers, and run all of that student's notebooks with
``pytest --nbval-lax`` — one pytest run per student — inside the student's
sandbox. A lesson passes when every cell runs and every cell tagged
``nbval-check-output`` prints what the reference printed.

The verdict comes from inside the sandbox, so it is not trusted: a lesson's
"notebook" point is awarded only when nbval passed **and** the hidden suite
gave every exercise of the lesson full marks. nbval can take that point away;
it can never add to what honest answers earn. So the grader runs the hidden
suite first and gives nbval only the lessons with full hidden marks: for the
others the point is 0 whatever nbval would say, and their run is ``skipped``
with that reason (:func:`not_run_for_lost_points`).
"""

import json
import os
import select
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from autograder.authoring.release import CODE_STUB
from autograder.grading.results import NotebookRun
from autograder.lessons import cells
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.paths import SOLUTIONS
from autograder.sandbox import launcher

SANITIZE = """[hex addresses]
regex: 0x[0-9a-fA-F]+
replace: 0xADDRESS

[negative zero]
regex: -0\\.0+\\b
replace: 0.0
"""
SUMMARY_LIMIT = 1 << 20


def merged_notebook(master, program):
    """The master with its answer cells replaced by the student's (stubs where they have none)."""
    student_cells = dict(program.cells)
    for cell in master.cells:
        if cells.is_answer_cell(cell):
            cell.source = student_cells.get(cells.grade_id(cell), CODE_STUB)
    return master


def _stage_timeout(count):
    return 60.0 + 45.0 * count


def run_notebooks(folder, lessons, options, catalog, solutions_dir=SOLUTIONS):
    """Run nbval on every readable lesson notebook of one student.

    Returns ``{lesson number: NotebookRun}`` with points decided later by
    :func:`award`; here ``points`` is 0 and ``status`` is nbval's verdict.
    """
    runnable = [(shell, program) for shell, _, program in lessons if program is not None]
    runs = {}
    with tempfile.TemporaryDirectory(prefix="autograder-nbval-") as base:
        sandbox_dir, scratch_dir = launcher.prepare_dirs(base)
        (sandbox_dir / "nbval_sanitize.cfg").write_text(SANITIZE)
        names = []
        for shell, program in runnable:
            lesson = catalog.lesson(shell.number)
            nb = merged_notebook(read_master(Path(solutions_dir) / lesson.filename), program)
            (scratch_dir / lesson.filename).write_text(canonical_text(nb), encoding="utf-8")
            os.chmod(scratch_dir / lesson.filename, 0o644)
            names.append(lesson.filename)
        limits = launcher.Limits(
            memory_bytes=options.limits.memory_bytes, cpu_seconds=int(_stage_timeout(len(names))),
            processes=options.limits.processes, file_bytes=options.limits.file_bytes,
            open_files=max(options.limits.open_files, 1024),
            extra_env={"PYTHONPATH": "/sandbox", "JUPYTER_RUNTIME_DIR": "/tmp/.jupyter-runtime",
                       "IPYTHONDIR": "/tmp/.ipython", "JUPYTER_PLATFORM_DIRS": "1"})
        summary, error = _run(names, sandbox_dir, scratch_dir, limits, _stage_timeout(len(names)))
    for shell, _ in runnable:
        lesson = catalog.lesson(shell.number)
        entry = (summary or {}).get(lesson.filename) if summary else None
        if error or not isinstance(entry, dict):
            runs[shell.number] = NotebookRun(status="failed", max_points=options.notebook_points,
                                             failures=[error or "the notebook did not run"])
            continue
        failures = [str(f)[:300] for f in entry.get("failures", [])][:20]
        runs[shell.number] = NotebookRun(status="failed" if failures else "passed",
                                         max_points=options.notebook_points, failures=failures)
    return runs


def _run(names, sandbox_dir, scratch_dir, limits, timeout):
    """Start the runner in the sandbox; return (summary dict or None, error line or '')."""
    program = [sys.executable, "-I", "-B", "/sandbox/nbval_runner.py"] + launcher.worker_flags() + names
    process = launcher.spawn(program, sandbox_dir, scratch_dir, limits, stdin=subprocess.DEVNULL)
    deadline = time.monotonic() + timeout
    output = b""
    try:
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return None, f"the notebooks did not finish within {timeout:g} s"
            ready, _, _ = select.select([process.stdout], [], [], remaining)
            if not ready:
                continue
            chunk = os.read(process.stdout.fileno(), 65536)
            if not chunk:
                break
            output += chunk
            if len(output) > SUMMARY_LIMIT:
                return None, "the notebook stage produced too much output"
    finally:
        launcher.terminate(process)
    lines = output.decode("utf-8", "replace").strip().splitlines()
    try:
        data = json.loads(lines[-1]) if lines else None
        notebooks = data["notebooks"]
        if not isinstance(notebooks, dict):
            raise TypeError
    except (ValueError, KeyError, TypeError, IndexError):
        return None, "the notebook stage ended without a result (did the student's code end the process?)"
    return notebooks, ""


NEEDS_FULL_MARKS = "the point needs every exercise of the lesson to pass its hidden checks"


def full_hidden_marks(lesson_result):
    """Did every exercise of the lesson earn full marks in the hidden suite?"""
    return all(e.points >= e.max_points for e in lesson_result.exercises)


def not_run_for_lost_points(max_points):
    """The run of a lesson that lost hidden points: nbval is not started, the point is 0 whatever it says."""
    return NotebookRun(status="skipped", max_points=max_points,
                       failures=[f"not run: {NEEDS_FULL_MARKS}"])


def award(lesson_result):
    """Give the notebook point only if nbval passed and every exercise earned full marks."""
    run = lesson_result.run
    if run is None:
        return
    full = full_hidden_marks(lesson_result)
    if run.status == "passed" and full:
        run.points = run.max_points
    else:
        run.points = 0.0
        if run.status == "passed" and not full:
            run.failures = [f"the notebook ran, but {NEEDS_FULL_MARKS}"]
