"""The grader's side of a student's sandbox: load their cells, call their functions.

A :class:`StudentSandbox` starts the worker lazily, runs each lesson's setup
cell and the student's answer cells, and then serves calls. If the student's
code kills the process (``os._exit``, a segfault, the memory limit) or a call
hangs, the sandbox is restarted without the cell that crashed it and the call
fails with a :class:`StudentError` that says what happened; the other
exercises are unaffected.

Examples
--------
>>> program = {"01": LessonProgram(setup="import numpy as np",
...                                cells=[("rot_z", "def rot_z(a):\\n    return np.eye(3)")])}
>>> with StudentSandbox(program, course.support) as box:       # doctest: +SKIP
...     box.call("01", "rot_z", [0.3])
array([[1., 0., 0.], ...
"""

from __future__ import annotations

import os
import selectors
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from autograder.sandbox import cleanup, launcher, warm
from autograder.sandbox.child import wire

_SIGNAL_REASONS = {
    signal.SIGKILL: "was killed (memory or time limit, or a kill signal)",
    signal.SIGXCPU: "used up its CPU time limit",
    signal.SIGSEGV: "crashed with a segmentation fault (runaway recursion?)",
    signal.SIGXFSZ: "wrote a file larger than the limit",
    signal.SIGABRT: "aborted",
}


class StudentError(Exception):
    """A student's function could not produce a value.

    Attributes
    ----------
    kind : str
        ``"exception"``, ``"not_implemented"``, ``"timeout"``, ``"crash"``,
        ``"missing"``, ``"bad_value"`` or ``"delegated"`` (it handed its work to a library function
        that the exercise asks the student to write).
    message : str
        One line for the feedback page.
    stdout : str
        What the student's code printed (capped).
    """

    def __init__(self, kind, message, stdout=""):
        super().__init__(message)
        self.kind = kind
        self.message = message
        self.stdout = stdout


@dataclass
class LessonProgram:
    """What to run for one lesson: the master's setup cell, then the student's cells."""

    setup: str
    cells: list  # [(label, source)]
    problems: list = field(default_factory=list)  # notes from extraction, e.g. "grade_id missing"


@dataclass
class CellOutcome:
    lesson: str
    label: str
    ok: bool
    message: str = ""
    stdout: str = ""


MAX_REPLY_BYTES = 12 * 1024**2  # a batch's replies (the feeder stops a batch at 8 MiB) and one more


class _Dead(Exception):
    """The worker process is gone or stopped answering."""


class SandboxUnavailable(RuntimeError):
    """The sandbox's worker did not start: a failure of the grader or this machine, never the student's
    (no student code has run yet). It stops this student's grading instead of costing points."""


class StudentSandbox:
    """One student's sandbox; use as a context manager."""

    def __init__(self, program, support, limits=None, base_dir=None, slot=None, resets_slot=True, direct=False):
        self.program = program
        self.support = Path(support)  # the course's coursekit folder, copied into the sandbox
        self.limits = limits or launcher.Limits()
        # a warm slot (see warm.py) when the caller has a usable one with the same limits and course, else
        # cold starts
        self.slot = (
            slot
            if (slot is not None and slot.usable() and slot.limits == self.limits and slot.support == self.support)
            else None
        )
        # the first sandbox of a student resets the slot before and after; more sandboxes of the same
        # student (the notebook stage's, one per lesson) share it without resetting
        self._slot_reset = not resets_slot
        self._resets_slot = resets_slot
        self.direct = direct  # for hand_over: the worker talks to its caller itself (worker.start)
        self._tmp = None
        self._base_dir = base_dir
        self.process = None
        self.loaded = False
        self.bad_cells = {}  # (lesson, label) -> why the cell is skipped
        self.outcomes = []  # CellOutcome of each cell, from the first time it ran
        self.restarts = 0
        self.time_used = 0.0
        self.last_stdout = ""
        self.last_changed = []  # arguments the last call changed in place (names)
        self.hung = {}  # (lesson, name) -> seconds it ran before being stopped
        self._next_id = 0
        self._buffer = b""

    # ------------------------------------------------------------ lifecycle
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _dirs(self):
        if self._tmp is None:
            if self._base_dir is None:
                self._tmp = base = cleanup.private_folder("sandbox")
            else:
                base = self._base_dir
            self.sandbox_dir, self.scratch_dir = launcher.prepare_dirs(base, self.support)
        return self.sandbox_dir, self.scratch_dir

    def _fork_warm(self):
        """A worker forked by the slot's zygote (the slot reset first, for this student), or None."""
        try:
            if not self._slot_reset:
                self.slot.reset()  # whatever the previous student left in the slot goes
                self._slot_reset = True
            return self.slot.fork_worker(self.direct)
        except warm.SlotBroken:
            self.slot.discard()
            self.slot = None  # this student goes on with cold sandboxes
            return None

    def _start(self):
        self._buffer = b""
        self.process = self._fork_warm() if self.slot is not None else None
        if self.process is None:
            sandbox_dir, scratch_dir = self._dirs()
            # the venv's own interpreter path (not its realpath), so Python finds the venv's packages
            self.process = launcher.spawn(
                [sys.executable, "-I", "-B", "/sandbox/worker.py"]
                + launcher.worker_flags(jail=True)
                + (["--direct"] if self.direct else []),
                sandbox_dir,
                scratch_dir,
                self.limits,
            )
        self._selector = selectors.DefaultSelector()
        self._selector.register(self.process.stdout, selectors.EVENT_READ)
        try:
            hello = self._receive(deadline=time.monotonic() + 60.0)
        except _Dead:
            hello = None
        self._next_id = 0
        if not (isinstance(hello, dict) and hello.get("ready")):
            if isinstance(self.process, warm.WarmWorker):  # the slot's fault, before any student code
                self.slot.discard()
                self._kill()
                self.slot = None
                return self._start()  # cold
            why = hello.get("error") if isinstance(hello, dict) else None
            raise _Dead(f"the sandbox did not start ({why})" if why else "the sandbox did not start")

    def _kill(self):
        if self.process is None:
            return
        if isinstance(self.process, warm.WarmWorker):
            self.process.stop()
            if self.process.slot.broken:
                self.slot = None
        else:
            launcher.terminate(self.process)
        self._selector.close()
        self.process = None
        self.loaded = False

    def close(self) -> None:
        if self.process is not None:
            try:
                self._send({"op": "bye"})
            except _Dead:
                pass
        self._kill()
        if self.slot is not None and self._slot_reset and self._resets_slot:
            try:
                self.slot.reset()  # leave nothing running in the slot
            except warm.SlotBroken:
                self.slot.discard()
        if self._tmp is not None:
            cleanup.remove_tree(self._tmp)  # in limits mode, whatever the student left there (any depth)
            self._tmp = None

    def hand_over(self) -> tuple[int, int]:
        """Load the student's cells and hand over the worker's two pipe ends: ``(request fd, reply fd)``.

        The notebook stage's kernel calls the student's functions through them (``child/student_client.py``).
        This sandbox makes no call afterwards; close it once the kernel is done.

        Raises
        ------
        SandboxUnavailable, StudentError
            As for the first call.
        """
        self._ensure_loaded()
        return self.process.stdin.fileno(), self.process.stdout.fileno()

    def _death_reason(self):
        code = self.process.poll() if self.process else None
        if code is None:
            return "stopped answering"
        return _code_reason(code)

    # ------------------------------------------------------------ messages
    def _send(self, message):
        self._send_line(wire.dumps(message))

    def _send_line(self, line):
        try:
            self.process.stdin.write(line.encode("utf-8") + b"\n")
            self.process.stdin.flush()
        except (BrokenPipeError, OSError, ValueError, AttributeError):
            raise _Dead(self._death_reason() if self.process else "not running") from None

    def _receive(self, deadline):
        while b"\n" not in self._buffer:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise _Dead("timeout")
            if not self._selector.select(timeout=remaining):
                continue
            chunk = os.read(self.process.stdout.fileno(), 1 << 20)
            if not chunk:
                try:
                    self.process.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    pass  # it closed its replies but lives on: "stopped answering"
                raise _Dead(self._death_reason())
            self._buffer += chunk
            if len(self._buffer) > MAX_REPLY_BYTES:
                raise _Dead("sent a reply larger than the limit")
        line, self._buffer = self._buffer.split(b"\n", 1)
        try:
            message = wire.loads(line.decode("utf-8"), max_bytes=MAX_REPLY_BYTES)
        except (wire.WireError, UnicodeDecodeError) as error:
            raise _Dead(f"sent a malformed reply ({error})") from None
        if isinstance(message, dict) and "died" in message:  # the feeder saw the student's process end
            raise _Dead(_names([message.get("why")])[0] if message.get("why") else _status_reason(message["died"]))
        return message

    def _request(self, message, timeout):
        """Send one request and wait for the reply that carries its id.

        Replies must echo the request's id: a line the student's code forged
        into the reply channel cannot stand in for the worker's answer.
        """
        started = time.monotonic()
        self._next_id += 1
        message = dict(message, id=self._next_id)
        try:
            self._send(message)
            reply = self._receive(deadline=started + timeout + 2.0)
        finally:
            self.time_used += time.monotonic() - started
        if not isinstance(reply, dict) or "ok" not in reply or reply.get("id") != self._next_id:
            raise _Dead("sent a reply that does not match the request (forged output?)")
        return reply

    # ------------------------------------------------------------ loading
    def _ensure_loaded(self):
        if self.loaded:
            return
        recorded = {(o.lesson, o.label) for o in self.outcomes}
        while True:
            try:
                self._start()
            except _Dead as death:
                self._kill()
                raise SandboxUnavailable(f"the sandbox did not start ({death})") from None
            try:
                for lesson, program in sorted(self.program.items()):
                    for label, source in [("setup", program.setup)] + list(program.cells):
                        if (lesson, label) in self.bad_cells:
                            continue
                        self._current = (lesson, label)
                        reply = self._request(
                            {
                                "op": "exec",
                                "lesson": lesson,
                                "label": label,
                                "source": source,
                                "timeout": self.limits.load_timeout,
                            },
                            self.limits.load_timeout,
                        )
                        if (lesson, label) not in recorded:
                            recorded.add((lesson, label))
                            error = reply.get("error") or {}
                            self.outcomes.append(
                                CellOutcome(
                                    lesson,
                                    label,
                                    bool(reply["ok"]),
                                    _format_error(error) if not reply["ok"] else "",
                                    str(reply.get("stdout", "")),
                                )
                            )
                self.loaded = True
                return
            except _Dead as death:
                reason = str(death)
                if reason == "timeout":
                    reason = f"did not finish within {self.limits.load_timeout:g} s"
                lesson, label = self._current
                self.bad_cells[(lesson, label)] = f"running this cell {reason}"
                if (lesson, label) not in recorded:
                    recorded.add((lesson, label))
                    self.outcomes.append(CellOutcome(lesson, label, False, f"running this cell {reason}"))
                self._kill()
                self.restarts += 1
                if self.restarts > 8:
                    raise StudentError("crash", "the student's code crashed the sandbox too many times") from None

    # ------------------------------------------------------------ calls
    def check_callable(self, lesson: str, name: str) -> None:
        """Raise the :class:`StudentError` a call of ``name`` would get without running (budget, hang)."""
        if self.time_used > self.limits.student_seconds:
            raise StudentError(
                "timeout",
                f"not run: this student's code already used its {self.limits.student_seconds:g} s time budget",
            )
        if (lesson, name) in self.hung:
            raise StudentError(
                "timeout",
                f"{name} did not return within {self.hung[(lesson, name)]:g} s "
                "in an earlier check, so it was not called again",
            )

    def call(
        self,
        lesson: str,
        name: str,
        args: tuple = (),
        kwargs: dict | None = None,
        timeout: float | None = None,
        forbid: tuple = (),
    ) -> object:
        """Call the student's ``name`` from ``lesson``; return the decoded value.

        ``forbid``: library functions the call must not use (see :mod:`coursekit.watching`).

        Raises
        ------
        StudentError
            The function raised, timed out, crashed the process, is missing,
            or returned something that is not plain data.
        """
        timeout = self.limits.call_timeout if timeout is None else timeout
        self.last_stdout, self.last_changed = "", []
        self.check_callable(lesson, name)
        self._ensure_loaded()
        request = call_request(lesson, name, args, kwargs, timeout, forbid)
        try:
            reply = self._request(request, timeout)
        except _Dead as death:
            reason = str(death)
            self._kill()
            self.restarts += 1
            if reason == "timeout":
                self.hung[(lesson, name)] = timeout
                raise StudentError(
                    "timeout", f"{name} did not return within {timeout:g} s (an endless loop, or far too slow?)"
                ) from None
            raise StudentError("crash", f"calling {name}, the student's process {reason}") from None
        return self.take_reply(lesson, name, reply, timeout)

    def take_reply(self, lesson: str, name: str, reply: dict, timeout: float) -> object:
        """The value of a call's reply, or the :class:`StudentError` it stands for (as :meth:`call`).

        A call that changed its arguments in place still returns its value; their names are kept in
        :attr:`last_changed` for the hidden suite's contract check.
        """
        stdout = str(reply.get("stdout", ""))
        self.last_stdout = stdout if reply["ok"] else ""
        self.last_changed = _names(reply.get("changed"))
        delegated = _names(reply.get("delegated"))
        if reply["ok"] and delegated:
            raise StudentError(
                "delegated",
                str(reply.get("refusal") or "")[:400]
                or f"{name} calls {', '.join(delegated)}: this exercise asks for "
                "your own implementation, so it earns no points",
                stdout,
            )
        if reply["ok"]:
            if "text" in reply:  # a call's value travels as wire text
                try:
                    return wire.loads(reply["text"], max_bytes=MAX_REPLY_BYTES)
                except wire.WireError as error:
                    raise StudentError(
                        "crash", f"calling {name}, the student's process sent a malformed reply ({error})"
                    ) from None
            return reply.get("value")
        error = reply.get("error") or {}
        kind = {
            "NotImplementedError": "not_implemented",
            "Timeout": "timeout",
            "NameError": "missing" if "not defined in the graded cells" in str(error.get("message")) else "exception",
            "UnsupportedValue": "bad_value",
        }.get(error.get("type"), "exception")
        if kind == "not_implemented":
            raise StudentError(kind, f"{name} is not written yet (it raises NotImplementedError)", stdout)
        if kind == "timeout":
            self.hung[(lesson, name)] = timeout
            raise StudentError(
                kind, f"{name} did not return within {timeout:g} s (an endless loop, or far too slow?)", stdout
            )
        if kind == "missing":
            raise StudentError(kind, f"{name} is not defined by the graded cells of the notebook", stdout)
        if kind == "bad_value":
            raise StudentError(kind, f"{name} {error.get('message', '')}", stdout)
        raise StudentError(kind, f"{name} raised {_format_error(error)}", stdout)

    def call_batch(
        self,
        calls: list[str],
        timeouts: list[float | None],
        budget: float = 2.0,
        expect: list[str] | None = None,
        callbacks: list[list] | None = None,
    ) -> list[dict] | None:
        """Make several calls in one round trip; return their raw replies, in order, or None.

        ``calls`` are the calls as wire text (``{"lesson", "name", "args",
        "kwargs", "timeout"}`` each), ``timeouts`` their time limits (None:
        the limits' ``call_timeout``, also when the call's own is null). The
        worker stops after the first call that fails or once the calls have
        run ``budget`` seconds, so there may be fewer replies than calls; hand
        each to :meth:`take_reply`. None means the batch could not be made (the
        process died or hung): nothing is counted against the student, and
        the caller makes its calls one at a time, which says what happened.
        ``expect``: the wire text of each call's expected value; the batch also stops after the first call
        whose value is another (the inputs of the calls after it may have been computed from that value).
        ``callbacks``: per call, the callbacks it may make and their answers (``[handle, args as wire text, kwargs
        as wire text, answer]`` each, in order, as :mod:`~autograder.grading.notebook_calls` notes them); the
        feeder answers them, and a call that calls back in any other way fails.
        """
        try:
            self._ensure_loaded()
        except StudentError:
            return None
        default = float(self.limits.call_timeout)
        timeouts = [default if t is None else t for t in timeouts]
        self._next_id += 1
        # the request as wire.dumps would write it, with the calls' text, already wire text, put in as is
        line = '{"__dict__":[["op","batch"],["id",%d],["budget",%r],["timeout",%r],["calls",[%s]]]}' % (
            self._next_id,
            float(budget),
            default,
            ",".join(calls),
        )
        if expect is not None:
            line = line[:-2] + ',["expect",%s]]}' % wire.dumps(list(expect))
        if callbacks is not None:
            line = line[:-2] + ',["callbacks",%s]]}' % wire.dumps(list(callbacks))
        started = time.monotonic()
        try:
            self._send_line(line)
            # a working worker stops within the budget plus one call's limit; a call that outlives its
            # own alarm (student code that swallows it) is found here, and then again one at a time
            reply = self._receive(deadline=started + float(budget) + max(timeouts) + 2.0)
        except _Dead:
            self._kill()
            return None
        self.time_used += time.monotonic() - started
        replies = reply.get("replies") if isinstance(reply, dict) and reply.get("id") == self._next_id else None
        if (
            not isinstance(replies, list)
            or len(replies) > len(calls)
            or not all(
                isinstance(r, dict)
                and isinstance(r.get("ok"), bool)
                and (not r["ok"] or isinstance(r.get("text"), str))
                for r in replies
            )
        ):
            self._kill()  # a forged or malformed reply: start afresh, one call at a time
            return None
        return replies


def _code_reason(code):
    """How a process ended, from a return code as :class:`subprocess.Popen` gives it (-N: signal N)."""
    if code < 0:
        return _SIGNAL_REASONS.get(-code, f"was killed by signal {-code}")
    return f"exited with status {code} (sys.exit or os._exit in the student's code?)"


def _status_reason(status):
    """How the student's process ended, from the raw wait status its feeder reported."""
    if type(status) is not int:
        return "ended"
    if os.WIFSIGNALED(status):
        return _code_reason(-os.WTERMSIG(status))
    return _code_reason(os.WEXITSTATUS(status))


def call_request(
    lesson: str, name: str, args: tuple | list, kwargs: dict | None, timeout: float | None, forbid: tuple = ()
) -> dict:
    """The worker's request for one call (see ``child/worker.py``); ``forbid`` only when not empty."""
    request = {
        "op": "call",
        "lesson": lesson,
        "name": name,
        "args": list(args),
        "kwargs": dict(kwargs or {}),
        "timeout": timeout,
    }
    if forbid:
        request["forbid"] = list(forbid)
    return request


def _names(value, keep=8):
    """A reply's list of names (changed arguments, delegated functions) as short strings; [] if absent."""
    if not isinstance(value, list):
        return []
    return [" ".join(str(item).split())[:80] for item in value[:keep]]


def _format_error(error):
    text = f"{error.get('type', 'Error')}: {error.get('message', '')}".rstrip(": ")
    if error.get("where"):
        text += f" ({error['where']})"
    return text
