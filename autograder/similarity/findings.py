"""Which answers are worth a look: pairs far above their exercise's own distribution, in clusters.

For each exercise, every pair of this class's answers, every answer against the
reference solution and every answer against each past-term answer is scored
(:func:`~autograder.similarity.fingerprints.shared_share`). Answers shorter
than :data:`MIN_LENGTH` normalised characters outside the stub are left out
(everybody writes ``return R.T``). A pair of students is flagged when its score
is at least ``max(PAIR_FLOOR, median + SPREAD · 1.4826 · MAD)`` of that
exercise's pair scores in this class, so an exercise whose answers all look
alike (short, one obvious formula) raises its own bar; with fewer than
:data:`MIN_ANSWERS_FOR_SPREAD` answers the distribution says too little (five
copies among seven answers would be its median) and the floor alone is used. An answer is a reference
match when it shares at least :data:`REFERENCE_FLOOR` with the published
solution: that bar is absolute, since copying the reference is the same
finding however many students did it. A pair that shares no more with each
other than each of them shares with the reference (two students who both
started from the published solution) is explained by it and is not a pair
finding. Nor is a pair whose shared code is shorter than :data:`MIN_SHARED`
fingerprints (about two statements), however large a share of a short answer
that is: two students who both write the textbook one-line SVD of
``align_svd`` share that line and little else, and one line cannot tell a copy
from the lecture's idiom. Flagged pairs are joined into clusters (connected
components over all exercises).

Examples
--------
>>> findings = find_similar(answers, references, stubs)          # doctest: +SKIP
>>> [(c.members, c.exercises) for c in findings.clusters]
[(('ana', 'bo'), ('rot_z', 'quat_multiply'))]
"""

from __future__ import annotations

import multiprocessing
from dataclasses import dataclass, field

import numpy as np
from copydetect import CodeFingerprint

from autograder.similarity.fingerprints import fingerprint, longest_coverage, share_of_smaller, shared_counts

MIN_LENGTH = 40  # normalised characters of an answer outside the stub (a name counts as one)
PAIR_FLOOR = 0.7  # a pair below this share is never flagged, however unusual for its exercise
SPREAD = 4.0  # robust z-score above the exercise's median pair score
MIN_ANSWERS_FOR_SPREAD = 12  # fewer answers than this: the floor alone
REFERENCE_FLOOR = 0.8  # share of the published solution that makes a reference match
MIN_SHARED = 60  # fingerprints (12-character k-grams of normalised code) a flagged pair shares at least
REFERENCE = "reference solution"
MIN_ANSWERS_FOR_WORKERS = 400  # fewer answers in a class: forking costs more than it saves


@dataclass(frozen=True)
class Pair:
    """Two answers to ``exercise`` with ``score`` (0..1) at or above the exercise's ``threshold``; ``shared``:
    the fingerprints they have in common."""

    exercise: str
    first: str
    second: str
    score: float
    threshold: float
    shared: int = 0


@dataclass(frozen=True)
class Cluster:
    """Students linked by flagged pairs: ``members`` (sorted), the ``exercises`` spanned, its ``pairs``."""

    members: tuple
    exercises: tuple
    pairs: tuple

    @property
    def score(self) -> float:
        return max(pair.score for pair in self.pairs)


@dataclass
class Findings:
    clusters: list = field(default_factory=list)  # Cluster, strongest first
    reference_matches: list = field(default_factory=list)  # Pair with second == REFERENCE
    thresholds: dict = field(default_factory=dict)  # exercise -> pair threshold in this class
    compared: dict = field(default_factory=dict)  # exercise -> answers long enough to compare
    sources: dict = field(default_factory=dict)  # (exercise, author) -> (answer, stub), for the views
    unread: dict = field(default_factory=dict)  # author -> why their folder could not be read

    def fingerprint(self, exercise: str, author: str) -> CodeFingerprint | None:
        """The fingerprint of ``author``'s answer to ``exercise`` (made here, for a side-by-side view), or None."""
        if (exercise, author) not in self.sources:
            return None
        return fingerprint(*self.sources[exercise, author])


def pair_threshold(scores: list[float] | np.ndarray, answers: int) -> float:
    """``max(PAIR_FLOOR, median + SPREAD · 1.4826 · MAD)`` of an exercise's pair ``scores`` among ``answers``
    answers (the floor alone below :data:`MIN_ANSWERS_FOR_SPREAD`)."""
    scores = np.asarray(scores, dtype=float)
    if scores.size == 0 or answers < MIN_ANSWERS_FOR_SPREAD:
        return PAIR_FLOOR
    median = float(np.median(scores))
    mad = float(np.median(np.abs(scores - median)))
    return max(PAIR_FLOOR, median + SPREAD * 1.4826 * mad)


@dataclass
class ExerciseFindings:
    """What one exercise contributes: its flagged ``pairs``, ``reference_matches``, ``threshold``, and how
    many of this class's answers were ``compared``."""

    pairs: list
    reference_matches: list
    threshold: float
    compared: int


def distinct_fingerprints(sources: list[str], stub: str) -> tuple[list[CodeFingerprint], list[int]]:
    """``(prints, index)``: one fingerprint per distinct text of ``sources`` long enough to compare, and for
    each source the position of its fingerprint in ``prints`` (-1: the untouched stub or too short).

    Many students hand in the same text; each text is tokenised once, and a text whose characters outside
    whitespace are fewer than :data:`MIN_LENGTH` is never tokenised (see
    :func:`~autograder.similarity.fingerprints.longest_coverage`).

    >>> prints, index = distinct_fingerprints(["def f(x):\\n    return x.T\\n"] * 2, "")
    >>> prints, index
    ([], [-1, -1])
    """
    position, prints, index = {}, [], []
    for source in sources:
        if source not in position:
            position[source] = -1
            if source.strip() != stub.strip() and longest_coverage(source, stub) >= MIN_LENGTH:
                fp = fingerprint(source, stub)
                if fp.token_coverage >= MIN_LENGTH:
                    position[source] = len(prints)
                    prints.append(fp)
        index.append(position[source])
    return prints, index


def score_exercise(
    exercise: str, current: dict[str, str], past: dict[str, str], reference: str | None, stub: str
) -> ExerciseFindings:
    """The :class:`ExerciseFindings` of one exercise, in one pass.

    ``current`` and ``past``: ``{author: source}`` of this class and of past terms; ``reference``: the
    published answer (or None); ``stub``: the released cell. Every distinct long-enough text is
    fingerprinted once, and one sparse product scores every pair of texts and every text against the
    reference (:func:`~autograder.similarity.fingerprints.shared_share`).
    """
    authors = list(current) + [author for author in past if author not in current]
    sources = [current[a] if a in current else past[a] for a in authors]
    has_reference = reference is not None
    prints, index = distinct_fingerprints(sources + ([reference] if has_reference else []), stub)
    kept = [i for i, at in enumerate(index[: len(authors)]) if at >= 0]
    authors, rows = [authors[i] for i in kept], np.array([index[i] for i in kept], dtype=int)
    reference_row = index[-1] if has_reference else -1
    is_current = np.array([author in current for author in authors], dtype=bool)
    compared = int(is_current.sum())
    counts, sizes = shared_counts(prints) if prints else (np.zeros((0, 0), dtype=int), np.zeros(0, dtype=int))
    distinct = share_of_smaller(counts, sizes)
    reference_scores = distinct[rows, reference_row] if reference_row >= 0 else np.zeros(len(authors))
    matches_reference = reference_scores >= REFERENCE_FLOOR
    reference_matches = [
        Pair(
            exercise,
            authors[i],
            REFERENCE,
            float(reference_scores[i]),
            REFERENCE_FLOOR,
            int(counts[rows[i], reference_row]),
        )
        for i in np.flatnonzero(matches_reference & is_current)
    ]
    if len(authors) < 2:
        return ExerciseFindings([], reference_matches, PAIR_FLOOR, compared)
    first, second = np.triu_indices(len(authors), k=1)
    scores, shared = distinct[rows[first], rows[second]], counts[rows[first], rows[second]]
    both_current = is_current[first] & is_current[second]
    explained = scores <= np.minimum(reference_scores[first], reference_scores[second])
    baseline = both_current & ~explained
    threshold = pair_threshold(scores[baseline], len(set(first[baseline]) | set(second[baseline])))
    wanted = (is_current[first] | is_current[second]) & ~explained & (scores >= threshold) & (shared >= MIN_SHARED)
    pairs = [
        Pair(exercise, authors[i], authors[j], float(score), threshold, int(common))
        for i, j, score, common in zip(first[wanted], second[wanted], scores[wanted], shared[wanted])
    ]
    return ExerciseFindings(pairs, reference_matches, threshold, compared)


def _score_task(task):
    return score_exercise(*task)


def _scored(tasks, jobs):
    """``[score_exercise(*task) for task in tasks]``, the exercises shared among ``jobs`` forked processes
    (each returns only its pairs and numbers; the fingerprints stay in the worker)."""
    answers = sum(len(task[1]) + len(task[2]) for task in tasks)
    if (
        jobs <= 1
        or len(tasks) < 2
        or answers < MIN_ANSWERS_FOR_WORKERS
        or "fork" not in multiprocessing.get_all_start_methods()
    ):
        return [score_exercise(*task) for task in tasks]
    biggest_first = sorted(range(len(tasks)), key=lambda i: -(len(tasks[i][1]) + len(tasks[i][2])))
    with multiprocessing.get_context("fork").Pool(min(jobs, len(tasks))) as pool:
        done = pool.map(_score_task, [tasks[i] for i in biggest_first], chunksize=1)
    results = [None] * len(tasks)
    for i, result in zip(biggest_first, done):
        results[i] = result
    return results


def clusters_of(pairs: list[Pair]) -> list[Cluster]:
    """Connected components of the flagged ``pairs``, strongest first."""
    parent = {}

    def root(author):
        parent.setdefault(author, author)
        while parent[author] != author:
            parent[author] = parent[parent[author]]
            author = parent[author]
        return author

    for pair in pairs:
        parent[root(pair.first)] = root(pair.second)
    groups = {}
    for pair in pairs:
        groups.setdefault(root(pair.first), []).append(pair)
    found = []
    for members_pairs in groups.values():
        members = sorted({a for p in members_pairs for a in (p.first, p.second)})
        exercises = tuple(dict.fromkeys(p.exercise for p in members_pairs))
        found.append(Cluster(tuple(members), exercises, tuple(sorted(members_pairs, key=lambda p: -p.score))))
    return sorted(found, key=lambda c: (-len(c.exercises), -c.score, c.members))


def find_similar(
    current: dict[str, dict[str, str]],
    references: dict[str, str],
    stubs: dict[str, str],
    past: dict[str, dict[str, str]] | None = None,
    unread: dict[str, str] | None = None,
    jobs: int = 1,
) -> Findings:
    """The findings of a class.

    Parameters
    ----------
    current : dict
        ``{exercise: {student: answer source}}`` of this class.
    references : dict
        ``{exercise: reference answer source}``.
    stubs : dict
        ``{exercise: released stub source}`` (boilerplate).
    past : dict, optional
        ``{exercise: {author: source}}`` of past terms (authors named apart from this class's).
    unread : dict, optional
        ``{author: why}`` for the folders that could not be read.
    jobs : int
        Processes that score the exercises (each fingerprints and scores its own answers).

    Returns
    -------
    Findings
    """
    past = past or {}
    findings = Findings(unread=dict(unread or {}))
    exercises = sorted(current)
    tasks = [
        (exercise, current[exercise], past.get(exercise, {}), references.get(exercise), stubs.get(exercise, ""))
        for exercise in exercises
    ]
    pairs = []
    for (exercise, answers, earlier, reference, stub), found in zip(tasks, _scored(tasks, jobs)):
        findings.thresholds[exercise] = found.threshold
        findings.compared[exercise] = found.compared
        findings.reference_matches += found.reference_matches
        pairs += found.pairs
        for pair in found.pairs + found.reference_matches:
            for author in (pair.first, pair.second):
                text = reference if author == REFERENCE else answers.get(author, earlier.get(author))
                findings.sources[exercise, author] = (text, stub)
    findings.clusters = clusters_of(pairs)
    findings.reference_matches.sort(key=lambda p: (p.first, p.exercise))
    return findings
