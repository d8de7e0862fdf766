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
finding. Flagged pairs are
joined into clusters (connected components over all exercises).

Examples
--------
>>> findings = find_similar(answers, references, stubs)          # doctest: +SKIP
>>> [(c.members, c.exercises) for c in findings.clusters]
[(('ana', 'bo'), ('rot_z', 'quat_multiply'))]
"""

from dataclasses import dataclass, field

import numpy as np

from autograder.similarity.fingerprints import fingerprint_many, shared_share

MIN_LENGTH = 40  # normalised characters of an answer outside the stub (a name counts as one)
PAIR_FLOOR = 0.7  # a pair below this share is never flagged, however unusual for its exercise
SPREAD = 4.0  # robust z-score above the exercise's median pair score
MIN_ANSWERS_FOR_SPREAD = 12  # fewer answers than this: the floor alone
REFERENCE_FLOOR = 0.8  # share of the published solution that makes a reference match
REFERENCE = "reference solution"


@dataclass(frozen=True)
class Pair:
    """Two answers to ``exercise`` with ``score`` (0..1) at or above the exercise's ``threshold``."""

    exercise: str
    first: str
    second: str
    score: float
    threshold: float


@dataclass(frozen=True)
class Cluster:
    """Students linked by flagged pairs: ``members`` (sorted), the ``exercises`` spanned, its ``pairs``."""

    members: tuple
    exercises: tuple
    pairs: tuple

    @property
    def score(self):
        return max(pair.score for pair in self.pairs)


@dataclass
class Findings:
    clusters: list = field(default_factory=list)  # Cluster, strongest first
    reference_matches: list = field(default_factory=list)  # Pair with second == REFERENCE
    thresholds: dict = field(default_factory=dict)  # exercise -> pair threshold in this class
    compared: dict = field(default_factory=dict)  # exercise -> answers long enough to compare
    fingerprints: dict = field(default_factory=dict)  # (exercise, author) -> CodeFingerprint, for the views
    unread: dict = field(default_factory=dict)  # author -> why their folder could not be read


def pair_threshold(scores, answers):
    """``max(PAIR_FLOOR, median + SPREAD · 1.4826 · MAD)`` of an exercise's pair ``scores`` among ``answers``
    answers (the floor alone below :data:`MIN_ANSWERS_FOR_SPREAD`)."""
    scores = np.asarray(scores, dtype=float)
    if scores.size == 0 or answers < MIN_ANSWERS_FOR_SPREAD:
        return PAIR_FLOOR
    median = float(np.median(scores))
    mad = float(np.median(np.abs(scores - median)))
    return max(PAIR_FLOOR, median + SPREAD * 1.4826 * mad)


def _long_enough(fp):
    return fp.token_coverage >= MIN_LENGTH


def _exercise_pairs(exercise, current, prints, reference_fp, findings):
    """Score one exercise's answers (``prints``: ``{author: fingerprint}``, current and past); add its reference
    matches to ``findings``; return its flagged pairs."""
    authors = [author for author, fp in prints.items() if _long_enough(fp)]
    prints = [prints[author] for author in authors]
    findings.fingerprints.update(((exercise, author), fp) for author, fp in zip(authors, prints))
    is_current = np.array([author in current for author in authors], dtype=bool)
    findings.compared[exercise] = int(is_current.sum())
    matches_reference = np.zeros(len(authors), dtype=bool)
    reference_scores = np.zeros(len(authors))
    if reference_fp is not None:
        if _long_enough(reference_fp):
            findings.fingerprints[exercise, REFERENCE] = reference_fp
            reference_scores = shared_share(prints + [reference_fp])[-1, :-1]
            matches_reference = reference_scores >= REFERENCE_FLOOR
            findings.reference_matches += [Pair(exercise, authors[i], REFERENCE, float(reference_scores[i]),
                                                REFERENCE_FLOOR)
                                           for i in np.flatnonzero(matches_reference & is_current)]
    if len(authors) < 2:
        findings.thresholds[exercise] = PAIR_FLOOR
        return []
    scores = shared_share(prints)
    first, second = np.triu_indices(len(authors), k=1)
    both_current = is_current[first] & is_current[second]
    explained = scores[first, second] <= np.minimum(reference_scores[first], reference_scores[second])
    baseline = both_current & ~explained
    threshold = pair_threshold(scores[first, second][baseline],
                               len(set(first[baseline]) | set(second[baseline])))
    findings.thresholds[exercise] = threshold
    wanted = (is_current[first] | is_current[second]) & ~explained & (scores[first, second] >= threshold)
    return [Pair(exercise, authors[i], authors[j], float(scores[i, j]), threshold)
            for i, j in zip(first[wanted], second[wanted])]


def clusters_of(pairs):
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
        found.append(Cluster(tuple(members), exercises,
                             tuple(sorted(members_pairs, key=lambda p: -p.score))))
    return sorted(found, key=lambda c: (-len(c.exercises), -c.score, c.members))


def find_similar(current, references, stubs, past=None, unread=None, jobs=1):
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
        Processes that fingerprint the answers.

    Returns
    -------
    Findings
    """
    past = past or {}
    findings = Findings(unread=dict(unread or {}))
    keys, items = [], []
    for exercise in sorted(current):
        stub = stubs.get(exercise, "")
        for author, source in list(current[exercise].items()) + list(past.get(exercise, {}).items()):
            if source.strip() != stub.strip():  # the untouched stub: nothing to compare
                keys.append((exercise, author))
                items.append((source, stub))
        if exercise in references:
            keys.append((exercise, REFERENCE))
            items.append((references[exercise], stub))
    prints = {}
    for (exercise, author), fp in zip(keys, fingerprint_many(items, jobs)):
        prints.setdefault(exercise, {})[author] = fp
    pairs = []
    for exercise in sorted(current):
        found = prints.get(exercise, {})
        reference_fp = found.pop(REFERENCE, None)
        pairs += _exercise_pairs(exercise, current[exercise], found, reference_fp, findings)
    findings.clusters = clusters_of(pairs)
    findings.reference_matches.sort(key=lambda p: (p.first, p.exercise))
    return findings
