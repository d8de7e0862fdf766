"""The feeder: PID 1 of a student's namespaces, between the grader and the student's process.

Student code runs in the *runner* (``worker.Worker``), a child of the feeder.
The feeder holds what the student must not reach, and hands the runner one
request at a time:

- **a batch of calls** (one round trip from the grader for a whole hidden
  test): the runner only ever holds the call it is running; the rest stay
  here until the one before has returned;
- **the probes** (``probes.py``: named callables a test passes to a student's
  function, some of which are operations an exercise asks for): read from a
  descriptor opened before ``/sandbox/probes.py`` was covered, evaluated
  here, and only for the callables passed in the current call.

Student code cannot reach the feeder: it is PID 1 of the student's PID
namespace (no signal from inside reaches it), not dumpable (its memory,
descriptors and ptrace are refused) and holds no capability.

Protocol (JSON lines, :mod:`wire`): the grader's requests are those of
``worker.py`` (``exec``, ``call``, ``batch``, ``bye``). The feeder forwards
``exec``, ``call`` and ``bye`` as they are and the runner's reply back. For a
``batch`` it sends the runner one ``call`` at a time and answers with
``{"ok": true, "replies": [...]}``, stopping after the first call that fails (or that returns another value than
the batch names in its ``expect`` list, or calls back otherwise than its ``callbacks`` list says),
once the calls have run ``budget`` seconds, or once the replies reach
:data:`MAX_BATCH_BYTES`. If the runner dies, the feeder says
``{"died": <raw wait status>, "id": <request>}`` and exits (taking every
process of the namespace with it).

A callable argument reaches the runner as a *handle*: its position among the
call's callable arguments (:func:`callables_in`). When the student's code
calls it, the runner asks ``{"callback": k, "args", "kwargs"}``; the feeder
evaluates a probe itself and passes any other callable (the notebook stage's
functions) up to whoever sent the call, who answers
``{"op": "callback_result", "seq", "ok", "text"|"error"}``. In a ``batch``
with a ``callbacks`` list (the notebook stage's replay of a recorded lesson),
the feeder answers a call's callbacks from that list instead, in order, each
only when the runner asks for the same callable with the same arguments (as
wire text) and, first, the calls that callable made to student functions,
made again in the runner, return the values noted; any other callback fails
the call.
"""

from __future__ import annotations

import json
import os
import signal
import time
import types

import wire

MAX_REPLY_BYTES = 3 * 1024**2  # one reply of the runner: a value of at most 1 MiB (worker.MAX_VALUE_BYTES), quoted
MAX_BATCH_BYTES = 8 * 1024**2


class RunnerGone(Exception):
    """The runner died, or broke the protocol (a reply too large or not plain data)."""


def callables_in(value: object, found: list | None = None) -> list:
    """The callable arguments (:class:`wire.Probe`, :class:`wire.Callback`) of a call's ``args`` and
    ``kwargs``, in a fixed order (depth first, dict items in order): a handle is an index into it."""
    found = [] if found is None else found
    if isinstance(value, (wire.Probe, wire.Callback)):
        found.append(value)
    elif isinstance(value, (list, tuple)):
        for item in value:
            callables_in(item, found)
    elif isinstance(value, dict):
        for item in value.values():
            callables_in(item, found)
    return found


class LineChannel:
    """Bounded line reads from a descriptor (nothing is parsed before its size is known)."""

    def __init__(self, fd, limit):
        self.fd, self.limit, self.buffer = fd, limit, b""

    def read_line(self) -> bytes | None:
        """The next line (without its newline), or None at the end of the stream."""
        while b"\n" not in self.buffer:
            if len(self.buffer) > self.limit:
                raise RunnerGone(f"sent a line longer than {self.limit} bytes")
            chunk = os.read(self.fd, 1 << 20)
            if not chunk:
                return None
            self.buffer += chunk
        line, self.buffer = self.buffer.split(b"\n", 1)
        if len(line) > self.limit:
            raise RunnerGone(f"sent a line longer than {self.limit} bytes")
        return line


def _fields(raw):
    """The items of a wire dict as JSON parsed them (``{"__dict__": [[key, value], ...]}``), values not decoded."""
    items = raw.get("__dict__", []) if isinstance(raw, dict) else []
    return {pair[0]: pair[1] for pair in items if isinstance(pair, list) and len(pair) == 2 and type(pair[0]) is str}


def _op_and_id(line):
    """A request's ``op``, ``id`` and items (a wire dict), read without decoding its arguments: a batch's calls
    go to the runner as the grader wrote them (the runner decodes each, strictly), not decoded and written again."""
    found = _fields(json.loads(line))
    return found.get("op"), found.get("id", 0), found


def _call_line(call, number, timeout):
    """The runner's request for one call of a batch (``call`` as JSON parsed it), with its ``op``, ``id`` and
    time limit, and the callable arguments in it (decoded only when there are any)."""
    fields = _fields(call)
    items = [pair for pair in call["__dict__"] if not (isinstance(pair, list) and pair and pair[0] in _SET_HERE)]
    items += [["op", "call"], ["id", number], ["timeout", fields.get("timeout") or timeout]]
    text = json.dumps({"__dict__": items}, separators=(",", ":"), allow_nan=False)
    found = []
    if '"__probe__"' in text or '"__callback__"' in text:
        decoded = wire.decode(call)
        found = callables_in([decoded.get("args", []), decoded.get("kwargs", {})])
    return text.encode() + b"\n", found


_SET_HERE = ("op", "id", "timeout")


def _write(fd, data):
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]


def wait_and_report(pid: int, replies_fd: int) -> None:
    """Direct mode (``worker.start``): wait for the runner; if it did not end by the caller's ``bye``,
    say how it ended (its raw wait status), as :meth:`Feeder.report_death` does. Never returns."""
    _, status = os.waitpid(pid, 0)  # retried by Python itself when a signal interrupts it (PEP 475)
    if not (os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0):
        try:
            _write(replies_fd, wire.dumps({"died": status, "id": 0}).encode() + b"\n")
        except OSError:
            pass
    os._exit(0)


class Feeder:
    """Serves the grader (``upstream_*``) with the runner (``runner_fd``, a connected socket)."""

    def __init__(self, upstream_in, upstream_out, runner_fd, runner_pid, probes_fd=None):
        self.upstream = LineChannel(upstream_in, wire.MAX_LINE_BYTES)
        self.upstream_out = upstream_out
        self.runner = LineChannel(runner_fd, MAX_REPLY_BYTES)
        self.runner_fd, self.runner_pid = runner_fd, runner_pid
        self.request_id = 0
        self._probes_fd, self._probes = probes_fd, None
        self._callables = []  # the callable arguments of the call the runner is running
        self._answers = None  # in a batch with a callbacks list: the running call's expected callbacks, left
        self._answers_broken = False  # the running call called back otherwise than its list says
        self._inner_id = 1 << 30  # ids of the calls made again inside a callback (far from the batch's)

    # ------------------------------------------------------------ probes
    def probes(self) -> types.ModuleType:
        """The probes module, compiled from the descriptor opened before the file was covered."""
        if self._probes is None:
            import types

            module = types.ModuleType("probes")
            source = b""
            if self._probes_fd is not None:
                while True:
                    chunk = os.pread(self._probes_fd, 1 << 20, len(source))
                    if not chunk:
                        break
                    source += chunk
            exec(compile(source, "probes.py", "exec"), module.__dict__)
            self._probes = module
        return self._probes

    # ------------------------------------------------------------ the runner
    def send_runner(self, message: dict) -> None:
        try:
            _write(self.runner_fd, wire.dumps(message).encode() + b"\n")
        except OSError:
            raise RunnerGone("stopped reading its requests") from None

    def runner_reply(self) -> tuple[dict, bytes]:
        """The runner's reply to the request it is running, answering its callbacks meanwhile."""
        while True:
            line = self.runner.read_line()
            if line is None:
                raise RunnerGone("ended")
            try:
                message = wire.loads(line.decode("utf-8"))
            except (wire.WireError, UnicodeDecodeError) as error:
                raise RunnerGone(f"sent a malformed reply ({error})") from None
            if not isinstance(message, dict):
                raise RunnerGone("sent a reply that is not a message")
            if "callback" in message:
                self.answer_callback(message)
                continue
            return message, line

    def answer_callback(self, message: dict) -> None:
        handle, seq = message.get("callback"), message.get("seq")
        target = self._callables[handle] if type(handle) is int and 0 <= handle < len(self._callables) else None
        if isinstance(target, wire.Probe):
            result = self.evaluate_probe(target, message)
        elif isinstance(target, wire.Callback) and self._answers is not None:
            result = self.noted_answer(handle, message)
        elif isinstance(target, wire.Callback):
            result = self.ask_upstream(message)
        else:
            result = {"ok": False, "error": "not a callable argument of this call"}
        self.send_runner(dict(result, op="callback_result", seq=seq))

    def noted_answer(self, handle: int, message: dict) -> dict:
        """The answer noted for the running call's next callback, if the runner asks exactly for it."""
        try:
            asked = [handle, wire.dumps(message.get("args", [])), wire.dumps(message.get("kwargs", {}))]
        except wire.WireError:
            asked = None
        if self._answers and not self._answers_broken and asked == self._answers[0][:3]:
            _, _, _, answer, inner = self._answers.pop(0)
            if all(self.call_again(call, value) for call, value in inner):
                return dict(answer)
        self._answers_broken = True
        return {"ok": False, "error": "called back otherwise than the reference's answer did"}

    def call_again(self, call: str, value: str) -> bool:
        """Make, while the runner waits for a callback, a call the callable made to a student function when it
        was noted (``call``, wire text); True when it returns ``value``, bit for bit."""
        if not (isinstance(call, str) and call.endswith("]]}") and isinstance(value, str)):
            return False
        self._inner_id += 1
        outer, self._callables = self._callables, []
        try:
            _write(self.runner_fd, (call[:-2] + ',["op","call"],["id",%d]]}\n' % self._inner_id).encode())
            reply, _ = self.runner_reply()
        except OSError:
            raise RunnerGone("stopped reading its requests") from None
        finally:
            self._callables = outer
        return reply.get("ok") is True and reply.get("text") == value

    def evaluate_probe(self, probe: wire.Probe, message: dict) -> dict:
        args, kwargs = message.get("args"), message.get("kwargs")
        if not isinstance(args, list) or not isinstance(kwargs, dict):
            return {"ok": False, "error": "bad callback arguments"}
        try:
            function = self.probes().resolve(probe.name, probe.args)
            return {"ok": True, "text": wire.dumps(function(*args, **kwargs))}
        except Exception as error:  # the student's arguments made the probe fail: say so in their code
            return {"ok": False, "error": f"{type(error).__name__}: {error}"[:300]}

    def ask_upstream(self, message: dict) -> dict:
        """A callable of the sender's own (the notebook stage): ask the sender, wait for its answer."""
        self.send_upstream(
            {
                "callback": message["callback"],
                "args": message.get("args", []),
                "kwargs": message.get("kwargs", {}),
                "id": self.request_id,
            }
        )
        while True:
            line = self.upstream.read_line()
            if line is None:
                os._exit(0)
            try:
                answer = wire.loads(line.decode("utf-8"))
            except (wire.WireError, UnicodeDecodeError):
                answer = None
            if isinstance(answer, dict) and answer.get("op") == "callback_result":
                return {key: answer[key] for key in ("ok", "text", "error") if key in answer}
            if not isinstance(answer, dict) or answer.get("op") != "call":
                return {"ok": False, "error": "the caller did not answer the callback"}
            # the callable calls a student function in turn (a demonstration passing boxplus_right): the
            # runner, waiting for this callback, answers that call first
            outer = self._callables, self.request_id
            self.request_id = answer.get("id", 0)
            self.forward(None, line)
            self._callables, self.request_id = outer

    # ------------------------------------------------------------ the grader
    def send_upstream(self, message: dict) -> None:
        try:
            _write(self.upstream_out, wire.dumps(message).encode() + b"\n")
        except OSError:
            os._exit(0)  # the grader has gone: everything here goes with us

    def forward(self, request: dict | None, line: bytes) -> None:
        """Relay one request to the runner and its reply back, as they are."""
        if b'"__probe__"' in line or b'"__callback__"' in line:  # decode the arguments only when needed
            request = wire.loads(line.decode("utf-8"))
            self._callables = callables_in([request.get("args", []), request.get("kwargs", {})])
        else:
            self._callables = []
        try:
            _write(self.runner_fd, line + b"\n")
        except OSError:
            raise RunnerGone("stopped reading its requests") from None
        _, reply_line = self.runner_reply()
        try:
            _write(self.upstream_out, reply_line + b"\n")
        except OSError:
            os._exit(0)

    def batch(self, request: dict) -> None:
        """Run a batch's calls one at a time (``request``: the batch's items as JSON parsed them, see
        :func:`_op_and_id`); answer with the replies as the runner wrote them."""
        replies, spent, size = [], 0.0, 0
        timeout = request.get("timeout") or 5.0
        expect = request.get("expect") if isinstance(request.get("expect"), list) else None
        noted = wire.decode(request["callbacks"]) if isinstance(request.get("callbacks"), list) else None
        budget = request.get("budget") if type(request.get("budget")) in (int, float) else 2.0
        for number, call in enumerate(request.get("calls") or []):
            if not isinstance(call, dict) or not isinstance(call.get("__dict__"), list):
                break
            line, self._callables = _call_line(call, number + 1, timeout)
            answers = noted[number] if noted is not None and number < len(noted) else None
            self._answers = list(answers) if isinstance(answers, list) else None
            self._answers_broken = False
            try:
                _write(self.runner_fd, line)
            except OSError:
                raise RunnerGone("stopped reading its requests") from None
            try:
                reply, line = self.runner_reply()
            finally:
                left, self._answers = self._answers, None
            if left is not None and (left or self._answers_broken):  # called back otherwise, or fewer times
                reply = {"ok": False, "error": {"type": "Replay", "message": "called back otherwise", "where": ""}}
                line = wire.dumps(reply).encode()
            replies.append(line)
            spent += float(reply.get("seconds") or 0.0)
            size += len(line)
            if not reply.get("ok") or spent > budget or size > MAX_BATCH_BYTES:
                break
            if expect is not None and (number >= len(expect) or reply.get("text") != expect[number]):
                break  # a value other than the one expected: the inputs of later calls may come from it
        # the replies as the runner wrote them (each decoded above, so plain data), each still with its "id"
        head = b'{"__dict__":[["ok",true],["replies",['
        tail = b']],["id",%d]]}\n' % int(self.request_id)
        try:
            _write(self.upstream_out, head + b",".join(replies) + tail)
        except OSError:
            os._exit(0)

    def report_death(self, why: str | None = None) -> None:
        """Tell the grader how the runner ended (its raw wait status, or ``why`` it was stopped), then
        end the namespace."""
        try:
            os.kill(self.runner_pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        status = None
        deadline = time.monotonic() + 5.0
        while time.monotonic() < deadline:
            pid, raw = os.waitpid(self.runner_pid, os.WNOHANG)
            if pid:
                status = raw
                break
            time.sleep(0.002)
        message = {"died": status, "id": self.request_id}
        if why:
            message["why"] = why
        self.send_upstream(message)
        os._exit(0)

    def serve(self) -> None:
        try:
            hello, line = self.runner_reply()
            _write(self.upstream_out, line + b"\n")
            while True:
                line = self.upstream.read_line()
                if line is None:
                    return
                op, self.request_id, fields = _op_and_id(line)
                if op == "batch":
                    self.batch(fields)
                else:
                    self.forward(None, line)
                    if op == "bye":
                        return
        except RunnerGone as gone:
            self.report_death(None if str(gone) == "ended" else str(gone))
