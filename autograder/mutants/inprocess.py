"""Grade an answer cell in this process, with the grader's own parts: fast enough for thousands of mutants.

:class:`InProcessSandbox` stands in for :class:`~autograder.sandbox.session.StudentSandbox`:
it runs a lesson's setup and answer cells, and each call, with the sandbox
worker's own code (``sandbox/child/worker.py``: the same guard, alarm, watching
of arguments and delegation, and wire text of the value), and reads each reply
with ``StudentSandbox.take_reply``; only the process boundary is missing. So the
hidden suite (:func:`grade_hidden`, the grader's :func:`run_hidden_suite`, replay
included) and the public checks (:func:`run_public_checks`, the check cell's
``coursekit.check``) see what they would see in a real grading, in milliseconds.

Only trusted code belongs here: the reference's mutants and the project's own
corpus. Student submissions are graded in the real sandbox.

Examples
--------
>>> hidden = grade_hidden(course, "rot_z", "def rot_z(a):\\n    return np.eye(3)\\n")   # doctest: +SKIP
>>> hidden.points < hidden.max_points                                        # doctest: +SKIP
True
"""

from __future__ import annotations

import contextlib
import io
import signal
import sys
from dataclasses import dataclass, field
from functools import lru_cache

from autograder.grading.suite import StudentProxy, run_hidden_suite
from autograder.lessons.course import Course
from autograder.lessons.reference import answer_sources
from autograder.sandbox.launcher import Limits
from autograder.sandbox.session import CellOutcome, LessonProgram, StudentSandbox

PUBLIC_SECONDS = 20.0  # a check cell that runs longer than this counts as failed (a student would see it hang)


@lru_cache(maxsize=1)
def _worker_module():
    """The sandbox worker's module, imported here (it imports ``coursekit.watching``: the course's
    :meth:`~autograder.lessons.course.Course.use_support_package` comes first)."""
    from autograder.sandbox.child import worker

    return worker


class InProcessSandbox:
    """A lesson's cells and calls run by the sandbox worker's code, in this process (trusted code only)."""

    def __init__(self, programs, limits=None):
        worker = _worker_module()
        self.limits = limits or Limits()
        from autograder.sandbox.child import probes

        self.worker = worker.Worker(None, None, local_probes=probes)
        self.hung, self.time_used, self.outcomes = {}, 0.0, []
        self.last_stdout, self.last_changed = "", []
        with _kept_streams():
            for lesson, program in programs.items():
                for label, source in [("setup", program.setup)] + list(program.cells):
                    self._exec(lesson, label, source)

    def _exec(self, lesson, label, source):
        namespace = self.worker.namespace(lesson)
        code = compile(source, f"<lesson {lesson} cell {label}>", "exec")
        ok, result, printed = self.worker.run_guarded(lambda: exec(code, namespace), self.limits.load_timeout)
        self.outcomes.append(CellOutcome(lesson, label, ok, "" if ok else str(result.get("message", "")), printed))

    def namespace(self, lesson: str) -> dict:
        return self.worker.namespace(lesson)

    def _reply(self, text, timeout):
        call = _worker_module().wire.loads(text)  # the worker's own wire module: its Probe class
        with _kept_streams():
            return self.worker.call_reply(call, timeout)

    def check_callable(self, lesson: str, name: str) -> None:
        return StudentSandbox.check_callable(self, lesson, name)

    def take_reply(self, lesson: str, name: str, reply: dict, timeout: float) -> object:
        return StudentSandbox.take_reply(self, lesson, name, reply, timeout)

    def call(
        self,
        lesson: str,
        name: str,
        args: tuple = (),
        kwargs: dict | None = None,
        timeout: float | None = None,
        forbid: tuple = (),
    ) -> object:
        from autograder.grading.transcripts import call_text

        timeout = self.limits.call_timeout if timeout is None else timeout
        self.last_stdout, self.last_changed = "", []
        self.check_callable(lesson, name)
        reply = self._reply(call_text(lesson, name, args, kwargs, timeout, forbid), timeout)
        return self.take_reply(lesson, name, reply, timeout)

    def call_batch(self, calls: list[str], timeouts: list[float | None], budget: float = 2.0) -> list[dict]:
        replies, spent = [], 0.0
        for text, timeout in zip(calls, timeouts):
            reply = self._reply(text, self.limits.call_timeout if timeout is None else timeout)
            replies.append(reply)
            spent += reply.get("seconds", 0.0)
            if not reply["ok"] or spent > budget:
                break
        return replies


@contextlib.contextmanager
def _kept_streams():
    """The worker points sys.stdout back at sys.__stdout__ after each call: keep whatever was there."""
    saved = sys.stdout, sys.stderr
    try:
        yield
    finally:
        sys.stdout, sys.stderr = saved


def lesson_programs(course: Course, lesson: str, overrides: dict[str, str]) -> dict[str, LessonProgram]:
    """``{lesson: LessonProgram}``: the master's setup and answers, with ``overrides`` ({exercise: source})."""
    course.use_support_package()
    catalog = course.catalog
    sources = answer_sources(course.solutions)
    setup = catalog.lesson(lesson).setup_source
    cells = [(e.name, overrides.get(e.name, sources[e.name])) for e in catalog.lesson(lesson).exercises]
    return {lesson: LessonProgram(setup=setup, cells=cells)}


@dataclass
class HiddenGrade:
    """What the hidden suite gave one exercise (and whether any other exercise of its lesson lost points)."""

    exercise: str
    points: float
    max_points: float
    failed: list = field(default_factory=list)  # (description, reason, hint) of each failed check
    elsewhere: list = field(default_factory=list)  # other exercises that lost points

    @property
    def killed(self) -> bool:
        return self.points < self.max_points


def _score(max_points, checks):
    total = sum(c.weight for c in checks)
    return round(max_points * sum(c.weight for c in checks if c.passed) / total, 2) if total else 0.0


def grade_hidden(course: Course, exercise: str, source: str, sandbox: InProcessSandbox | None = None) -> HiddenGrade:
    """The hidden suite's verdict on ``source`` as the answer to ``exercise`` (other answers: the reference's)."""
    catalog = course.catalog
    lesson = catalog.exercise(exercise).lesson
    sandbox = sandbox or InProcessSandbox(lesson_programs(course, lesson, {exercise: source}))
    proxy = StudentProxy(sandbox, catalog)
    checks, _ = run_hidden_suite(proxy, course.reference, course, lessons=[lesson])
    grade = HiddenGrade(exercise, 0.0, catalog.exercise(exercise).points)
    for other in catalog.lesson(lesson).exercises:
        own = [c for c in checks if c.exercise == other.name]
        points = _score(other.points, own)
        if other.name == exercise:
            grade.points = points
            grade.failed = [(c.description, c.reason, c.hint) for c in own if not c.passed]
        elif points < other.points:
            grade.elsewhere.append(other.name)
    return grade


class _Alarm(BaseException):
    pass


def _on_alarm(signum, frame):
    raise _Alarm()


def run_public_checks(
    course: Course, exercise: str, source: str, sandbox: InProcessSandbox | None = None
) -> tuple[bool, str]:
    """``(passed, printed)``: did every public check of ``exercise`` pass for the answer ``source``?

    The answer runs as the check cell would see it: after the lesson's setup cell
    and the other answers (the reference's), in a namespace named ``__main__``.
    """
    course.use_support_package()
    import coursekit
    from coursekit.checking import CheckFailed

    lesson = course.catalog.exercise(exercise).lesson
    sandbox = sandbox or InProcessSandbox(lesson_programs(course, lesson, {exercise: source}))
    function = sandbox.namespace(lesson).get(exercise)
    out = io.StringIO()
    if not callable(function):
        return False, f"{exercise} is not defined"
    previous = signal.signal(signal.SIGALRM, _on_alarm)
    signal.setitimer(signal.ITIMER_REAL, PUBLIC_SECONDS)
    try:
        with contextlib.redirect_stdout(out):
            coursekit.check(exercise, function)
    except (CheckFailed, NotImplementedError):
        return False, out.getvalue()
    except _Alarm:
        return False, out.getvalue() + f"\n  ✗ the check cell did not finish within {PUBLIC_SECONDS:g} s"
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    return "✗" not in out.getvalue(), out.getvalue()
