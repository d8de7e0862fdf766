"""Warm slots (autograder/sandbox/warm.py): a student's worker is forked from a long-lived zygote.

Oracles: what one student leaves in a slot (processes, files, unreadable
folders, System V IPC, a locked /tmp) is gone when the next student's worker
starts; student code cannot reach the zygote (its fds, memory, ptrace) or
the control socket; a student who kills the zygote loses only the call that
did it, and the batch's next student gets a fresh warm slot. The behaviour of
a warm worker against a cold one (timeouts, crashes, limits, isolation) is
checked by tests/test_sandbox.py, which runs every case both ways.
"""

import os
import signal
import time

import pytest

from autograder.sandbox import launcher, process_tree, warm
from autograder.sandbox.session import LessonProgram, StudentError, StudentSandbox
from support import THIS_COURSE, started_warm_slot

pytestmark = pytest.mark.skipif(not warm.enabled(), reason="warm slots need the namespace sandbox")

LEAVE_EVERYTHING = r"""
import ctypes, os, time

def leave():
    if os.fork() == 0:                  # a detached grandchild that keeps writing
        os.setsid()
        if os.fork() == 0:
            while True:
                try:
                    open("/tmp/daemon", "w").write(str(time.time()))
                except OSError:
                    pass
                time.sleep(0.01)
        os._exit(0)
    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    made = [libc.shmget(4242, 4096, 0o1666), libc.semget(4243, 1, 0o1666), libc.msgget(4244, 0o1666),
            libc.mq_open(b"/left-behind", 0o100 | 2, 0o666, None)]         # POSIX message queue (O_CREAT|O_RDWR)
    for ring in (-4, -5, -3):                                               # @u, @us, @s keyrings: add_key
        made.append(libc.syscall(248, b"user", b"left-behind", b"the previous student's work", 27, ring))
    open("/tmp/answers.txt", "w").write("the previous student's work")
    for name in os.listdir("/tmp"):  # folders bubblewrap made (a Python installed under /tmp)
        try:
            open(os.path.join("/tmp", name, "left.txt"), "w").write("x")
        except OSError:
            pass
    os.makedirs("/tmp/locked/inner")
    open("/tmp/locked/inner/f", "w").write("x")
    os.chmod("/tmp/locked/inner", 0)
    os.chmod("/tmp/locked", 0)
    os.mkdir("/tmp/deep")
    os.chdir("/tmp/deep")
    for _ in range(2000):                                                   # deeper than any recursive walk
        os.mkdir("d")
        os.chdir("d")
    open("bottom.txt", "w").write("x")
    os.chdir("/tmp")
    time.sleep(0.1)
    os.chmod("/tmp", 0)
    return made
"""

LOOK_AROUND = r"""
import ctypes, os

def _ppid(pid):
    for line in open(f"/proc/{pid}/status"):
        if line.startswith("PPid:"):
            return int(line.split()[1])
    return 0

def look():
    processes = sorted(int(p) for p in os.listdir("/proc") if p.isdigit())
    chain, pid = set(), int(os.readlink("/proc/self"))
    while pid > 1:                       # this student's own processes: the runner, its feeder, the waiter
        chain.add(pid)
        pid = _ppid(pid)
    mounts = {line.split()[4] for line in open("/proc/self/mountinfo")}
    tmp, stack = [], ["/tmp"]
    while stack:                         # iterative: a recursive walk would stop at a deep tree
        folder = stack.pop()
        try:
            entries = list(os.scandir(folder))
        except PermissionError:          # a folder made unreadable (chmod 0): seen, not entered
            continue
        for entry in entries:
            tmp.append(entry.path)
            if entry.is_dir(follow_symlinks=False) and entry.path not in mounts:
                stack.append(entry.path)
    ipc = {table: len(open(f"/proc/sysvipc/{table}").read().splitlines()) - 1 for table in ("shm", "sem", "msg")}
    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    queue = libc.mq_open(b"/left-behind", 2, 0, None)                      # without O_CREAT: ENOENT when gone
    key = libc.syscall(249, b"user", b"left-behind", None, 0)               # request_key searches every keyring
    return {"others": sorted(set(processes) - chain - {1}), "tmp": sorted(p for p in tmp if len(p) < 200),
            "deep": sum(len(p) >= 200 for p in tmp), "ipc": ipc,
            "tmp_writable": os.access("/tmp", os.W_OK), "queue": queue, "key": key}
"""

REACH_FOR_THE_ZYGOTE = r"""
import ctypes, os, stat

def reach():
    found = {}
    for who in sorted({os.getppid(), 1}):  # the feeder (the runner's parent) and PID 1 as /proc shows it
        for what, attempt in (("fds", lambda: os.listdir(f"/proc/{who}/fd")),
                              ("memory", lambda: open(f"/proc/{who}/mem", "rb").read(1)),
                              ("environment", lambda: open(f"/proc/{who}/environ", "rb").read(1)),
                              ("root", lambda: os.listdir(f"/proc/{who}/root/tmp"))):
            try:
                attempt()
                found[f"{what} of {who}"] = "reachable"
            except OSError as error:
                found[f"{what} of {who}"] = type(error).__name__
        found[f"ptrace of {who}"] = ctypes.CDLL(None, use_errno=True).ptrace(16, who, None, None)  # ATTACH
    found["sockets"] = []
    for fd in os.listdir("/proc/self/fd"):
        try:
            if os.readlink(f"/proc/self/fd/{fd}").startswith("socket:"):
                import socket
                kind = socket.socket(fileno=os.dup(int(fd)))
                found["sockets"].append(kind.type.name)
                kind.close()
        except OSError:  # the folder listing's own descriptor, closed by now
            pass
    return found
"""


def _program(source):
    return {"01": LessonProgram(setup="import numpy as np", cells=[("code", source)])}


@pytest.fixture
def slot():
    with started_warm_slot() as started:
        yield started


def test_workers_are_forked_from_the_slot(slot):
    with StudentSandbox(support=THIS_COURSE.support, program=_program("def f():\n    return 1"), slot=slot) as box:
        assert box.call("01", "f") == 1
        assert isinstance(box.process, warm.WarmWorker)


def test_the_next_student_finds_nothing_the_previous_one_left(slot):
    with StudentSandbox(support=THIS_COURSE.support, program=_program(LOOK_AROUND), slot=slot) as fresh:
        before = fresh.call("01", "look")  # /tmp holds the folders of a Python installed under /tmp, if any
    with StudentSandbox(support=THIS_COURSE.support, program=_program(LEAVE_EVERYTHING), slot=slot) as first:
        made = first.call("01", "leave")
        assert all(ident >= 0 for ident in made[:4]), made
        assert made[4:] == [-1, -1, -1], made  # no key can be made at all (the jail's filter: EPERM)
    with StudentSandbox(support=THIS_COURSE.support, program=_program(LOOK_AROUND), slot=slot) as second:
        seen = second.call("01", "look")
        assert isinstance(second.process, warm.WarmWorker)
    # nothing of the first student: no process, no file at any depth, no IPC object, no key
    assert seen["others"] == [], seen
    assert seen["tmp"] == before["tmp"] and seen["deep"] == 0 and seen["tmp_writable"], (before, seen)
    assert seen["ipc"] == {"shm": 0, "sem": 0, "msg": 0}, seen
    assert seen["queue"] == -1 and seen["key"] == -1, seen


def test_the_look_around_sees_what_a_student_leaves(slot):
    """The oracle above can fail: within one student's sandbox it finds every kind of thing left."""
    program = _program(LEAVE_EVERYTHING.replace('os.chmod("/tmp", 0)', "pass") + LOOK_AROUND)
    with StudentSandbox(support=THIS_COURSE.support, program=program, slot=slot) as box:
        box.call("01", "leave")
        seen = box.call("01", "look")
    assert seen["others"], "the daemon"
    assert seen["deep"] > 1900 and "/tmp/answers.txt" in seen["tmp"], seen["tmp"]
    # keys: none can be made (the jail's filter; tests/test_fresh_process_state.py), so none is looked for here
    assert seen["ipc"] == {"shm": 1, "sem": 1, "msg": 1} and seen["queue"] >= 0, seen


def test_student_code_cannot_reach_the_zygote(slot):
    with StudentSandbox(support=THIS_COURSE.support, program=_program(REACH_FOR_THE_ZYGOTE), slot=slot) as box:
        found = box.call("01", "reach")
    refused = {key: value for key, value in found.items() if key != "sockets" and value not in ("PermissionError", -1)}
    assert not refused, found
    # its one socket to the feeder (as two descriptors: requests, replies), never the zygote's control channel
    assert set(found["sockets"]) == {"SOCK_STREAM"}, found["sockets"]


def test_student_code_cannot_kill_the_zygote(slot):
    """It is PID 1 of the sandbox (and root, when the grader is): signals from student code never reach it."""
    attack = (
        "import os, signal, time\ndef attack():\n    for number in (signal.SIGKILL, signal.SIGSTOP, signal.SIGTERM):\n"
        "        for target in (os.getppid(), -1):\n            try:\n                os.kill(target, number)\n"
        "            except OSError:\n                pass\n    time.sleep(0.3)\n    return os.getppid()"
    )
    with StudentSandbox(support=THIS_COURSE.support, program=_program(attack), slot=slot) as box:
        try:
            assert box.call("01", "attack") == 1
        except StudentError as error:  # kill(-1, SIGKILL) also hits the worker itself: a crash, as when cold
            assert error.kind == "crash", error
    assert slot.alive()
    with StudentSandbox(support=THIS_COURSE.support, program=_program("def f():\n    return 1"), slot=slot) as box:
        assert box.call("01", "f") == 1
        assert isinstance(box.process, warm.WarmWorker)


def test_a_slot_that_dies_costs_one_call_and_the_pool_replaces_it():
    """The OOM killer or an operator may still kill a slot from outside: the student goes on cold."""
    with warm.SlotPool(1, launcher.Limits(), THIS_COURSE.support) as pool:
        slot = pool.slots[0]
        with StudentSandbox(support=THIS_COURSE.support, program=_program("def ok():\n    return 7"), slot=slot) as box:
            assert box.call("01", "ok") == 7
            zygote = process_tree.descendants(slot.process.pid)[0]
            os.kill(zygote, signal.SIGKILL)  # as the OOM killer would
            while process_tree.descendants(slot.process.pid):
                time.sleep(0.01)
            with pytest.raises(StudentError) as error:
                box.call("01", "ok")
            assert error.value.kind == "crash"
            assert box.call("01", "ok") == 7, "the student goes on, in a cold sandbox"
            assert not isinstance(box.process, warm.WarmWorker)
        assert not slot.alive()
        pool.repair(0)
        replaced = pool.slots[0]
        assert replaced.alive()
        with StudentSandbox(
            support=THIS_COURSE.support, program=_program("def f():\n    return 1"), slot=replaced
        ) as box:
            assert box.call("01", "f") == 1
            assert isinstance(box.process, warm.WarmWorker)


def test_a_slot_with_other_limits_is_not_used(slot):
    with StudentSandbox(
        support=THIS_COURSE.support,
        program=_program("def f():\n    return 1"),
        slot=slot,
        limits=launcher.Limits(memory_bytes=2**30),
    ) as box:
        assert box.call("01", "f") == 1
        assert not isinstance(box.process, warm.WarmWorker)


def test_concurrent_slots_run_as_different_users():
    """RLIMIT_NPROC counts per user: one student's fork bomb must not starve another slot's student."""
    if os.geteuid() != 0:
        pytest.skip("as an ordinary user every sandbox runs as that user, in its own user namespace")
    who = "def who():\n    return int(open('/proc/self/uid_map').read().split()[1])  # the uid outside"
    with warm.SlotPool(2, launcher.Limits(), THIS_COURSE.support) as pool:
        uids = []
        for slot in pool.slots:
            with StudentSandbox(support=THIS_COURSE.support, program=_program(who), slot=slot) as box:
                uids.append(box.call("01", "who"))
    with StudentSandbox(support=THIS_COURSE.support, program=_program(who)) as cold:
        uids.append(cold.call("01", "who"))
    assert len(set(uids)) == 3 and 0 not in uids, uids


def test_a_slot_that_cannot_start_leaves_its_graders_cold(monkeypatch):
    def no_bubblewrap(*args, **kwargs):
        raise OSError("bwrap: no such file")

    monkeypatch.setattr(launcher, "spawn", no_bubblewrap)
    with warm.SlotPool(1, launcher.Limits(), THIS_COURSE.support) as pool:
        slot = pool.slots[0]
        assert not slot.usable()
        monkeypatch.undo()
        with StudentSandbox(support=THIS_COURSE.support, program=_program("def f():\n    return 1"), slot=slot) as box:
            assert box.call("01", "f") == 1
            assert not isinstance(box.process, warm.WarmWorker)


def test_no_zygote_starts_without_namespaces(monkeypatch):
    """Limits mode (or a bubblewrap that cannot run here) grades cold: a zygote outside a PID namespace of its
    own would kill every process the user may signal at its first reset (as root, the whole machine)."""
    started = []
    monkeypatch.setattr(launcher, "isolation", lambda: ("limits", "asked for"))
    monkeypatch.setattr(launcher, "spawn", lambda *args, **kwargs: started.append(args))
    slot = warm.WarmSlot(0, launcher.Limits(), THIS_COURSE.support)
    slot.spawn()
    assert not started and not slot.usable()


def test_a_zygote_that_is_not_pid_1_kills_nothing(monkeypatch):
    """The zygote's reset signals -1 only as PID 1 of its sandbox; run anywhere else it kills nothing and the
    reset fails (the grader discards the slot)."""
    import importlib.util

    path = launcher.Path(launcher.__file__).parent / "child" / "zygote.py"
    spec = importlib.util.spec_from_file_location("zygote_outside", path)
    zygote = importlib.util.module_from_spec(spec)
    monkeypatch.syspath_prepend(str(path.parent))
    monkeypatch.syspath_prepend(str(THIS_COURSE.solutions))  # coursekit, which the zygote preloads
    spec.loader.exec_module(zygote)
    signals = []
    monkeypatch.setattr(zygote.os, "kill", lambda pid, sig: signals.append((pid, sig)))
    assert os.getpid() != 1
    assert zygote._kill_others() >= 1 and signals == []


def test_a_worker_that_does_not_start_leaves_the_student_cold(slot, monkeypatch):
    """A slot whose workers die before saying hello (before any student code) is dropped, not the student."""

    def stillborn(self, direct=False):
        worker = original(self, direct)
        worker.stdout.close()
        read_end, write_end = os.pipe()
        os.close(write_end)  # reads end at once, as when the worker dies at start
        worker.stdout = os.fdopen(read_end, "rb")
        return worker

    original = warm.WarmSlot.fork_worker
    monkeypatch.setattr(warm.WarmSlot, "fork_worker", stillborn)
    with StudentSandbox(support=THIS_COURSE.support, program=_program("def f():\n    return 1"), slot=slot) as box:
        assert box.call("01", "f") == 1
        assert not isinstance(box.process, warm.WarmWorker)
    assert slot.broken


def test_each_forked_grader_is_handed_a_slot_no_other_running_grader_has(tmp_path):
    """fork_each passes each child its slot (no module global holds it); the child's sandboxes fork from
    it, and two graders running at once never share one."""
    from autograder.sandbox.forking import fork_each

    def grade(item, slot):
        assert slot is not None and slot.usable()
        with StudentSandbox(support=THIS_COURSE.support, program=_program("def f():\n    return 1"), slot=slot) as box:
            assert box.call("01", "f") == 1
            assert isinstance(box.process, warm.WarmWorker)
        with open(item, "w") as out:  # which slot, and while this grader was running
            out.write(f"{slot.index} {time.monotonic()}")
        time.sleep(0.3)
        with open(item, "a") as out:
            out.write(f" {time.monotonic()}")

    items = [str(tmp_path / str(n)) for n in range(4)]
    problems = []
    with warm.SlotPool(2, launcher.Limits(), THIS_COURSE.support) as pool:
        fork_each(grade, items, 2, lambda _, problem: problems.append(problem), slots=pool)
    assert problems == [None] * 4, problems
    runs = [tuple(map(float, open(item).read().split())) for item in items]
    for first, (slot_a, start_a, end_a) in enumerate(runs):
        for slot_b, start_b, end_b in runs[first + 1 :]:
            overlapping = start_a < end_b and start_b < end_a
            assert not (overlapping and slot_a == slot_b), runs
