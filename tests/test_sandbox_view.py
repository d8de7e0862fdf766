"""What a sandbox sees of this machine: its allow-list and nothing else; the canary refuses to grade when the
hidden suite, the masters, the submissions or the output can be seen from inside (SECURITY.md)."""

import importlib.util
import os
import shutil
import signal
import subprocess
import sys
import zipfile
from dataclasses import replace

import pytest

from autograder import cli
from autograder.grading import canary
from autograder.grading.fingerprint import cache_dir
from autograder.integrations.gradescope import build_bundle, unpack_bundle
from autograder.lessons.course import Course
from autograder.lessons.hand_ins import write_submission
from autograder.lessons.paths import PROJECT_ROOT
from autograder.sandbox import allowlist, launcher, warm
from autograder.sandbox.session import LessonProgram, StudentSandbox
from support import THIS_COURSE

NAMESPACES = launcher.isolation()[0] == "namespaces"
needs_namespaces = pytest.mark.skipif(not NAMESPACES, reason="bubblewrap is not available: limits-only sandbox")

LOOK = """
import os, sys
def exists(paths):
    return {p: os.path.lexists(p) for p in paths}
def listing(path):
    try:
        return sorted(os.listdir(path))
    except OSError:
        return None
def site_folders():
    return {p: sorted(os.listdir(p)) for p in sys.path
            if p.endswith(("site-packages", "dist-packages")) and os.path.isdir(p)}
"""


@pytest.fixture(scope="module", params=["cold", "warm"])
def look(request):
    """A sandbox running LOOK: cold (started for the student) and forked from a warm slot's zygote."""
    if request.param == "warm" and not warm.enabled():
        pytest.skip("warm slots need the namespace sandbox")
    slot = None
    if request.param == "warm":
        slot = warm.WarmSlot(0, launcher.Limits(), THIS_COURSE.support)
        slot.spawn()
        slot.wait_ready()
    program = {"01": LessonProgram(setup="import numpy as np", cells=[("code", LOOK)])}
    box = StudentSandbox(support=THIS_COURSE.support, program=program, limits=launcher.Limits(), slot=slot)
    with box:
        yield lambda name, *args: box.call("01", name, list(args))
    if slot is not None:
        slot.close()


def _view_names(folder):
    """Names the allow-list puts directly in ``folder`` inside a sandbox."""
    prefix = folder.rstrip("/") + "/"
    return {p[len(prefix) :].split("/", 1)[0] for p in allowlist.sandbox_view().paths() if p.startswith(prefix)}


@needs_namespaces
def test_a_sandbox_sees_its_allow_list_and_nothing_else(look):
    view_paths = set(allowlist.sandbox_view().paths())
    assert set(look("listing", "/")) <= _view_names("/") | {"dev", "proc", "sandbox", "tmp"}
    assert set(look("listing", "/etc")) <= _view_names("/etc")
    assert set(look("listing", "/usr") or []) <= _view_names("/usr")
    never = [
        "/usr/share",
        "/usr/include",
        "/usr/local/bin",
        "/usr/lib/python3/dist-packages",
        "/opt",
        "/home",
        str(launcher.GRADER_ROOT / "autograder"),
        str(launcher.GRADER_ROOT / "solutions"),
        str(THIS_COURSE.hidden_suite),
        str(THIS_COURSE.solutions),
        str(cache_dir()),
    ]
    seen = look("exists", [p for p in never if p not in view_paths])
    assert not any(seen.values()), f"visible from a sandbox: {[p for p, there in seen.items() if there]}"
    # each site-packages inside holds the allowed distributions' own entries only: numpy, not dask or sphinx
    sites = look("site_folders")
    assert sites and any("numpy" in names for names in sites.values())
    for folder, names in sites.items():
        assert set(names) <= _view_names(folder), folder
        assert not {n for n in names if n.split("-")[0].lower() in ("dask", "sphinx", "nbgrader", "jupyterlab")}
        assert not [n for n in names if n.endswith(".pth")]


def test_the_allow_list_never_binds_a_system_folder_and_is_computed_once():
    view = allowlist.sandbox_view()
    assert allowlist.sandbox_view() is view
    wholesale = {"/", "/usr", "/usr/lib", "/usr/local", "/lib", "/lib64", "/bin", "/opt", "/home", "/root", "/etc"}
    wholesale |= {sys.prefix, sys.base_prefix, os.path.expanduser("~"), str(launcher.GRADER_ROOT)}
    dests = [dest for _, dest in view.binds]
    assert not set(dests) & ({os.path.realpath(p) for p in wholesale} | wholesale)
    assert not [d for d in dests if os.path.basename(d) in ("site-packages", "dist-packages")]
    assert not [d for d in dests if str(launcher.GRADER_ROOT).startswith(d.rstrip("/") + "/")]
    assert not [d for d in dests if d.startswith(str(launcher.GRADER_ROOT / "autograder"))]
    # the interpreter, its standard library, numpy, scipy and the libraries they link to are there
    assert os.path.dirname(os.__file__) in dests or any(os.path.dirname(os.__file__).startswith(d) for d in dests)
    assert any(d.endswith("/numpy") for d in dests) and any(d.endswith("/scipy") for d in dests)
    assert any("libc.so" in d for d in dests)


def _course_copy(target, hidden_in_coursekit=False):
    """A copy of this repository's course at ``target`` (masters, coursekit, released notebooks, hidden suite)."""
    shutil.copytree(THIS_COURSE.solutions, target / "solutions", ignore=shutil.ignore_patterns("__pycache__", ".*"))
    shutil.copytree(THIS_COURSE.released, target / "course", ignore=shutil.ignore_patterns("__pycache__", ".*"))
    hidden = "solutions/coursekit/tests_hidden" if hidden_in_coursekit else "hidden"
    shutil.copytree(THIS_COURSE.hidden_suite, target / hidden, ignore=shutil.ignore_patterns("__pycache__"))
    (target / "layout.toml").write_text(f'[course]\ntitle = "Copy"\nhidden = "{hidden}"\n', encoding="utf-8")
    return Course.at(target)


def _class(folder):
    write_submission(THIS_COURSE, folder / "ada", {}, ("01",))
    return folder


@needs_namespaces
@pytest.mark.parametrize("where", ["hidden suite in coursekit", "class in coursekit"])
def test_grade_refuses_when_the_sandbox_can_see_the_hidden_suite_or_the_class(tmp_path, where):
    """A course whose hidden suite, or a class folder, sits in coursekit (copied into every sandbox): grade
    says what it saw and where, exits with status 3 and grades no one."""
    course = _course_copy(tmp_path / "course", hidden_in_coursekit=where.startswith("hidden"))
    if where.startswith("class"):
        submissions = _class(course.support / "class_2026")
    else:
        submissions = _class(tmp_path / "class")
    out = tmp_path / "out"
    env = dict(os.environ, AUTOGRADER_CACHE=str(tmp_path / "cache"))
    command = [sys.executable, "-m", "autograder", "grade", str(submissions), "--out", str(out)]
    command += ["--course", str(course.root), "--lessons", "01", "--no-nbval", "--no-similarity"]
    done = subprocess.run(command, capture_output=True, text=True, timeout=900, env=env, cwd=tmp_path)
    assert done.returncode == 3, done.stdout[-2000:] + done.stderr[-2000:]
    assert "canary failed: student code could see" in done.stderr and "no student was graded" in done.stderr
    label = "the course's hidden suite" if where.startswith("hidden") else "the submissions folder"
    assert f"{label}: " in done.stderr and "/sandbox/coursekit/" in done.stderr
    assert not (out / "grades.csv").exists() and "project files out of reach" not in done.stdout


@needs_namespaces
def test_grade_refuses_a_checkout_under_a_folder_the_sandbox_binds(tmp_path, monkeypatch, capsys):
    """The red team's container: the checkout (course, class, output) under a folder the sandbox binds whole, as
    the old sandbox bound /usr. Whatever the allow-list lets through, the canary's look from inside refuses."""
    usr = tmp_path / "usr"
    app = usr / "src" / "app"
    course = _course_copy(app)
    submissions = _class(app / "submissions")
    view = allowlist.sandbox_view()
    widened = replace(view, binds=view.binds + ((str(usr), str(usr)),))
    monkeypatch.setattr(allowlist, "sandbox_view", lambda: widened)
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    handler = signal.getsignal(signal.SIGINT)
    try:
        status = cli.main(
            ["grade", str(submissions), "--out", str(app / "out"), "--course", str(course.root), "--lessons", "01"]
        )
    finally:
        signal.signal(signal.SIGINT, handler)
    output = capsys.readouterr()
    assert status == 3, output.out[-2000:] + output.err[-2000:]
    for label in ("the course's hidden suite", "the course's masters (solutions)", "the submissions folder"):
        assert f"{label}: {app}" in output.err, output.err
    assert not (app / "out" / "grades.csv").exists()


@needs_namespaces
def test_the_isolation_line_says_what_the_look_from_inside_found(tmp_path):
    check = canary.check_sandbox_view(THIS_COURSE, submissions=_class(tmp_path / "class"), output=tmp_path / "out")
    assert (
        check.mode == "namespaces"
        and check.entries > 1000
        and check.binds == len(allowlist.sandbox_view().binds) + len(allowlist.sandbox_view().links)
    )
    line = launcher.describe_isolation(check.line())
    assert "project files out of reach (checked from inside a sandbox" in line
    for label in ("hidden suite", "masters", "submissions folder", "output folder", "cache folder", "checkout"):
        assert label in line
    assert "out of reach" not in launcher.describe_isolation()  # no look, no claim


def _build_package(tmp_path):
    """The files a wheel of this project holds, built from a copy (nothing is written into the checkout)."""
    source = tmp_path / "source"
    source.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy2(PROJECT_ROOT / name, source / name)
    shutil.copytree(PROJECT_ROOT / "autograder", source / "autograder", ignore=shutil.ignore_patterns("__pycache__"))
    out = tmp_path / "built"
    if importlib.util.find_spec("wheel") is not None:
        command = [sys.executable, "-m", "pip", "wheel", ".", "--no-deps", "--no-build-isolation", "-w", str(out)]
        subprocess.run(command, cwd=source, check=True, capture_output=True, timeout=600)
        (wheel,) = out.glob("*.whl")
        return zipfile.ZipFile(wheel).namelist()
    # no `wheel` here: setuptools' build_py, which chooses the wheel's files the same way
    command = [sys.executable, "-c", "from setuptools import setup; setup()", "-q", "build_py", "--build-lib", str(out)]
    subprocess.run(command, cwd=source, check=True, capture_output=True, timeout=600)
    return [p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file()]


def test_the_hidden_suite_never_ships_in_a_wheel(tmp_path):
    names = _build_package(tmp_path)
    assert "autograder/cli.py" in names and "autograder/grading/hidden_suite.ini" in names
    leaked = [n for n in names if n.startswith(("autograder/hidden/", "autograder/mistakes/"))]
    assert not leaked, leaked
    # the editable install (environment.txt's `-e .`) still finds both in the checkout
    assert importlib.util.find_spec("autograder.hidden") is not None
    assert importlib.util.find_spec("autograder.mistakes") is not None
    assert sorted(THIS_COURSE.hidden_suite.glob("test_*.py"))


@needs_namespaces
def test_gradescope_bundle_keeps_the_hidden_suite_out_of_the_sandbox(tmp_path):
    """In the container the hidden suite sits in source/, beside the grader: in the bundle, out of every
    sandbox's view (checked from inside, as run_autograder does before each submission)."""
    bundle = build_bundle(tmp_path / "autograder.zip", THIS_COURSE, lessons=("01",))
    root = tmp_path / "autograder"
    source = unpack_bundle(bundle, root)
    course = Course.at(source)
    assert sorted(course.hidden_suite.glob("test_01_*.py")) and course.hidden_suite.is_relative_to(source)
    submission = _class(tmp_path / "class") / "ada"
    (root / "results").mkdir()
    check = canary.check_sandbox_view(course, submissions=submission, output=root / "results")
    assert "the course's hidden suite" in check.checked
    assert not [p for p in allowlist.sandbox_view().paths() if p.startswith(str(root))]
