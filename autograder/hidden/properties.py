"""Property-based checks for the hidden suite: inputs over the whole domain, the same calls on every run.

:func:`for_all` runs a check on values drawn by Hypothesis from a strategy,
plus explicit edge cases that every run tries first. Hypothesis runs
derandomized (its random stream comes from the check's code, not the clock),
with no example database, no deadline and no health checks (they time the
run), and a bounded number of examples: a hidden test stays a deterministic
function of what its calls return, as the grader's replay needs
(``autograder/grading/transcripts.py``). When a check fails, Hypothesis shrinks
the input and :func:`for_all` re-raises the failure of the simplest failing
input, so the hint names it ("off by 3.1e-08 at θ = 0.0046").

The strategies cover what the exercises' docstrings allow:

- :func:`angles`: magnitudes log-uniform from 1e-12 to π (every decade is
  hit), both signs, exactly 0, and within 1e-9 … 1e-3 of π from both sides;
- :func:`rotation_vectors`: a random axis times such an angle;
- :func:`quaternions`: unit quaternions from both hemispheres (w < 0 too), and
  with near-unit norms (1 ± 1e-6) where the exercise normalises;
- :func:`pitches`: pitch angles anywhere in [-π/2, π/2], at ±π/2 and within
  1e-12 … 1e-3 of the gimbal lock, from both sides;
- :func:`as_given`: an array, a plain list, or a list of integers when the
  values are integers (so "accepts lists" is part of every property);
- :func:`batches`: N points as rows, N = 1 and 3 (a (3, 3) batch must be read
  as rows) and 7.

Examples
--------
>>> def check(theta):
...     assert abs(np.sin(theta) - theta) <= theta ** 3   # sin θ ≈ θ to third order
>>> for_all(angles(low=1e-12), check)
"""

import contextlib
import math

import numpy as np
from hypothesis import HealthCheck, Phase, example, given, settings
from hypothesis import strategies as st

try:
    from hypothesis.internal.conjecture import providers as _providers
except ImportError:  # an older Hypothesis, which has no local constants to turn off
    _providers = None

from autograder.grading.hidden_api import fail

EXAMPLES = 24  # drawn values per property, after the explicit ones (which hit every decade already)
SETTINGS = dict(
    derandomize=True,
    database=None,
    deadline=None,
    suppress_health_check=list(HealthCheck),
    phases=(Phase.explicit, Phase.generate, Phase.shrink),
    report_multiple_bugs=False,
    print_blob=False,
)
DECADES = tuple(10.0**-k for k in range(12, -1, -1))  # 1e-12 … 1


def for_all(strategy, check, examples=EXAMPLES, explicit=()):
    """Run ``check(value)`` for the ``explicit`` values, then for ``examples`` values drawn from ``strategy``.

    A failure (any exception: :class:`Wrong`, a student's error) is shrunk by
    Hypothesis to its simplest input and raised as it was raised for that input.
    """

    @settings(max_examples=examples, **SETTINGS)
    @given(strategy)
    def run(value):
        check(value)

    for value in reversed(list(explicit)):
        run = example(value)(run)
    try:
        with _no_local_constants():
            run()
    except BaseException as error:
        notes = getattr(error, "__notes__", None)
        if notes is not None:
            error.__notes__ = []  # Hypothesis's "Falsifying example" report: the reason already says it
        raise


@contextlib.contextmanager
def _no_local_constants():
    """Hypothesis without its "local constants" while a property runs.

    Hypothesis 6.131 and later also draws literals it finds in the project's modules
    loaded at the time. The grader, the test suite and the mutation tool load different
    modules, so the same property would try other inputs in each, and a recording of the
    reference's calls made in one process would not be the calls of another
    (``tests/test_suite_runner.py`` checks it across processes). Only the global constants,
    the same in every process, stay.
    """
    original = getattr(_providers, "_get_local_constants", None)
    if original is None:
        yield
        return
    empty = _providers.Constants()
    _providers.CONSTANTS_CACHE.cache.clear()  # it may hold constants drawn before
    _providers._get_local_constants = lambda: empty
    try:
        yield
    finally:
        _providers._get_local_constants = original
        _providers.CONSTANTS_CACHE.cache.clear()


# ---------------------------------------------------------------- strategies
def _signed(magnitudes, sign):
    return magnitudes.flatmap(lambda m: st.sampled_from([m, -m]) if sign else st.just(m))


def angles(low=1e-12, high=math.pi, sign=True, near_pi=True, zero=True):
    """Angles with magnitudes log-uniform in [low, high], both signs; 0 and just below/above π too."""
    parts = [st.floats(math.log10(low), math.log10(high)).map(lambda e: 10.0**e)]
    if near_pi:
        parts.append(st.floats(-9.0, -3.0).flatmap(lambda e: st.sampled_from([math.pi - 10.0**e, math.pi + 10.0**e])))
    magnitudes = st.one_of(*parts)
    angle = _signed(magnitudes, sign)
    return st.one_of(st.just(0.0), angle) if zero else angle


def unit_vectors():
    """Random unit 3-vectors (any direction; axes and diagonals among them)."""
    special = [
        (1.0, 0.0, 0.0),
        (0.0, 1.0, 0.0),
        (0.0, 0.0, 1.0),
        (0.0, 0.0, -1.0),
        (1.0, 1.0, 1.0),
        (-1.0, 1.0, 0.0),
        (0.6, 0.0, -0.8),
    ]
    raw = st.one_of(
        st.sampled_from(special), st.tuples(*[st.floats(-1.0, 1.0)] * 3).filter(lambda v: sum(x * x for x in v) > 1e-2)
    )
    return raw.map(lambda v: np.asarray(v, dtype=float) / np.linalg.norm(v))


def rotation_vectors(low=1e-12, high=math.pi, **kwargs):
    """θ u for a unit axis u and an angle θ from :func:`angles` (0 included)."""
    return st.tuples(unit_vectors(), angles(low, high, **kwargs)).map(lambda pair: pair[1] * pair[0])


def rotations(**kwargs):
    """Rotation matrices Exp(θ u), θ from :func:`angles` (tiny, generic, near π), built by scipy."""
    from scipy.spatial.transform import Rotation

    return rotation_vectors(**kwargs).map(lambda w: Rotation.from_rotvec(w).as_matrix())


def quaternions(near_unit=False):
    """Unit quaternions ``[w, x, y, z]`` from both hemispheres (scaled by 1 ± 1e-6 when ``near_unit``)."""

    def make(pair):
        (axis, angle), sign = pair
        q = sign * np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])
        return q

    unit = st.tuples(st.tuples(unit_vectors(), angles(sign=False)), st.sampled_from([1.0, -1.0])).map(make)
    if not near_unit:
        return unit
    return st.tuples(unit, st.sampled_from([1.0, 1.0 + 1e-6, 1.0 - 1e-6, 2.0, 0.5])).map(lambda p: p[0] * p[1])


def pitches():
    """Pitch angles in [-π/2, π/2]: generic ones, exactly ±π/2, and within 1e-12 … 1e-3 of ±π/2."""
    half = math.pi / 2
    near = st.tuples(st.floats(-12.0, -3.0), st.sampled_from([1.0, -1.0])).map(lambda p: p[1] * (half - 10.0 ** p[0]))
    return st.one_of(st.floats(-half, half), st.sampled_from([half, -half]), near)


def as_given(value):
    """A strategy giving ``value`` as an array, as a plain list (or nested list), and as integers if exact."""
    array = np.asarray(value, dtype=float)
    forms = [array, array.tolist()]
    if np.all(array == np.round(array)):
        forms.append(array.astype(int).tolist())
    return st.sampled_from(forms)


def given_forms(values):
    """``(value, form)`` pairs: each value of the strategy ``values`` and one of its :func:`as_given` forms."""
    return values.flatmap(lambda value: st.tuples(st.just(value), as_given(value)))


def decade_edges(low=1e-12, high=1.0, factors=(0.97, 0.5)):
    """Angles just below each power of ten from ``high`` down to ``low``: where small-angle thresholds sit,
    so a branch whose series is too short shows its largest error (0.97e-3, 0.5e-3, 0.97e-4, ...)."""
    found = []
    exponent = round(math.log10(high))
    while 10.0**exponent >= low:
        found += [f * 10.0**exponent for f in factors]
        exponent -= 1
    return found


GENERIC_AXIS = np.array([2.0, -1.0, 2.0]) / 3.0


def decade_vectors(axis=GENERIC_AXIS, **kwargs):
    """``(w, w)`` cases for :func:`given_forms` strategies: θ u for the angles of :func:`decade_edges`."""
    return [(t * axis, t * axis) for t in decade_edges(**kwargs)]


def batches(row, sizes=(1, 3, 7)):
    """``(N, k)`` arrays of N rows drawn from ``row`` (a strategy of k-vectors), N in ``sizes``."""
    return st.sampled_from(sizes).flatmap(lambda n: st.lists(row, min_size=n, max_size=n)).map(np.array)


def points(scale=10.0):
    """3-vectors with entries in [-scale, scale] (zero and integers among them)."""
    return st.tuples(*[st.floats(-scale, scale)] * 3).map(lambda v: np.asarray(v, dtype=float))


def worst(got, expected):
    """The largest entrywise difference of two arrays (inf when their shapes differ)."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if got.shape != expected.shape:
        return math.inf
    return float(np.max(np.abs(got - expected))) if got.size else 0.0


def expect_within(got, expected, tol, what, at, hint=""):
    """:class:`Wrong` unless ``got`` matches ``expected`` within ``tol`` (max abs): "off by E at ``at``".

    ``hint`` may be a function of no arguments, called only on a failure (naming a slip costs time that a
    passing answer should not pay for each of a property's examples).
    """
    error = worst(got, expected)
    if not error <= tol:
        fail(f"{what} is off by {error:.2g} at {at} (tolerance {tol:.2g})", hint)


def angle_text(theta):
    """θ for a message: ``"θ = 0.0046"``, ``"θ = 1e-08"``, ``"θ = π - 1e-06"``."""
    theta = float(theta)
    gap = abs(abs(theta) - math.pi)
    if 0 < gap < 1e-2:
        sign = "-" if theta < 0 else ""
        return f"θ = {sign}π {'-' if abs(theta) < math.pi else '+'} {gap:.2g}"
    return f"θ = {theta:.2g}"
