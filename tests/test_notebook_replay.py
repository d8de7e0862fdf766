"""The notebook stage's skip path gives the verdicts of its full path (autograder/grading/notebook_calls.py).

Oracle: the same submission graded with the notebook transcripts (a lesson whose recorded calls all return
the reference's values, bit for bit, is ``passed`` without a kernel) and without them (every kernel runs, as
before): the same notebook status, points and failures, lesson by lesson. Cases, on lesson 01's real master:
the reference answers (the skip path is taken); ``rotate_point`` off by one unit in the last place (full
hidden marks, not bit for bit the reference's: the kernel runs); ``rotate_point`` right on its first call
and wrong on every later one (stateful: the replay stops at the second call, the kernel runs and fails);
the demonstration's own point raising (the walls test's flaw: the replay's call fails, the kernel runs).
Lesson 06's master passes its own functions to the student's ``numerical_jacobian`` (callbacks, some of which
call the student's ``boxplus_right`` in turn): the reference (replayed, its callbacks answered from the notes);
central differences (correct, other callbacks: the kernel runs); one evaluation more than the reference's (the
kernel runs); ``boxplus_right`` one unit in the last place off only on the steps a Jacobian takes (its calls
from inside a callback differ, the master's own calls do not: the kernel runs).
"""

import json

import pytest

from autograder.grading import nbval_stage, notebook_calls
from autograder.grading.options import GradingOptions
from autograder.sandbox import launcher
from support import THIS_COURSE, build_submission, grade, references

pytestmark = pytest.mark.skipif(launcher.isolation()[0] != "namespaces", reason="needs the namespace sandbox")

BODY = "    R_wb = np.asarray(R_wb, dtype=float)"


def _rotate_point(prefix, replacement):
    source = references()["rotate_point"]
    changed = source.replace(BODY, replacement + BODY, 1)
    assert changed != source
    return prefix + changed


ONE_ULP = _rotate_point(
    "",
    "    if np.asarray(p_b).ndim == 1:\n"
    "        out = np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float).T\n"
    "        return np.nextafter(out, np.inf)\n",
)
FIRST_CALL_ONLY = _rotate_point(
    "_CALLS = [0]\n\n",
    "    _CALLS[0] += 1\n    if _CALLS[0] > 1:\n        return np.asarray(p_b, dtype=float) * 2.0\n",
)
DEMONSTRATION_RAISES = _rotate_point(
    "",
    "    if np.array_equal(np.asarray(p_b, dtype=float), [0.5, 0.3, 2.0]):\n"
    '        raise RuntimeError("only on the demonstration\'s point")\n',
)
CASES = {"reference": None, "one_ulp": ONE_ULP, "first_call_only": FIRST_CALL_ONLY, "raises": DEMONSTRATION_RAISES}

JACOBIAN_HEAD = "def numerical_jacobian(f, x, boxplus=None):\n"
CENTRAL_DIFFERENCES = JACOBIAN_HEAD + (
    "    h = 1e-6\n"
    "    move = boxplus if boxplus is not None else (lambda x, d: np.asarray(x, dtype=float) + d)\n"
    "    n = 3 if boxplus is not None else np.asarray(x).size\n"
    "    columns = []\n"
    "    for j in range(n):\n"
    "        d = np.zeros(n)\n"
    "        d[j] = h\n"
    "        ahead = np.atleast_1d(np.asarray(f(move(x, d)), dtype=float))\n"
    "        behind = np.atleast_1d(np.asarray(f(move(x, -d)), dtype=float))\n"
    "        columns.append((ahead - behind) / (2 * h))\n"
    "    return np.column_stack(columns)\n"
)
CALLBACK_CASES = {
    "reference": {},
    "central_differences": {"numerical_jacobian": CENTRAL_DIFFERENCES},
    "one_more_evaluation": {
        "numerical_jacobian": lambda source: source.replace(
            "    f0 = np.atleast_1d(", "    f(x)  # looked at once more, then thrown away\n    f0 = np.atleast_1d(", 1
        )
    },
    "off_only_on_a_jacobian_step": {
        "boxplus_right": lambda source: source.replace(
            "    return np.asarray(R, dtype=float) @ Exp(d)",
            "    moved = np.asarray(R, dtype=float) @ Exp(d)\n"
            "    if np.count_nonzero(d) == 1 and np.abs(d).max() == 1e-6:\n"
            "        return np.nextafter(moved, np.inf)\n"
            "    return moved",
            1,
        )
    },
}


@pytest.fixture(scope="module")
def transcripts():
    learned = nbval_stage.record_notebook_calls(THIS_COURSE, GradingOptions(), lessons=("01",))
    assert learned.get("01") is not None and learned["01"].calls, "lesson 01's master should be replayable"
    return learned


def _notebook_verdicts(result):
    return {
        lesson.number: (lesson.run.status, lesson.run.points, tuple(lesson.run.failures))
        for lesson in result.lessons
        if lesson.run is not None
    }


def _graded_both_ways(monkeypatch, folder, lesson):
    """``(with the transcripts, with every kernel run, what each replay returned)`` for one submission's lesson."""
    replayed = []
    original = notebook_calls.replays_as_recorded

    def spy(box, transcript):
        replayed.append(original(box, transcript))
        return replayed[-1]

    monkeypatch.setattr(notebook_calls, "replays_as_recorded", spy)
    with_skip = grade(folder, lessons=(lesson,), nbval=True)
    monkeypatch.setitem(THIS_COURSE.reference.memo, notebook_calls.MEMO_KEY, {})  # the old path: every kernel runs
    full = grade(folder, lessons=(lesson,), nbval=True)
    return with_skip, full, replayed


@pytest.mark.parametrize("case", list(CASES))
def test_the_skip_path_gives_the_full_paths_verdicts(tmp_path, monkeypatch, transcripts, case):
    overrides = {"rotate_point": CASES[case]} if CASES[case] else {}
    folder = build_submission(tmp_path / case, overrides, lessons=("01",))
    with_skip, full, replayed = _graded_both_ways(monkeypatch, folder, "01")

    assert _notebook_verdicts(with_skip) == _notebook_verdicts(full)
    assert with_skip.score == full.score
    full_hidden = nbval_stage.full_hidden_marks(full.lessons[0])
    if case == "reference":
        assert replayed == [True], "the reference's calls return the reference's values: no kernel"
        assert _notebook_verdicts(full)["01"][0] == "passed"
    elif case == "one_ulp":  # within every tolerance, not bit for bit: the kernel decides
        assert full_hidden and replayed == [False]
    elif case == "first_call_only":
        assert replayed == ([False] if full_hidden else []) and _notebook_verdicts(full)["01"][0] != "passed"
    else:
        assert _notebook_verdicts(full)["01"][0] != "passed"


@pytest.fixture(scope="module")
def transcripts_06():
    learned = nbval_stage.record_notebook_calls(THIS_COURSE, GradingOptions(), lessons=("06",))
    transcript = learned.get("06")
    assert transcript is not None and any(transcript.exchanges), "lesson 06's master should be replayable"
    assert any(inner for exchanges in transcript.exchanges for *_, inner in exchanges), "and call back in turn"
    return learned


@pytest.mark.parametrize("case", list(CALLBACK_CASES))
def test_callbacks_are_replayed_only_when_called_as_the_reference_did(tmp_path, monkeypatch, transcripts_06, case):
    overrides = {
        name: change(references()[name]) if callable(change) else change
        for name, change in CALLBACK_CASES[case].items()
    }
    folder = build_submission(tmp_path / case, overrides, lessons=("06",))
    with_skip, full, replayed = _graded_both_ways(monkeypatch, folder, "06")

    assert _notebook_verdicts(with_skip) == _notebook_verdicts(full)
    assert with_skip.score == full.score
    assert nbval_stage.full_hidden_marks(full.lessons[0]), "each case is a correct answer: the replay is tried"
    assert replayed == [case == "reference"]


def test_a_master_that_differs_between_runs_or_calls_back_unnoted_gets_no_transcript():
    call = '{"__dict__":[["lesson","01"],["name","f"],["args",[1.0]],["kwargs",{"__dict__":[]}],["timeout",5.0]]}'
    entry = {"lesson": "01", "call": call, "ok": True, "text": "2.0", "callbacks": 0}
    assert notebook_calls.transcript_from([[entry], [dict(entry)]]).results == ["2.0"]
    assert notebook_calls.transcript_from([[entry], [dict(entry, text="2.0000000000000004")]]) is None
    assert notebook_calls.transcript_from([[dict(entry, callbacks=1)]] * 2) is None  # callbacks, none noted
    assert notebook_calls.transcript_from([[dict(entry, callbacks=1, exchanges=None)]] * 2) is None  # not notable
    noted = [[0, "[2.0]", '{"__dict__":[]}', {"ok": True, "text": "4.0"}, [[call, "2.0"]]]]
    assert notebook_calls.transcript_from([[dict(entry, callbacks=1, exchanges=noted)]] * 2).exchanges == [noted]
    assert notebook_calls.transcript_from([[dict(entry, callbacks=1, exchanges=[noted[0][:4]])]] * 2) is None
    assert notebook_calls.transcript_from([[dict(entry, ok=False, text=None)]] * 2) is None
    assert notebook_calls.transcript_from([[entry], None]) is None


def test_a_lesson_whose_notes_are_damaged_or_too_long_alone_loses_its_transcript(tmp_path):
    call = '{"__dict__":[["lesson","01"],["name","f"],["args",[1.0]],["kwargs",{"__dict__":[]}],["timeout",5.0]]}'
    entry = {"lesson": "01", "call": call, "ok": True, "text": "2.0", "callbacks": 0}
    prefix = tmp_path / notebook_calls.RECORD_PREFIX
    (tmp_path / f"{prefix.name}-01.jsonl").write_text(json.dumps(entry) + "\n")
    (tmp_path / f"{prefix.name}-03.jsonl").write_text(json.dumps(dict(entry, lesson="03"))[:40])  # cut by a full disk
    (tmp_path / f"{prefix.name}-04.jsonl").write_text(json.dumps({"lesson": "04", "overflow": True}) + "\n")
    records = notebook_calls.read_records(tmp_path)
    by_lesson = {n: [r for r in records if r.get("lesson") == n] for n in ("01", "03", "04")}
    assert notebook_calls.transcript_from([by_lesson["01"]] * 2).results == ["2.0"]
    assert notebook_calls.transcript_from([by_lesson["03"]] * 2) is None
    assert notebook_calls.transcript_from([by_lesson["04"]] * 2) is None


def test_every_master_is_replayable():
    """The course's own masters, all lessons recorded in one run as a class run records them: each lesson's
    notes stay within its budget and every callback is noted (02 and 06 pass functions), so no lesson needs a
    kernel for a student whose functions return the reference's values."""
    learned = nbval_stage.record_notebook_calls(THIS_COURSE, GradingOptions())
    not_replayable = {number for number, transcript in learned.items() if transcript is None}
    assert not_replayable == set()
