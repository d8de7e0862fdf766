"""The similarity stage on a planted class (every planted finding reported) and an honest one (none).

One module-scoped fixture writes both classes as notebooks (tests/similarity_classes.py) and runs the
real command, ``python -m autograder similarity``, on each; the rest reads its outputs.
"""

import csv
import subprocess
import sys

import pytest

from autograder.lessons.paths import PROJECT_ROOT
from autograder.lessons.reference import answer_sources
from autograder.mistakes import all_mistakes
from autograder.similarity import findings as findings_module
from autograder.similarity.answers import MAX_ANSWER_CHARACTERS, read_class, released_stubs
from autograder.similarity.findings import (
    MIN_LENGTH,
    MIN_SHARED,
    PAIR_FLOOR,
    REFERENCE_FLOOR,
    find_similar,
    pair_threshold,
)
from autograder.similarity.fingerprints import fingerprint, shared_counts
from autograder.similarity.report import similar_answers_html
from similarity_classes import honest_answers, planted_answers, write_class
from support import THIS_COURSE


def _run(folder, out, *past):
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "autograder",
            "similarity",
            str(folder),
            "--out",
            str(out),
            *(["--past", *map(str, past)] if past else []),
        ],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    with open(out / "similar_answers.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return rows, (out / "similar_answers.html").read_text(encoding="utf-8"), result.stdout


@pytest.fixture(scope="module")
def classes(tmp_path_factory):
    root = tmp_path_factory.mktemp("similarity")
    students, planted = planted_answers()
    honest = write_class(root / "honest", honest_answers())
    planted_class = write_class(root / "planted", students)
    return {
        "honest": _run(honest, root / "honest_out"),
        "planted": _run(planted_class, root / "planted_out"),
        "planted findings": planted,
    }


def _findings(rows):
    """``{finding number: (members, exercises)}`` of the student rows; reference rows apart."""
    found = {}
    for row in rows:
        if row["kind"] != "reference":
            members, exercises = found.setdefault(row["finding"], (set(), set()))
            members |= {row["first"], row["second"]}
            exercises.add(row["exercise"])
    return found, {(row["first"], row["exercise"]) for row in rows if row["kind"] == "reference"}


def test_every_planted_finding_is_reported_and_nothing_else(classes):
    rows, _, _ = classes["planted"]
    found, reference = _findings(rows)
    clusters = {(frozenset(members), frozenset(exercises)) for members, exercises in found.values()}
    expected = {(frozenset(m), frozenset(e)) for kind, m, e in classes["planted findings"] if kind == "cluster"}
    assert clusters == expected
    assert reference == {
        (student, exercise) for kind, student, exercise in classes["planted findings"] if kind == "reference"
    }


def test_the_honest_class_has_no_finding(classes):
    rows, html, stdout = classes["honest"]
    assert rows == []
    assert "No pair of students' answers stands out" in html
    assert "nothing was sent anywhere" in stdout


def test_the_page_marks_shared_spans_says_worth_a_look_and_never_copied(classes):
    _, html, _ = classes["planted"]
    assert html.count("<mark>") >= 6 and "worth a look" in html
    assert "copied" not in html.lower() and "no answer was sent anywhere" in html


def test_the_stub_never_counts_and_short_answers_are_not_compared():
    stubs = released_stubs(THIS_COURSE.released)
    answers = {
        "rot_z": {"a": stubs["rot_z"], "b": stubs["rot_z"]},
        "invert_rotation": {
            "a": "def invert_rotation(R):\n    return R.T\n",
            "b": "def invert_rotation(M):\n    return M.T\n",
        },
    }
    findings = find_similar(answers, {}, stubs)
    assert findings.clusters == [] and findings.compared == {"rot_z": 0, "invert_rotation": 0}


def test_a_past_term_answer_is_compared_with_this_class(tmp_path):
    students, _ = planted_answers()
    write_class(tmp_path / "now", {"ana": {"quat_multiply": students["pair_rename"]["quat_multiply"]}})
    write_class(tmp_path / "2025", {"ben": {"quat_multiply": students["pair_rename_source"]["quat_multiply"]}})
    rows, _, _ = _run(tmp_path / "now", tmp_path / "out", tmp_path / "2025")
    assert [(r["kind"], r["first"], r["second"]) for r in rows] in (
        [("past term", "ana", "2025/ben")],
        [("past term", "2025/ben", "ana")],
    )


def test_the_bar_rises_with_an_exercise_whose_answers_all_look_alike():
    alike = [0.8, 0.82, 0.85, 0.8, 0.83, 0.81] * 20
    assert pair_threshold(alike, answers=30) > 0.85 > PAIR_FLOOR
    assert pair_threshold(alike, answers=5) == PAIR_FLOOR


def test_student_text_is_escaped_in_the_section():
    evil = "<script>alert(1)</script>"
    source = planted_answers()[0]["pair_rename"]["quat_multiply"]
    findings = find_similar(
        {"quat_multiply": {evil: source, "b": source + f"\n# {evil}\n"}}, {}, released_stubs(THIS_COURSE.released)
    )
    html = similar_answers_html(findings)
    assert findings.clusters and "<script>" not in html and "&lt;script&gt;" in html


def test_a_huge_answer_costs_no_more_than_a_long_one(tmp_path):
    source = planted_answers()[0]["pair_rename"]["quat_multiply"]
    huge = source + "\n    unused = [" + "1, " * 400_000 + "]\n"  # one line: a notebook's lines are bounded
    write_class(tmp_path / "class", {"ana": {"quat_multiply": huge}, "bo": {"quat_multiply": source}})
    answers = read_class(tmp_path / "class", THIS_COURSE)
    assert len(answers.by_exercise["quat_multiply"]["ana"]) == MAX_ANSWER_CHARACTERS


def _by_exercise(students):
    found = {}
    for student, answers in students.items():
        for exercise, source in answers.items():
            found.setdefault(exercise, {})[student] = source
    return found


def _pairwise(answers, references, stubs):
    """The findings worked out the slow, obvious way: every answer fingerprinted on its own, every pair
    scored by a set intersection in a double loop. ``(flagged pairs, reference matches)`` as sets."""
    flagged, reference_matches = set(), set()
    for exercise, by_author in answers.items():
        stub = stubs.get(exercise, "")
        prints = {a: fingerprint(s, stub) for a, s in by_author.items() if s.strip() != stub.strip()}
        prints = {a: fp for a, fp in prints.items() if fp.token_coverage >= MIN_LENGTH}
        reference = fingerprint(references[exercise], stub) if exercise in references else None

        def share(a, b):
            return len(a.hashes & b.hashes) / min(len(a.hashes), len(b.hashes)), len(a.hashes & b.hashes)

        to_reference = {
            a: share(fp, reference)[0] if reference and reference.token_coverage >= MIN_LENGTH else 0.0
            for a, fp in prints.items()
        }
        reference_matches |= {(exercise, a, round(s, 9)) for a, s in to_reference.items() if s >= REFERENCE_FLOOR}
        authors = list(prints)
        scored = [(a, b, *share(prints[a], prints[b])) for i, a in enumerate(authors) for b in authors[i + 1 :]]
        unexplained = [(a, b, s, n) for a, b, s, n in scored if s > min(to_reference[a], to_reference[b])]
        threshold = pair_threshold([s for _, _, s, _ in unexplained], len({x for p in unexplained for x in p[:2]}))
        flagged |= {(exercise, a, b, round(s, 9)) for a, b, s, n in unexplained if s >= threshold and n >= MIN_SHARED}
    return flagged, reference_matches


def test_one_pass_finds_what_pairwise_scoring_finds(monkeypatch):
    """The fast path (each distinct text tokenised once, short answers skipped before tokenising, one sparse
    product per exercise, exercises in forked workers) finds what scoring every pair by hand finds, on the
    planted class plus students who hand in the same text as another or the untouched stub."""
    students, _ = planted_answers()
    students["twin"] = dict(students["honest1"])  # the same texts as honest1: tokenised once
    students["twin_of_ring"] = dict(students["ring3"])
    students["untouched"] = {
        exercise: source
        for exercise, source in released_stubs(THIS_COURSE.released).items()
        if exercise in students["honest2"]
    }
    answers, references, stubs = (
        _by_exercise(students),
        answer_sources(THIS_COURSE.solutions),
        released_stubs(THIS_COURSE.released),
    )
    monkeypatch.setattr(findings_module, "MIN_ANSWERS_FOR_WORKERS", 0)  # fork even for this small class
    for jobs in (1, 2):
        found = find_similar(answers, references, stubs, jobs=jobs)
        flagged = {(p.exercise, p.first, p.second, round(p.score, 9)) for c in found.clusters for p in c.pairs}
        matches = {(p.exercise, p.first, round(p.score, 9)) for p in found.reference_matches}
        assert (flagged, matches) == _pairwise(answers, references, stubs)
        assert ("adjoint_se3", "honest1", "twin", 1.0) in flagged or ("adjoint_se3", "twin", "honest1", 1.0) in flagged
        assert found.compared["numerical_jacobian"] == len(
            {a for a in answers["numerical_jacobian"] if a != "untouched"}
        )


def test_two_short_standard_answers_are_not_a_finding():
    """Two students who each write the textbook SVD solution of align_svd in two or three lines (one with the
    reflection case forgotten, one with the correlation matrix transposed, as the sample class's dev and
    farid do) share its one long line: most of the shorter answer, and nothing else. One shared line cannot
    tell a copy from the lecture's idiom, so it is not a finding; the same answers with a longer shared
    body are."""
    mistakes = all_mistakes()
    short = {"dev": mistakes["align_svd_transposed"].source, "farid": mistakes["align_svd_reflection"].source}
    stubs = released_stubs(THIS_COURSE.released)
    prints = [fingerprint(source, stubs["align_svd"]) for source in short.values()]
    counts, sizes = shared_counts(prints)
    assert counts[0, 1] / sizes.min() >= PAIR_FLOOR and counts[0, 1] < MIN_SHARED  # alike, but one line
    assert find_similar({"align_svd": short}, answer_sources(THIS_COURSE.solutions), stubs).clusters == []
    longer = {
        author: source
        + "    "
        + "\n    ".join(
            ["check = np.linalg.norm(P @ np.eye(3) - P, axis=1)", "spread = float(np.sum(check ** 2)) + len(Q)"]
        )
        + "\n"
        for author, source in short.items()
    }
    assert [
        c.members for c in find_similar({"align_svd": longer}, answer_sources(THIS_COURSE.solutions), stubs).clusters
    ] == [("dev", "farid")]
