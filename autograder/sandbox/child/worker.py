"""The process that runs one student's code, inside the sandbox.

It speaks JSON lines (see :mod:`wire`) on the file descriptors that were its
stdin and stdout when it started; the student's code gets ``/dev/null`` for
those and a capped in-memory buffer for ``sys.stdout`` and ``sys.stderr``, so
printing can neither break the protocol nor flood the grader.

Requests and replies (all dicts):

- ``{"op": "exec", "lesson": "01", "label": "rot_z", "source": ...}`` runs one
  cell in the lesson's namespace; reply ``{"ok": bool, "error"?, "stdout"}``.
- ``{"op": "call", "lesson": "01", "name": "rot_z", "args": [...],
  "kwargs": {...}, "timeout": 5.0}``; reply ``{"ok": True, "value", "stdout"}``
  or ``{"ok": False, "error": {"type", "message", "where"}, "stdout"}``.
- ``{"op": "batch", "calls": [call, ...], "budget": 2.0, "timeout": 5.0}`` makes several calls
  in order, one round trip for all (speed); reply ``{"ok": True, "replies":
  [...]}`` with, per call made, the reply of ``call`` plus its ``seconds``, and
  its value as wire text (``"text"``) rather than decoded; a call whose
  ``timeout`` is null gets the batch's. The batch stops
  after the first call that fails, or once its calls have run ``budget``
  seconds: the grader makes any call it still needs one at a time.

The grader trusts none of this: it decodes replies strictly and compares
values in its own process.
"""

import builtins
import os
import signal
import sys
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import jail  # noqa: E402

if __name__ == "__main__" and "--keep-user" not in sys.argv:  # (a zygote's fork drops them itself)
    jail.drop_privileges(jail.sandbox_uid(sys.argv))

import numpy  # noqa: E402,F401  (imported before student code, as a notebook would)

import wire  # noqa: E402
from coursekit import watching  # noqa: E402  (the course's own definition of a call's contracts)

STDOUT_KEEP = 4000
MESSAGE_KEEP = 300


class CallTimeout(BaseException):
    """Raised inside a student function that runs past its time."""


class CappedText:
    """A write-only text stream that keeps the first ``STDOUT_KEEP`` characters."""

    def __init__(self):
        self.reset()

    def reset(self):
        self.parts, self.kept, self.dropped = [], 0, 0

    def write(self, text):
        text = str(text)
        room = STDOUT_KEEP - self.kept
        if room > 0:
            self.parts.append(text[:room])
            self.kept += min(room, len(text))
        self.dropped += max(0, len(text) - max(room, 0))
        return len(text)

    def flush(self):
        pass

    def isatty(self):
        return False

    def text(self):
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


def _describe(error):
    message = " ".join(str(error).split())
    if len(message) > MESSAGE_KEEP:
        message = message[: MESSAGE_KEEP - 1] + "…"
    return {"type": type(error).__name__, "message": message, "where": _where(error)}


def _unsupported(error):
    return {"type": "UnsupportedValue", "where": "",
            "message": f"returned {error}; return numbers, numpy arrays, tuples, lists or dicts of those"}


def _on_alarm(signum, frame):
    raise CallTimeout()


class Worker:
    def __init__(self, requests, replies):
        self.requests = requests
        self.replies = replies
        self.namespaces = {}
        self.output = CappedText()
        self.request_id = 0

    def namespace(self, lesson):
        if lesson not in self.namespaces:
            self.namespaces[lesson] = {"__name__": "__main__", "__builtins__": builtins}
        return self.namespaces[lesson]

    def reply(self, message):
        message["id"] = self.request_id
        try:
            line = wire.dumps(message)
        except wire.WireError as error:
            line = wire.dumps({"ok": False, "stdout": self.output.text(), "id": self.request_id,
                               "error": _unsupported(error)})
        self.replies.write(line.encode("utf-8") + b"\n")
        self.replies.flush()

    def run_guarded(self, action, timeout):
        """Run ``action()`` with the output captured and an alarm; return (ok, value or error)."""
        self.output.reset()
        sys.stdout = sys.stderr = self.output
        signal.signal(signal.SIGALRM, _on_alarm)
        signal.setitimer(signal.ITIMER_REAL, max(float(timeout), 0.001))
        try:
            return True, action()
        except CallTimeout:
            return False, {"type": "Timeout", "message": f"still running after {timeout:g} s", "where": ""}
        except BaseException as error:  # SystemExit and KeyboardInterrupt too: report, go on
            return False, _describe(error)
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            sys.stdout, sys.stderr = sys.__stdout__, sys.__stderr__

    def do_exec(self, request):
        namespace = self.namespace(request["lesson"])
        filename = f"<lesson {request['lesson']} cell {request['label']}>"

        def action():
            exec(compile(request["source"], filename, "exec"), namespace)

        ok, result = self.run_guarded(action, request.get("timeout", 10.0))
        message = {"ok": ok, "stdout": self.output.text()}
        if not ok:
            message["error"] = result
        self.reply(message)

    def invoke(self, call, timeout):
        """Call ``call``'s function with its arguments, guarded and watched (:mod:`coursekit.watching`).

        Returns ``(ok, value or error dict, notes)``: ``notes`` holds ``"changed"`` (the arguments the
        call changed in place) and ``"delegated"`` (functions of the call's ``forbid`` list that the
        student's code called), each only when not empty.
        """
        function = self.namespace(call["lesson"]).get(call["name"])
        if not callable(function):
            self.output.reset()
            return False, {"type": "NameError", "where": "",
                           "message": f"{call['name']} is not defined in the graded cells"}, {}
        args = [self.materialize(a) for a in call.get("args", [])]
        kwargs = {k: self.materialize(v) for k, v in call.get("kwargs", {}).items()}
        forbidden = [str(name) for name in call.get("forbid") or ()]
        ok, result = self.run_guarded(lambda: watching.watch_call(function, args, kwargs, forbidden), timeout)
        if not ok:
            return False, result, {}
        value, seen = result
        notes = {}
        if seen.changed:
            notes["changed"] = seen.changed
        if seen.used or seen.tampered:
            notes["delegated"] = seen.used + (["sys.setprofile"] if seen.tampered else [])
        return True, value, notes

    def do_call(self, request):
        ok, result, notes = self.invoke(request, request.get("timeout", 5.0))
        message = {"ok": ok, "stdout": self.output.text(), **notes}
        message["value" if ok else "error"] = result
        self.reply(message)

    def call_for_batch(self, call, default_timeout):
        """One call of a batch: its reply, with the value as wire text (checked to be plain data)."""
        started = time.monotonic()
        ok, result, notes = self.invoke(call, call.get("timeout") or default_timeout)
        message = {"ok": ok, "stdout": self.output.text(), **notes}
        if ok:
            try:
                message["text"] = wire.dumps(result)
            except wire.WireError as error:
                message["ok"] = False
                message["error"] = _unsupported(error)
        else:
            message["error"] = result
        message["seconds"] = time.monotonic() - started
        return message

    def do_batch(self, request):
        replies, spent = [], 0.0
        for call in request.get("calls", []):
            reply = self.call_for_batch(call, request.get("timeout") or 5.0)
            replies.append(reply)
            spent += reply["seconds"]
            if not reply["ok"] or spent > request.get("budget", 2.0):
                break
        self.reply({"ok": True, "replies": replies})

    @staticmethod
    def materialize(value):
        if isinstance(value, wire.Probe):
            import probes

            return probes.resolve(value.name, value.args)
        return value

    def serve(self):
        self.reply({"ready": True})
        while True:
            line = self.requests.readline(wire.MAX_LINE_BYTES)
            if not line:
                return
            request = wire.loads(line.decode("utf-8"))
            self.request_id = request.get("id", 0)
            op = request.get("op")
            if op == "exec":
                self.do_exec(request)
            elif op == "call":
                self.do_call(request)
            elif op == "batch":
                self.do_batch(request)
            elif op == "bye":
                return
            else:
                self.reply({"ok": False, "stdout": "", "error": {"type": "ProtocolError",
                                                                 "message": f"unknown op {op!r}", "where": ""}})


def main():
    requests = os.fdopen(os.dup(0), "rb")
    replies = os.fdopen(os.dup(1), "wb")
    devnull = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(devnull, fd)
    sys.stdin = open(os.devnull)
    Worker(requests, replies).serve()
    replies.flush()
    os._exit(0)


if __name__ == "__main__":
    main()
