"""The grader's runner of the hidden suite gives exactly what plain pytest gives, check by check.

Oracle: ``run_hidden_suite_with_pytest``, the suite run by ``pytest.main`` with
every call to the student made one at a time, as the grader ran it before
batches and the transcript memo (``autograder/grading/transcripts.py``). Every
field of every check must agree: exercise, description, weight, pass or fail,
reason, hint and what the student's code printed.

Edge cases: the reference (most tests pass "as recorded", unrun); the stubs
(every batch stops at its first call); typical mistakes, several per exercise
(tests that fail part-way, with hints); correct alternatives (answers that
differ from the reference's in the last bits, so the tests run); a function
that hangs on some inputs, one that kills its process on others, and one that
prints; a lesson whose notebook is missing.
"""

import subprocess
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from autograder.grading import pipeline, transcripts
from autograder.grading.pipeline import GradingContext, GradingOptions, grade_student
from autograder.grading.suite import run_hidden_suite_with_pytest
from autograder.lessons.paths import PROJECT_ROOT
from autograder.sandbox.child import wire
from autograder.sandbox.launcher import Limits
from autograder.sandbox.session import StudentError
from support import STUB, build_submission, mistakes
from support import THIS_COURSE

FAULTS = {
    # hangs for angles above 5 rad (the checks use angles in [-2π, 2π])
    "rot_z": (
        "def rot_z(a):\n    while a > 5.0:\n        pass\n    c, s = np.cos(a), np.sin(a)\n"
        "    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])"
    ),
    # kills its own process for angles below -5 rad
    "rot_y": (
        "import os\n\ndef rot_y(a):\n    if a < -5.0:\n        os._exit(3)\n    c, s = np.cos(a), np.sin(a)\n"
        "    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])"
    ),
    # right, and chatty
    "rot_x": (
        "def rot_x(a):\n    print('rot_x of', round(a, 3))\n    c, s = np.cos(a), np.sin(a)\n"
        "    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])"
    ),
}


def _nth_of_kind(kind, n):
    """``{exercise: source}`` of the n-th answer of ``kind`` ("mistake" or "alternative") for each exercise."""
    by_exercise = {}
    for answer in mistakes().values():
        if answer.kind == kind:
            by_exercise.setdefault(answer.exercise, []).append(answer.source)
    return {exercise: sources[n % len(sources)] for exercise, sources in by_exercise.items()}


def _without(folder, notebook):
    (folder / notebook).unlink()
    return folder


SUBMISSIONS = {
    "reference": lambda folder: build_submission(folder),
    "stubs": lambda folder: build_submission(folder, default=STUB),
    "mistakes-1": lambda folder: build_submission(folder, _nth_of_kind("mistake", 0)),
    "mistakes-2": lambda folder: build_submission(folder, _nth_of_kind("mistake", 1)),
    "mistakes-3": lambda folder: build_submission(folder, _nth_of_kind("mistake", 2)),
    "alternatives-1": lambda folder: build_submission(folder, _nth_of_kind("alternative", 0)),
    "alternatives-2": lambda folder: build_submission(folder, _nth_of_kind("alternative", 1)),
    "faults": lambda folder: build_submission(folder, FAULTS, lessons=("01",)),
    "lesson 05 missing": lambda folder: _without(
        build_submission(folder, lessons=("04", "05", "06")), "05_euler_angles.ipynb"
    ),
}

# short, so the faults' endless loops cost little; not 1 s: on a loaded CI machine a correct alternative that
# makes many probe round trips (numerical_jacobian) has taken longer than that in one run and not the other
OPTIONS = GradingOptions(nbval=False, limits=Limits(call_timeout=3.0))


def _as_rows(result):
    return [
        (c.exercise, c.description, c.weight, c.passed, c.reason, c.hint, c.printed)
        for e in result.exercises
        for c in e.checks
    ], result.problems


@pytest.mark.parametrize("name", sorted(SUBMISSIONS))
def test_the_runner_agrees_with_plain_pytest_check_by_check(name, tmp_path, monkeypatch):
    folder = SUBMISSIONS[name](tmp_path / name)
    fast = grade_student(name, folder, GradingContext(THIS_COURSE, OPTIONS))
    monkeypatch.setattr(pipeline, "run_hidden_suite", run_hidden_suite_with_pytest)
    plain = grade_student(name, folder, GradingContext(THIS_COURSE, OPTIONS))

    fast_rows, fast_problems = _as_rows(fast)
    plain_rows, plain_problems = _as_rows(plain)
    assert len(fast_rows) == len(plain_rows) > 0
    for ours, theirs in zip(fast_rows, plain_rows):
        assert ours == theirs
    assert fast_problems == plain_problems
    assert [(e.name, e.points) for e in fast.exercises] == [(e.name, e.points) for e in plain.exercises]


def _count_unrun(monkeypatch):
    counts = {"unrun": 0, "run": 0}
    original = transcripts.Replay.passes_as_recorded

    def counting(self):
        verdict = original(self)
        counts["unrun" if verdict else "run"] += 1
        return verdict

    monkeypatch.setattr(transcripts.Replay, "passes_as_recorded", counting)
    return counts


def test_answers_equal_to_the_references_bit_for_bit_are_passed_without_running(tmp_path, monkeypatch):
    counts = _count_unrun(monkeypatch)
    result = grade_student(
        "ada",
        build_submission(tmp_path / "ada", lessons=("01", "02")),
        GradingContext(THIS_COURSE, GradingOptions(nbval=False, lessons=("01", "02"))),
    )
    assert result.score == result.max_score
    # rot_z and friends return the same bits as the reference's; a few results differ from the
    # reference's run in this process in the last bit (BLAS on differently aligned memory): those run
    assert counts["unrun"] >= 20 and counts["unrun"] > counts["run"]


def test_an_answer_one_rounding_away_from_the_reference_runs_its_tests_and_passes(tmp_path, monkeypatch):
    nudged = (
        "def rot_z(a):\n    c, s = np.cos(a), np.sin(a)\n"
        "    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) * (1.0 + 2.0 ** -52)"
    )
    folder = build_submission(tmp_path / "nudged", {"rot_z": nudged}, lessons=("01",))
    counts = _count_unrun(monkeypatch)
    result = grade_student("nudged", folder, GradingContext(THIS_COURSE, GradingOptions(nbval=False, lessons=("01",))))
    rot_z = next(e for e in result.exercises if e.name == "rot_z")
    assert rot_z.points == rot_z.max_points and all(c.passed for c in rot_z.checks)
    assert counts["run"] >= len(rot_z.checks)  # its tests could not be skipped: they ran, and passed


def _transcripts():
    from autograder.grading import suite

    return suite.transcripts_for(THIS_COURSE.reference, THIS_COURSE)


def test_recording_is_deterministic(tmp_path, monkeypatch):
    """The same calls and values in another process, one that loaded other modules (a grader's), as in this one:
    the transcripts kept on disk by one process are used by the next (autograder/grading/transcript_cache.py)."""
    from autograder.grading import suite, transcript_cache

    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path))
    record = (
        "from autograder.grading import suite; from autograder.lessons.paths import this_course; "
        "course = this_course(); suite.transcripts_for(course.reference, course)"
    )
    subprocess.run([sys.executable, "-c", record], cwd=PROJECT_ROOT, check=True, timeout=600)
    first, _ = transcript_cache.load(THIS_COURSE)
    suite.single_threaded_blas()
    second = suite._record_transcripts(THIS_COURSE.reference, THIS_COURSE.catalog, suite.hidden_tests(THIS_COURSE)[0])
    assert first.keys() == second.keys()
    differ = [
        k
        for k in first
        if first[k].calls != second[k].calls
        or first[k].results != second[k].results
        or not (first[k].passed and second[k].passed)
    ]
    assert not differ, differ[:5]
    assert sum(len(t.calls) for t in first.values()) > 1000
    assert np.mean([len(t.calls) for t in first.values()]) > 5


class _AnsweringSandbox:
    """A stand-in sandbox whose batches return ``values`` (wire text) for the calls."""

    limits = Limits()

    def __init__(self, values):
        self.values = values

    def check_callable(self, lesson, name):
        pass

    def call_batch(self, calls, timeouts, budget):
        return [{"ok": True, "stdout": "", "text": value} for value in self.values[: len(calls)]]


def _passes_unrun(transcript, values):
    replay = transcripts.Replay(_AnsweringSandbox([wire.dumps(v) for v in values]))
    replay.prefetch(transcript)
    return replay.passes_as_recorded()


def test_only_the_references_exact_values_pass_a_test_unrun_and_never_where_it_raised():
    recorder = transcripts.ReferenceRecorder(SimpleNamespace(halve=lambda x: 1.0 / 0.0 if x == 0 else x / 2))
    plain = recorder.start()
    recorder.call("01", "halve", [3.0])
    plain.passed = True
    assert _passes_unrun(plain, [1.5])  # exactly the reference's value for every call
    assert not _passes_unrun(plain, [1.5 + 2**-51])  # the last bits differ: the test runs

    raising = recorder.start()
    assert recorder.call("01", "halve", [3.0]) == 1.5
    with pytest.raises(StudentError):  # what a test that expects the raise catches
        recorder.call("01", "halve", [0.0])
    raising.passed = True
    assert raising.results[1] is None
    assert not _passes_unrun(raising, [1.5, 0.0])  # returned where the reference raised: the test runs
    assert not _passes_unrun(raising, [1.5])  # a call short: the test runs


class _ServingSandbox(_AnsweringSandbox):
    """Also serves the calls a test makes: from the batch (take_reply) or, off the recording, live."""

    def take_reply(self, lesson, name, reply, timeout):
        return wire.loads(reply["text"])

    def call(self, lesson, name, args, kwargs, timeout=None, forbid=()):
        return 0.0


def _run_on_batch(transcript, values, calls):
    """A replay of ``transcript`` whose batch returns ``values``, after a test made ``calls``."""
    replay = transcripts.Replay(_ServingSandbox([wire.dumps(v) for v in values]))
    replay.prefetch(transcript)
    for argument in calls:
        replay.call("01", "halve", [argument], {}, None)
    return replay


def test_values_are_learned_only_from_a_test_that_passed_on_exactly_its_batch():
    recorder = transcripts.ReferenceRecorder(SimpleNamespace(halve=lambda x: x / 2))
    recorded = recorder.start()
    recorder.call("01", "halve", [3.0])
    recorder.call("01", "halve", [5.0])
    recorded.passed = True
    sandbox_values = [1.5 + 2**-51, 2.5]

    assert not _run_on_batch(recorded, sandbox_values, [3.0, 5.0]).note_if_passed(False)  # it failed
    assert not _run_on_batch(recorded, sandbox_values, [3.0]).note_if_passed(True)  # a call left over
    assert not _run_on_batch(recorded, sandbox_values, [3.0, 7.0]).note_if_passed(True)  # left the recording
    assert not _run_on_batch(recorded, sandbox_values, [3.0, 5.0, 9.0]).note_if_passed(True)  # one call more
    assert recorded.also_passing == [] and not _passes_unrun(recorded, sandbox_values)

    assert _run_on_batch(recorded, sandbox_values, [3.0, 5.0]).note_if_passed(True)
    assert _passes_unrun(recorded, sandbox_values)  # now known to pass, bit for bit
    assert _passes_unrun(recorded, [1.5, 2.5])  # the reference's own values still do
    assert not _passes_unrun(recorded, [1.5 + 2**-51, 2.5 + 2**-51])  # anything else runs the test


def test_a_student_whose_code_is_the_references_runs_almost_no_test_once_learned(tmp_path, monkeypatch):
    """learn_reference_in_sandbox: the reference's sandbox values pass unrun too (and verdicts stay full)."""
    from autograder.grading import suite

    suite.learn_reference_in_sandbox(THIS_COURSE.reference, THIS_COURSE)
    cut = sum(not t.complete for t in suite.transcripts_for(THIS_COURSE.reference, THIS_COURSE).values())
    counts = _count_unrun(monkeypatch)
    result = grade_student(
        "ada", build_submission(tmp_path / "ada"), GradingContext(THIS_COURSE, GradingOptions(nbval=False))
    )
    assert result.score == result.max_score
    total = counts["run"] + counts["unrun"]
    # the tests cut for chained inputs always run (tests/test_transcripts_independent.py); of the rest, ≤ 2%
    assert total > 150 and counts["run"] - cut <= 0.02 * total, (counts, cut)
