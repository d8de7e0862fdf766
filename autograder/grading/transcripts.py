"""The reference's calls in each hidden test, recorded once, so a student's are made in one round trip.

A hidden test calls the student's functions one by one, and each call is a
round trip to the sandbox (about 0.1 ms of CPU on each side, ~2,200 of them
for a student who answers everything). The calls a test makes are nearly
always the same for every student: its inputs are seeded and come from the
test, not from the student. So, once per grader process:

1. **Record.** Every hidden test runs against the reference solutions in this
   process; each call it makes is noted (as wire text: lesson, function,
   arguments, time limit) with the value the reference returned
   (:func:`transcripts_for`).
2. **Prefetch.** Before a test runs for a student, all its recorded calls go
   to the student's sandbox as one batch (:meth:`Replay.prefetch`).
3. **Replay.** While the test runs, a call that is the next recorded call,
   exactly, is answered from the batch; the first call that differs (the
   test took another path because of the student's answer), and every call
   after it, is made one at a time as before (:meth:`Replay.call`). The
   sandbox stops a batch at the first call that fails, so a function that
   raises or hangs does so once, at the same point as without batches.
4. **Same answers, same verdict.** A test is a deterministic function of what
   its calls return: its inputs are seeded, it reads no clock, and its other
   oracles (scipy, the reference) are deterministic. So when every call of a
   batch returned, bit for bit, the value the reference returned, the test
   would pass exactly as it did for the reference, and it is not run again
   (:meth:`Replay.passes_as_recorded`). Any other answer runs the test.

The student's code never sees the recorded values, nor any input computed from
them: only the calls go into the sandbox, and only calls whose inputs are the
test's own. Each test is recorded a second time with every answer of the
reference :func:`nudged` (those of the ``ref`` fixture too), its checks not
enforced (:func:`~autograder.grading.hidden_api.checks_not_enforced`: a check as
tight as the nudge, or an exact one, would otherwise end that run before its later
calls are seen, and the test would run in full for every student); a call whose input
moved was fed by an answer (``pose_inverse(pose_inverse(T))``), and the
transcript stops before it (:meth:`Transcript.cut`), so that call and every
later one are made one at a time, with the inputs the test computes from the
student's own answers. The sandbox's feeder hands the student's process one
call at a time, so even the calls of a batch are never readable ahead. One difference remains, by design:
when a test stops early (a wrong value), the rest of its batch has already
run, so a function that keeps state between calls sees more calls than it
would one at a time. Graded exercises are pure functions of their arguments,
so such an answer is wrong for the course either way; its grade stays
deterministic. A batch stops after :data:`BATCH_BUDGET` seconds of calls, so
slow answers cost little extra. ``tests/test_suite_runner.py`` holds
this runner to plain pytest, check by check, on the sample class and on every
typical mistake.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from autograder.sandbox.child import probes, wire
from autograder.sandbox.session import StudentError, call_request

BATCH_BUDGET = 2.0  # seconds of student calls in one batch; slower calls are made one at a time
NUDGE = 1e-14  # how far the second recording moves every answer (see nudged)


@dataclass
class Transcript:
    """The calls one hidden test made on the reference, in order: only those whose inputs are the test's
    own (:func:`independent_prefix`), so that no input sent ahead in a batch comes from an answer."""

    calls: list  # wire text of {"lesson", "name", "args", "kwargs", "timeout"} per call
    keys: list  # (lesson, name) per call
    timeouts: list  # the call's own time limit, or None for the sandbox's default
    results: list  # wire text of the value the reference returned, per call (None: it raised)
    passed: bool = False  # the test passed on the reference: only then can a replay pass it unrun
    # other complete lists of values (wire text) with which the test was run and passed: the reference's
    # own answers computed in a sandbox, which may differ from ``results`` in the last bits
    also_passing: list = field(default_factory=list)
    complete: bool = True  # False: later calls were cut, their inputs came from answers; never passed unrun

    def cut(self, count: int) -> None:
        """Keep the first ``count`` calls; a test cut short always runs (its later calls must be made)."""
        if count < len(self.calls):
            del self.calls[count:], self.keys[count:], self.timeouts[count:], self.results[count:]
            self.complete = False


def call_text(
    lesson: str, name: str, args: tuple | list, kwargs: dict, timeout: float | None, forbid: tuple = ()
) -> str:
    """The wire text that identifies one call (raises :class:`wire.WireError` for non-data arguments)."""
    request = call_request(lesson, name, args, kwargs, timeout, forbid)
    del request["op"]
    return wire.dumps(request)


def _materialize(value):
    return probes.resolve(value.name, value.args) if isinstance(value, wire.Probe) else value


def nudged(value: object) -> object:
    """``value`` with every float moved by :data:`NUDGE` (relative, and a thousandth of it absolute); the
    rest as is. It is far inside every hidden test's tolerance, so the test goes on as it did, and far
    above rounding (about 50 units in the last place), so an input computed from the value moves too.

    Recording a test a second time with the reference's answers nudged shows which of its later inputs
    were computed from an answer: those inputs change (:func:`independent_prefix`).

    Examples
    --------
    >>> nudged((1.0, [0.0, 2]))[0] != 1.0
    True
    """
    import numpy as np

    if isinstance(value, float):
        return value * (1 + NUDGE) + NUDGE * 1e-3
    if isinstance(value, complex):
        return complex(nudged(value.real), nudged(value.imag))
    if isinstance(value, np.ndarray) and value.dtype.kind in "fc":
        return value * (1 + NUDGE) + NUDGE * 1e-3
    if isinstance(value, list):
        return [nudged(v) for v in value]
    if isinstance(value, tuple):
        return tuple(nudged(v) for v in value)
    if isinstance(value, dict):
        return {k: nudged(v) for k, v in value.items()}
    return value


class NudgedReference:
    """The reference module as a test's ``ref`` fixture sees it, with every answer :func:`nudged`."""

    def __init__(self, reference):
        self._reference = reference

    def __getattr__(self, name):
        target = getattr(self._reference, name)
        if not callable(target):
            return target

        def call(*args, **kwargs):
            return nudged(target(*args, **kwargs))

        return call


def independent_prefix(calls: list[str], nudged_calls: list[str]) -> int:
    """How many of a test's calls, from the first, have inputs that no answer of the reference fed:
    the calls that a second recording with nudged answers (``nudged_calls``) made exactly alike."""
    count = 0
    for text, other in zip(calls, nudged_calls):
        if text != other:
            break
        count += 1
    return count


class ReferenceRecorder:
    """Stands in for a student's sandbox while recording: calls the reference, notes each call.

    With ``nudge``, every answer is :func:`nudged` before the test sees it (the second recording).
    """

    last_stdout = ""
    last_changed = ()

    def __init__(self, reference, nudge=False):
        self.reference = reference
        self.transcript = None
        self.nudge = nudge

    def start(self) -> Transcript:
        self.transcript = Transcript(calls=[], keys=[], timeouts=[], results=[])
        return self.transcript

    def call(
        self,
        lesson: str,
        name: str,
        args: tuple = (),
        kwargs: dict | None = None,
        timeout: float | None = None,
        forbid: tuple = (),
    ) -> object:
        text = call_text(lesson, name, args, kwargs, timeout, forbid)
        request = wire.loads(text)  # the arguments exactly as the sandbox would receive them
        try:
            value = getattr(self.reference, name)(
                *[_materialize(a) for a in request["args"]],
                **{k: _materialize(v) for k, v in request["kwargs"].items()},
            )
            result = wire.dumps(value)
        except Exception as error:
            # noted with no value, so no replay can pass this test unrun; the test sees what a
            # student's raising function would give it
            self._note(text, lesson, name, timeout, None)
            raise StudentError("exception", f"{name} raised {type(error).__name__}: {error}") from None
        self._note(text, lesson, name, timeout, result)
        return nudged(wire.loads(result)) if self.nudge else wire.loads(result)

    def _note(self, text, lesson, name, timeout, result):
        if self.transcript is not None:
            self.transcript.calls.append(text)
            self.transcript.keys.append((lesson, name))
            self.transcript.timeouts.append(timeout)
            self.transcript.results.append(result)


class Replay:
    """Serves one test's calls from a prefetched batch while they follow the recorded ones."""

    def __init__(self, sandbox):
        self.sandbox = sandbox
        self._transcript = None
        self._replies = []
        self._next = 0

    def prefetch(self, transcript: Transcript | None, unavailable: dict | tuple = ()) -> None:
        """Make ``transcript``'s calls in the student's sandbox, in one round trip when possible."""
        self.stop()
        if transcript is None or not transcript.calls:
            return
        if any(lesson in unavailable for lesson, _ in transcript.keys):
            return
        try:
            for lesson, name in set(transcript.keys):
                self.sandbox.check_callable(lesson, name)
        except StudentError:
            return  # the calls themselves will say why
        replies = self.sandbox.call_batch(transcript.calls, transcript.timeouts, BATCH_BUDGET)
        if replies:
            self._transcript, self._replies, self._next = transcript, replies, 0

    def _answers(self):
        """The batch's values as wire text, when every recorded call was made and returned one; else None."""
        transcript = self._transcript
        if (
            transcript is None
            or len(self._replies) != len(transcript.calls)
            or not all(
                reply["ok"] and not reply.get("changed") and not reply.get("delegated") for reply in self._replies
            )
        ):
            return None
        return [reply["text"] for reply in self._replies]

    def passes_as_recorded(self) -> bool:
        """True when every recorded call returned, bit for bit, values with which the test passed before:
        the reference's (:attr:`Transcript.results`) or a list in :attr:`Transcript.also_passing`."""
        answers = self._answers()
        return (
            answers is not None
            and self._transcript.passed
            and self._transcript.complete
            and (answers == self._transcript.results or answers in self._transcript.also_passing)
        )

    def note_if_passed(self, passed: bool) -> bool:
        """After the test ran on the batch: if it passed, and every call it made was answered from the
        batch, in order, with nothing left over, the batch's values are known to pass (for
        :meth:`passes_as_recorded`). Return whether they were noted."""
        transcript, answers = self._transcript, self._answers()
        if not passed or answers is None or not transcript.complete or self._next != len(transcript.calls):
            return False
        if answers != transcript.results and answers not in transcript.also_passing:
            transcript.also_passing.append(answers)
        return True

    def printed(self) -> list[str]:
        """What the batch's calls printed, in order (as the proxy would have collected it)."""
        return [str(reply.get("stdout", "")) for reply in self._replies if reply.get("stdout")]

    def call(
        self, lesson: str, name: str, args: tuple, kwargs: dict, timeout: float | None, forbid: tuple = ()
    ) -> object:
        """The call's value: from the batch while calls follow the recording, else from the sandbox."""
        if self._transcript is not None and self._next < len(self._replies):
            try:
                text = call_text(lesson, name, args, kwargs, timeout, forbid)
            except wire.WireError:
                text = None
            if text == self._transcript.calls[self._next]:
                reply = self._replies[self._next]
                self._next += 1
                effective = self.sandbox.limits.call_timeout if timeout is None else timeout
                return self.sandbox.take_reply(lesson, name, reply, effective)
        self.stop()  # the test left the recorded path: one call at a time from here on
        return self.sandbox.call(lesson, name, args, kwargs, timeout=timeout, forbid=forbid)

    def stop(self) -> None:
        self._transcript, self._replies, self._next = None, [], 0
