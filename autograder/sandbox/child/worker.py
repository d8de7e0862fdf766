"""The process that runs one student's code (the *runner*), and how a sandbox starts (copied there).

A sandbox starts here, cold (``python worker.py``, from bubblewrap) or forked
from a warm slot's zygote (:func:`start`): the process enters the student's
own namespaces (``jail.enter_student_jail``: fresh user, mount, PID, IPC, UTS,
network and cgroup namespaces, a fresh ``/tmp``, a new empty session keyring and
nothing else of the grader's process), becomes the *feeder* (``feeder.py``, PID 1
there, out of the student's reach) and forks the runner, which executes the
student's cells and calls their functions, one request at a time.

The runner speaks JSON lines (see :mod:`wire`) with the feeder over a socket;
the student's code gets ``/dev/null`` for stdin and stdout and a capped
in-memory buffer for ``sys.stdout`` and ``sys.stderr``, so printing can
neither break the protocol nor flood the grader.

Requests and replies (all dicts):

- ``{"op": "exec", "lesson": "01", "label": "rot_z", "source": ...}`` runs one
  cell in the lesson's namespace; reply ``{"ok": bool, "error"?, "stdout"}``.
- ``{"op": "call", "lesson": "01", "name": "rot_z", "args": [...],
  "kwargs": {...}, "timeout": 5.0, "forbid"?: [...]}``; reply ``{"ok": True,
  "text", "stdout", "seconds", "changed"?, "delegated"?}`` (``text``: the value
  as wire text, at most :data:`MAX_VALUE_BYTES`; ``changed``/``delegated``:
  see :mod:`coursekit.watching`) or ``{"ok": False, "error": {"type",
  "message", "where"}, "stdout", "seconds"}``.
- ``{"op": "bye"}`` ends the runner.

A callable argument (:class:`wire.Probe`, :class:`wire.Callback`) becomes a
function that asks the feeder to evaluate it (``{"callback": k, "seq",
"args", "kwargs"}``); the runner never holds the code of a probe.

The grader trusts none of this: it decodes replies strictly and compares
values in its own process.
"""

from __future__ import annotations

import builtins
import os
import signal
import socket
import sys
import time
import traceback
from collections.abc import Callable

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import jail
import numpy  # noqa: F401  (imported before student code, as a notebook would)

import wire
from coursekit import watching  # the course's own definition of a call's contracts

STDOUT_KEEP = 4000
MESSAGE_KEEP = 300
MAX_VALUE_BYTES = 1024**2  # far above any answer of the course (a 3×3 matrix is about 100 bytes)


class CallTimeout(BaseException):
    """Raised inside a student function that runs past its time."""


class CappedText:
    """A write-only text stream that keeps the first ``STDOUT_KEEP`` characters."""

    def __init__(self):
        self.reset()

    def reset(self) -> None:
        self.parts, self.kept, self.dropped = [], 0, 0

    def write(self, text: str) -> int:
        text = str(text)
        room = STDOUT_KEEP - self.kept
        if room > 0:
            self.parts.append(text[:room])
            self.kept += min(room, len(text))
        self.dropped += max(0, len(text) - max(room, 0))
        return len(text)

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False

    def text(self) -> str:
        out = "".join(self.parts)
        if self.dropped:
            out += f"\n[… {self.dropped} more characters not kept]"
        return out


def _where(error):
    for frame in reversed(traceback.extract_tb(error.__traceback__)):
        if frame.filename.startswith("<lesson"):
            cell = frame.filename[1:-1]
            return f"line {frame.lineno} of {cell}, in {frame.name}"
    return ""


def _clean(text):
    """Text that encodes as UTF-8 whatever the student printed or raised (lone surrogates become "?")."""
    return str(text).encode("utf-8", "replace").decode("utf-8")


def _describe(error):
    try:
        message = " ".join(str(error).split())
    except Exception:  # an exception whose str() raises
        message = "(its message could not be read)"
    if len(message) > MESSAGE_KEEP:
        message = message[: MESSAGE_KEEP - 1] + "…"
    return {"type": _clean(type(error).__name__)[:80], "message": _clean(message), "where": _clean(_where(error))}


def _unsupported(error):
    return {
        "type": "UnsupportedValue",
        "where": "",
        "message": f"returned {error}; return numbers, numpy arrays, tuples, lists or dicts of those",
    }


def _on_alarm(signum, frame):
    raise CallTimeout()


class CallbackFailed(RuntimeError):
    """A callable argument could not be evaluated with the arguments the student's code gave it."""


class Worker:
    """The runner: executes cells and calls functions, one request at a time (requests and replies are two
    descriptors: one socket to the feeder, or the caller's two pipes in direct mode)."""

    def __init__(self, requests_fd, replies_fd, local_probes=None):
        self.requests = os.fdopen(requests_fd, "rb") if requests_fd is not None else None
        self.replies = os.fdopen(replies_fd, "wb") if replies_fd is not None else None
        # trusted in-process use only (autograder/mutants/inprocess.py): probes resolved here, no feeder
        self.local_probes = local_probes
        self.namespaces = {}
        self.output = CappedText()
        self.request_id = 0
        self.callback_seq = 0

    def namespace(self, lesson: str) -> dict:
        if lesson not in self.namespaces:
            self.namespaces[lesson] = {"__name__": "__main__", "__builtins__": builtins}
        return self.namespaces[lesson]

    def send(self, message: dict) -> None:
        self.replies.write(wire.dumps(message).encode("utf-8") + b"\n")
        self.replies.flush()

    def reply(self, message: dict) -> None:
        message["id"] = self.request_id
        message["stdout"] = _clean(message.get("stdout", ""))
        try:
            line = wire.dumps(message)
        except wire.WireError as error:
            line = wire.dumps(
                {
                    "ok": False,
                    "stdout": message["stdout"],
                    "id": self.request_id,
                    "error": _unsupported(error),
                    "seconds": message.get("seconds", 0.0),
                }
            )
        self.replies.write(line.encode("utf-8") + b"\n")
        self.replies.flush()

    def run_guarded(self, action: Callable[[], object], timeout: float) -> tuple[bool, object, str]:
        """Run ``action()`` with its output captured and an alarm; return (ok, value or error, printed).

        A call made from inside another (the notebook stage's callback that calls a student function)
        keeps within the time left to the outer one, and the outer one's alarm and output go on after.
        """
        outer_output, outer_streams = self.output, (sys.stdout, sys.stderr)
        left, _ = signal.getitimer(signal.ITIMER_REAL)
        started = time.monotonic()
        self.output = CappedText()
        sys.stdout = sys.stderr = self.output
        signal.signal(signal.SIGALRM, _on_alarm)
        limit = max(float(timeout), 0.001)
        outer_expires = bool(left) and left <= limit  # this call's alarm is the outer call's
        signal.setitimer(signal.ITIMER_REAL, left if outer_expires else limit)
        try:
            return True, action(), self.output.text()
        except CallTimeout:
            if outer_expires:
                raise  # the outer call's time is up: it is the one that timed out
            return (
                False,
                {"type": "Timeout", "message": f"still running after {timeout:g} s", "where": ""},
                self.output.text(),
            )
        except BaseException as error:  # SystemExit and KeyboardInterrupt too: report, go on
            return False, _describe(error), self.output.text()
        finally:
            rest = left - (time.monotonic() - started)
            signal.setitimer(signal.ITIMER_REAL, rest if left and rest > 0 else 0)
            if left and rest <= 0 and not outer_expires:
                signal.setitimer(signal.ITIMER_REAL, 0.001)  # the outer call's time ran out meanwhile
            self.output = outer_output
            sys.stdout, sys.stderr = outer_streams

    def do_exec(self, request: dict) -> None:
        namespace = self.namespace(request["lesson"])
        filename = f"<lesson {request['lesson']} cell {request['label']}>"

        def action():
            exec(compile(request["source"], filename, "exec"), namespace)

        ok, result, printed = self.run_guarded(action, request.get("timeout", 10.0))
        message = {"ok": ok, "stdout": printed}
        if not ok:
            message["error"] = result
        self.reply(message)

    def invoke(self, call: dict, timeout: float) -> tuple[bool, object, list]:
        """Call ``call``'s function with its arguments, guarded and watched (:mod:`coursekit.watching`).

        Returns ``(ok, value or error dict, notes)``: ``notes`` holds ``"changed"`` (the arguments the
        call changed in place) and ``"delegated"`` (functions of the call's ``forbid`` list that the
        student's code called), each only when not empty.
        """
        function = self.namespace(call["lesson"]).get(call["name"])
        if not callable(function):
            return (
                False,
                {"type": "NameError", "where": "", "message": f"{call['name']} is not defined in the graded cells"},
                {"stdout": ""},
            )
        handles = iter(range(1 << 20))
        args = [self.materialize(a, handles) for a in call.get("args", [])]
        kwargs = {k: self.materialize(v, handles) for k, v in call.get("kwargs", {}).items()}
        forbidden = [str(name) for name in call.get("forbid") or ()]
        ok, result, printed = self.run_guarded(lambda: watching.watch_call(function, args, kwargs, forbidden), timeout)
        if not ok:
            return False, result, {"stdout": printed}
        value, seen = result
        notes = {"stdout": printed}
        if seen.changed:
            notes["changed"] = seen.changed
        if seen.used or seen.tampered:
            notes["delegated"] = seen.used + (["sys.setprofile"] if seen.tampered else [])
            if any(str(name).startswith("allowance:") for name in forbidden):  # the one line (coursekit.contracts)
                from coursekit.contracts import refusal

                notes["refusal"] = refusal(call["name"], notes["delegated"], call["lesson"])
        return True, value, notes

    def do_call(self, request: dict) -> None:
        self.reply(self.call_reply(request))

    def call_reply(self, request: dict, timeout: float | None = None) -> dict:
        """One call's reply; its value travels as wire text (checked to be plain data, and bounded)."""
        started = time.monotonic()
        ok, result, notes = self.invoke(request, timeout or request.get("timeout") or 5.0)
        message = {"ok": ok, **notes}
        if ok:
            try:
                message["text"] = wire.dumps(result)
                if len(message["text"]) > MAX_VALUE_BYTES:
                    raise wire.WireError(
                        f"a value of {len(message.pop('text')) / 1024**2:.1f} MB "
                        f"(limit {MAX_VALUE_BYTES / 1024**2:g} MB)"
                    )
            except (wire.WireError, RecursionError) as error:
                message.pop("text", None)
                message["ok"] = False
                message["error"] = _unsupported(error)
        else:
            message["error"] = result
        message["seconds"] = time.monotonic() - started
        message["stdout"] = _clean(message.get("stdout", ""))
        return message

    def materialize(self, value: object, handles: list) -> object:
        """A call's argument with each callable argument made a function that asks the feeder (in the
        order of ``feeder.callables_in``)."""
        if isinstance(value, wire.Probe) and self.local_probes is not None:
            return self.local_probes.resolve(value.name, value.args)
        if isinstance(value, (wire.Probe, wire.Callback)):
            return self._handle(next(handles), value)
        if isinstance(value, list):
            return [self.materialize(v, handles) for v in value]
        if isinstance(value, tuple):
            return tuple(self.materialize(v, handles) for v in value)
        if isinstance(value, dict):
            return {k: self.materialize(v, handles) for k, v in value.items()}
        return value

    def _handle(self, number, target):
        worker = self

        def callback(*args, **kwargs):
            worker.callback_seq += 1
            seq = worker.callback_seq
            try:
                worker.send({"callback": number, "seq": seq, "args": list(args), "kwargs": dict(kwargs)})
            except wire.WireError as error:
                raise TypeError(f"{target!r} takes numbers and arrays, not {error}") from None
            while True:
                line = worker.requests.readline(wire.MAX_LINE_BYTES)
                if not line:
                    os._exit(0)
                answer = wire.loads(line.decode("utf-8"))
                if isinstance(answer, dict) and answer.get("op") == "callback_result" and answer.get("seq") == seq:
                    break
                if isinstance(answer, dict) and answer.get("op") == "call":
                    worker.nested_call(answer)  # the callable called a student function in turn
            if not answer.get("ok"):
                raise CallbackFailed(str(answer.get("error", "the callable argument failed")))
            return wire.loads(answer["text"])

        callback.__name__ = getattr(target, "name", None) or getattr(target, "label", "") or "callback"
        return callback

    def nested_call(self, request: dict) -> None:
        """Answer a call that arrives while a callback of another call is being evaluated."""
        outer = self.request_id
        self.request_id = request.get("id", 0)
        try:
            self.do_call(request)
        finally:
            self.request_id = outer

    def serve(self) -> None:
        self.reply({"ready": True})
        while True:
            line = self.requests.readline(wire.MAX_LINE_BYTES)
            if not line:
                return
            request = wire.loads(line.decode("utf-8"))
            if not isinstance(request, dict) or request.get("op") == "callback_result":
                continue  # a callback's answer that came after its call had timed out
            self.request_id = request.get("id", 0)
            op = request.get("op")
            if op == "exec":
                self.do_exec(request)
            elif op == "call":
                self.do_call(request)
            elif op == "bye":
                return
            else:
                self.reply(
                    {
                        "ok": False,
                        "stdout": "",
                        "error": {"type": "ProtocolError", "message": f"unknown op {op!r}", "where": ""},
                    }
                )


# ---------------------------------------------------------------- how a sandbox starts
PR_SET_DUMPABLE = 4


def _become_runner(requests_fd, replies_fd):
    """In the feeder's child: keep only its two descriptors, then serve the student's requests."""
    jail.close_all_but({requests_fd, replies_fd})
    import ctypes

    ctypes.CDLL(None).prctl(PR_SET_DUMPABLE, 1, 0, 0, 0)  # its own /proc/self readable, as in a notebook
    sys.stdin = open(os.devnull)
    try:
        Worker(requests_fd, replies_fd).serve()
    finally:
        os._exit(0)


def start(
    requests_fd: int, replies_fd: int, uid: int, keep_user: bool = False, in_jail: bool = True, direct: bool = False
) -> None:
    """Become this student's sandbox: the jail (unless ``in_jail`` is False: limits mode), the feeder,
    the runner. ``requests_fd``/``replies_fd`` talk to the grader. Never returns.

    ``direct``: the runner talks to the caller over those two pipes itself, and the feeder only waits
    and says how it ended. For the notebook stage's kernel, which sends one call at a time and no
    probe: nothing ahead to hold back, and one process hop less on each of its many calls.
    """
    import ctypes

    import feeder

    try:
        probes_fd = None if direct else os.open(os.path.join(HERE, "probes.py"), os.O_RDONLY | os.O_CLOEXEC)
    except OSError:
        probes_fd = None
    keep = {requests_fd, replies_fd} | ({probes_fd} if probes_fd is not None else set())
    try:
        if in_jail:
            jail.enter_student_jail(uid, keep_user, HERE, keep_fds=keep)
        else:  # limits mode: no namespaces, but not the grader's keyring, signals or personality either
            if not keep_user:
                jail.drop_privileges(uid)
            jail.start_afresh()
    except (jail.JailError, OSError) as error:
        os.write(
            replies_fd,
            wire.dumps({"ready": False, "error": f"the student's namespaces: {error}", "id": 0}).encode() + b"\n",
        )
        os._exit(0)
    ctypes.CDLL(None).prctl(PR_SET_DUMPABLE, 0, 0, 0, 0)
    for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT, signal.SIGUSR1, signal.SIGUSR2):
        signal.signal(number, signal.SIG_DFL)  # PID 1 with no handler: no signal from the student reaches it
    if direct:
        pid = os.fork()
        if pid == 0:
            _become_runner(requests_fd, replies_fd)
        os.close(requests_fd)
        feeder.wait_and_report(pid, replies_fd)
    ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    pid = os.fork()
    if pid == 0:
        ours.close()
        _become_runner(theirs.fileno(), os.dup(theirs.fileno()))
    theirs.close()
    try:
        feeder.Feeder(requests_fd, replies_fd, ours.fileno(), pid, probes_fd).serve()
    finally:
        os._exit(0)


def main() -> None:
    requests, replies = os.dup(0), os.dup(1)
    devnull = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(devnull, fd)
    os.close(devnull)
    start(
        requests,
        replies,
        jail.sandbox_uid(sys.argv),
        keep_user="--keep-user" in sys.argv,
        in_jail="--no-jail" not in sys.argv,
        direct="--direct" in sys.argv,
    )


if __name__ == "__main__":
    main()
