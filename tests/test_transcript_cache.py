"""The reference's transcripts on disk (autograder/grading/transcript_cache.py).

Oracles: a saved transcript loads back field for field; the file's name changes with the
OpenBLAS kernel and with any content the transcripts depend on; a damaged or foreign file is
never used (recording runs again); a process that finds the file records nothing; lessons learned
in a sandbox are learned once, only those asked for, and remembered on disk.
Every test has its own cache folder (``AUTOGRADER_CACHE``).
"""

import pytest

from autograder.grading import fingerprint, suite, transcript_cache
from autograder.grading.transcripts import Transcript
from support import THIS_COURSE


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """An empty cache folder, and the reference's memo of transcripts forgotten (restored after)."""
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    monkeypatch.setattr(THIS_COURSE.reference, "memo", {})
    return tmp_path / "cache"


def _sample():
    return {
        "t::a": Transcript(
            calls=['{"x": 1}'],
            keys=[("01", "rot_z")],
            timeouts=[None],
            results=["0.5"],
            passed=True,
            also_passing=[["0.5000000000000001"]],
            complete=True,
        ),
        "t::b": Transcript(calls=[], keys=[], timeouts=[], results=[], passed=False, complete=False),
    }


def test_a_saved_transcript_loads_back_field_for_field(fresh):
    transcript_cache.save(THIS_COURSE, _sample(), learned={"03", "01"})
    loaded, learned = transcript_cache.load(THIS_COURSE)
    assert loaded == _sample() and learned == {"01", "03"}
    assert loaded["t::a"].keys == [("01", "rot_z")]  # tuples again, as the recorder makes them


def test_the_file_name_follows_the_kernel_and_the_content(fresh, monkeypatch):
    # Whatever the environment holds (.ci/run sets OPENBLAS_CORETYPE=Prescott, a machine may set Haswell):
    # monkeypatch puts the variables back as they were, set or unset.
    monkeypatch.delenv("OPENBLAS_L2_SIZE", raising=False)
    monkeypatch.delenv("OPENBLAS_CORETYPE", raising=False)
    unset = transcript_cache.path(THIS_COURSE)
    names = {unset}
    for kernel in ("Prescott", "Haswell"):
        monkeypatch.setenv("OPENBLAS_CORETYPE", kernel)
        names.add(transcript_cache.path(THIS_COURSE))
    assert len(names) == 3
    monkeypatch.delenv("OPENBLAS_CORETYPE")
    assert transcript_cache.path(THIS_COURSE) == unset
    monkeypatch.setenv("OPENBLAS_CORETYPE", "Prescott")
    first = transcript_cache.path(THIS_COURSE)
    parts = fingerprint.content_parts(THIS_COURSE)
    monkeypatch.setattr(transcript_cache, "content_parts", lambda course: dict(parts, **{"hidden suite": "other"}))
    assert transcript_cache.path(THIS_COURSE) != first


@pytest.mark.parametrize(
    "text",
    [
        "",
        "{not json",
        '{"format": 0, "learned": [], "transcripts": {}}',
        '{"format": 1, "learned": [], "transcripts": {"t": {"calls": 3}}}',
    ],
)
def test_a_damaged_or_foreign_file_is_never_used(fresh, text):
    transcript_cache.path(THIS_COURSE).parent.mkdir(parents=True)
    transcript_cache.path(THIS_COURSE).write_text(text, encoding="utf-8")
    assert transcript_cache.load(THIS_COURSE) is None


def test_a_process_that_finds_the_file_records_nothing(fresh, monkeypatch):
    reference = THIS_COURSE.reference
    recorded = suite.transcripts_for(reference, THIS_COURSE)
    assert transcript_cache.path(THIS_COURSE).exists()
    reference.memo.clear()

    def refuse(*args):
        raise AssertionError("recorded again although the file was there")

    monkeypatch.setattr(suite, "_record_transcripts", refuse)
    assert suite.transcripts_for(reference, THIS_COURSE) == recorded


def test_a_file_for_other_tests_is_recorded_again(fresh, monkeypatch):
    reference = THIS_COURSE.reference
    transcript_cache.save(THIS_COURSE, _sample())  # names tests the suite does not have
    found = suite.transcripts_for(reference, THIS_COURSE)
    assert set(found) == {test.nodeid for test in suite.hidden_tests(THIS_COURSE)[0]}
    assert transcript_cache.load(THIS_COURSE)[0] == found


def test_another_reference_is_never_cached(fresh):
    from types import SimpleNamespace

    reference = THIS_COURSE.reference
    copy = SimpleNamespace(**vars(reference))
    suite.transcripts_for(copy, THIS_COURSE)
    assert not transcript_cache.path(THIS_COURSE).exists()


def test_lessons_are_learned_once_and_only_those_asked_for(fresh, monkeypatch):
    reference = THIS_COURSE.reference
    suite.transcripts_for(reference, THIS_COURSE)  # recorded first: every test runs once in this process
    sent = set()
    real_prefetch = suite.Replay.prefetch

    def prefetch(self, transcript, *rest):
        sent.update(lesson for lesson, _ in transcript.keys)
        return real_prefetch(self, transcript, *rest)

    monkeypatch.setattr(suite.Replay, "prefetch", prefetch)
    suite.learn_reference_in_sandbox(reference, THIS_COURSE, lessons=("02",))
    assert sent == {"02"}  # only lesson 02's calls went to the sandbox
    assert transcript_cache.load(THIS_COURSE)[1] == {"02"}
    reference.memo.clear()

    def no_sandbox(*args, **kwargs):
        raise AssertionError("a learned lesson was run in a sandbox again")

    monkeypatch.setattr(suite, "StudentSandbox", no_sandbox)
    assert suite.learn_reference_in_sandbox(reference, THIS_COURSE, lessons=("02",)) == 0
