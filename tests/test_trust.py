"""Grades an instructor can trust on any machine: the canary and honest resume.

- A broken stage (simulated in a copy of the project: a notebook stage that cannot run, a sandbox
  whose worker cannot start) stops the batch at the canary with exit status 3, a message naming the
  lesson and the stage, and an existing gradebook left byte for byte as it was.
- Re-running ``grade`` re-grades when the grader's code, the reference solutions or the isolation mode
  changed, and ``status`` says why; an unchanged grader reuses every result.
"""

import os
import shutil
import subprocess
import sys

import pytest

from autograder.lessons.paths import PROJECT_ROOT
from autograder.sandbox import launcher
from support import build_submission

LESSON = "01"
IGNORED = shutil.ignore_patterns(
    ".git", ".venv", "__pycache__", ".pytest_cache", "grading-output", "test-artifacts", "benchmark-output", "*.pyc"
)


def _copy_project(target):
    shutil.copytree(PROJECT_ROOT, target, ignore=IGNORED)
    return target


def _grade(project, submissions, out, *extra, sandbox=None, cache=None):
    env = {key: value for key, value in os.environ.items() if key != "AUTOGRADER_SANDBOX"}
    if sandbox:
        env["AUTOGRADER_SANDBOX"] = sandbox
    if cache:
        env["AUTOGRADER_CACHE"] = str(cache)
    return subprocess.run(
        [sys.executable, "-m", "autograder", "grade", str(submissions), "--out", str(out), "--lessons", LESSON, *extra],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=900,
        env=env,
    )


def _status(project, out):
    return subprocess.run(
        [sys.executable, "-m", "autograder", "status", "--out", str(out)],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=120,
    ).stdout


@pytest.fixture(scope="module")
def small_class(tmp_path_factory):
    root = tmp_path_factory.mktemp("class")
    build_submission(root / "alice", lessons=(LESSON,))
    build_submission(root / "bob", default="stub", lessons=(LESSON,))
    return root


def _snapshot(out):
    return {str(p.relative_to(out)): p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}


BREAKAGES = {
    # the notebook stage cannot run: nbval is handed an option it does not know
    "nbval": (
        "autograder/sandbox/child/nbval_runner.py",
        '"--nbval-lax",',
        '"--nbval-lax", "--no-such-option",',
        (),
        "notebook stage (nbval)",
    ),
    # the sandbox's worker cannot start: it imports a module its Python does not have
    "sandbox": (
        "autograder/sandbox/child/worker.py",
        "import numpy  # noqa",
        "import numpy_missing  # noqa",
        ("--no-nbval",),
        "hidden suite",
    ),
}


@pytest.mark.parametrize("stage", sorted(BREAKAGES))
def test_a_broken_stage_stops_the_batch_at_the_canary(stage, small_class, tmp_path):
    path, old, new, flags, named = BREAKAGES[stage]
    out = tmp_path / "results"
    first = _grade(PROJECT_ROOT, small_class, out, *flags)
    assert first.returncode == 0, first.stderr[-2000:]
    before = _snapshot(out)

    project = _copy_project(tmp_path / "project")
    source = (project / path).read_text(encoding="utf-8")
    assert old in source, f"the simulated breakage no longer applies to {path}"
    (project / path).write_text(source.replace(old, new, 1), encoding="utf-8")
    broken = _grade(project, small_class, out, *flags, "--force", cache=tmp_path / "cache")

    assert broken.returncode == 3, broken.stdout[-1000:] + broken.stderr[-2000:]
    assert "canary failed" in broken.stderr and "no student was graded" in broken.stderr
    assert f"lesson {LESSON}, {named}" in broken.stderr, broken.stderr[-2000:]
    assert _snapshot(out) == before, "the failed canary changed files in the results folder"


def test_any_change_to_the_grader_regrades_and_status_says_why(small_class, tmp_path):
    project = _copy_project(tmp_path / "project")
    out, cache = tmp_path / "results", tmp_path / "cache"
    flags = ("--no-nbval",)
    first = _grade(project, small_class, out, *flags, cache=cache)
    assert first.returncode == 0, first.stderr[-2000:]
    assert "canary: the reference solutions got full marks (" in first.stdout

    again = _grade(project, small_class, out, *flags, cache=cache)
    assert "graded 0 student(s), 2 unchanged and reused" in again.stdout
    assert "(cached)" in again.stdout

    feedback = project / "autograder" / "reports" / "feedback.py"
    feedback.write_text(feedback.read_text(encoding="utf-8") + "\n# a change to the grader\n", encoding="utf-8")
    after_code = _grade(project, small_class, out, *flags, cache=cache)
    assert "graded 2 student(s)" in after_code.stdout
    assert "2 re-graded: changed since the last grading: grader code" in after_code.stdout
    assert "alice: changed since the last grading: grader code" in _status(project, out)

    master = next((project / "solutions").glob(f"{LESSON}_*.ipynb"))
    master.write_text(master.read_text(encoding="utf-8").replace("Lesson", "Lesson ", 1), encoding="utf-8")
    after_reference = _grade(project, small_class, out, *flags, cache=cache)
    assert "2 re-graded: changed since the last grading: reference solutions" in after_reference.stdout

    if launcher.isolation()[0] != "namespaces":
        pytest.skip("this machine has no namespaces: the isolation mode cannot change")
    limits = _grade(project, small_class, out, *flags, sandbox="limits", cache=cache)
    assert "2 re-graded: changed since the last grading: isolation mode (namespaces → limits)" in limits.stdout
    assert "bob: changed since the last grading: isolation mode (namespaces → limits)" in _status(project, out)
