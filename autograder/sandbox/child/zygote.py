"""A warm process that forks a fresh worker per request, inside the sandbox (copied there).

Starting a worker from scratch costs about a tenth of a CPU-second (bubblewrap,
the interpreter, numpy), and a student whose code calls ``coursekit.lie``
pays another fifth for scipy. The zygote pays that once per grading slot: it
imports what every worker needs and then forks one worker per request. Each
worker is a copy of a process that never ran student code; it enters the
student's own namespaces (``jail.enter_student_jail``: fresh user, mount, PID,
IPC, UTS, network and cgroup namespaces, a fresh tmpfs on ``/tmp``, a new empty
session keyring, and nothing else the zygote inherited from the grader) and runs the student's code
there (``worker.start``), so every student, and every restart after a crash,
starts from the same clean state.

The zygote is PID 1 of the sandbox's PID namespace (``bwrap --as-pid-1``); a
student's processes live in a PID namespace nested in it, where the zygote
has no pid at all. As root it runs as root with three capabilities (setuid,
setgid, kill) and its workers as the sandbox's user. It is not dumpable:
``/proc/1/fd``, ``/proc/1/mem``, ptrace and ``pidfd_getfd`` are refused, and a
worker closes the control socket before anything else.

Between two students the grader asks for a *reset*: every other process in the
sandbox is killed, and with them the student's namespaces and everything in
them (files, IPC objects, network state, keyrings). The zygote proves it: no process is left,
and the slot's own ``/tmp`` is as bubblewrap made it (students never write
there); otherwise the grader discards the slot.

The control channel is a Unix ``SOCK_SEQPACKET`` socket (message boundaries kept) on
fd 0; each message is one JSON object, and every reply echoes the request's
``nonce``:

- ``{"op": "fork", "cpu_seconds": N, "direct": bool}``: fork a worker (with that CPU limit; ``direct``:
  see ``worker.start``);
  reply ``{"ok": true, "pid": P}`` carrying two file descriptors: the write end
  of the worker's requests and the read end of its replies.
- ``{"op": "status", "pid": P, "wait": seconds}``: reply ``{"status": S}``, the
  raw wait status once the worker has exited, or ``null`` while it runs.
- ``{"op": "kill", "pid": P}``: kill worker P (its feeder, so its namespaces and all in them too);
  reply ``{"ok": true}`` once it is gone.
- ``{"op": "reset"}``: kill every other process and reap them; reply
  ``{"ok": true, "left": n}`` with the number of processes that could not be
  killed (0), plus one if the slot's ``/tmp`` was touched.

Examples
--------
>>> # bwrap --as-pid-1 ... -- python -I -B /sandbox/zygote.py --uid 4394304    (see autograder.sandbox.warm)
"""

from __future__ import annotations

import ctypes
import json
import os
import resource
import select
import signal
import socket
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import jail
import worker  # imports numpy; imported, it leaves privileges alone

KEEP_USER = "--keep-user" in sys.argv
SANDBOX_UID = jail.sandbox_uid(sys.argv)

PR_SET_PDEATHSIG = 1
PR_SET_DUMPABLE = 4
WARM_MODULES = ("scipy.spatial.transform", "coursekit", "coursekit.lie", "feeder")
CLEANER_SECONDS = 5.0


def _libc():
    return ctypes.CDLL(None, use_errno=True)


def _warm_up():
    for name in WARM_MODULES:
        try:
            __import__(name)
        except Exception:  # noqa: BLE001 - a module that cannot be imported fails in the worker, as usual
            pass


# ---------------------------------------------------------------- messages
def _send(control, message, fds=()):
    data = json.dumps(message).encode()
    if fds:
        socket.send_fds(control, [data], list(fds))
    else:
        control.send(data)


def _receive(control):
    """The next request; meanwhile, as PID 1, reap the orphans student code leaves."""
    while not select.select([control], [], [], 1.0)[0]:
        _reap()
    data = control.recv(65536)
    return json.loads(data) if data else None


# ---------------------------------------------------------------- fork
def _fork_worker(control, cpu_seconds, direct=False):
    """Fork a worker on two new pipes; return (pid, the grader's two ends).

    The worker enters the student's own namespaces (``jail.enter_student_jail``) and becomes the
    feeder and the runner there (``worker.start``); the pid is that of the process waiting for them.
    """
    requests_read, requests_write = os.pipe()
    replies_read, replies_write = os.pipe()
    pid = os.fork()
    if pid == 0:
        try:
            control.close()
            os.dup2(requests_read, 0)
            os.dup2(replies_write, 1)
            os.closerange(3, resource.getrlimit(resource.RLIMIT_NOFILE)[0])
            resource.setrlimit(resource.RLIMIT_CPU, (cpu_seconds, cpu_seconds))
            os.setsid()
            requests, replies = os.dup(0), os.dup(1)
            devnull = os.open(os.devnull, os.O_RDWR)
            for fd in (0, 1, 2):
                os.dup2(devnull, fd)
            worker.start(requests, replies, SANDBOX_UID, keep_user=KEEP_USER, direct=direct)
        finally:
            os._exit(70)
    os.close(requests_read)
    os.close(replies_write)
    _children.add(pid)
    return pid, (requests_write, replies_read)


# ---------------------------------------------------------------- status
_finished = {}  # pid -> raw wait status, for workers reaped before anyone asked
_children = set()  # pids of the workers forked (and not yet reset away)


def _reap():
    while True:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        _finished[pid] = status


def _status(pid, wait):
    deadline = time.monotonic() + max(0.0, float(wait))
    while True:
        _reap()
        if pid in _finished:
            return _finished.pop(pid)
        if time.monotonic() >= deadline:
            return None
        time.sleep(0.005)


# ---------------------------------------------------------------- reset
def _others():
    return [int(e) for e in os.listdir("/proc") if e.isdigit() and int(e) != os.getpid()]


def _kill_others():
    """SIGKILL every process of the sandbox but us; return how many remain.

    Only as PID 1 of the sandbox's own PID namespace: anywhere else kill(-1) would reach every process
    the user may signal (as root, the whole machine), so a zygote started outside bubblewrap kills
    nothing, and its reset fails (the grader discards the slot)."""
    if os.getpid() != 1:
        return max(1, len(_others()))
    for _ in range(200):
        if not _others():
            break
        try:
            os.kill(-1, signal.SIGKILL)  # every process of this PID namespace but us
        except OSError:
            pass
        _reap()
        time.sleep(0.002)
    _reap()
    _finished.clear()
    _children.clear()
    return len(_others())


def _kill_worker(pid):
    """Kill one worker: its process group (the waiter and the feeder; the feeder is PID 1 of the student's
    namespaces, so every process in them dies too). True when it is gone."""
    if pid not in _children:
        return True  # not one of ours any more: reaped and forgotten by a reset
    for target in (lambda: os.killpg(pid, signal.SIGKILL), lambda: os.kill(pid, signal.SIGKILL)):
        try:
            target()
        except OSError:
            pass
    return _status(pid, CLEANER_SECONDS) is not None or pid in _finished


def _tmp_untouched():
    """The slot's own /tmp holds nothing but what bubblewrap put there (students write in their own tmpfs)."""
    expected = {point.split("/")[2] for point in jail._mount_points_under("/tmp")}
    try:
        return set(os.listdir("/tmp")) <= expected
    except OSError:
        return False


def _reset():
    """Kill every process but the zygote. Each student's namespaces (its tmpfs, IPC objects, keyrings)
    die with its processes, so that is the whole reset; it is proved by no process being left and the
    slot's own /tmp being untouched, else the grader discards the slot."""
    left = _kill_others()
    if not _tmp_untouched():
        left += 1
    return left


# ---------------------------------------------------------------- main
def _answer(control, request, reply):
    """Carry out one request, filling in ``reply``; return the file descriptors to send with it."""
    op = request.get("op")
    if op == "fork":
        reply["pid"], fds = _fork_worker(control, int(request.get("cpu_seconds", 120)), bool(request.get("direct")))
        reply["ok"] = True
        return fds
    if op == "status":
        reply["status"] = _status(int(request["pid"]), request.get("wait", 0))
    elif op == "reset":
        reply["left"] = _reset()
        reply["ok"] = reply["left"] == 0
    elif op == "kill":
        reply["ok"] = _kill_worker(int(request["pid"]))
    else:
        reply.update(ok=False, error=f"unknown op {op!r}")
    return ()


def serve(control: socket.socket) -> None:
    _send(control, {"ready": True})
    while True:
        try:
            request = _receive(control)
        except (OSError, ValueError):
            request = None
        if not isinstance(request, dict):
            os._exit(0)  # the grader has gone (or spoke nonsense): everything here dies with us
        reply, fds = {"nonce": request.get("nonce")}, ()
        try:
            fds = _answer(control, request, reply)
        except Exception as error:  # noqa: BLE001 - say what went wrong; the grader discards the slot
            reply.update(ok=False, error=f"{type(error).__name__}: {error}")
        _send(control, reply, fds)
        for fd in fds:
            os.close(fd)


def main() -> None:
    control = socket.socket(fileno=os.dup(0))
    devnull = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(devnull, fd)
    os.close(devnull)
    libc = _libc()
    libc.prctl(PR_SET_DUMPABLE, 0, 0, 0, 0)
    # bubblewrap's own death signal does not survive its dropping of capabilities: ask again, so that the
    # sandbox (everything in it dies with PID 1) ends with the bubblewrap that runs it
    libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    os.chdir("/tmp")
    _warm_up()
    serve(control)


if __name__ == "__main__":
    main()
