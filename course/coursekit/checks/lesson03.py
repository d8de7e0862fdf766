"""Public checks for lesson 03: the Lie algebra so(3), exp and log.

The checks use rotations whose axis and angle are known by construction —
quarter and half turns written out entry by entry, a tiny turn about z built
from cos and sin, scipy's rotation through ``coursekit.lie.Exp`` — and defining properties: hat(w) @ v is the cross product,
exp of a rotation vector fixes its axis, log undoes exp.

The hints name a typical slip by comparing your answer with what that slip
returns at the checks' fixed inputs. Those values are stored below as numbers
(computed once, and rechecked by the course's own tests), so this file
contains no way to compute the exercises' answers.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import FLOAT32_HINT, LISTS_HINT, close, explains, float32_rounding, rotation_problem
from ..lie import Exp
from .common import fmt, off_by, require_same_with_lists, require_shape

QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
HALF_TURN_Z = np.diag([-1.0, -1.0, 1.0])
DIAGONAL = np.ones(3) / np.sqrt(3.0)
HALF_TURN_DIAGONAL = 2.0 * np.outer(DIAGONAL, DIAGONAL) - np.eye(3)   # π about (1, 1, 1)/√3
W_SAMPLE = np.array([0.3, -1.2, 0.5])
V_SAMPLE = np.array([2.0, 0.1, -0.7])
SKEW_SAMPLE = np.array([[0.0, -0.5, -1.2], [0.5, 0.0, -0.3], [1.2, 0.3, 0.0]])   # hat of (0.3, -1.2, 0.5)
AXIS_221 = np.array([2.0, -1.0, 2.0]) / 3.0
AXIS_BELOW_PI = np.array([0.0, -0.6, -0.8])            # its largest component is negative
R_TWO_RAD = Exp(2.0 * AXIS_221)                        # 2 rad about (2, -1, 2)/3
E_X_HAT = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])   # [e_x]×
E_Y_HAT = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])   # [e_y]×
E_Z_HAT = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])   # [e_z]× = [e_x × e_y]×
A_2X2 = np.array([[1.0, 2.0], [0.0, -1.0]])
B_2X2 = np.array([[0.0, 1.0], [3.0, 0.5]])
BRACKET_2X2 = np.array([[6.0, 3.0], [-6.0, -6.0]])    # [A_2X2, B_2X2], worked out by hand
QUARTER_W = np.array([[0.0, -1.5707963267948966, 0.0],   # [π/2 e_z]×
                      [1.5707963267948966, 0.0, 0.0], [0.0, 0.0, 0.0]])

# ---- what typical slips return at the fixed inputs above (values only; see the module docstring)
# hat(W_SAMPLE) without the minus signs: [[0, w3, w2], [w3, 0, w1], [w2, w1, 0]]
HAT_SYMMETRIC_AT_W = np.array([[0.0, 0.5, -1.2], [0.5, 0.0, 0.3], [-1.2, 0.3, 0.0]])
# hat of W_SAMPLE with its components permuted in these orders
PERMUTATIONS = ((2, 1, 0), (1, 0, 2), (0, 2, 1), (1, 2, 0), (2, 0, 1))
HAT_PERMUTED_AT_W = [np.array([[0.0, -0.3, -1.2], [0.3, 0.0, -0.5], [1.2, 0.5, 0.0]]),
                     np.array([[0.0, -0.5, 0.3], [0.5, 0.0, 1.2], [-0.3, -1.2, 0.0]]),
                     np.array([[0.0, 1.2, 0.5], [-1.2, 0.0, -0.3], [-0.5, 0.3, 0.0]]),
                     np.array([[0.0, -0.3, 0.5], [0.3, 0.0, 1.2], [-0.5, -1.2, 0.0]]),
                     np.array([[0.0, 1.2, 0.3], [-1.2, 0.0, -0.5], [-0.3, 0.5, 0.0]])]
# bracket slips: AB + BA, A * B - B * A (entry-wise, always zero), AB alone, BA alone
BRACKET_SLIPS = {
    "e_x, e_y": {"anticommutator": np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]),
                 "entrywise": np.zeros((3, 3)),
                 "AB": np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]),
                 "BA": np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])},
    "2x2": {"anticommutator": np.array([[6.0, 1.0], [0.0, 5.0]]),
            "entrywise": np.zeros((2, 2)),
            "AB": np.array([[6.0, 2.0], [-3.0, -0.5]]),
            "BA": np.array([[0.0, -1.0], [3.0, 5.5]])},
}
# exp_series(SKEW_SAMPLE, n) for n = 1 … 4: I, I + W, I + W + W²/2, I + W + W²/2 + W³/6
SERIES_AT_SKEW = {
    1: np.eye(3),
    2: np.array([[1.0, -0.5, -1.2], [0.5, 1.0, -0.3], [1.2, 0.3, 1.0]]),
    3: np.array([[0.15500000000000003, -0.6799999999999999, -1.125],
                 [0.32, 0.8300000000000001, -0.6],
                 [1.275, 0.0, 0.235]]),
    4: np.array([[0.15500000000000003, -0.5316666666666666, -0.7689999999999999],
                 [0.1716666666666667, 0.8300000000000001, -0.511],
                 [0.9189999999999998, -0.08900000000000001, 0.235]]),
}
# the n-term slip with entry-wise powers W ** k / k!
SERIES_ENTRYWISE_AT_SKEW = {
    1: np.ones((3, 3)),
    2: np.array([[1.0, 0.5, -0.19999999999999996], [1.5, 1.0, 0.7], [2.2, 1.3, 1.0]]),
    3: np.array([[1.0, 0.625, 0.52], [1.625, 1.0, 0.745], [2.92, 1.345, 1.0]]),
}
# the n-term slip without the 1/k!
SERIES_NO_FACTORIAL_AT_SKEW = {
    1: np.eye(3),
    2: np.array([[1.0, -0.5, -1.2], [0.5, 1.0, -0.3], [1.2, 0.3, 1.0]]),
    3: np.array([[-0.69, -0.86, -1.05], [0.14, 0.66, -0.8999999999999999], [1.3499999999999999, -0.3, -0.53]]),
}
# the same two slips with 30 terms of QUARTER_W
SERIES_ENTRYWISE_QUARTER_30 = np.array([[1.0, 0.20787957635069995, 1.0], [4.810477380965104, 1.0, 1.0],
                                        [1.0, 1.0, 1.0]])
SERIES_NO_FACTORIAL_QUARTER_30 = np.array([[220593.54299530966, -346507.52705170447, 0.0],
                                           [346507.52705170447, 220593.54299530966, 0.0],
                                           [0.0, 0.0, 1.0]])
# exp_so3 slips at [0, 0, π/2], W_SAMPLE and [0, 0, 1e-8]: sin θ and (1 - cos θ) swapped; [w]× in place of [w/θ]×
EXP_SLIPS = {
    "quarter": {"swapped": np.array([[0.0, -0.9999999999999999, 0.0], [0.9999999999999999, 0.0, 0.0], [0.0, 0.0, 1.0]]),
                "unnormalised": np.array([[-1.467401100272339, -1.5707963267948966, 0.0],
                                          [1.5707963267948966, -1.467401100272339, 0.0],
                                          [0.0, 0.0, 1.0]])},
    "sample": {"swapped": np.array([[0.07701928498050536, -0.4835215899531728, -0.6066633868759179],
                                    [0.09029903680877277, 0.8143115721262555, -0.4998316489822504],
                                    [0.7705061173527512, -0.1555392729250831, 0.16440207456814993]]),
               "unnormalised": np.array([[-0.29381702396980613, -0.761672760352947, -1.051724410465189],
                                         [0.21046077380959766, 0.7397054507989739, -0.7509833823682213],
                                         [1.281396071524918, -0.16770326187069445, -0.1713254714046173]])},
    "tiny": {"swapped": np.array([[0.99999999, 0.0, 0.0], [0.0, 0.99999999, 0.0], [0.0, 0.0, 1.0]]),
             "unnormalised": np.array([[1.0, -1.0000000000000001e-16, 0.0], [1.0000000000000001e-16, 1.0, 0.0],
                                       [0.0, 0.0, 1.0]])},
}
# log_so3 slips at the checks' rotations: the values that the usual wrong answers return there (each one is
# recomputed from its wrong answer by tests/test_public_check_constants_lesson03.py). Near π, "column_logs" holds
# what a log returns that always reads its axis from one fixed column (either sign), and "weak_column" whether
# one of those columns is (nearly) zero at that rotation, so that such a log divides by about zero.
LOG_SLIPS = {
    "quarter": {"arccos_angle": 1.5707963267948966},
    "tiny_1e-08": {"arccos_angle": 0.0,
                   "sin_angle_axis": np.array([6.666666666666667e-09, -3.3333333333333334e-09, 6.666666666666667e-09])},
    "tiny_0.001": {"arccos_angle": 0.0009999999997701238,
                   "sin_angle_axis": np.array([0.0006666665555555612, -0.0003333332777777806, 0.0006666665555555612])},
    "half_z": {"arccos_angle": 3.141592653589793, "no_branch": [np.zeros(3), np.zeros(3)],
               "weak_column": True,
               "column_logs": [np.array([0.0, 0.0, 3.141592653589793]), np.array([-0.0, -0.0, -3.141592653589793])]},
    "half_diagonal": {"arccos_angle": 3.1415926325163688, "no_branch": [np.zeros(3), np.zeros(3)],
                      "weak_column": False,
                      "column_logs": [np.array([-1.8137993642342176, -1.8137993642342183, -1.8137993642342183]),
                                      np.array([-1.8137993642342183, -1.8137993642342176, -1.8137993642342183]),
                                      np.array([-1.8137993642342183, -1.8137993642342183, -1.8137993642342176]),
                                      np.array([1.8137993642342176, 1.8137993642342183, 1.8137993642342183]),
                                      np.array([1.8137993642342183, 1.8137993642342176, 1.8137993642342183]),
                                      np.array([1.8137993642342183, 1.8137993642342183, 1.8137993642342176])]},
    "below_pi": {"arccos_angle": 3.141591653545344,
                 "no_branch": [np.array([0.0, -1.884954992153876, -2.5132733228718345]),
                               np.array([0.0, -1.8848712116959343, -2.513161615594579])],
                 "weak_column": True,
                 "column_logs": [np.array([-3.141591653589793, 0.0, 0.0]),
                                 np.array([-0.0, -1.8849549921538757, -2.5132733228718345]),
                                 np.array([-0.0, -1.884954992153876, -2.5132733228718345]),
                                 np.array([0.0, 1.8849549921538757, 2.5132733228718345]),
                                 np.array([0.0, 1.884954992153876, 2.5132733228718345])]},
}
# axis_from_eigen slips that miss the axis: a row of eig's vector matrix, the SVD null space of R itself,
# eigh's vector (R_TWO_RAD); the first eigenvector and its eigenvalue (HALF_TURN_Z). Each slip is a line (the sign
# is free), or several lines where LAPACK's choices vary with the CPU's kernel: the row of the matrix is read for
# the real eigenvalue listed first or last (a complex pair stays together) and each column's sign is LAPACK's.
EIGEN_SLIPS = {
    "two_rad": {"row": np.array([[-0.9428090415820635, 0.23570226039551567, 0.23570226039551567],
                                 [-0.9428090415820635, -0.23570226039551567, -0.23570226039551567],
                                 [0.2357022603955158, 0.2357022603955158, -0.9428090415820634],
                                 [-0.2357022603955158, -0.2357022603955158, -0.9428090415820634]]),
                "svd_of_R": np.array([0.0, -0.7071067811865472, 0.7071067811865475]),
                "eigh": np.array([-0.6823480532366004, -0.2623018652019903, -0.6823480532366004])},
    "half_z": {"first": np.array([1.0, 0.0, 0.0]), "first_eigenvalue": -1.0},
}


def _rot_z(angle):
    return Exp([0.0, 0.0, angle])




def _trace_outside(R):
    """The trace of a rotation lies in [-1, 3]; rounding can push it just outside."""
    return not -1.0 <= float(np.trace(np.asarray(R, dtype=float))) <= 3.0


# ---------------------------------------------------------------- hat, vee
def _hat_hint(W):
    """The slip behind a wrong hat(W_SAMPLE) = ``W``."""
    truth = SKEW_SAMPLE
    if explains(W, truth.T, truth):
        return "the signs are swapped (the transpose, -[w]×): the top row is [0, -w3, w2]"
    if explains(W, HAT_SYMMETRIC_AT_W, truth):
        return hints.MINUS_SIGNS_MISSING_SYMMETRIC_HINT
    if explains(W, np.diag(W_SAMPLE), truth):
        return hints.W_SITS_DIAGONAL_W_HINT
    if any(explains(W, permuted, truth) for permuted in HAT_PERMUTED_AT_W):
        return "the components of w are permuted: W[2, 1] = w1, W[0, 2] = w2, W[1, 0] = w3"
    return hints.COMPARE_ENTRY_ENTRY_W3_HINT


@public_check("hat", "hat(w) @ v equals the cross product w × v")
def _(hat):
    W = require_shape(hat(W_SAMPLE), (3, 3))
    got, want = W @ V_SAMPLE, np.cross(W_SAMPLE, V_SAMPLE)
    if not close(got, want, 1e-12):
        raise Mismatch(f"hat(w) @ v = {fmt(got)}, but w × v = {fmt(want)} ({off_by(got, want)})", _hat_hint(W))


@public_check("hat", "returns a skew-symmetric matrix (Wᵀ = -W)")
def _(hat):
    W = require_shape(hat(W_SAMPLE), (3, 3))
    if not close(W, -W.T, 1e-15):
        raise Mismatch(f"hat(w) + hat(w)ᵀ is not zero (its largest entry is {np.max(np.abs(W + W.T)):.2g})",
                       "the diagonal is zero and W[j, i] = -W[i, j]")


def vee_hint(got, W, w):
    """Name the slip behind a wrong vee(W) = ``got`` for the skew-symmetric ``W`` = [w]× (shared with the
    hidden suite)."""
    w = np.asarray(w, dtype=float)
    if explains(got, -w, w):
        return "the negative of w: read w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0] (the entries with a plus sign)"
    if explains(got, np.array([W[0, 1], W[0, 2], W[1, 2]]), w):
        return ("read the entries above the diagonal in row order (W[0, 1], W[0, 2], W[1, 2] = -w3, w2, -w1): "
                "w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0]")
    if explains(got, 2.0 * w, w):
        return "twice w: W - Wᵀ = 2[w]×, so take half of it (or read the entries of W directly)"
    if explains(got, np.diag(W), w):
        return "returned the diagonal of W, which is zero: w sits off the diagonal (w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0])"
    return "vee reads w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0]"


@public_check("vee", "vee undoes hat: vee([w]×) = w")
def _(vee):
    got = require_shape(vee(SKEW_SAMPLE), (3,))
    if not close(got, W_SAMPLE, 1e-12):
        raise Mismatch(f"vee returned {fmt(got)}, expected {fmt(W_SAMPLE)} ({off_by(got, W_SAMPLE)})",
                       vee_hint(got, SKEW_SAMPLE, W_SAMPLE))


@public_check("vee", "accepts a nested list")
def _(vee):
    require_same_with_lists(vee, (SKEW_SAMPLE,), (3,), "vee")


# ---------------------------------------------------------------- bracket
def _bracket_hint(got, truth, slips):
    """The slip behind a wrong bracket = ``got``; ``slips`` holds what each slip returns for these A, B."""
    if explains(got, slips["anticommutator"], truth):
        return hints.AB_BA_BRACKET_DIFFERENCE_HINT
    if explains(got, -truth, truth):
        return "the order is AB - BA, not BA - AB"
    if explains(got, slips["entrywise"], truth):
        return hints.GOT_ZERO_MULTIPLIES_ENTRY_HINT
    if explains(got, slips["AB"], truth):
        return hints.ONLY_AB_BRACKET_SUBTRACTS_HINT
    if explains(got, slips["BA"], truth):
        return "that is only BA: the bracket is AB - BA"
    return "[A, B] = A @ B - B @ A, with matrix products"


@public_check("bracket", "[e_x^, e_y^] = e_z^ (the cross product e_x × e_y = e_z)")
def _(bracket):
    got = require_shape(bracket(E_X_HAT, E_Y_HAT), (3, 3))
    if not close(got, E_Z_HAT, 1e-12):
        raise Mismatch(f"bracket(X, Y) =\n{got}\nexpected [e_z]× ({off_by(got, E_Z_HAT)})",
                       _bracket_hint(got, E_Z_HAT, BRACKET_SLIPS["e_x, e_y"]))


@public_check("bracket", "works for square matrices of any size (2×2)")
def _(bracket):
    got = require_shape(bracket(A_2X2, B_2X2), (2, 2))
    if not close(got, BRACKET_2X2, 1e-12):
        raise Mismatch(f"bracket of two 2×2 matrices returned {fmt(got)} ({off_by(got, BRACKET_2X2)})",
                       _bracket_hint(got, BRACKET_2X2, BRACKET_SLIPS["2x2"]))


# [w^, v^] = (w × v)^ for W_SAMPLE and V_SAMPLE: the hat of V_SAMPLE and of W_SAMPLE × V_SAMPLE = (0.79, 1.21, 2.43).
HAT_V_SAMPLE = np.array([[0.0, 0.7, 0.1], [-0.7, 0.0, -2.0], [-0.1, 2.0, 0.0]])
HAT_W_CROSS_V = np.array([[0.0, -2.43, 1.21], [2.43, 0.0, -0.79], [-1.21, 0.79, 0.0]])


@public_check("bracket", "[w^, v^] = (w × v)^ to 1e-12 for generic w and v")
def _(bracket):
    got = require_shape(bracket(SKEW_SAMPLE.copy(), HAT_V_SAMPLE.copy()), (3, 3))
    if not close(got, HAT_W_CROSS_V, 1e-12):
        raise Mismatch(f"[w^, v^] for w = {fmt(W_SAMPLE)}, v = {fmt(V_SAMPLE)} is {off_by(got, HAT_W_CROSS_V)} "
                       f"from (w × v)^", FLOAT32_HINT if float32_rounding(got, HAT_W_CROSS_V) else None)


# ---------------------------------------------------------------- exp_series
def _series_hint(got, truth, slips):
    """The slip behind a wrong exp_series = ``got``; ``slips`` holds what each slip returns for this W and n."""
    if any(explains(got, candidate, truth) for candidate in slips.get("no_identity", ())):
        return hints.IDENTITY_TERM_MISSING_SUM_HINT
    if "one_extra" in slips and explains(got, slips["one_extra"], truth):
        return hints.ONE_TERM_TOO_MANY_HINT
    if "one_short" in slips and explains(got, slips["one_short"], truth):
        return hints.ONE_TERM_TOO_FEW_HINT
    if explains(got, slips["entrywise"], truth):
        return hints.ENTRYWISE_POWER_HINT
    if explains(got, slips["no_factorial"], truth):
        return hints.FACTORIAL_MISSING_HINT
    return hints.SUM_TERMS_W_K_HINT


def _series_slips_at_sample(n):
    """What each slip returns for exp_series(SKEW_SAMPLE, n), from the stored sums of 0 … 4 terms."""
    sums = {0: np.zeros((3, 3)), **SERIES_AT_SKEW}
    slips = {"no_identity": (sums[n + 1] - np.eye(3), sums[n] - np.eye(3)),   # k = 1 … n, k = 1 … n - 1
             "one_extra": sums[n + 1],                                         # k = 0 … n
             "entrywise": SERIES_ENTRYWISE_AT_SKEW[n], "no_factorial": SERIES_NO_FACTORIAL_AT_SKEW[n]}
    if n >= 2:
        slips["one_short"] = sums[n - 1]                                       # k = 0 … n - 2
    return slips


@public_check("exp_series", "n_terms = 1, 2, 3 give I, I + W, I + W + W²/2")
def _(exp_series):
    W = SKEW_SAMPLE
    for n in (1, 2, 3):
        got = require_shape(exp_series(W, n), (3, 3))
        expected = SERIES_AT_SKEW[n]
        if not close(got, expected, 1e-12):
            raise Mismatch(f"exp_series(W, {n}) differs from the sum of its first {n} terms "
                           f"({off_by(got, expected)})", _series_hint(got, expected, _series_slips_at_sample(n)))


@public_check("exp_series", "many terms sum to a rotation: the quarter turn about z")
def _(exp_series):
    got = require_shape(exp_series(QUARTER_W, 30), (3, 3))
    if not close(got, QUARTER_TURN_Z, 1e-12):
        # 30 terms are the rotation to rounding, so one term more or less is invisible here
        slips = {"no_identity": (QUARTER_TURN_Z - np.eye(3),), "entrywise": SERIES_ENTRYWISE_QUARTER_30,
                 "no_factorial": SERIES_NO_FACTORIAL_QUARTER_30}
        raise Mismatch(f"30 terms of exp([π/2 e_z]×) give x → {fmt(got[:, 0])}, expected [0, 1, 0] "
                       f"({off_by(got, QUARTER_TURN_Z)})", _series_hint(got, QUARTER_TURN_Z, slips))


# ---------------------------------------------------------------- exp_so3
def _exp_hint(got, w, slips):
    """The slip behind a wrong exp_so3(w) = ``got``; ``slips`` holds what each slip returns for this w."""
    w = np.asarray(w, dtype=float)
    angle = float(np.linalg.norm(w))
    expected = Exp(w)
    if angle > 0.0 and np.array_equal(got, np.eye(3)):
        return f"returned exactly I: the turn of {angle:.3g} rad was dropped; use the Taylor coefficients, never return I"
    if explains(got, expected.T, expected):
        return "got the inverse rotation: check the sign of the sin θ term against the page"
    if explains(got, slips["swapped"], expected):
        return hints.COEFFICIENTS_SWAPPED_R_I_HINT
    if explains(got, slips["unnormalised"], expected):
        return hints.RODRIGUES_FORMULA_NEEDS_UNIT_HINT
    return hints.RODRIGUES_FORMULA_HINT


@public_check("exp_so3", "a quarter turn about z sends x to y")
def _(exp_so3):
    R = require_shape(exp_so3([0.0, 0.0, np.pi / 2]), (3, 3))
    if not close(R, QUARTER_TURN_Z, 1e-12):
        raise Mismatch(f"exp_so3([0, 0, π/2]) sends x to {fmt(R[:, 0])}, expected [0, 1, 0] "
                       f"({off_by(R, QUARTER_TURN_Z)})", _exp_hint(R, [0.0, 0.0, np.pi / 2], EXP_SLIPS["quarter"]))


@public_check("exp_so3", "returns a rotation that leaves its axis fixed")
def _(exp_so3):
    R = require_shape(exp_so3(W_SAMPLE), (3, 3))
    problem = rotation_problem(R, 1e-12)
    if problem:
        raise Mismatch(f"exp_so3(w) is not a rotation: {problem}", _exp_hint(R, W_SAMPLE, EXP_SLIPS["sample"]))
    if not close(R @ W_SAMPLE, W_SAMPLE, 1e-12):
        raise Mismatch(f"exp_so3(w) moves its own axis w ({off_by(R @ W_SAMPLE, W_SAMPLE)})",
                       _exp_hint(R, W_SAMPLE, EXP_SLIPS["sample"]))


@public_check("exp_so3", "exp_so3(w)² = exp_so3(2w) to 1e-14 just below 0.1, 0.01, … 1e-8 rad (its small-angle "
                         "branch is as exact as its closed form)")
def _(exp_so3):
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    for k in range(1, 9):
        w = 0.97 * 10.0 ** -k * axis
        once = require_shape(exp_so3(w), (3, 3))
        twice = require_shape(exp_so3(2 * w), (3, 3))
        error = float(np.max(np.abs(once @ once - twice)))
        if error > 1e-14:
            raise Mismatch(f"exp_so3(w) @ exp_so3(w) differs from exp_so3(2w) by {error:.2g} at θ = {0.97 * 10.0 ** -k:.2g}",
                           "a series used up to a small angle must stay exact there: below about 1e-4 keep each "
                           "coefficient's θ² term as well as its limit, the closed form above")


@public_check("exp_so3", "w = 0 gives I, and a tiny turn (1e-8 rad) is not lost")
def _(exp_so3):
    got = require_shape(exp_so3([0.0, 0.0, 0.0]), (3, 3))
    if not close(got, np.eye(3), 1e-15):
        raise Mismatch(f"exp_so3(0) is not the identity ({off_by(got, np.eye(3))})",
                       "at θ = 0 the coefficients are 0/0: use their limits (the page gives them)")
    w = [0.0, 0.0, 1e-8]
    got = require_shape(exp_so3(w), (3, 3))
    if not close(got, _rot_z(1e-8), 1e-15):
        raise Mismatch(f"exp_so3([0, 0, 1e-8]) is {off_by(got, _rot_z(1e-8))} (R[1, 0] = {got[1, 0]:.3g}, "
                       "expected 1e-08)", _exp_hint(got, w, EXP_SLIPS["tiny"]))


# ---------------------------------------------------------------- log_so3
COLUMN_HINT = ("an axis read from one fixed column fails near π when the axis is nearly perpendicular to that "
               "column's direction, and here it is: that column is (nearly) zero, so the direction read from it is "
               "rounding noise")


def _log_hint(got, R, expected, slips):
    """The slip behind a wrong log_so3(R) = ``got``; ``slips`` holds what each slip returns for this R."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    angle = float(np.linalg.norm(expected))
    if not np.all(np.isfinite(got)):
        if _trace_outside(R):
            return "NaN: (tr R - 1)/2 is just outside [-1, 1] by rounding, and arccos of it is NaN: clip it first"
        if angle < 1e-3:
            return hints.NAN_AT_ZERO_ANGLE_HINT
        if angle > 3.0 and slips.get("weak_column"):
            return COLUMN_HINT
        return hints.NAN_NEAR_PI_HINT
    if angle == 0.0:
        return "the identity's log is the zero vector"
    unit = expected / angle
    if explains(got, -expected, expected):
        return hints.LOG_AXIS_SIGN_NEAR_PI_HINT if angle > 3.0 else hints.OPPOSITE_ROTATION_CHECK_SIGN_HINT
    if explains(got, 2.0 * expected, expected):
        return hints.TWICE_ROTATION_VECTOR_VEE_HINT
    if angle < 0.5 and explains(got, slips["sin_angle_axis"], expected):
        return (f"returned vee(R - Rᵀ)/2 = sin θ u, off by about {angle ** 3 / 6:.1e} at θ = {angle:.3g}: below your "
                "small-angle threshold the log has lost its relative accuracy (the check asks for 1e-10 of θ)")
    theta_acos = slips["arccos_angle"]
    if explains(got, theta_acos * unit, expected):
        if theta_acos == 0.0:
            return hints.RETURNED_ZERO_TINY_ROTATION_HINT
        return (f"θ from arccos is off by {abs(theta_acos - angle):.1e}: arccos loses accuracy where its argument "
                "is near ±1, so the angle must come from numbers that keep it")
    if any(explains(got, candidate, expected) for candidate in slips.get("no_branch", ())) or (
            angle > 3.0 and np.linalg.norm(got) <= 1e-3 * angle):
        return (f"θ/(2 sin θ)·vee(R - Rᵀ) divides two tiny numbers near π (here sin θ = {abs(np.sin(angle)):.1e}): the log "
                "needs its own branch near π that does not divide by sin θ (section 5: which part of R still holds "
                "the axis there?)")
    if angle > 3.0 and any(explains(got, candidate, expected) for candidate in slips.get("column_logs", ())):
        return COLUMN_HINT
    if angle > 3.0:
        return hints.LOG_OFF_NEAR_TAKE_HINT
    return hints.LOG_FORMULA_HINT


@public_check("log_so3", "undoes a quarter turn about z: [0, 0, π/2]")
def _(log_so3):
    got = require_shape(log_so3(QUARTER_TURN_Z), (3,))
    want = np.array([0.0, 0.0, np.pi / 2])
    if not close(got, want, 1e-12):
        raise Mismatch(f"log_so3 of the quarter turn is {off_by(got, want)}: returned {fmt(got)}",
                       _log_hint(got, QUARTER_TURN_Z, want, LOG_SLIPS["quarter"]))


@public_check("log_so3", "the identity gives 0, and tiny turns keep their relative accuracy")
def _(log_so3):
    got = require_shape(log_so3(np.eye(3)), (3,), "log_so3(I)", lambda got: _log_hint(got, np.eye(3), np.zeros(3), {}))
    if not close(got, np.zeros(3), 1e-15):
        raise Mismatch(f"log_so3(I) returned {fmt(got)}", _log_hint(got, np.eye(3), np.zeros(3), {}))
    for angle in (1e-8, 1e-3):
        want = angle * AXIS_221
        R = Exp(want)
        slips = LOG_SLIPS[f"tiny_{angle:g}"]
        got = require_shape(log_so3(R), (3,), f"log_so3 at θ = {angle:g}", lambda got: _log_hint(got, R, want, slips))
        if not close(got, want, 1e-15 + 1e-10 * angle):
            raise Mismatch(f"log_so3 of a {angle:g} rad turn is {off_by(got, want)} "
                           f"(relative {np.max(np.abs(got - want)) / angle:.2g}): returned {got}",
                           _log_hint(got, R, want, slips))


@public_check("log_so3", "within 1e-10 at θ = π, also about (1, 1, 1)/√3 (either sign)")
def _(log_so3):
    for name, R, axis, key in [("the half turn about z", HALF_TURN_Z, np.array([0.0, 0.0, 1.0]), "half_z"),
                               ("the half turn about (1, 1, 1)/√3", HALF_TURN_DIAGONAL, DIAGONAL, "half_diagonal")]:
        got = require_shape(log_so3(R), (3,), f"log_so3 of {name}",
                            lambda got: _log_hint(got, R, np.pi * axis, LOG_SLIPS[key]))
        want = np.pi * axis if np.linalg.norm(got - np.pi * axis) <= np.linalg.norm(got + np.pi * axis) \
            else -np.pi * axis
        if not close(got, want, 1e-10):
            raise Mismatch(f"log_so3 of {name} is {off_by(got, want)} (either sign accepted): returned {fmt(got)}",
                           _log_hint(got, R, want, LOG_SLIPS[key]))


@public_check("log_so3", "just below π (θ = π - 1e-6) within 1e-8, sign of the axis included")
def _(log_so3):
    angle = np.pi - 1e-6
    R = Exp(angle * AXIS_BELOW_PI)
    got = require_shape(log_so3(R), (3,))
    want = angle * AXIS_BELOW_PI
    if not close(got, want, 1e-8):
        raise Mismatch(f"log_so3 is {off_by(got, want)} at θ = π - 1e-6 about {fmt(AXIS_BELOW_PI)}: "
                       f"returned {fmt(got)}",
                       _log_hint(got, R, want, LOG_SLIPS["below_pi"]))


# ---------------------------------------------------------------- axis_angle
def _theta_hint(theta, true_angle, theta_acos):
    """The slip behind a wrong angle ``theta``; ``theta_acos`` is what arccos of the trace gives for this R."""
    if explains(theta, np.degrees(true_angle), true_angle):
        return hints.DEGREES_VALUE_RADIANS_COURSE_HINT
    if explains(theta, theta_acos, true_angle):
        return (f"θ from arccos is off by {abs(theta_acos - true_angle):.1e}: arccos is inaccurate next to ±1; "
                "the angle must come from numbers that keep it")
    return hints.ANGLE_FORMULA_HINT


def _pair(value, R):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(f"returned {type(value).__name__}, expected a pair (u, theta)", "return u, theta")
    theta = require_shape(value[1], (), "θ", lambda _: (
        "(tr R - 1)/2 is just above 1 by rounding, so arccos gives NaN: clip (tr R - 1)/2 to [-1, 1] before "
        "arccos" if _trace_outside(R) else "θ must be a number"))
    u = require_shape(value[0], (3,), "u", lambda _: (
        hints.AXIS_AT_ZERO_ANGLE_HINT
        if theta == 0.0 else "look for a division by a vanishing sin θ or norm"))
    return u, float(theta)


@public_check("axis_angle", "a quarter turn about z: u = [0, 0, 1], θ = π/2")
def _(axis_angle):
    u, theta = _pair(axis_angle(QUARTER_TURN_Z), QUARTER_TURN_Z)
    if not close(theta, np.pi / 2, 1e-12):
        raise Mismatch(f"θ = {theta:.6g}, expected π/2 ({off_by(theta, np.pi / 2)})",
                       _theta_hint(theta, np.pi / 2, LOG_SLIPS["quarter"]["arccos_angle"]))
    if not close(u, [0.0, 0.0, 1.0], 1e-12):
        raise Mismatch(f"got u = {fmt(u)}, expected u = [0, 0, 1] ({off_by(u, [0.0, 0.0, 1.0])})",
                       "u is wrong at a quarter turn, far from 0 and π: check the axis against R u = u and the sense "
                       "of the turn")


@public_check("axis_angle", "the identity, also up to rounding (trace just above 3): θ = 0 with a unit axis (no NaN)")
def _(axis_angle):
    for name, R in [("the identity", np.eye(3)), ("an identity up to rounding", np.diag([1.0 + 4.5e-16, 1.0, 1.0]))]:
        u, theta = _pair(axis_angle(R), R)
        if not (close(theta, 0.0, 1e-15) and close(np.linalg.norm(u), 1.0, 1e-12)):
            raise Mismatch(f"for {name} got u = {fmt(u)}, θ = {theta:.3g}",
                           "at θ = 0 the axis is arbitrary: return the unit vector [1, 0, 0]")


@public_check("axis_angle", "accepts a plain (nested) list")
def _(axis_angle):
    R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    u, theta = _pair(axis_angle(R), R)
    try:
        listed = axis_angle(R.tolist())
    except Exception as error:
        raise Mismatch(f"axis_angle(a nested list) raised {type(error).__name__}: {error}", LISTS_HINT) from None
    u_list, theta_list = _pair(listed, R)
    if not (close(u_list, u, 1e-12) and close(theta_list, theta, 1e-12)):
        raise Mismatch("axis_angle of a nested list differs from axis_angle of the same array", LISTS_HINT)


# A generic axis (no zero component, largest component negative) and every decade of θ up to just below π.
GENERIC_AXIS = np.array([0.36, -0.48, -0.8])   # a unit vector
AXIS_ANGLE_THETAS = [10.0 ** -k for k in range(8, 0, -1)] + [1.0, 2.0, 3.0, np.pi - 1e-6]


@public_check("axis_angle", "θ u rebuilds the rotation vector to 1e-9 about a generic axis at every decade of θ, "
                            "1e-8 … 3, and at π - 1e-6")
def _(axis_angle):
    for angle in AXIS_ANGLE_THETAS:
        w = angle * GENERIC_AXIS
        R = Exp(w)
        u, theta = _pair(axis_angle(R.copy()), R)
        if abs(theta - angle) > 1e-9:
            raise Mismatch(f"θ = {theta:.12g} at a true angle of {angle:.12g} ({off_by(theta, angle)})",
                           FLOAT32_HINT if float32_rounding(theta, angle) and angle >= 0.1
                           else _theta_hint(theta, angle, np.nan))
        if not close(theta * u, w, 1e-9):
            hint = None
            if explains(u, -GENERIC_AXIS, GENERIC_AXIS):
                hint = hints.U_POINTS_WRONG_WAY_HINT
            elif float32_rounding(theta * u, w):
                hint = FLOAT32_HINT
            raise Mismatch(f"at θ = {angle:.3g}, u = {fmt(u, 6)} and θ u is {off_by(theta * u, w)} from the "
                           f"rotation vector {fmt(w, 6)}", hint)


@public_check("axis_angle", "a half turn about (1, 1, 1)/√3: θ = π, u = ±(1, 1, 1)/√3")
def _(axis_angle):
    R = HALF_TURN_DIAGONAL
    u, theta = _pair(axis_angle(R), R)
    if not close(theta, np.pi, 1e-12):
        raise Mismatch(f"θ = {theta:.12f} is {off_by(theta, np.pi)} from π",
                       _theta_hint(theta, np.pi, LOG_SLIPS["half_diagonal"]["arccos_angle"]))
    if not (close(u, DIAGONAL, 1e-10) or close(u, -DIAGONAL, 1e-10)):
        raise Mismatch(f"got u = {fmt(u)}, expected ±(1, 1, 1)/√3",
                       hints.AXIS_AT_HALF_TURN_HINT if np.max(np.abs(R - R.T)) <= 1e-9 else
                       "the axis is off at θ = π, where R - Rᵀ vanishes (section 5)")


# ---------------------------------------------------------------- axis_from_eigen
REAL_AXIS_HINT = "the eigenvector of the eigenvalue 1 is real: return np.real(...) of it"


def _real(value):
    """A real (3,) vector; a complex one (np.linalg.eig's dtype) is refused: the docstring promises a real axis."""
    array = np.asarray(value) if value is not None else None
    if array is not None and np.iscomplexobj(array):
        raise Mismatch(f"returned a complex vector (dtype {array.dtype}), imaginary part up to "
                       f"{np.max(np.abs(array.imag), initial=0.0):.2g}",
                       REAL_AXIS_HINT)
    return require_shape(value, (3,))


def _eigen_hint(u, axis, slips):
    """The slip behind a wrong axis ``u`` (up to sign); ``slips`` holds what each slip returns for this R."""
    def same_line(lines):
        """u lies on one of ``lines`` ((3,) or (n, 3))."""
        lines = np.atleast_2d(lines)
        apart = np.minimum(np.max(np.abs(u - lines), axis=1), np.max(np.abs(u + lines), axis=1))
        return bool(np.min(apart) <= 1e-6)

    messages = {
        "row": hints.ROW_EIGENVECTOR_MATRIX_EIGENVECTORS_HINT,
        "first": f"that is the first eigenvector, whose eigenvalue is {slips.get('first_eigenvalue', 0.0):.3g}, not 1: "
                 "take k = argmin |λ - 1|",
        "svd_of_R": hints.SVD_NULL_SPACE_R_HINT,
        "eigh": hints.NP_LINALG_EIGH_ASSUMES_HINT,
    }
    for key, hint in messages.items():
        if key in slips and same_line(slips[key]) and not same_line(axis):
            return hint
    return "u must be the eigenvector of the eigenvalue 1: the column vectors[:, k] with k = argmin |λ - 1|"


@public_check("axis_from_eigen", "returns a real unit vector with R u = u")
def _(axis_from_eigen):
    R = R_TWO_RAD
    u = _real(axis_from_eigen(R))
    if not close(np.linalg.norm(u), 1.0, 1e-12):
        raise Mismatch(f"|u| = {np.linalg.norm(u):.6g}", "normalise the eigenvector")
    if not close(R @ u, u, 1e-10):
        raise Mismatch(f"R u ≠ u for u = {fmt(u)} (|R u - u| up to {np.max(np.abs(R @ u - u)):.2g})",
                       _eigen_hint(u, AXIS_221, EIGEN_SLIPS["two_rad"]))


@public_check("axis_from_eigen", "a half turn about z: u = ±e_z")
def _(axis_from_eigen):
    u = _real(axis_from_eigen(HALF_TURN_Z))
    if not (close(u, [0.0, 0.0, 1.0], 1e-12) or close(u, [0.0, 0.0, -1.0], 1e-12)):
        raise Mismatch(f"got {fmt(u)}, expected ±e_z",
                       _eigen_hint(u, np.array([0.0, 0.0, 1.0]), EIGEN_SLIPS["half_z"]))
