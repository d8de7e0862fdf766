"""Warm grading slots: one long-lived sandbox per slot, whose zygote forks each student's worker.

A cold sandbox costs about 0.1 CPU-s to start (bubblewrap, Python, numpy) and
0.2 more when the student's code first calls scipy through ``coursekit.lie``.
A batch has ``jobs`` grading slots; each runs one student at a time. Here each
slot keeps one sandbox alive for the whole batch, with a *zygote* inside
(``child/zygote.py``) that has imported all of that once and forks a fresh
worker for each student, and for each restart after a crash.

What a student sees does not change: the same uid, limits and folders; a
worker that is a copy of a process no student code ever ran in, which enters
namespaces of its own before any student code runs (``child/jail.py``: new
user, mount, PID, IPC, UTS, network and cgroup namespaces, a fresh tmpfs on
``/tmp``, a new empty session keyring, the key system calls refused), as a
cold sandbox does. Everything a student makes lives in those namespaces and
dies with the student's last process, so nothing one student leaves behind
reaches the next by construction. Before a student's first worker the slot
is *reset*: every process left in the sandbox is killed, and the zygote proves
it (no process left, the slot's own ``/tmp`` untouched: students never write
there), else the slot is discarded. SECURITY.md lists what a slot shares
between students and why that is safe.

Any failure of a slot (its zygote killed by a student, a reply that does not
come) discards the slot: that student's sandbox goes on cold, and the batch
starts a new slot for the next student. Only ``namespaces`` isolation uses
slots (in ``limits`` mode a reset could not tell a student's processes from
the grader's). ``AUTOGRADER_WARM=0`` turns them off.

Examples
--------
>>> with SlotPool(2, Limits(), course.support) as pool:        # doctest: +SKIP
...     pool.enter(0)                      # in a forked grader: StudentSandbox now forks from slot 0
"""

from __future__ import annotations

import json
import os
import secrets
import signal
import socket
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

from autograder.sandbox import cleanup, cpus, launcher

PID_LIMIT = 2**22  # the kernel's largest pid_max: slot uids never meet a cold sandbox's uid
ZYGOTE_MEMORY = 512 * 1024**2  # room for the zygote's own pages in the slot's memory cap
ZYGOTE_CPU_SECONDS = 3600  # the zygote's own CPU limit (each worker gets the student's limit)
START_SECONDS = 60.0
REPLY_SECONDS = 10.0


class SlotBroken(RuntimeError):
    """A slot's zygote is gone or did not answer: the slot must be discarded."""


def enabled() -> bool:
    """Whether this machine grades with warm slots (namespaces isolation, not turned off)."""
    return launcher.isolation()[0] == "namespaces" and os.environ.get("AUTOGRADER_WARM", "1") != "0"


class WarmWorker:
    """A worker forked by a slot's zygote: the parts of :class:`subprocess.Popen` a session uses."""

    def __init__(self, slot, pid, request_fd, reply_fd):
        self.slot, self.pid = slot, pid
        self.stdin = os.fdopen(request_fd, "wb")
        self.stdout = os.fdopen(reply_fd, "rb")
        self.returncode = None

    def _take(self, status):
        if status is not None:
            self.returncode = -os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status)
        return self.returncode

    def poll(self) -> int | None:
        if self.returncode is None:
            try:
                self._take(self.slot.status(self.pid, 0))
            except SlotBroken:
                self.returncode = -signal.SIGKILL  # the whole sandbox went down with the zygote
        return self.returncode

    def wait(self, timeout: float | None = None) -> int | None:
        if self.returncode is None:
            try:
                if self._take(self.slot.status(self.pid, REPLY_SECONDS if timeout is None else timeout)) is None:
                    raise subprocess.TimeoutExpired("worker", timeout)
            except SlotBroken:
                self.returncode = -signal.SIGKILL
        return self.returncode

    def stop(self) -> None:
        """Kill this worker and everything it started (all of it lives in the namespaces its feeder heads);
        close the pipes."""
        try:
            self.slot.kill(self.pid)
        except SlotBroken:
            self.slot.discard()
        if self.returncode is None:
            self.returncode = -signal.SIGKILL
        for stream in (self.stdin, self.stdout):
            try:
                stream.close()
            except OSError:
                pass


class WarmSlot:
    """One long-lived sandbox with a zygote; started by the batch's parent, used by one grader at a time."""

    def __init__(self, index, limits, support, cpu=None):
        self.index, self.limits, self.support = index, limits, Path(support)
        self.cpu = cpu  # the CPU its zygote, and so every worker it forks, keeps to (cpus.py), or None
        self.process = self.control = None
        self._base = None
        self.broken = False

    # ------------------------------------------------------------ lifecycle (the batch's parent)
    def spawn(self) -> None:
        """Start the sandbox; :meth:`wait_ready` then waits for its zygote. A slot that cannot start is
        left broken: its graders use cold sandboxes, as they do wherever there are no namespaces (a zygote
        must be PID 1 of a sandbox of its own: its reset kills every other process it can see)."""
        if launcher.isolation()[0] != "namespaces":
            self.discard()
            return
        try:
            self._spawn()
        except OSError:
            self.discard()

    def _spawn(self):
        self._base = cleanup.private_folder(f"slot{self.index}")
        uid = launcher.sandbox_uid() + PID_LIMIT * (self.index + 1)
        sandbox_dir, scratch_dir = launcher.prepare_dirs(self._base, self.support, uid)
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        slot_limits = replace(
            self.limits,
            memory_bytes=self.limits.memory_bytes + ZYGOTE_MEMORY,
            processes=self.limits.processes + 2,
            cpu_seconds=ZYGOTE_CPU_SECONDS,
        )
        try:
            with cpus.pinned(self.cpu):
                self.process = launcher.spawn(
                    [sys.executable, "-I", "-B", "/sandbox/zygote.py"] + launcher.worker_flags(uid),
                    sandbox_dir,
                    scratch_dir,
                    slot_limits,
                    stdin=theirs.fileno(),
                    stdout=subprocess.DEVNULL,
                    zygote=True,
                )
        finally:
            theirs.close()
        self.control = ours
        self.broken = False

    def wait_ready(self) -> None:
        if not self.usable():
            return
        try:
            self._read(None, time.monotonic() + START_SECONDS, want="ready")
        except SlotBroken:
            self.discard()

    def close(self) -> None:
        """Stop the sandbox and remove its folders (the parent that started it)."""
        if self.process is not None:
            launcher.terminate(self.process)
            self.process = None
        if self.control is not None:
            self.control.close()
            self.control = None
        if self._base is not None:
            cleanup.remove_tree(self._base)
            self._base = None

    def alive(self) -> bool:
        return self.process is not None and not self.broken and self.process.poll() is None

    def usable(self) -> bool:
        return self.process is not None and self.control is not None and not self.broken

    def discard(self) -> None:
        """Kill the whole sandbox, from whichever process uses the slot; the parent starts a new one."""
        self.broken = True
        if self.process is not None:
            launcher.kill_tree(self.process)

    # ------------------------------------------------------------ requests (the grader using the slot)
    def _read(self, nonce, deadline, want="nonce"):
        """The next message that answers ``nonce`` (or the ready message); stale replies are dropped."""
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise SlotBroken("the sandbox's zygote did not answer in time")
            self.control.settimeout(remaining)
            try:
                data, fds, _, _ = socket.recv_fds(self.control, 65536, 2)
            except (socket.timeout, OSError) as error:
                raise SlotBroken(f"the sandbox's zygote is gone ({error})") from None
            if not data:
                raise SlotBroken("the sandbox's zygote is gone")
            try:
                message = json.loads(data)
            except ValueError:
                message = None
            if isinstance(message, dict) and (
                message.get("ready") if want == "ready" else message.get("nonce") == nonce
            ):
                return message, fds
            for fd in fds:  # a reply to a request of a grader that died before reading it
                os.close(fd)

    def _exchange(self, request, seconds=REPLY_SECONDS):
        if not self.usable():
            raise SlotBroken("the slot was discarded")
        nonce = secrets.token_hex(8)
        try:
            self.control.settimeout(seconds)
            self.control.send(json.dumps(dict(request, nonce=nonce)).encode())
        except OSError as error:
            raise SlotBroken(f"the sandbox's zygote is gone ({error})") from None
        return self._read(nonce, time.monotonic() + seconds)

    def fork_worker(self, direct: bool = False) -> WarmWorker:
        """A fresh worker for the student, as a :class:`WarmWorker` (``direct``: see ``worker.start``)."""
        reply, fds = self._exchange({"op": "fork", "cpu_seconds": self.limits.cpu_seconds, "direct": direct})
        if not reply.get("ok") or len(fds) != 2:
            for fd in fds:
                os.close(fd)
            raise SlotBroken("the zygote could not fork a worker")
        return WarmWorker(self, int(reply["pid"]), fds[0], fds[1])

    def status(self, pid: int, wait: float) -> int | None:
        """The raw wait status of worker ``pid`` once it has exited (waiting up to ``wait`` s), else None."""
        reply, _ = self._exchange({"op": "status", "pid": pid, "wait": float(wait)}, float(wait) + REPLY_SECONDS)
        return reply.get("status")

    def kill(self, pid: int) -> None:
        """Kill worker ``pid`` and everything in its namespaces; the slot's other workers go on."""
        reply, _ = self._exchange({"op": "kill", "pid": int(pid)})
        if not reply.get("ok"):
            raise SlotBroken(f"worker {pid} could not be killed")

    def reset(self) -> None:
        """Kill every process in the sandbox but the zygote, and with them the students' namespaces."""
        reply, _ = self._exchange({"op": "reset"})
        if not reply.get("ok"):
            raise SlotBroken(reply.get("error") or f"{reply.get('left', '?')} processes survived the reset")


class SlotPool:
    """The batch's slots: started by the parent before it forks graders, one per concurrent grader."""

    def __init__(self, count, limits, support):
        self.slots = [WarmSlot(index, limits, support, cpus.cpu_of_slot(index, count)) for index in range(count)]

    def __enter__(self):
        for slot in self.slots:
            slot.spawn()
        for slot in self.slots:
            slot.wait_ready()
        return self

    def __exit__(self, *exc):
        for slot in self.slots:
            slot.close()

    def enter(self, index: int) -> WarmSlot:
        """In a forked grader: let go of the other slots' control sockets and return slot ``index``, the
        one this grader grades with (passed down to each :class:`~autograder.sandbox.session.StudentSandbox`)."""
        for slot in self.slots:
            if slot.index != index and slot.control is not None:
                slot.control.close()
                slot.control = None
        return self.slots[index]

    def repair(self, index: int) -> None:
        """In the parent, after a grader ends: replace slot ``index`` if it is dead or was discarded."""
        slot = self.slots[index]
        if slot.alive():
            return
        slot.close()
        slot.spawn()
        slot.wait_ready()
