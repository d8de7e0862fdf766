"""Run the hidden pytest suite against one student, in the grader's process.

The suite's tests ask for a ``student`` fixture; here it is a
:class:`StudentProxy` whose attributes are the student's exercise functions:
``student.rot_z(0.3)`` sends the call to the student's sandbox and returns the
plain value that comes back. Every comparison therefore runs here, in trusted
code, on data the student's code cannot tamper with.

:func:`run_hidden_suite` returns one :class:`~autograder.grading.results.CheckResult`
per test, with the one-line reason and hint of each failure.

How it runs (speed; the ``--no-nbval`` path is this module plus the sandbox):

- pytest collects the suite once per process (:func:`hidden_tests`); for each
  student the runner then calls each test function with its fixtures
  (``student``, ``ref``), which is all pytest's run protocol would do for
  these tests, without its ~1 ms of hooks and reports per test.
  :func:`run_hidden_suite_with_pytest` is the plain pytest run, kept as the
  yardstick: ``tests/test_suite_runner.py`` holds the two to the same results.
- each test's calls reach the sandbox in one batch, and a test whose calls
  return exactly the reference's values is not run again
  (:mod:`autograder.grading.transcripts`); before a batch,
  :func:`learn_reference_in_sandbox` adds the reference's values as computed in
  a sandbox, which can differ from this process's in the last bits.
- the preloaded heap is frozen out of the garbage collector, and OpenBLAS
  runs one thread (its pool made a 4×4 ``expm`` 50× slower).
"""

from __future__ import annotations

import contextlib
import functools
import os
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace

import pytest

from autograder.grading import transcript_cache
from autograder.grading.budget import cut
from autograder.grading.hidden_api import checks_not_enforced
from autograder.grading.results import CheckResult
from autograder.grading.transcripts import NudgedReference, ReferenceRecorder, Replay, Transcript, independent_prefix
from autograder.lessons.course import Course
from autograder.lessons.reference import answer_sources
from autograder.sandbox import launcher
from autograder.sandbox.session import LessonProgram, SandboxUnavailable, StudentError, StudentSandbox
from autograder.sandbox.warm import WarmSlot

CONTEXT = SimpleNamespace(student=None, reference=None)
PRINTED_KEEP = 2000  # characters of a check's printed output kept for the feedback page


class SuiteError(RuntimeError):
    """The hidden suite itself could not run: an infrastructure failure, never a zero."""


HINTS = {
    "not_implemented": "replace the line `raise NotImplementedError(...)` with your code",
    "timeout": "look for a loop that never ends, or a huge loop that numpy could do at once",
    "crash": "the process running your code stopped: look for os._exit, sys.exit, "
    "unbounded recursion or a huge allocation",
    "missing": "keep your code in the exercise's answer cell, under the same function name; "
    "helper functions must be defined in that cell too",
    "bad_value": "return numpy arrays, numbers, tuples, lists or dicts",
}
CONTRACT_SHARE = 0.25  # of an exercise's points, lost when it changes its arguments in place


def _crash_hint(message):
    """The graded course's hint for a known crash (:func:`coursekit.checking.crash_hint`), or ""."""
    try:
        from coursekit.checking import crash_hint
    except ImportError:  # a course whose coursekit has no such helper
        return ""
    return crash_hint(message)


def _contracts():
    """The graded course's ``coursekit.contracts`` (which library calls each exercise must not hand its
    work to, and the two contract hints); the course put its coursekit on ``sys.path``
    (:meth:`~autograder.lessons.course.Course.use_support_package`)."""
    import coursekit.contracts

    return coursekit.contracts


def contract_results(proxy: StudentProxy, tests: list[HiddenTest]) -> list[CheckResult]:
    """A failed check per exercise whose calls changed an argument in place (none when they did not).

    It weighs a third of the exercise's other checks, so it costs :data:`CONTRACT_SHARE` of the
    exercise's points; answers that leave their arguments alone are not affected at all.
    """
    results = []
    for exercise, (names, check) in proxy.changed.items():
        weight = sum(t.weight for t in tests if t.exercise == exercise) * CONTRACT_SHARE / (1 - CONTRACT_SHARE)
        where = f" (seen in the check “{check}”)" if check else ""
        results.append(
            CheckResult(
                exercise=exercise,
                description="leaves its arguments unchanged",
                weight=weight,
                passed=False,
                reason=f"{exercise} changed its argument{'s' if len(names) > 1 else ''} {', '.join(names)} "
                f"in place{where}",
                hint=_contracts().CHANGED_HINT,
            )
        )
    return results


class StudentProxy:
    """``student.<exercise>(*args)`` calls the student's function in their sandbox.

    ``unavailable`` maps a lesson number to the reason its notebook could not
    be used (missing, unreadable): calls into it fail with that reason.
    """

    def __init__(self, sandbox, catalog, unavailable=None, timeout=None, replay=None):
        self._sandbox = sandbox
        self._catalog = catalog
        self._unavailable = unavailable or {}
        self._timeout = timeout
        self._replay = replay
        self.printed = []
        self.changed = {}  # exercise -> the argument names its first in-place change touched
        self.check = ""  # the description of the hidden check running now (for the contract's reason)

    def with_timeout(self, seconds: float) -> StudentProxy:
        """The same proxy with a longer per-call time limit, for slow exercises."""
        clone = StudentProxy(self._sandbox, self._catalog, self._unavailable, seconds, self._replay)
        clone.printed, clone.changed = self.printed, self.changed
        return clone

    def changed_arguments(self) -> list[str]:
        """The arguments the last call changed in place (names; empty when it left them alone)."""
        return list(getattr(self._sandbox, "last_changed", ()) or ())

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        lesson = self._catalog.exercise(name).lesson
        forbid = _contracts().guard_for(name, lesson)  # the exercise's allowance and its FORBIDDEN entries

        def call(*args, **kwargs):
            if lesson in self._unavailable:
                raise StudentError("missing", self._unavailable[lesson])
            try:
                if self._replay is not None:
                    value = self._replay.call(lesson, name, args, kwargs, self._timeout, forbid)
                else:
                    value = self._sandbox.call(lesson, name, args, kwargs, timeout=self._timeout, forbid=forbid)
                changed = self.changed_arguments()
                if changed and name not in self.changed:
                    self.changed[name] = (changed, self.check)
                return value
            except StudentError as error:
                if error.stdout:
                    self.printed.append(error.stdout)
                raise
            finally:
                if self._sandbox.last_stdout:
                    self.printed.append(self._sandbox.last_stdout)

        call.__name__ = name
        return call


def _first_line(text, limit=240):
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _explain(error):
    """(reason, hint) for an exception raised by a hidden test."""
    from autograder.grading.hidden_api import Wrong

    if isinstance(error, Wrong):
        return _first_line(error.reason), _first_line(error.hint)
    if isinstance(error, StudentError):
        hint = _contracts().delegated_hint(error.message) if error.kind == "delegated" else HINTS.get(error.kind, "")
        if error.kind == "exception":
            hint = _crash_hint(error.message) or hint
        return _first_line(error.message), hint
    if isinstance(error, AssertionError):
        return _first_line(str(error).splitlines()[0] if str(error) else "a check failed"), ""
    return (
        _first_line(f"the result could not be checked ({type(error).__name__}: {error})"),
        "is the return value of the documented type and shape?",
    )


@dataclass(frozen=True)
class HiddenTest:
    """One collected hidden test: what to call, and what its result is about."""

    nodeid: str
    lesson: str
    function: object
    fixtures: tuple  # of "student" and "ref"
    params: dict = field(default_factory=dict)  # from @pytest.mark.parametrize
    exercise: str = ""
    weight: float = 1.0
    description: str = ""
    share: float = 0.0  # > 0: counts only when failed, then costs this share of the exercise (see weigh_shares)


FIXTURES = ("student", "ref")


def weigh_shares(results: list[CheckResult], shares: dict[tuple[str, str], float]) -> list[CheckResult]:
    """Checks marked ``share=s`` (``{(exercise, description): s}``) count only when they fail, and then cost the
    share ``s`` of their exercise's points (as :func:`contract_results`); passed, they are left out."""
    if not shares:
        return results
    kept = []
    for result in results:
        share = shares.get((result.exercise, result.description))
        if share is None:
            kept.append(result)
        elif not result.passed:
            others = sum(r.weight for r in results if r.exercise == result.exercise and r is not result)
            result.weight = max(others, 1.0) * share / (1 - share)
            kept.append(result)
    return kept


def _shares(tests) -> dict[tuple[str, str], float]:
    return {(t.exercise, t.description): t.share for t in tests if t.share}


class _Grabber:
    """pytest plugin: keeps the collected items."""

    def __init__(self):
        self.items = []

    def pytest_collection_modifyitems(self, session, config, items):
        self.items = list(items)


@contextlib.contextmanager
def _no_plugin_autoload():
    """Inner pytest runs load no installed plugins; the process's environment is left as it was."""
    before = os.environ.get("PYTEST_DISABLE_PLUGIN_AUTOLOAD")
    os.environ["PYTEST_DISABLE_PLUGIN_AUTOLOAD"] = "1"
    try:
        yield
    finally:
        if before is None:
            os.environ.pop("PYTEST_DISABLE_PLUGIN_AUTOLOAD", None)
        else:
            os.environ["PYTEST_DISABLE_PLUGIN_AUTOLOAD"] = before


SUITE_INI = Path(__file__).with_name("hidden_suite.ini")  # the ``exercise`` marker; the same for every course


def _pytest_args(files, course):
    return [str(f) for f in files] + [
        # no conftest.py: the fixtures are the grader's own, and a conftest above the course folder is not ours
        "-c",
        str(SUITE_INI),
        "--rootdir",
        str(course.root),
        "--noconftest",
        "-p",
        "autograder.grading.hidden_fixtures",
        "-p",
        "no:cacheprovider",
        "-p",
        "no:terminal",
        "-p",
        "no:warnings",
        # these two end every session with gc.collect() several times (~0.2 s a student) to find
        # exceptions nobody reads here
        "-p",
        "no:unraisableexception",
        "-p",
        "no:threadexception",
    ]


def _describe(item):
    doc = (item.function.__doc__ or item.name).strip().splitlines()[0]
    if getattr(item, "callspec", None) is not None:
        doc += f" [{item.callspec.id}]"
    return doc


def hidden_test_files(course: Course) -> list[Path]:
    """The course's hidden test files, ``test_NN_*.py``, in name order."""
    return sorted(course.hidden_suite.glob("test_*.py"))


@functools.lru_cache(maxsize=2)
def hidden_tests(course: Course) -> tuple[list[HiddenTest], list[str]]:
    """(tests, problems): ``course``'s hidden suite as pytest collects it, in pytest's order; once per process.

    Raises :class:`SuiteError` if pytest cannot collect it, or if a test asks
    for a fixture other than ``student`` and ``ref`` (the runner provides
    only those; write the test with them, or extend :data:`FIXTURES`).
    """
    grabber = _Grabber()
    with _no_plugin_autoload():
        course.use_support_package()
        code = pytest.main(_pytest_args(hidden_test_files(course), course) + ["--collect-only"], plugins=[grabber])
    if code != pytest.ExitCode.OK or not grabber.items:
        raise SuiteError(f"the hidden suite could not be collected (pytest exit status {int(code)})")
    tests, problems = [], []
    for item in grabber.items:
        mark = item.get_closest_marker("exercise")
        if mark is None:
            problems.append(f"hidden test {item.nodeid} names no exercise")
            continue
        callspec = getattr(item, "callspec", None)
        params = dict(callspec.params) if callspec is not None else {}
        unknown = set(item.fixturenames) - set(FIXTURES) - set(params)
        if unknown:
            raise SuiteError(
                f"hidden test {item.nodeid} asks for fixtures {sorted(unknown)}; "
                f"the grader's runner provides {', '.join(FIXTURES)}"
            )
        tests.append(
            HiddenTest(
                nodeid=item.nodeid,
                lesson=item.path.stem.split("_")[1],
                function=item.function,
                fixtures=tuple(n for n in FIXTURES if n in item.fixturenames),
                params=params,
                exercise=mark.kwargs["name"],
                weight=mark.kwargs.get("weight", 1.0),
                description=_describe(item),
                share=mark.kwargs.get("share", 0.0),
            )
        )
    return tests, problems


def _memo(reference):
    """What this process learned about ``reference``: ``{"transcripts": {nodeid: Transcript}, "learned":
    {lessons run in a sandbox}}``, kept on the reference itself (``ReferenceSolutions.memo``); a
    reference without a memo (a test's own namespace) gets an empty one each time."""
    memo = getattr(reference, "memo", None)
    if not isinstance(memo, dict):
        memo = {}
    memo.setdefault("learned", set())
    return memo


def _is_course_reference(reference, course):
    """True for the course's own reference (the masters'), the only one whose transcripts go to disk."""
    return reference is course.reference


def transcripts_for(reference: object, course: Course) -> dict[str, Transcript]:
    """``{nodeid: Transcript}``: every hidden test of ``course`` run once on ``reference``, its calls recorded.

    Kept in the reference's memo. For the course's own reference the transcripts
    are also read from, and saved to, :mod:`autograder.grading.transcript_cache`,
    so a machine records them once per grader version.
    """
    memo = _memo(reference)
    if memo.get("transcripts") is not None:
        return memo["transcripts"]
    single_threaded_blas()  # as in the sandbox, so that equal answers are equal bit for bit
    tests = hidden_tests(course)[0]
    saved = transcript_cache.load(course) if _is_course_reference(reference, course) else None
    if saved is not None and set(saved[0]) == {test.nodeid for test in tests}:
        found, memo["learned"] = saved
    else:
        found = _record_transcripts(reference, course.catalog, tests)
        if _is_course_reference(reference, course):
            transcript_cache.save(course, found)
    memo["transcripts"] = found
    return found


def _record_transcripts(reference, catalog, tests):
    """Run each test on ``reference`` twice (as is, then nudged) and keep its independent calls."""
    recorder, nudging = ReferenceRecorder(reference), ReferenceRecorder(reference, nudge=True)
    proxy, nudged_proxy = StudentProxy(recorder, catalog), StudentProxy(nudging, catalog)
    nudged_reference = NudgedReference(reference)
    found = {}
    for test in tests:
        transcript = recorder.start()
        passed, _, _ = _call_test(test, proxy, reference)
        transcript.passed = passed
        # a second time with every answer nudged: a call whose input moved was fed by an answer, and
        # it and every call after it are made one at a time, never sent ahead. Checks do not stop this run
        # (a check as tight as the nudge, or an exact one, would end it before its later calls are seen).
        second = nudging.start()
        with checks_not_enforced():
            _call_test(test, nudged_proxy, nudged_reference)
        transcript.cut(independent_prefix(transcript.calls, second.calls))
        found[test.nodeid] = transcript
    recorder.transcript = nudging.transcript = None
    return found


def reference_programs(course: Course) -> dict[str, LessonProgram]:
    """``{lesson: LessonProgram}`` of the reference solutions: each master's setup and answer cells."""
    sources, catalog = answer_sources(course.solutions), course.catalog
    return {
        lesson.number: LessonProgram(
            setup=lesson.setup_source, cells=[(e.name, sources[e.name]) for e in lesson.exercises]
        )
        for lesson in catalog.graded_lessons
    }


def learn_reference_in_sandbox(
    reference: object,
    course: Course,
    limits: launcher.Limits | None = None,
    slot: WarmSlot | None = None,
    lessons: tuple[str, ...] = (),
) -> int:
    """Run the hidden tests of ``lessons`` (all when empty) once on the reference solutions in a sandbox,
    as a student; return how many tests taught a new passing list of values.

    The reference's values computed in a sandbox can differ from this process's
    recording in the last bits (BLAS takes other paths on differently aligned
    memory), so without this a student whose code is the reference's would
    re-run about a quarter of the tests. A test teaches its values only when
    it passed with every call answered from its batch, in the recorded order,
    so a student who returns the same values, bit for bit, would pass it the
    same way (:meth:`~autograder.grading.transcripts.Replay.note_if_passed`).
    Lessons learned once, by this process or one before it on this machine
    (:mod:`autograder.grading.transcript_cache`), are not run again.
    Speed only: any failure here just leaves the memo as it was.
    """
    transcripts, catalog = transcripts_for(reference, course), course.catalog
    done = _memo(reference)["learned"]
    wanted = {lesson.number for lesson in catalog.graded_lessons if not lessons or lesson.number in lessons}
    todo = wanted - done
    if not todo:
        return 0
    done |= todo
    learned = 0
    try:
        with StudentSandbox(reference_programs(course), course.support, limits=limits, slot=slot) as sandbox:
            proxy = StudentProxy(sandbox, catalog)
            replay = proxy._replay = Replay(sandbox)
            for test in hidden_tests(course)[0]:
                transcript = transcripts.get(test.nodeid)
                if test.lesson not in todo or transcript is None or not transcript.passed:
                    continue
                replay.prefetch(transcript)
                if replay.passes_as_recorded():
                    continue
                passed, _, _ = _call_test(test, proxy, reference)
                learned += replay.note_if_passed(passed)
                replay.stop()
    except (SandboxUnavailable, StudentError):
        return learned
    if _is_course_reference(reference, course):
        transcript_cache.save(course, transcripts, done)
    return learned


def _call_test(test, proxy, reference):
    """Run one test function; return (passed, reason, hint)."""
    arguments = dict(test.params)
    if "student" in test.fixtures:
        arguments["student"] = proxy
    if "ref" in test.fixtures:
        arguments["ref"] = reference
    try:
        test.function(**arguments)
    except (KeyboardInterrupt, SandboxUnavailable):
        raise
    except BaseException as error:  # noqa: B036 (pytest, too, fails a test on any exception)
        reason, hint = _explain(error)
        return False, reason, hint
    return True, "", ""


def _printed_text(parts):
    printed = "".join(parts)
    if len(printed) > PRINTED_KEEP:
        printed = printed[:PRINTED_KEEP] + "\n[… more characters not kept]"
    return printed


def run_hidden_suite(
    proxy: StudentProxy, reference: object, course: Course, lessons: list[str] | None = None
) -> tuple[list[CheckResult], list[str]]:
    """Run ``course``'s hidden suite for one student; return (list of CheckResult, problems).

    ``lessons``: only run the tests of these lesson numbers (default all).
    """
    tests, problems = hidden_tests(course)
    tests = [t for t in tests if lessons is None or t.lesson in lessons]
    if not tests:
        return [], []
    transcripts = transcripts_for(reference, course)
    replay = proxy._replay = Replay(proxy._sandbox)
    results = []
    try:
        for test in tests:
            proxy.printed.clear()
            proxy.check = test.description
            replay.prefetch(transcripts.get(test.nodeid), proxy._unavailable)
            if replay.passes_as_recorded():
                passed, reason, hint = True, "", ""
                proxy.printed.extend(replay.printed())
            else:
                passed, reason, hint = _call_test(test, proxy, reference)
            replay.stop()
            results.append(
                CheckResult(
                    exercise=test.exercise,
                    description=test.description,
                    weight=test.weight,
                    passed=passed,
                    reason=cut(reason),
                    hint=hint,
                    printed=_printed_text(proxy.printed),
                )
            )
    finally:
        proxy._replay = None
    return weigh_shares(results, _shares(tests)) + contract_results(proxy, tests), list(problems)


def _short_repr(excinfo, style=None):
    """A failure's report text without pytest's source-parsing traceback formatter."""
    try:
        return f"{excinfo.typename}: {_first_line(excinfo.value)}"
    except Exception:  # an exception whose str() fails
        return excinfo.typename


class _Collector:
    """pytest plugin: turns each test item into a CheckResult."""

    def __init__(self, proxy):
        self.proxy = proxy
        self.results = []
        self.problems = []

    def pytest_collection_modifyitems(self, session, config, items):
        for item in items:
            if item.get_closest_marker("exercise") is None:
                self.problems.append(f"hidden test {item.nodeid} names no exercise")
            # Speed: pytest formats every failure's traceback (re-parsing the test module's source
            # for each frame, ~60 ms a failure); nobody reads it, the verdict comes from
            # call.excinfo below. A one-line text keeps report.failed and everything else as it was.
            item.repr_failure = _short_repr
            item._repr_failure_py = _short_repr

    @pytest.hookimpl(hookwrapper=True)
    def pytest_runtest_makereport(self, item, call):
        outcome = yield
        report = outcome.get_result()
        if report.when == "setup":
            self.proxy.printed.clear()
            self.proxy.check = _describe(item)
        failed_now = report.failed and report.when in ("setup", "call")
        finished = report.when == "call" or failed_now
        if not finished or getattr(item, "_graded", False):
            return
        item._graded = True
        mark = item.get_closest_marker("exercise")
        if mark is None:
            return
        reason, hint = ("", "")
        if report.failed and call.excinfo is not None:
            reason, hint = _explain(call.excinfo.value)
        self.results.append(
            CheckResult(
                exercise=mark.kwargs["name"],
                description=_describe(item),
                weight=mark.kwargs.get("weight", 1.0),
                passed=report.passed,
                reason=cut(reason),
                hint=hint,
                printed=_printed_text(self.proxy.printed),
            )
        )


_BLAS_THREAD_SETTERS = (
    "scipy_openblas_set_num_threads64_",
    "scipy_openblas_set_num_threads",
    "openblas_set_num_threads64_",
    "openblas_set_num_threads",
)


def single_threaded_blas() -> int:
    """Make every OpenBLAS loaded in this process (numpy's and scipy's) use one thread.

    The hidden suite works on 3×3 and 4×4 matrices, where OpenBLAS's thread pool costs far
    more than it saves (``scipy.linalg.expm`` of a 4×4: 0.4 ms with the pool, 0.01 ms
    without; 5 ms on a busy machine), and the pool's threads compete with the other graders.
    Forked graders inherit the setting. Returns how many libraries were set.
    """
    import ctypes

    try:
        with open("/proc/self/maps", encoding="utf-8") as maps:
            paths = {line.split()[-1] for line in maps if "openblas" in line.lower() and "/" in line}
    except OSError:
        return 0
    done = 0
    for path in sorted(paths):
        try:
            library = ctypes.CDLL(path)
        except OSError:
            continue
        for name in _BLAS_THREAD_SETTERS:
            setter = getattr(library, name, None)
            if setter is not None:
                setter(ctypes.c_int(1))
                done += 1
                break
    return done


def preload_hidden_suite(course: Course) -> None:
    """Collect the hidden suite and record the reference's calls once, so forked graders reuse them (speed)."""
    import gc

    single_threaded_blas()
    hidden_tests(course)
    transcripts_for(course.reference, course)
    # Everything imported so far lives as long as the process: keep it out of the garbage
    # collector's scans (each forked grader would otherwise walk, and copy, the whole heap).
    gc.collect()
    gc.freeze()


def run_hidden_suite_with_pytest(
    proxy: StudentProxy, reference: object, course: Course, lessons: list[str] | None = None
) -> tuple[list[CheckResult], list[str]]:
    """:func:`run_hidden_suite` as a plain ``pytest.main`` run, call by call: the yardstick of the fast runner.

    Same arguments and results; about twice the CPU time.
    """
    CONTEXT.student, CONTEXT.reference = proxy, reference
    collector = _Collector(proxy)
    files = hidden_test_files(course)
    if lessons is not None:
        files = [f for f in files if f.stem.split("_")[1] in lessons]
    if not files:
        return [], []
    with _no_plugin_autoload():
        course.use_support_package()
        code = pytest.main(_pytest_args(files, course), plugins=[collector])
    if code not in (pytest.ExitCode.OK, pytest.ExitCode.TESTS_FAILED) or not collector.results:
        raise SuiteError(
            f"the hidden suite did not run (pytest exit status {int(code)}, {len(collector.results)} checks collected)"
        )
    tests = [t for t in hidden_tests(course)[0] if lessons is None or t.lesson in lessons]
    return weigh_shares(collector.results, _shares(tests)) + contract_results(proxy, tests), collector.problems
