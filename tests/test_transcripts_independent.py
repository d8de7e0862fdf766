"""No input the grader sends ahead to a student's sandbox is computed from the reference's answers.

The transcripts (autograder/grading/transcripts.py) are the calls a hidden test makes, sent to the
sandbox in one batch before the test runs. A test that chains calls (``pose_inverse`` of
``pose_inverse(T)``) would put the reference's answer in a later call's input; such calls are cut
from the transcript. Oracles, over every transcript of the real hidden suite:

- no argument of a kept call equals, bit for bit, a value an earlier call of the same test returned,
  or a value the test got from the ``ref`` fixture (or a row or column of one);
- a second recording with answers moved by another amount keeps exactly the same calls;
- a chained test of our own is cut before its chained call, and a cut test is never passed unrun;
- a check tighter than the nudge (an exact comparison) does not end the nudged recording: the calls after it
  are kept, and the test passes unrun for a student whose values are the reference's;
- checks are relaxed only inside ``checks_not_enforced`` and only in its own thread, and a hint given as a
  function is made only when its check fails.
"""

import threading
from types import SimpleNamespace

import numpy as np
import pytest

from autograder.grading import suite, transcripts
from autograder.grading.hidden_api import Wrong, checks_not_enforced, expect, expect_close
from autograder.sandbox.child import wire
from support import THIS_COURSE


def _arrays(value):
    """Every float array and float in ``value`` (nested in lists, tuples, dicts), as arrays."""
    if isinstance(value, np.ndarray) and value.dtype.kind in "fc":
        return [value]
    if isinstance(value, float):
        return [np.array(value)]
    if isinstance(value, (list, tuple)):
        return [a for item in value for a in _arrays(item)]
    if isinstance(value, dict):
        return [a for item in value.values() for a in _arrays(item)]
    return []


def _pieces(array):
    """The array, its rows and its columns: the parts of an answer a test might pass on."""
    pieces = [array]
    if array.ndim == 2:
        pieces += list(array) + list(array.T)
    return [p for p in pieces if p.size > 1 and np.any(p != 0) and not np.all(np.isin(p, (0.0, 1.0, -1.0)))]


class _Watching:
    """A ``ref`` fixture that remembers every value the test got from it."""

    def __init__(self, reference, seen):
        self._reference, self._seen = reference, seen

    def __getattr__(self, name):
        target = getattr(self._reference, name)
        if not callable(target):
            return target

        def call(*args, **kwargs):
            value = target(*args, **kwargs)
            self._seen.extend(_arrays(value))
            return value

        return call


@pytest.fixture(scope="module")
def recorded():
    reference, catalog = THIS_COURSE.reference, THIS_COURSE.catalog
    return reference, catalog, suite.transcripts_for(reference, THIS_COURSE)


def _contract_samples(test):
    """The fixed sample arguments of a contract check (``test_NN_contracts.py``), as lists; [] for other tests."""
    if "_contracts.py::test_contract[" not in test.nodeid:
        return []
    from coursekit.exercise_contracts import sample_sets

    name = test.nodeid.rsplit("[", 1)[1].rstrip("]")
    return [a for _, arguments in sample_sets(name) for a in arguments if isinstance(a, list)]


def test_no_kept_input_is_an_answer_the_test_got_earlier(recorded):
    reference, catalog, found = recorded
    recorder = transcripts.ReferenceRecorder(reference)
    proxy = suite.StudentProxy(recorder, catalog)
    offending = []
    for test in suite.hidden_tests(THIS_COURSE)[0]:
        kept = found[test.nodeid]
        from_ref = []
        recorder.start()
        suite._call_test(test, proxy, _Watching(reference, from_ref))
        inputs = [_arrays(wire.loads(text)["args"]) for text in kept.calls]
        literals = _contract_samples(test)
        for number, arguments in enumerate(inputs):
            answers = [
                p
                for result in kept.results[:number]
                if result is not None
                for a in _arrays(wire.loads(result))
                for p in _pieces(a)
            ]
            answers += [p for a in from_ref for p in _pieces(a)]
            own = [a for earlier in inputs[: number + 1] for a in earlier]
            for argument in arguments:
                same = lambda p: argument.shape == p.shape and np.array_equal(argument, p)  # noqa: E731
                # an answer that equals one of the test's own inputs (compose(R, I) = R) proves nothing
                if any(np.array_equal(argument, np.asarray(x, dtype=float)) for x in literals):
                    continue  # a contract check's fixed sample (the identity quaternion), equal to an answer by chance
                if any(same(p) for p in answers) and not any(same(a) for a in own if a is not argument):
                    offending.append(f"{test.nodeid} call {number + 1}")
    assert not offending, offending


def test_a_second_recording_with_other_nudges_keeps_the_same_calls(recorded, monkeypatch):
    reference, catalog, found = recorded
    monkeypatch.setattr(transcripts, "NUDGE", 3e-13)
    recorder = transcripts.ReferenceRecorder(reference, nudge=True)
    proxy = suite.StudentProxy(recorder, catalog)
    moved = []
    for test in suite.hidden_tests(THIS_COURSE)[0]:
        second = recorder.start()
        suite._call_test(test, proxy, transcripts.NudgedReference(reference))
        kept = found[test.nodeid].calls
        common = min(len(kept), len(second.calls))  # a run that stopped early shows fewer calls, not others
        if second.calls[:common] != kept[:common]:
            moved.append(test.nodeid)
    assert not moved, moved


def test_the_chained_tests_the_issue_names_are_cut(recorded):
    _, _, found = recorded
    for name in ("test_pose_inverse_undoes", "test_transform_points_chain", "test_pose_compose_laws"):
        cut = [t for nodeid, t in found.items() if nodeid.endswith(name)]
        assert cut and not cut[0].complete, name


def _chained(student):
    T = np.eye(4)
    T[:3, 3] = [1.0, 2.0, 3.0]
    once = student.pose_inverse(T)
    twice = student.pose_inverse(once)
    assert np.allclose(twice, T)


def test_a_chained_call_is_cut_and_the_test_always_runs():
    reference, catalog = THIS_COURSE.reference, THIS_COURSE.catalog
    test = SimpleNamespace(function=_chained, params={}, fixtures=("student",))
    first, second = transcripts.ReferenceRecorder(reference), transcripts.ReferenceRecorder(reference, nudge=True)
    recorded, nudged = first.start(), second.start()
    assert suite._call_test(test, suite.StudentProxy(first, catalog), reference)[0]
    suite._call_test(test, suite.StudentProxy(second, catalog), transcripts.NudgedReference(reference))
    assert len(recorded.calls) == 2
    recorded.passed = True
    recorded.cut(transcripts.independent_prefix(recorded.calls, nudged.calls))
    assert len(recorded.calls) == 1 and not recorded.complete

    class Answering:  # a sandbox that answers the one kept call with the reference's value
        limits = SimpleNamespace(call_timeout=5.0)

        def check_callable(self, lesson, name):
            pass

        def call_batch(self, calls, timeouts, budget):
            return [{"ok": True, "stdout": "", "text": recorded.results[0]}]

    replay = transcripts.Replay(Answering())
    replay.prefetch(recorded)
    assert not replay.passes_as_recorded(), "a test cut short must run: its chained call is still to be made"


def _exact_then_independent(student, ref):
    T = np.eye(4)
    T[:3, 3] = [1.0, 2.0, 3.0]
    expect(np.array_equal(student.pose_inverse(T), ref.pose_inverse(T)), "not exact")  # fails when nudged
    expect_close(student.pose_inverse(np.eye(4)), np.eye(4), 0.0, "the identity")  # so does this one
    T[:3, 3] = [-1.0, 0.5, 0.0]
    expect_close(student.pose_inverse(T)[:3, 3], [1.0, -0.5, 0.0], 1e-15, "a shift")


def test_an_exact_check_does_not_cut_the_transcript():
    reference, catalog = THIS_COURSE.reference, THIS_COURSE.catalog
    test = SimpleNamespace(
        function=_exact_then_independent, params={}, fixtures=("student", "ref"), nodeid="synthetic::exact"
    )
    found = suite._record_transcripts(reference, catalog, [test])["synthetic::exact"]
    assert found.passed and found.complete and len(found.calls) == 3, (found.passed, found.complete, found.calls)


def test_checks_are_relaxed_only_inside_and_in_their_own_thread():
    made = []

    def hint():
        made.append(1)
        return "the hint"

    expect(True, "passes", hint)
    expect_close([1.0], [1.0], 0.0, "passes", hint)
    assert not made, "a passing check made its hint"
    with pytest.raises(Wrong) as failed:
        expect_close([1.0], [2.0], 0.5, "fails", hint)
    assert failed.value.hint == "the hint" and made == [1]
    raised = []
    with checks_not_enforced():
        expect(False, "relaxed")
        expect_close([1.0, 2.0], [1.0], 0.0, "relaxed: shapes differ")

        def elsewhere():
            try:
                expect(False, "another thread")
            except Wrong:
                raised.append(True)

        other = threading.Thread(target=elsewhere)
        other.start()
        other.join()
    assert raised == [True], "another thread's checks were relaxed"
    with pytest.raises(Wrong):
        expect(False, "enforced again")
