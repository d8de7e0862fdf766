"""One grader at a time records the reference on a machine; the others wait and start warm.

Oracles: a second holder of :func:`recording_turn` waits until the first lets go (told by the
lines it prints, never by timing); the kernel drops the lock of a killed holder; a folder that
cannot hold a lock file, or a wait past the timeout, costs nothing but the speed; and two real
``grade`` commands held at the lock together on a fresh cache run the canary once between them.
"""

import os
import queue
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

from autograder.grading import recording_lock
from autograder.grading.recording_lock import recording_turn
from autograder.lessons.paths import PROJECT_ROOT
from support import THIS_COURSE, build_submission

# Another process that takes its turn (waiting at most argv[1] seconds), stays inside for argv[2] seconds and
# says what happened, one line per step.
OTHER_GRADER = textwrap.dedent(
    """
    import sys, time
    from autograder.grading.recording_lock import recording_turn
    from autograder.lessons.paths import this_course
    say = lambda line: print(line, flush=True)
    with recording_turn(this_course(), announce=say, timeout=float(sys.argv[1])) as held:
        say("held" if held else "not held")
        time.sleep(float(sys.argv[2]))
    """
)


class Watched:
    """A process whose output lines are read as they come (a thread per process, so no line waits in a buffer)."""

    def __init__(self, command, **kwargs):
        self.process = subprocess.Popen(command, cwd=PROJECT_ROOT, stdout=subprocess.PIPE, text=True, **kwargs)
        self.lines = queue.Queue()
        self.seen = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.process.stdout:
            self.lines.put(line.rstrip("\n"))
        self.lines.put(None)

    def line_starting(self, prefix, seconds=300):
        """The first line from now on that starts with ``prefix``; fail after ``seconds``."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            try:
                line = self.lines.get(timeout=1.0)
            except queue.Empty:
                continue
            if line is None:
                break
            self.seen.append(line)
            if line.startswith(prefix):
                return line
        raise AssertionError(f"no line starting {prefix!r} came; it said:\n" + "\n".join(self.seen))

    def rest(self, seconds=600):
        """Wait for the process to end; return every line it printed."""
        self.process.wait(timeout=seconds)
        while (line := self.lines.get(timeout=30)) is not None:
            self.seen.append(line)
        return self.seen


@pytest.fixture(autouse=True)
def lock_on(monkeypatch):
    """The lock as a machine has it by default, whatever this shell's environment holds."""
    monkeypatch.delenv("AUTOGRADER_RECORDING_LOCK", raising=False)


def _other_grader(cache, timeout=120, linger=0):
    command = [sys.executable, "-c", OTHER_GRADER, str(timeout), str(linger)]
    return Watched(command, env=dict(os.environ, AUTOGRADER_CACHE=str(cache)))


def test_a_second_grader_waits_for_the_first_and_is_told_why(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    with recording_turn(THIS_COURSE) as held:
        assert held
        other = _other_grader(tmp_path / "cache")
        first = other.line_starting("waiting")  # the other process is blocked now, and says so
        assert first.startswith("waiting for another grader on this machine") and f"(pid {os.getpid()})" in first
        assert other.process.poll() is None, "it went on while the lock was held"
    said = other.rest()
    assert other.process.returncode == 0, said
    assert said[1].startswith("waited ") and said[2:] == ["held"], said


def test_a_killed_holder_never_keeps_the_others_waiting(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    stuck = _other_grader(tmp_path / "cache", linger=600)
    stuck.line_starting("held")
    os.kill(stuck.process.pid, signal.SIGKILL)
    stuck.rest(seconds=30)
    with recording_turn(THIS_COURSE, timeout=5) as held:
        assert held


def test_a_wait_past_the_timeout_goes_on_without_the_lock(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    with recording_turn(THIS_COURSE):
        said = _other_grader(tmp_path / "cache", timeout=0.5).rest(seconds=60)
    assert said[0].startswith("waiting for another grader on this machine"), said
    assert said[1:] == ["still locked after 0.5 s: recording the reference in this run too", "not held"], said


def test_a_lock_file_of_garbage_only_loses_the_pid_from_the_message(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    with recording_turn(THIS_COURSE):
        recording_lock.lock_path(THIS_COURSE).write_bytes(b"\xff\xfe not a pid")
        said = _other_grader(tmp_path / "cache", timeout=0.5).rest(seconds=60)
    assert said[0].startswith("waiting for another grader on this machine that is recording"), said
    assert said[-1] == "not held", said


def test_a_cache_folder_that_cannot_hold_a_lock_costs_nothing(tmp_path, monkeypatch):
    (tmp_path / "a file").write_text("not a folder", encoding="utf-8")
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "a file" / "cache"))
    told = []
    with recording_turn(THIS_COURSE, announce=told.append) as held:
        assert held is False
    assert told == []


def test_the_benchmarks_switch_turns_it_off(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    with recording_turn(THIS_COURSE) as first:
        monkeypatch.setenv("AUTOGRADER_RECORDING_LOCK", "0")
        told = []
        with recording_turn(THIS_COURSE, announce=told.append, timeout=60) as second:
            assert first is True and second is False and told == []


def test_the_lock_is_named_by_the_transcripts_key_and_private(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    with recording_turn(THIS_COURSE):
        path = recording_lock.lock_path(THIS_COURSE)
        assert path.parent == tmp_path / "cache" and path.exists()
        assert path.read_text(encoding="ascii").strip() == str(os.getpid())
        assert path.stat().st_mode & 0o777 == 0o600


def test_two_grade_commands_on_a_fresh_machine_run_the_canary_once(tmp_path, monkeypatch):
    """Two sections graded at once on a fresh cache: one records and runs the canary, the other waits for it and
    starts warm (its canary cached), and both give the same answers the same points. Both are first held at the
    lock by this test, so that they surely overlap."""
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    runs = []
    with recording_turn(THIS_COURSE):
        for section in ("a", "b"):
            build_submission(tmp_path / section / "ana", lessons=("01",))
            command = [sys.executable, "-m", "autograder", "grade", str(tmp_path / section), "--lessons", "01"]
            command += ["--out", str(tmp_path / f"out-{section}"), "--jobs", "1", "--no-similarity", "--no-nbval"]
            runs.append(Watched(command))
        for run in runs:
            run.line_starting("waiting for another grader on this machine", seconds=180)
    outputs = ["\n".join(run.rest()) for run in runs]
    assert [run.process.returncode for run in runs] == [0, 0], outputs
    ran = [out for out in outputs if "canary: the reference solutions got full marks (" in out]
    cached = [out for out in outputs if "got full marks with this grader before (cached)" in out]
    assert len(ran) == 1 and len(cached) == 1, outputs
    assert len(list((tmp_path / "cache").glob("canary-*.json"))) == 1
    for section in ("a", "b"):
        grades = (tmp_path / f"out-{section}" / "grades.csv").read_text(encoding="utf-8").splitlines()
        assert grades[1].startswith("ana,") and ",graded," in grades[1], grades
