"""Public checks for lesson 09, section 7: the capstone, hand_eye_rotation.

Judged by the result only: the angle of the returned X from the truth, on datasets drawn here with fixed seeds
(the hidden checks draw their own), against 4 σ_X, the first-order spread of the best estimate from
the noise and the good pairs (or 1e-9 rad for exact data).
"""

import numpy as np
from scipy.spatial.transform import Rotation

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import rotation_problem
from ..lie import Exp, Log
from .common import require_shape


# Each noisy dataset of these checks, by (seed, pairs, σ, outliers): σ_X, the first-order spread of the best
# estimate from the noise and the good pairs (the lesson's own cell computes it the same way, in the open), and the
# rotation vectors of what two slips return on it (every pair trusted equally; only the first two pairs used). The
# slips' answers are stored as numbers so that the method behind them stays off the student's page;
# tests/test_public_check_constants_lesson09_capstone.py recomputes every figure.
NOISY = {
    (91, 20, 0.01, 4): {
        "spread": 0.00420638853633649,
        "all pairs": [-1.064946304987767, -0.9821483600242517, 2.216448663724497],
        "first two": [2.442707458038484, -1.1144693601964817, -1.3690485450792966],
    },
    (93, 24, 0.01, 6): {
        "spread": 0.003702893735289846,
        "all pairs": [1.7485617280596741, -0.6974159126183733, 1.7093859177797597],
        "first two": [1.5416754079656678, -1.0930803244168175, 1.5884062378060806],
    },
    (98, 12, 0.02, 4): {
        "spread": 0.013178538048457832,
        "all pairs": [-2.3752212694298835, -0.07132958841310943, 1.6193615940706414],
        "first two": [1.7579218400151737, 0.20840779195258843, -1.5264257394879568],
    },
    (92, 30, 0.03, 12): {
        "spread": 0.010050053187149596,
        "all pairs": [1.7294982741728027, 0.9280026906581532, 0.9189845037272131],
        "first two": [1.6007506493898775, 0.3587966772766077, 0.7858681960721587],
    },
}


def _dataset(seed, pairs, sigma, outliers, plane=False):
    """As, Bs (arrays of shape (pairs, 3, 3)), the true X, and the figures of ``NOISY`` (None for exact data)."""
    rng = np.random.default_rng(seed)
    X = Rotation.random(random_state=rng).as_matrix()
    normal = rng.normal(size=3) if plane else None
    Bs, As = [], []
    for _ in range(pairs):
        axis = rng.normal(size=3)
        if plane:  # every turn's axis in one plane: X is still determined
            axis = axis - (axis @ normal) / (normal @ normal) * normal
        B = Exp(rng.uniform(0.3, 2.5) * axis / np.linalg.norm(axis))
        Bs.append(B)
        As.append(X @ B @ X.T @ Exp(sigma * rng.normal(size=3)))
    wrong = rng.choice(pairs, outliers, replace=False)
    for i in wrong:
        As[i] = Rotation.random(random_state=rng).as_matrix()
    figures = NOISY.get((seed, pairs, sigma, outliers)) if sigma > 0 else None
    return np.array(As), np.array(Bs), X, figures


PLANE_HINT = (
    "right when the turn axes point every way, wrong when they all lie in one plane: these exact pairs still "
    "determine X, and the answer must still be a proper rotation"
)


def _answer(hand_eye_rotation, As, Bs):
    X = require_shape(hand_eye_rotation(As, Bs), (3, 3), "hand_eye_rotation(As, Bs)")
    problem = rotation_problem(X)
    if problem:
        raise Mismatch(
            f"hand_eye_rotation returned a matrix that is not a rotation: {problem}",
            hints.HAND_EYE_NOT_A_ROTATION_HINT,
        )
    return X


def _angle(X, Y):
    return float(np.linalg.norm(Log(X.T @ Y)))


def _hint(X, X_true, figures=None):
    if _angle(X.T, X_true) < 0.05:
        return (
            "that is Xᵀ: in A X = X B, X carries B's frame into A's; check your answer on one exact pair, "
            "A X against X B"
        )
    if figures is not None and _angle(X, Exp(figures["first two"])) < 1e-9:
        return "the answer comes from the first pairs alone: the noise averages out only over all the good pairs"
    if figures is not None and _angle(X, Exp(figures["all pairs"])) < 1e-9:
        return (
            "the wrong pairs pulled the answer away: some pairs are far from any single X, and your estimate "
            "follows them"
        )
    return "compare your X with the truth pair by pair: which pairs does it explain, and which not?"


def _require_within_bound(hand_eye_rotation, seed, pairs, sigma, outliers):
    """The answer on the dataset drawn with these figures must be within 4 σ_X of the truth."""
    As, Bs, X_true, figures = _dataset(seed, pairs, sigma, outliers)
    X = _answer(hand_eye_rotation, As, Bs)
    spread = figures["spread"]
    if _angle(X, X_true) > 4 * spread:
        raise Mismatch(
            f"X is {_angle(X, X_true):.3g} rad from the truth, more than 4 σ_X = {4 * spread:.3g} rad",
            _hint(X, X_true, figures),
        )


@public_check("hand_eye_rotation", "recovers X to 1e-9 rad from 10 exact pairs")
def _(hand_eye_rotation):
    As, Bs, X_true, _ = _dataset(90, 10, 0.0, 0)
    X = _answer(hand_eye_rotation, As, Bs)
    if _angle(X, X_true) > 1e-9:
        raise Mismatch(f"X is {_angle(X, X_true):.3g} rad from the truth on exact data", _hint(X, X_true))


@public_check("hand_eye_rotation", "recovers X to 1e-9 rad from exact pairs whose turn axes all lie in one plane")
def _(hand_eye_rotation):
    for seed in (93, 95):
        As, Bs, X_true, _ = _dataset(seed, 8, 0.0, 0, plane=True)
        X = _answer(hand_eye_rotation, As, Bs)
        if _angle(X, X_true) > 1e-9:
            general = _dataset(90, 10, 0.0, 0)
            right_in_general = _angle(_answer(hand_eye_rotation, *general[:2]), general[2]) <= 1e-9
            raise Mismatch(
                f"X is {_angle(X, X_true):.3g} rad from the truth on exact pairs whose axes share one plane",
                PLANE_HINT if right_in_general else _hint(X, X_true),
            )


@public_check("hand_eye_rotation", "within 4 σ_X of the truth: 20 pairs, σ = 0.01 rad, 4 outliers")
def _(hand_eye_rotation):
    _require_within_bound(hand_eye_rotation, 91, 20, 0.01, 4)


@public_check("hand_eye_rotation", "within 4 σ_X of the truth: 24 pairs, σ = 0.01 rad, 6 outliers (a tight bound)")
def _(hand_eye_rotation):
    _require_within_bound(hand_eye_rotation, 93, 24, 0.01, 6)


@public_check("hand_eye_rotation", "within 4 σ_X of the truth: only 12 pairs, σ = 0.02 rad, 4 of them outliers")
def _(hand_eye_rotation):
    _require_within_bound(hand_eye_rotation, 98, 12, 0.02, 4)


@public_check("hand_eye_rotation", "within 4 σ_X: 30 pairs, σ = 0.03 rad, 12 outliers; accepts lists, keeps inputs")
def _(hand_eye_rotation):
    As, Bs, X_true, figures = _dataset(92, 30, 0.03, 12)
    spread = figures["spread"]
    copies = [As.copy(), Bs.copy()]
    X = _answer(hand_eye_rotation, *copies)
    if not (np.array_equal(copies[0], As) and np.array_equal(copies[1], Bs)):
        raise Mismatch("hand_eye_rotation changed its input arrays", "work on copies (np.array(x, dtype=float))")
    if _angle(X, X_true) > 4 * spread:
        raise Mismatch(
            f"X is {_angle(X, X_true):.3g} rad from the truth, more than 4 σ_X = {4 * spread:.3g} rad",
            _hint(X, X_true, figures),
        )
    from_lists = _answer(hand_eye_rotation, As.tolist(), Bs.tolist())
    if _angle(from_lists, X) > 1e-12:
        raise Mismatch(
            hints.HAND_EYE_LISTS_REASON,
            "convert the arguments with np.asarray(x, dtype=float) first",
        )
