"""The student's functions, as the notebook stage's kernel calls them (copied into its sandbox).

In the notebook stage the reference notebook runs top to bottom in a kernel
that holds **no student code**: each answer cell is replaced by one that binds
the exercise's name to :func:`student_function`, and every call goes to the
student's own sandbox (its feeder and runner, ``feeder.py``, ``worker.py``)
over two pipes the grader handed to this sandbox, and comes back as plain
data. So nothing the student wrote can rewrite a later cell, replay recorded
outputs or read the notebook: the kernel is ours, and nbval's verdict is.

A callable argument (a demonstration's function, ``np.matmul``) stays here as
a :class:`wire.Callback`; when the student's code calls it, the feeder asks
for it and this module answers.

The pipes of each lesson are named in the environment variable
``AUTOGRADER_CHANNELS``: ``{"03": [pid, request fd, reply fd]}``, descriptors of
the process ``pid`` (the notebook stage's runner), reopened here through
``/proc``, so they reach a kernel however it was started.

Examples
--------
>>> rot_z = student_function("01", "rot_z")           # doctest: +SKIP
>>> rot_z(0.5)                                        # computed in the student's sandbox
array([[ 0.87758256, -0.47942554,  0.        ], ...
"""

from __future__ import annotations

import builtins
import json
import os
import select
import sys
import time
from collections.abc import Callable

import wire
from feeder import LineChannel, RunnerGone

CALL_TIMEOUT = 5.0
MARGIN = 10.0  # beyond the call's own time limit, in case the student's code swallowed its alarm
MAX_REPLY_BYTES = 12 * 1024**2


class StudentCodeError(Exception):
    """The student's function raised an exception that has no builtin name here (its type and message)."""


class StudentSandboxGone(RuntimeError):
    """The student's process ended (or stopped answering): no function of this lesson can be called."""


class _Channel:
    def __init__(self, pid, request_fd, reply_fd):
        self.out = os.open(f"/proc/{pid}/fd/{request_fd}", os.O_WRONLY | os.O_CLOEXEC)
        self.fd = os.open(f"/proc/{pid}/fd/{reply_fd}", os.O_RDONLY | os.O_CLOEXEC)
        self.lines = LineChannel(self.fd, MAX_REPLY_BYTES)
        self.next_id = 1_000_000  # far from the grader's ids, for the record
        self.gone = ""

    def write(self, data):
        view = memoryview(data)
        while view:
            view = view[os.write(self.out, view) :]

    def send(self, message):
        self.write(wire.dumps(message).encode() + b"\n")

    def receive(self, deadline):
        while b"\n" not in self.lines.buffer:
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not select.select([self.fd], [], [], remaining)[0]:
                raise StudentSandboxGone("stopped answering")
            chunk = os.read(self.fd, 1 << 20)
            if not chunk:
                raise StudentSandboxGone("ended")
            self.lines.buffer += chunk
        line = self.lines.read_line()
        return wire.loads(line.decode("utf-8"), max_bytes=MAX_REPLY_BYTES)


_CHANNELS = {}


def _channel(lesson):
    if lesson not in _CHANNELS:
        pid, request_fd, reply_fd = json.loads(os.environ.get("AUTOGRADER_CHANNELS", "{}"))[lesson]
        _CHANNELS[lesson] = _Channel(pid, request_fd, reply_fd)
    return _CHANNELS[lesson]


def _as_wire(value, callables):
    """``value`` with every callable in it replaced by a :class:`wire.Callback`, noted in ``callables``
    (in the order ``feeder.callables_in`` numbers them)."""
    if isinstance(value, (list, tuple)):
        converted = [_as_wire(v, callables) for v in value]
        return converted if isinstance(value, list) else tuple(converted)
    if isinstance(value, dict):
        return {k: _as_wire(v, callables) for k, v in value.items()}
    if callable(value) and not isinstance(value, type):
        callables.append(value)
        return wire.Callback(getattr(value, "__name__", "function"))
    return value


def _raise(name, error):
    kind, message = str(error.get("type", "Error")), str(error.get("message", ""))
    where = f" ({error['where']})" if error.get("where") else ""
    builtin = getattr(builtins, kind, None)
    if isinstance(builtin, type) and issubclass(builtin, Exception):
        raise builtin(f"{message}{where}")
    if kind == "Timeout":
        raise TimeoutError(f"{name} {message}")
    raise StudentCodeError(f"{kind}: {message}{where}")


def call(lesson: str, name: str, args: tuple = (), kwargs: dict | None = None, timeout: float = CALL_TIMEOUT) -> object:
    """Call the student's ``name`` of ``lesson`` in their sandbox; return its value, or raise what it raised."""
    channel = _channel(lesson)
    if channel.gone:
        raise StudentSandboxGone(f"the student's code {channel.gone} earlier in this notebook")
    callables = []
    request = {
        "op": "call",
        "lesson": lesson,
        "name": name,
        "timeout": timeout,
        "args": _as_wire(list(args), callables),
        "kwargs": _as_wire(dict(kwargs or {}), callables),
    }
    channel.next_id += 1
    request["id"] = channel.next_id
    try:
        line = wire.dumps(request).encode() + b"\n"
    except wire.WireError as error:
        raise TypeError(
            f"{name} can only be given numbers, arrays, lists, tuples, dicts and functions here, not {error}"
        ) from None
    deadline = time.monotonic() + timeout + MARGIN
    recording = bool(os.environ.get("AUTOGRADER_RECORD_CALLS"))
    noted = _Exchanges()
    parent = _OPEN[-1] if _OPEN else None  # this call is made by a callable that an outer call called back
    _OPEN.append(noted)
    try:
        channel.write(line)
        while True:
            message = channel.receive(deadline)
            if not isinstance(message, dict):
                raise StudentSandboxGone("sent something that is not a message")
            if "died" in message:
                raise StudentSandboxGone(str(message.get("why") or "ended"))
            if "callback" in message:
                answer = _answer_callback(callables, message)
                if recording:
                    noted.add(message, answer)
                channel.send(answer)
                continue
            if message.get("id") != request["id"]:
                raise StudentSandboxGone("answered another request")
            break
    except (StudentSandboxGone, RunnerGone, OSError, wire.WireError) as error:
        channel.gone = str(error) or type(error).__name__
        raise StudentSandboxGone(f"calling {name}, the student's code {channel.gone}") from None
    finally:
        _OPEN.pop()
    if parent is not None:
        parent.made(request, callables, message, noted)
    elif recording:
        _record(request, callables, message, noted)
    if message.get("stdout"):
        sys.stdout.write(str(message["stdout"]))
    if not message.get("ok"):
        _raise(name, message.get("error") or {})
    return wire.loads(message["text"], max_bytes=MAX_REPLY_BYTES)


class _Exchanges:
    """The callbacks one call made, in order, as the notebook stage's replay feeds them back: ``[handle, args as
    wire text, kwargs as wire text, the answer sent, the calls to student functions the callable made]`` each,
    the last as ``[call as wire text, value as wire text]`` pairs (a demonstration's map that calls
    ``boxplus_right``). ``nested`` when they cannot be replayed: such a call failed, passed a callable itself,
    or an argument could not be written down."""

    def __init__(self):
        self.items, self.nested, self.inner = [], False, []

    def made(self, request, callables, message, exchanges):
        """Note a call to a student function that the callable being answered made (only while recording)."""
        if not os.environ.get("AUTOGRADER_RECORD_CALLS"):
            return
        if callables or exchanges.items or not message.get("ok") or not isinstance(message.get("text"), str):
            self.nested = True
            return
        self.inner.append([_call_text(request), message["text"]])

    def add(self, message, answer):
        inner, self.inner = self.inner, []
        try:
            args, kwargs = wire.dumps(message.get("args", [])), wire.dumps(message.get("kwargs", {}))
        except wire.WireError:
            self.nested = True
            return
        kept = {key: answer[key] for key in ("ok", "text", "error") if key in answer}
        self.items.append([message.get("callback"), args, kwargs, kept, inner])

    def noted(self):
        return None if self.nested else self.items


def _call_text(request):
    return wire.dumps({key: request[key] for key in ("lesson", "name", "args", "kwargs", "timeout")})


_OPEN = []  # the exchanges of the calls in progress, outermost first (a callable may call a student function)
_RECORDED_BYTES = {}  # lesson -> bytes noted so far (-1 once over the budget)


def _record(request, callables, message, exchanges):
    """Note one call and its reply for the grader (only when the kernel runs the *reference*'s functions,
    once per lesson: ``nbval_stage.record_notebook_calls``) with the callbacks it made (``exchanges``), one JSON
    line per call in the lesson's own file,
    ``$AUTOGRADER_RECORD_CALLS-<lesson>.jsonl``. Past ``$AUTOGRADER_RECORD_BYTES`` one line saying so
    ends the lesson's notes (it will not be replayed); a failed write never reaches the notebook."""
    lesson = str(request["lesson"])
    written = _RECORDED_BYTES.get(lesson, 0)
    if written < 0 or not lesson.isalnum():
        return
    call_text = _call_text(request)
    entry = {
        "lesson": lesson,
        "call": call_text,
        "ok": bool(message.get("ok")),
        "text": message.get("text") if isinstance(message.get("text"), str) else None,
        "callbacks": len(callables),
        "exchanges": exchanges.noted(),
    }
    line = json.dumps(entry) + "\n"
    if written + len(line) > int(os.environ.get("AUTOGRADER_RECORD_BYTES", "0")):
        line, _RECORDED_BYTES[lesson] = json.dumps({"lesson": lesson, "overflow": True}) + "\n", -1
    else:
        _RECORDED_BYTES[lesson] = written + len(line)
    try:
        with open(f"{os.environ['AUTOGRADER_RECORD_CALLS']}-{lesson}.jsonl", "a", encoding="utf-8") as out:
            out.write(line)
    except OSError:
        _RECORDED_BYTES[lesson] = -1


def _answer_callback(callables, message):
    """The answer to a callback (echoing its ``seq``: a direct runner matches answers by it)."""
    handle, answer = message.get("callback"), {"op": "callback_result", "seq": message.get("seq")}
    if type(handle) is not int or not 0 <= handle < len(callables):
        return dict(answer, ok=False, error="no such callable argument")
    try:
        value = callables[handle](*message.get("args", []), **message.get("kwargs", {}))
        return dict(answer, ok=True, text=wire.dumps(value))
    except Exception as error:  # the callable failed on the student's arguments: they see why
        return dict(answer, ok=False, error=f"{type(error).__name__}: {error}"[:300])


def student_function(lesson: str, name: str) -> Callable:
    """A function that calls the student's ``name`` of ``lesson`` (see :func:`call`)."""

    def function(*args, **kwargs):
        return call(lesson, name, args, kwargs)

    function.__name__ = function.__qualname__ = name
    function.__doc__ = f"The student's {name}, called in their sandbox."
    return function
