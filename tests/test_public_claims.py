"""Every ✓ line of a public check is a claim some typical mistake violates (issue #43, item 3).

A public check that no mistake of the corpus ever fails proves nothing: a student
reads its ✓ as "this part is right", but no wrong answer we know of is told
otherwise. Each registered line (``coursekit.checking.public_check(exercise,
description)``) must therefore print ✗ for at least one
:class:`~autograder.mistakes.Mistake` of its exercise, run in process through the
lesson's check cell (:func:`autograder.mutants.inprocess.run_public_checks`).

The module fixture runs every mistake's public checks once (a few seconds for the
whole corpus); the failure message lists the lines no mistake fails, with their
exercise, so the fix is a typical mistake that breaks exactly that claim
(``autograder/mistakes/lessonNN*.py``).
"""

import time
import warnings
from collections import defaultdict

import pytest

from autograder.mistakes import all_mistakes
from public_runner import run_public_checks
from support import THIS_COURSE

# (exercise, description) -> why no typical mistake fails this line yet. Keep it short: a line listed here is a
# ✓ that proves nothing about the answers we know of. "open:" marks a line that wants a mistake the corpus rules
# (tests/test_mutations.py) do not let in yet, and says what is missing.
EXEMPT: dict[tuple[str, str], str] = {
    ("unit_vector", "returns a vector of length 1"): "lesson 00's practice exercise: ungraded, no hidden suite, "
    "so no mistake can lose points on it",
    ("unit_vector", "keeps the direction of the input"): "lesson 00's practice exercise: ungraded, no hidden suite, "
    "so no mistake can lose points on it",
    ("euler_rates_matrix_world", "accepts integers and NumPy scalars alike"): "np.cos and np.sin turn every angle "
    "type the docstring admits into a float64: no plausible answer depends on the type (a guard for float32 math)",
    ("filter_predict", "no gyro noise and no turn: the covariance is carried unchanged"): "every propagation "
    "F P Fᵀ + G Q Gᵀ with F = I at ω = 0 returns P when Q = 0, right or wrong; only noise added from nothing "
    "fails it, and the line's job is to say so to such an answer",
}

SECONDS = 150.0  # the whole corpus (about 390 mistakes), in process: 55-65 s on two shared cores


def _registry():
    THIS_COURSE.use_support_package()
    from coursekit import checking

    checking.registered_exercises()  # imports coursekit.checks: fills the registry
    return {exercise: [description for description, _ in checks] for exercise, checks in checking._REGISTRY.items()}


@pytest.fixture(scope="module")
def failed_lines():
    """``{(exercise, description): [mistakes that print ✗ on it]}`` over the corpus, and the seconds it took."""
    registry = _registry()
    found = defaultdict(list)
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the mistakes' own 0/0 and arccos(1 + ε)
        for name, mistake in sorted(all_mistakes().items()):
            if mistake.kind != "mistake" or mistake.exercise not in registry:
                continue  # a "fault" crashes, hangs or exits: it claims nothing about a line (and may end this process)
            _, printed = run_public_checks(THIS_COURSE, mistake.exercise, mistake.source)
            for description in registry[mistake.exercise]:
                if f"✗ {description}:" in printed:
                    found[(mistake.exercise, description)].append(name)
    return registry, found, time.perf_counter() - start


def test_every_public_line_is_failed_by_some_mistake(failed_lines):
    registry, found, _ = failed_lines
    unclaimed = [
        f"  {exercise}: {description}"
        for exercise, descriptions in sorted(registry.items())
        for description in descriptions
        if (exercise, description) not in found and (exercise, description) not in EXEMPT
    ]
    assert not unclaimed, (
        f"{len(unclaimed)} public check lines that no typical mistake fails (add a mistake that breaks each, "
        "in autograder/mistakes/lessonNN*.py, or an exemption with its reason):\n" + "\n".join(unclaimed)
    )


def test_exemptions_are_registered_and_still_needed(failed_lines):
    registry, found, _ = failed_lines
    unknown = [key for key in EXEMPT if key[1] not in registry.get(key[0], [])]
    assert not unknown, f"exempt lines that no public check registers: {unknown}"
    claimed = {key: found[key] for key in EXEMPT if key in found}
    assert not claimed, f"exempt lines that a mistake now fails (drop the exemption): {claimed}"
    assert all(reason.strip() for reason in EXEMPT.values()), "every exemption states its reason"


def test_the_corpus_runs_fast(failed_lines):
    *_, seconds = failed_lines
    assert seconds < SECONDS, f"the corpus's public checks took {seconds:.1f} s (at most {SECONDS:g} s)"
