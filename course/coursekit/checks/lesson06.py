"""Public checks for lesson 06: perturbations and Jacobians.

The checks use quarter turns written out by hand, the library maps of
:mod:`coursekit.lie`, and properties any correct answer has: results that stay
rotations, round trips, and first-order expansions whose remainder shrinks
like the square of the step.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import (FLOAT32_HINT, JACOBIAN_STEP_HINT, close, jacobian_error_allowed, rotation_problem,
                        shape_problem, single_precision_error)
from ..lie import Exp, Log, quat_product, skew
from .common import fmt, off_by, require_same_with_lists, require_shape

# A quarter turn about z (x goes to y) and about x (y goes to z), written out.
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
E = np.eye(3)
# A generic attitude and a generic small rotation vector.
R_SAMPLE = Exp([0.4, -0.7, 1.1])
D_SAMPLE = np.array([0.2, -0.3, 0.25])


# The slips of R ⊞ δ at (R_SAMPLE, D_SAMPLE), measured once and stored as numbers (the public checks never
# carry an answer's code); tests/test_public_check_constants_lesson06.py recomputes every one.
EXP_D_R_AT_SAMPLE = np.array([[-0.11210323247062991, -0.9422637975123687, -0.31554999788814186],
                              [0.5350309427618545, 0.21035734200848025, -0.8182247117696269],
                              [0.8373617829570429, -0.26055464793531835, 0.4805585499003271]])     # Exp(δ) R: left
R_EXP_D_AT_SAMPLE = np.array([[-0.03892926881997936, -0.9867500384426655, -0.15750832886720764],
                              [0.51358620498841, 0.11545531160436137, -0.8502348387757015],
                              [0.8571544330368626, -0.11399312547578676, 0.5022866166537955]])     # R Exp(δ): right
R_EXP_MINUS_D_AT_SAMPLE = np.array([[0.5837275578661094, -0.7324271422226198, -0.3504463147520239],
                                    [0.6705934880328926, 0.6782324498870218, -0.30050809927209526],
                                    [0.45778435097275566, -0.05959215767074622, 0.8870638436711297]])  # R Exp(-δ)
EXP_MINUS_D_R_AT_SAMPLE = np.array([[0.6131203445835476, -0.7657748981881257, -0.19409340113130638],
                                    [0.6697869259719887, 0.6341730765666334, -0.38627708028694246],
                                    [0.418890101165862, 0.10683311407507094, 0.90173043027408]])       # Exp(-δ) R
RT_EXP_D_AT_SAMPLE = EXP_MINUS_D_R_AT_SAMPLE.T        # Rᵀ Exp(δ) = (Exp(-δ) R)ᵀ: R transposed
EXP_D_RT_AT_SAMPLE = R_EXP_MINUS_D_AT_SAMPLE.T        # Exp(δ) Rᵀ = (R Exp(-δ))ᵀ: R transposed

_LEFT_HINT = "that is the left perturbation Exp(δ) R; the right one is R @ Exp(δ)"
_RIGHT_HINT = "that is the right perturbation R Exp(δ); the left one is Exp(δ) @ R"
_ADDS_HINT = hints.R_ROTATIONS_DO_ADD_HINT


def _right_slips(R, d, exp_d_r, r_exp_minus_d, rt_exp_d):
    """(value, hint) of the usual wrong versions of R ⊞ δ (right), given the stored values of the slips."""
    return [(exp_d_r, _LEFT_HINT),
            (R @ (E + skew(d)), "looks like R (I + [δ]×), only the first-order approximation: use "
             "R @ Exp(δ), which stays a rotation"),
            (r_exp_minus_d, hints.TURNED_CHECK_SIGN_R_HINT),
            (rt_exp_d, "that is Rᵀ Exp(δ): R got transposed; the right perturbation is R @ Exp(δ)"),
            (R + skew(d), _ADDS_HINT)]


def _left_slips(R, d, r_exp_d, exp_minus_d_r, exp_d_rt):
    """(value, hint) of the usual wrong versions of δ ⊞ R (left), given the stored values of the slips."""
    return [(r_exp_d, _RIGHT_HINT),
            ((E + skew(d)) @ R, "looks like (I + [δ]×) R, only the first-order approximation: use "
             "Exp(δ) @ R, which stays a rotation"),
            (exp_minus_d_r, hints.TURNED_CHECK_SIGN_EXP_HINT),
            (exp_d_rt, "that is Exp(δ) Rᵀ: R got transposed; the left perturbation is Exp(δ) @ R"),
            (R + skew(d), _ADDS_HINT)]


QUARTER_D = np.array([0.0, 0.0, np.pi / 2])          # Exp(QUARTER_D) is QUARTER_TURN_Z
RIGHT_SLIPS_AT_SAMPLE = _right_slips(R_SAMPLE, D_SAMPLE, EXP_D_R_AT_SAMPLE, R_EXP_MINUS_D_AT_SAMPLE,
                                     RT_EXP_D_AT_SAMPLE)
LEFT_SLIPS_AT_SAMPLE = _left_slips(R_SAMPLE, D_SAMPLE, R_EXP_D_AT_SAMPLE, EXP_MINUS_D_R_AT_SAMPLE,
                                   EXP_D_RT_AT_SAMPLE)
# At R = Q_x, δ = (0, 0, π/2) every slip is a product of the hand-written quarter turns.
RIGHT_SLIPS_AT_QUARTER = _right_slips(QUARTER_TURN_X, QUARTER_D, QUARTER_TURN_Z @ QUARTER_TURN_X,
                                      QUARTER_TURN_X @ QUARTER_TURN_Z.T, QUARTER_TURN_X.T @ QUARTER_TURN_Z)
LEFT_SLIPS_AT_QUARTER = _left_slips(QUARTER_TURN_X, QUARTER_D, QUARTER_TURN_X @ QUARTER_TURN_Z,
                                    QUARTER_TURN_Z.T @ QUARTER_TURN_X, QUARTER_TURN_Z @ QUARTER_TURN_X.T)


def _boxplus_hint(got, slips, fallback=None):
    """Name the typical wrong version of R ⊞ δ that ``got`` is (``slips``: its stored values), else ``fallback``."""
    for value, hint in slips:
        if close(got, value, 1e-9):
            return hint
    return fallback


# ---------------------------------------------------------------- boxplus_right
@public_check("boxplus_right", "returns a rotation, and δ = 0 leaves R unchanged")
def _(boxplus_right):
    got = require_shape(boxplus_right(R_SAMPLE, D_SAMPLE), (3, 3))
    problem = rotation_problem(got)
    if problem:
        raise Mismatch(problem, _boxplus_hint(got, RIGHT_SLIPS_AT_SAMPLE,
                                              hints.RIGHT_UPDATE_IS_A_ROTATION_HINT))
    same = require_shape(boxplus_right(R_SAMPLE, np.zeros(3)), (3, 3))
    if not close(same, R_SAMPLE, 1e-12):
        raise Mismatch(f"boxplus_right(R, 0) differs from R, {off_by(same, R_SAMPLE)}",
                       "Exp(0) is the identity: nothing should move"
                       if not close(same, R_SAMPLE.T, 1e-9) else "boxplus_right(R, 0) returned Rᵀ: R got transposed")


@public_check("boxplus_right", "turns about the body's own axis: R ⊞ (0, 0, π/2) keeps the body z axis")
def _(boxplus_right):
    got = require_shape(boxplus_right(QUARTER_TURN_X, [0.0, 0.0, np.pi / 2]), (3, 3))
    expected = QUARTER_TURN_X @ QUARTER_TURN_Z
    if close(got, expected, 1e-9):
        return
    if rotation_problem(got):
        raise Mismatch(f"R ⊞ (0, 0, π/2) is not a rotation: {rotation_problem(got)}",
                       _boxplus_hint(got, RIGHT_SLIPS_AT_QUARTER,
                                     "a product of rotations, R @ Exp(δ), stays a rotation"))
    if close(got, QUARTER_TURN_Z @ QUARTER_TURN_X, 1e-9):
        raise Mismatch("turned about the world z axis instead of the body's z axis",
                       "that is the left perturbation Exp(δ) R; the right one is R @ Exp(δ)")
    if close(got, QUARTER_TURN_X @ QUARTER_TURN_Z.T, 1e-9):
        raise Mismatch("turned a quarter turn about the body's z axis, but the wrong way (x went to -y)",
                       hints.TURNED_CHECK_SIGN_R_HINT)
    raise Mismatch(f"R ⊞ (0, 0, π/2) is {off_by(got, expected)} from R Q_z; its body x axis went to {fmt(got[:, 0])}, "
                   f"expected {fmt(expected[:, 0])}", _boxplus_hint(got, RIGHT_SLIPS_AT_QUARTER,
                                                                      "the right perturbation is R @ Exp(δ)"))


# ---------------------------------------------------------------- boxplus_left
@public_check("boxplus_left", "returns a rotation, and δ = 0 leaves R unchanged")
def _(boxplus_left):
    got = require_shape(boxplus_left(R_SAMPLE, D_SAMPLE), (3, 3))
    problem = rotation_problem(got)
    if problem:
        raise Mismatch(problem, _boxplus_hint(got, LEFT_SLIPS_AT_SAMPLE,
                                              hints.LEFT_UPDATE_IS_A_ROTATION_HINT))
    same = require_shape(boxplus_left(R_SAMPLE, np.zeros(3)), (3, 3))
    if not close(same, R_SAMPLE, 1e-12):
        if close(same, R_SAMPLE.T, 1e-9):
            raise Mismatch("boxplus_left(R, 0) returned Rᵀ instead of R",
                           "that is Exp(δ) Rᵀ: R got transposed; the left perturbation is Exp(δ) @ R")
        raise Mismatch(f"boxplus_left(R, 0) differs from R, {off_by(same, R_SAMPLE)}",
                       "Exp(0) is the identity: nothing should move")


@public_check("boxplus_left", "turns about the world axis: (0, 0, π/2) sends the body z axis from -y to x")
def _(boxplus_left):
    got = require_shape(boxplus_left(QUARTER_TURN_X, [0.0, 0.0, np.pi / 2]), (3, 3))
    expected = QUARTER_TURN_Z @ QUARTER_TURN_X
    if close(got, expected, 1e-9):
        return
    if close(got, QUARTER_TURN_X @ QUARTER_TURN_Z, 1e-9):
        raise Mismatch("turned about the body's z axis instead of the world z axis",
                       "that is the right perturbation R Exp(δ); the left one is Exp(δ) @ R")
    raise Mismatch(f"the body z axis went to {fmt(got[:, 2])}, expected [1, 0, 0] ({off_by(got, expected)} overall)",
                   _left_hint_confirmed(boxplus_left, got))


_LEFT_GENERIC_HINT = ("the left perturbation is Exp(δ) @ R; written with R first it is R @ Exp(Rᵀ δ) (Rᵀ, not R: "
                      "R Exp(v) Rᵀ = Exp(R v))")


def _left_hint_confirmed(boxplus_left, got_at_quarter):
    """The slip's hint only when the generic sample (R_SAMPLE, D_SAMPLE) shows the same slip: at the quarter turns
    some other mistakes coincide with a slip (R Exp(R δ) equals Exp(-δ) R there, since R² δ = -δ)."""
    at_quarter = _boxplus_hint(got_at_quarter, LEFT_SLIPS_AT_QUARTER)
    at_sample = _boxplus_hint(require_shape(boxplus_left(R_SAMPLE, D_SAMPLE), (3, 3)), LEFT_SLIPS_AT_SAMPLE)
    return at_quarter if at_quarter is not None and at_quarter == at_sample else _LEFT_GENERIC_HINT


@public_check("boxplus_left", "equals Exp(δ) @ R for a generic R and δ (no special axes)")
def _(boxplus_left):
    got = require_shape(boxplus_left(R_SAMPLE, D_SAMPLE), (3, 3))
    if not close(got, EXP_D_R_AT_SAMPLE, 1e-12):
        raise Mismatch(f"boxplus_left(R, δ) is {off_by(got, EXP_D_R_AT_SAMPLE)} from Exp(δ) R",
                       _boxplus_hint(got, LEFT_SLIPS_AT_SAMPLE, _LEFT_GENERIC_HINT))


# ---------------------------------------------------------------- boxminus
@public_check("boxminus", "R ⊟ R is zero, shape (3,)")
def _(boxminus):
    got = require_shape(boxminus(R_SAMPLE, R_SAMPLE), (3,))
    if not close(got, np.zeros(3), 1e-9):
        raise Mismatch(f"boxminus(R, R) returned {fmt(got)}", "the difference of a rotation with itself is 0")


@public_check("boxminus", "a quarter turn about the body's z axis: (R Q_z) ⊟ R = (0, 0, π/2)")
def _(boxminus):
    R_a = R_SAMPLE @ QUARTER_TURN_Z
    got = require_shape(boxminus(R_a, R_SAMPLE), (3,))
    expected = [0.0, 0.0, np.pi / 2]
    if close(got, expected, 1e-9):
        return
    if close(got, [0.0, 0.0, -np.pi / 2], 1e-9):
        raise Mismatch(f"got {fmt(got)}, the step back",
                       "arguments swapped? boxminus(R_a, R_b) is the step from R_b to R_a")
    if close(got, [0.0, 0.0, 1.0], 1e-9):
        raise Mismatch(f"got {fmt(got)}: the length is sin(π/2) = 1 instead of the angle π/2",
                       hints.AXIS_TIMES_SIN_VEE_HINT)
    if close(got, Log(R_a) - Log(R_SAMPLE), 1e-9):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from (0, 0, π/2)",
                       hints.LOGS_DO_NOT_SUBTRACT_HINT)
    raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from (0, 0, π/2)",
                   "boxminus(R_a, R_b) is the body-frame step from R_b to R_a: R_b Exp(δ) = R_a")


@public_check("boxminus", "round trip: R_b Exp(R_a ⊟ R_b) = R_a")
def _(boxminus):
    R_b = Exp([-0.5, 0.2, 0.9])
    got = require_shape(boxminus(R_SAMPLE, R_b), (3,))
    if close(R_b @ Exp(got), R_SAMPLE, 1e-9):
        return
    if close(Exp(got) @ R_b, R_SAMPLE, 1e-9):
        raise Mismatch("Exp(δ) R_b gives R_a, but R_b Exp(δ) does not",
                       hints.LEFT_DIFFERENCE_STEP_RIGHT_HINT)
    raise Mismatch("R_b @ Exp(boxminus(R_a, R_b)) is not R_a",
                   "boxminus(R_a, R_b) is the step δ with R_b Exp(δ) = R_a: compare with the page")


@public_check("boxminus", "accepts plain lists")
def _(boxminus):
    require_same_with_lists(boxminus, (R_SAMPLE, Exp([-0.5, 0.2, 0.9])), (3,), "boxminus(R_a, R_b)")


# ---------------------------------------------------------------- quat_boxplus
@public_check("quat_boxplus", "identity ⊞ (0, 0, π/2) is the quarter turn [cos 45°, 0, 0, sin 45°]")
def _(quat_boxplus):
    got = require_shape(quat_boxplus([1.0, 0.0, 0.0, 0.0], [0.0, 0.0, np.pi / 2]), (4,))
    half = np.sqrt(0.5)
    if close(got, [half, 0.0, 0.0, half], 1e-9) or close(got, [-half, 0.0, 0.0, -half], 1e-9):
        return
    if close(np.abs(got), [0.0, 0.0, 0.0, 1.0], 1e-9):
        raise Mismatch(f"got {fmt(got)}: a half turn", hints.TURNED_TWICE_FAR_QUATERNION_HINT)
    if close(got, [1.0, 0.0, 0.0, np.pi / 4], 1e-9):
        raise Mismatch(f"got {fmt(got)}, of norm {np.linalg.norm(got):.4f}",
                       "that is [1, δ/2] without normalising: not a unit quaternion; use the exact Exp_q(δ) = "
                       "[cos(|δ|/2), sin(|δ|/2) δ/|δ|]")
    shortcut = np.array([1.0, 0.0, 0.0, np.pi / 4])
    if close(got, shortcut / np.linalg.norm(shortcut), 1e-9):
        raise Mismatch(f"got {fmt(got)}: a turn of 2·atan(π/4) = {2 * np.arctan(np.pi / 4):.4f} rad, not π/2",
                       "that is [1, δ/2] rescaled to unit length: a unit quaternion, but it turns by 2·atan(|δ|/2) "
                       "instead of |δ|; use the exact Exp_q(δ) = [cos(|δ|/2), sin(|δ|/2) δ/|δ|]")
    if close(got, [0.0, 0.0, half, half], 1e-9) or close(got, [half, half, 0.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(got)}", "scalar first: [w, x, y, z]")
    raise Mismatch(f"got {fmt(got)}, {off_by(got, [half, 0.0, 0.0, half])} from [0.707, 0, 0, 0.707]")


# q ⊗ [1, δ/2] (not normalised) at q = [cos 0.4, sin 0.4, 0, 0], δ = (0.6, -0.8, 0.5), recomputed by the tests.
QUAT_NOT_NORMALISED = np.array([0.8042354913102899, 0.665736640509516, -0.46577898317831673, 0.07449791157726104])


@public_check("quat_boxplus", "the result has unit norm, even for a large δ")
def _(quat_boxplus):
    q = np.array([np.cos(0.4), np.sin(0.4), 0.0, 0.0])
    got = require_shape(quat_boxplus(q, [0.6, -0.8, 0.5]), (4,))
    norm = np.linalg.norm(got)
    if abs(norm - 1.0) > 1e-9:
        if close(got, QUAT_NOT_NORMALISED, 1e-9):
            raise Mismatch(f"|q ⊞ δ| = {norm:.6f}", hints.Q_WITHOUT_NORMALISING_NORM_HINT)
        raise Mismatch(f"|q ⊞ δ| = {norm:.6f}", "q ⊗ Exp_q(δ) is a product of unit quaternions, so its norm is 1")


@public_check("quat_boxplus", "perturbs on the right (q ⊗ Exp_q(δ)), and δ = 0 returns q")
def _(quat_boxplus):
    half = np.sqrt(0.5)
    q = np.array([half, half, 0.0, 0.0])                  # a quarter turn about x
    exp_z = np.array([half, 0.0, 0.0, half])               # Exp_q of a quarter turn about z
    got = require_shape(quat_boxplus(q, [0.0, 0.0, np.pi / 2]), (4,))
    expected = quat_product(q, exp_z)
    if not (close(got, expected, 1e-9) or close(got, -expected, 1e-9)):
        if abs(np.linalg.norm(got) - 1.0) > 1e-9:
            raise Mismatch(f"got {fmt(got)}, of norm {np.linalg.norm(got):.4f}",
                           "use the exact Exp_q(δ) = [cos(|δ|/2), sin(|δ|/2) δ/|δ|] and return a unit quaternion")
        left = quat_product(exp_z, q)
        if close(got, left, 1e-9) or close(got, -left, 1e-9):
            raise Mismatch("got Exp_q(δ) ⊗ q", hints.LEFT_QUAT_PERTURBATION_HINT)
        twice = quat_product(q, [0.0, 0.0, 0.0, 1.0])
        if close(got, twice, 1e-9) or close(got, -twice, 1e-9):
            raise Mismatch(f"got {fmt(got)}: a half turn about the body z axis instead of a quarter turn",
                           hints.TURNED_TWICE_FAR_QUATERNION_HINT)
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from {fmt(expected)} (sign aside)")
    same = require_shape(quat_boxplus(q, np.zeros(3)), (4,))
    if not (close(same, q, 1e-12) or close(same, -q, 1e-12)):
        raise Mismatch(f"quat_boxplus(q, 0) returned {fmt(same)}",
                       hints.USE_BELOW_TINY_ANGLE_HINT)


# Angles just below each power of ten, from 0.97 down to 9.7e-9: where small-angle thresholds sit, so a series
# that is too short for its threshold shows its largest error there. The axis is generic.
DECADE_ANGLES = (0.97, 0.097, 0.0097, 0.00097, 9.7e-05, 9.7e-06, 9.7e-07, 9.7e-08, 9.7e-09)
DECADE_AXIS = np.array([2.0, -1.0, 2.0]) / 3.0
Q_GENERIC = np.array([0.5, -0.3, 0.7, 0.4]) / np.linalg.norm([0.5, -0.3, 0.7, 0.4])


def _exp_q(d):
    """Exp_q(δ) = [cos(|δ|/2), sin(|δ|/2) δ/|δ|] for |δ| > 0 (the cosine and sine keep every digit)."""
    angle = np.linalg.norm(d)
    return np.concatenate([[np.cos(angle / 2.0)], np.sin(angle / 2.0) * np.asarray(d) / angle])


def _series_hint(theta, float32_at_large, formula, closed_form):
    """Who to blame for a miss at angle ``theta``: at θ = 0.97, above every small-angle threshold, float32 when the
    miss has rounding's size, else the formula itself (``closed_form``); below, the small-angle branch (a series
    too short for its threshold)."""
    if theta == DECADE_ANGLES[0]:
        return FLOAT32_HINT if float32_at_large else closed_form
    return (f"below your small-angle threshold the series is too short for θ = {theta:.2g}: {formula}; or move the "
            "threshold down to where the short series is exact to rounding")


@public_check("quat_boxplus", "exact to 4e-15 just below each power of ten, |δ| = 0.97 … 9.7e-9 (sign of q aside)")
def _(quat_boxplus):
    for theta in DECADE_ANGLES:
        d = theta * DECADE_AXIS
        got = require_shape(quat_boxplus(Q_GENERIC, d), (4,), f"quat_boxplus(q, δ) at |δ| = {theta:.2g}")
        expected = quat_product(Q_GENERIC, _exp_q(d))
        expected = expected if np.dot(got, expected) >= 0 else -expected
        error = np.max(np.abs(got - expected))
        if error > 4e-15:
            large = theta == DECADE_ANGLES[0] and single_precision_error(got, expected)
            raise Mismatch(f"off by {error:.1e} at |δ| = {theta:.2g} (tolerance 4e-15)", _series_hint(
                theta, large, "[1, δ/2] (normalised or not) is off by about |δ|³/24, exact to rounding only below "
                "about 1e-8; use Exp_q(δ) = [cos(|δ|/2), sin(|δ|/2) δ/|δ|] above that",
                "q ⊞ δ = q ⊗ Exp_q(δ), with Exp_q(δ) = [cos(|δ|/2), sin(|δ|/2) δ/|δ|]"))


# ---------------------------------------------------------------- numerical_jacobian
def _polynomial(x):
    return np.array([x[0] * x[1], x[2] ** 2])


def _steps_taken(numerical_jacobian, f, x, plus=None):
    """The perturbations the student's numerical_jacobian(f, x[, plus]) makes, seen by wrapping f (or plus):
    a list of vectors (x' - x, or the δ handed to plus), or None when they cannot be recorded."""
    seen = []
    try:
        if plus is None:
            x = np.asarray(x, dtype=float)

            def probe(v):
                seen.append(np.asarray(v, dtype=float).reshape(x.shape) - x)
                return f(v)
            numerical_jacobian(probe, x.copy())
        else:
            def probe_plus(R, d):
                seen.append(np.array(d, dtype=float).reshape(-1))
                return plus(R, d)
            numerical_jacobian(f, x, probe_plus)
    except Exception:                          # noqa: BLE001 - a hint is a bonus, never a new failure
        return None
    return seen


def _fixed_step_taken(steps, x, n):
    """The one step h = 10^-k (k in 1…4, 10…15) every forward move used, if the moves were exactly one positive
    step of that size along each of the n inputs (and never backwards); else None."""
    if not steps:
        return None
    spacing = np.spacing(np.abs(np.asarray(x, dtype=float).reshape(-1))) if x is not None else np.zeros(n)
    moves = [np.ravel(step) for step in steps if np.any(np.ravel(step) != 0.0)]
    if len(moves) != n or any(move.size != n or np.count_nonzero(move) != 1 for move in moves):
        return None
    directions = sorted(int(np.flatnonzero(move)[0]) for move in moves)
    if directions != list(range(n)):
        return None
    for k in [1, 2, 3, 4, 10, 11, 12, 13, 14, 15]:
        h = 10.0 ** -k
        if all(abs(move[j] - h) <= 1e-6 * h + spacing[j] for move in moves for j in np.flatnonzero(move)):
            return h
    return None


def _step_hint(got, exact, numerical_jacobian, f, x, plus=None, fallback=JACOBIAN_STEP_HINT):
    """Name a fixed step far too large (1e-1 … 1e-4) or far too small (1e-10 … 1e-15) when the student's own
    function is seen taking exactly one forward step of that size per input; the transpose; else ``fallback``."""
    got, exact = np.asarray(got, dtype=float), np.asarray(exact, dtype=float)
    if got.shape != exact.shape or not np.all(np.isfinite(got)):
        return fallback
    error = np.max(np.abs(got - exact))
    if got.shape[0] == got.shape[1] and np.max(np.abs(got.T - exact)) <= 1e-3 * error:
        return hints.ROW_I_OUTPUT_F_I_HINT
    n = 3 if plus is not None else np.asarray(x).size
    h = _fixed_step_taken(_steps_taken(numerical_jacobian, f, x, plus), None if plus is not None else x, n)
    if h is None:
        return fallback
    if h >= 1e-4:
        return (f"that is forward differences with a fixed step h = {h:g}, a step far too large: the slope is "
                "biased by about h/2 · f'' (the right side of the V-curve); use δ_j = max(|1e-4 x_j|, 1e-6), "
                "a step near √ε ≈ 1e-8, or central differences")
    return (f"that is forward differences with a fixed step h = {h:g}, a step far too small: rounding noise "
            "of about ε·|f|/h swamps the slope (the left side of the V-curve); use δ_j = max(|1e-4 x_j|, "
            "1e-6) or a step near √ε ≈ 1e-8")


def floor_hint(x):
    """Said when NaN or inf sit exactly in the columns where x_j = 0 (a relative step with no floor).

    Returns ``hint(value)`` for ``require_shape``'s ``nan_hint``; the hidden suite uses it too.
    """
    x = np.asarray(x, dtype=float)

    def hint(value):
        bad = ~np.all(np.isfinite(value), axis=0)
        if value.ndim == 2 and value.shape[1] == x.size and np.any(bad) and np.array_equal(bad, x == 0.0):
            return ("NaN exactly in the columns where x_j = 0: the relative step 1e-4·|x_j| is 0 there and the slope "
                    "0/0; keep the floor, δ_j = max(|1e-4 x_j|, 1e-6)")
        return None
    return hint


@public_check("numerical_jacobian", "shape (len(f(x)), n) and the slopes of a small polynomial")
def _(numerical_jacobian):
    got = numerical_jacobian(_polynomial, np.array([1.0, 2.0, 3.0]))
    if np.shape(got) == (3, 2):
        raise Mismatch(hints.RETURNED_SHAPE_F_R3_HINT,
                       hints.ROW_I_OUTPUT_F_HINT)
    got = require_shape(got, (2, 3))
    expected = np.array([[2.0, 1.0, 0.0], [0.0, 0.0, 6.0]])
    if not close(got, expected, 1e-3):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from the slopes",
                       _step_hint(got, expected, numerical_jacobian, _polynomial, np.array([1.0, 2.0, 3.0]),
                                  fallback="column j: "
                                  "(f(x + δ_j e_j) - f(x)) / δ_j, e.g. with δ_j = max(|1e-4 x_j|, 1e-6)"))


JACOBIAN_TYPE_HINT = ("return a float64 numpy array, on every path (with and without boxplus): build J with np.zeros "
                      "or np.column_stack, never as a list, and keep numpy's default float64")


def jacobian_type_problem(value):
    """What is wrong with ``value`` as numerical_jacobian's promised ``ndarray`` (float64), or None."""
    if not isinstance(value, np.ndarray):
        return f"returned a {type(value).__name__}, not a numpy array"
    if value.dtype != np.float64:
        return f"returned a {value.dtype} array, not float64"
    return None


@public_check("numerical_jacobian", "returns a float64 numpy array, with and without boxplus")
def _(numerical_jacobian):
    for value, how in ((numerical_jacobian(_polynomial, np.array([1.0, 2.0, 3.0])), "without boxplus"),
                       (numerical_jacobian(lambda R: np.asarray(R) @ [1.0, 2.0, 3.0], np.eye(3),
                                           lambda R, d: np.asarray(R) @ Exp(d)), "with boxplus")):
        problem = jacobian_type_problem(value)
        if problem:
            raise Mismatch(f"{how}: {problem}", JACOBIAN_TYPE_HINT)


def _wavy(x):
    return np.array([np.sin(x[0]) * x[1], np.exp(0.5 * x[2]) + x[0] * x[1]])


def _wavy_jacobian(x):
    return np.array([[np.cos(x[0]) * x[1], np.sin(x[0]), 0.0], [x[1], x[0], 0.5 * np.exp(0.5 * x[2])]])


# How far the lecture's forward steps land from _wavy_jacobian at these points, measured once
# (numbers, not the rule's code: the public checks never carry an answer).
_LECTURE_ERRORS = ((np.array([1.2, -3.0, 2.5]), 1.68e-4), (np.array([0.0, 0.5, -1.0]), 7.58e-6),
                   (np.zeros(3), 1.25e-7))                     # at 0 every step is the floor 1e-6


@public_check("numerical_jacobian", "at least as accurate as the lecture's forward steps δ_j = max(|1e-4 x_j|, 1e-6)")
def _(numerical_jacobian):
    for x, lecture_error in _LECTURE_ERRORS:
        got = require_shape(numerical_jacobian(_wavy, x), (2, 3), nan_hint=floor_hint(x))
        exact = _wavy_jacobian(x)
        allowed = jacobian_error_allowed(lecture_error, exact)
        error = np.max(np.abs(got - exact))
        if error > allowed:
            raise Mismatch(f"at x = {fmt(x)} the Jacobian is off by {error:.2g}, more than the {allowed:.2g} allowed "
                           "(twice the error of the lecture's forward steps)",
                           _step_hint(got, exact, numerical_jacobian, _wavy, x))


INTEGER_X_HINT = ("x = [3, 0, -2] arrives as integers: convert it with np.asarray(x, dtype=float), else the step "
                  "added to an integer entry is rounded away")


@public_check("numerical_jacobian", "accepts x as a list of integers, [3, 0, -2]")
def _(numerical_jacobian):
    got = require_shape(numerical_jacobian(lambda x: 2.0 * np.asarray(x, dtype=float), [3, 0, -2]), (3, 3))
    if not close(got, 2.0 * np.eye(3), 1e-6):
        raise Mismatch(f"the Jacobian of 2x at the integers [3, 0, -2] came out {fmt(got)}, expected 2 I",
                       INTEGER_X_HINT)


@public_check("numerical_jacobian", "works where x_j = 0 (the floor 1e-6 of the step rule)")
def _(numerical_jacobian):
    got = require_shape(numerical_jacobian(np.sin, np.zeros(3)), (3, 3), nan_hint=floor_hint(np.zeros(3)))
    if not close(got, E, 1e-5):
        raise Mismatch(f"the Jacobian of sin at 0 is {off_by(got, E)} from the identity (tolerance 1e-05)",
                       _step_hint(got, E, numerical_jacobian, np.sin, np.zeros(3),
                                  fallback="at x_j = 0 the lecture's step is its floor, "
                                  "δ_j = 1e-6: the slope of sin there is 1"))


@public_check("numerical_jacobian", "with a boxplus: 3 columns, one per turning direction of δ")
def _(numerical_jacobian):
    def rotate_x_axis(R):
        return np.asarray(R, dtype=float) @ E[0]

    def plus(R, d):                         # scipy's composition, the trusted oracle of a right boxplus
        return (Rotation.from_matrix(np.asarray(R, dtype=float)) * Rotation.from_rotvec(d)).as_matrix()

    got = numerical_jacobian(rotate_x_axis, np.eye(3), plus)
    if shape_problem(got, (3, 3)) and np.asarray(got).shape == (3, 9):
        raise Mismatch("got 9 columns: the 9 entries of the matrix were perturbed",
                       "with a boxplus, perturb the 3-vector δ in boxplus(x, δ), starting from δ = 0")
    got = require_shape(got, (3, 3))
    # Turning about z moves x towards y, about y towards -z, about x not at all.
    expected = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    if not close(got, expected, 1e-4):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from the turning directions",
                       _step_hint(got, expected, numerical_jacobian, rotate_x_axis, np.eye(3), plus,
                                  fallback="column j: "
                                  "(f(boxplus(x, h e_j)) - f(x)) / h with a small h (e.g. 1e-6)"))


P_GENERIC = np.array([0.7, -1.3, 2.2])                  # a point with three nonzero coordinates


@public_check("numerical_jacobian", "with a boxplus at a generic attitude: all 3 columns of the Jacobian of R ↦ R p, "
              "to 5e-6 (1 + |p|)")
def _(numerical_jacobian):
    def rotate(R):
        return np.asarray(R, dtype=float) @ P_GENERIC

    def plus(R, d):                         # scipy's composition, the trusted oracle of a right boxplus
        return (Rotation.from_matrix(np.asarray(R, dtype=float)) * Rotation.from_rotvec(d)).as_matrix()

    got = require_shape(numerical_jacobian(rotate, R_SAMPLE, plus), (3, 3))
    exact = JRP_AT_GENERIC                                # the exact Jacobian of R ↦ R p here, stored below
    allowed = 5e-6 * (1.0 + np.linalg.norm(P_GENERIC))
    if np.max(np.abs(got - exact)) <= allowed:
        return
    missing = [j for j in range(3) if np.all(got[:, j] == 0.0)]
    if missing:
        hint = (f"column {missing[0]} is all zeros: perturb along each of the 3 directions, "
                "j = 0, 1 and 2 (range(3))")
    else:
        hint = _step_hint(got, exact, numerical_jacobian, rotate, R_SAMPLE, plus,
                          fallback="column j: (f(boxplus(x, h e_j)) - f(x)) / h with h near 1e-6; keep f's values "
                          "in float64 (their difference is only about h |J|, float32 keeps 7 digits)")
    raise Mismatch(f"the Jacobian is {off_by(got, exact)} from the exact one (allowed {allowed:.2g})", hint)


# ---------------------------------------------------------------- jacobian_rotate_point
@public_check("jacobian_rotate_point", "R = I, p = x: turning about z moves x towards y, about y towards -z")
def _(jacobian_rotate_point):
    got = require_shape(jacobian_rotate_point(np.eye(3), [1.0, 0.0, 0.0]), (3, 3))
    expected = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    if not close(got, expected, 1e-12):     # antisymmetric here: a sign slip and a transpose look alike
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)}; expected {fmt(expected)}",
                       "got exactly minus the expected matrix: a flipped sign or the transpose (here, with R = I "
                       "and p = x, the two look alike); the next check tells them apart"
                       if close(got, -expected, 1e-12) else None)


# The exact Jacobian of R ↦ R p at R_SAMPLE, P_GENERIC, stored as numbers (recomputed by the constants test).
JRP_AT_GENERIC = np.array([[2.4083548374554673, 0.8225192144346913, -0.28026063975169463],
                           [-0.11185358876016993, 1.9045908748636529, 1.1610298406613035],
                           [-0.8469449519220964, 1.0129144787551643, 0.868022858512355]])
_TEST_DIRECTIONS = np.array([[2.0, -1.0, 2.0], [0.6, 0.8, 0.0], [-0.48, 0.36, 0.8]]) / np.array([[3.0], [1.0], [1.0]])


def _first_order(J, R, p, left, directions):
    """The largest remainder of the turned point against J δ, relative to 2 |p| |δ|², for |δ| = 1e-3 and 1e-4 along
    each direction: at most 1 when J is the Jacobian of R Exp(δ) p (of Exp(δ) R p with ``left``)."""
    worst = 0.0
    for direction in directions:
        for size in (1e-3, 1e-4):
            d = size * direction
            turned = Exp(d) @ R @ p if left else R @ Exp(d) @ p
            worst = max(worst, np.linalg.norm(turned - R @ p - J @ d) / (2.0 * np.linalg.norm(p) * size**2))
    return worst


def _rotate_point_hint(jacobian_rotate_point, J, R, p):
    """Name the slip by what the answer does: J works for the left perturbation; -J or Jᵀ would pass; J is the
    student's own answer at R = I, where it passes; or J's columns are perpendicular to the body coordinates p
    instead of to the world point R p (a turn moves R p at right angles to itself)."""
    def passes(candidate, rotation=R, left=False):
        return _first_order(candidate, rotation, p, left, _TEST_DIRECTIONS) <= 1.0

    for candidate, left, hint in [(J, True, hints.LEFT_JACOBIAN_OF_ROTATED_POINT_HINT),
                                  (-J, False, hints.ROTATED_POINT_SIGN_FLIPPED_HINT),
                                  (J.T, False, hints.TRANSPOSE_R_P_ROW_HINT)]:
        if passes(candidate, left=left):
            return hint
    try:
        at_identity = np.asarray(jacobian_rotate_point(np.eye(3), p), dtype=float)
    except Exception:
        at_identity = None
    if at_identity is not None and at_identity.shape == (3, 3) and close(at_identity, J, 1e-12) and \
            passes(at_identity, rotation=np.eye(3)):
        return hints.ROTATED_POINT_R_MISSING_HINT
    size = np.linalg.norm(p) * np.max(np.abs(J))
    if size > 0 and np.max(np.abs(p @ J)) <= 1e-9 * size and np.max(np.abs((R @ p) @ J)) > 1e-3 * size:
        return hints.FACTORS_WRONG_ORDER_R_HINT
    return "column j of J is how R Exp(δ) p moves per radian of δ_j, at δ = 0"


@public_check("jacobian_rotate_point", "first order: R Exp(δ) p - R p - J δ shrinks like |δ|²")
def _(jacobian_rotate_point):
    p = np.array([0.5, -1.0, 2.0])
    J = require_shape(jacobian_rotate_point(R_SAMPLE, p), (3, 3))
    direction = _TEST_DIRECTIONS[0]
    for size in (1e-3, 1e-4):
        d = size * direction
        remainder = np.linalg.norm(R_SAMPLE @ Exp(d) @ p - R_SAMPLE @ p - J @ d)
        if remainder > 2.0 * np.linalg.norm(p) * size**2:
            raise Mismatch(f"for |δ| = {size:g} the remainder is {remainder:.1e}, not of order |δ|²",
                           _rotate_point_hint(jacobian_rotate_point, J, R_SAMPLE, p))


@public_check("jacobian_rotate_point", "exact (to 1e-12) at a generic attitude and point, and accepts plain lists")
def _(jacobian_rotate_point):
    got = require_shape(jacobian_rotate_point(R_SAMPLE, P_GENERIC), (3, 3), "jacobian_rotate_point(R, p)")
    exact = JRP_AT_GENERIC
    if not close(got, exact, 1e-12):
        raise Mismatch(f"jacobian_rotate_point(R, p) is {off_by(got, exact)} from the exact Jacobian",
                       FLOAT32_HINT if single_precision_error(got, exact) else
                       "each column is d(R Exp(δ) p)/dδ_j at δ = 0, exactly: no finite step, no rounding to float32")
    require_same_with_lists(jacobian_rotate_point, (R_SAMPLE, P_GENERIC), (3, 3), "jacobian_rotate_point(R, p)")


# ---------------------------------------------------------------- right_jacobian_so3
@public_check("right_jacobian_so3", "Jr(0) is the identity, with no NaN")
def _(right_jacobian_so3):
    got = right_jacobian_so3(np.zeros(3))
    problem = shape_problem(got, (3, 3))
    if problem:
        raise Mismatch(f"right_jacobian_so3(0) {problem}",
                       hints.CLOSED_FORM_USE_TAYLOR_HINT
                       if problem == "returned NaN or inf values" else None)
    if not close(got, E, 1e-12):
        raise Mismatch(f"right_jacobian_so3(0) returned {fmt(got)}")


def _wx_coefficient(J, w):
    """The coefficient c of [w]× in J = I + c [w]× + …, read from J's antisymmetric part."""
    anti = 0.5 * (J - J.T)
    return float(np.dot([anti[2, 1], anti[0, 2], anti[1, 0]], w) / np.dot(w, w))


# At w = θ (0.6, 0, 0.8), θ = 1e-9 and 1e-6: Jr to full precision, stored as numbers (recomputed by the constants
# test).
JR_TINY = {1e-9: np.array([[1.0, 4.0000000000000007e-10, 8.000000000000001e-20],
                           [-4.0000000000000007e-10, 1.0, 3e-10],
                           [8.000000000000001e-20, -3e-10, 1.0]]),
           1e-6: np.array([[0.9999999999998933, 4e-07, 8e-14],
                           [-4e-07, 0.9999999999998334, 3e-07],
                           [8e-14, -3e-07, 0.99999999999994]])}


def _loses_digits(right_jacobian_so3, u):
    """True when the [w]× coefficient of the student's Jr misses its limit -1/2 by far more than rounding, and by
    more at θ = 1e-9 than at θ = 1e-6: the signature of a difference of nearly equal numbers, whose lost digits
    grow as θ shrinks (a correct coefficient is within 1e-12 of -1/2 at both angles)."""
    misses = [abs(_wx_coefficient(require_shape(right_jacobian_so3(t * u), (3, 3)), t * u) + 0.5) for t in (1e-6, 1e-9)]
    return misses[0] > 1e-9 and misses[1] > 10.0 * misses[0]


@public_check("right_jacobian_so3", "tiny angles |w| = 1e-9 and 1e-6: Jr ≈ I - [w]×/2 to full precision")
def _(right_jacobian_so3):
    u = np.array([0.6, 0.0, 0.8])
    for theta in (1e-9, 1e-6):
        w = theta * u
        got = require_shape(right_jacobian_so3(w), (3, 3))
        expected = JR_TINY[theta]
        error = np.max(np.abs(got - expected))
        if error <= 1e-14 + 1e-6 * theta:
            continue
        c = _wx_coefficient(got, w)
        seen = f"off by {error:.1e} at θ = {theta:g}: the coefficient of [w]× is {c:.9g}, expected -0.5"
        if abs(c - 0.5) < 1e-6:
            raise Mismatch(seen, "that is the left Jacobian (the sign of the [w]× term is flipped); "
                           "Jr = I - a [w]× + b [w]×²")
        if abs(c + 1.0 / 6.0) < 1e-6:
            raise Mismatch(seen, hints.COEFFICIENTS_SWAPPED_COS_MULTIPLIES_HINT)
        if _loses_digits(right_jacobian_so3, u):
            raise Mismatch(seen, hints.CLOSED_FORM_LOSES_DIGITS_HINT)
        if close(got, E, 1e-300):
            raise Mismatch(seen, f"returned I at θ = {theta:g}: the first-order term -[w]×/2 is missing; below a "
                           "small angle use the Taylor series of a and b in Jr = I - a [w]× + b [w]×², not I")
        raise Mismatch(seen, "Jr is off at a tiny angle: below a small angle use the Taylor series of a and b in "
                       "Jr = I - a [w]× + b [w]×² (find them from your series), each with its θ² term")


@public_check("right_jacobian_so3", "first order: Exp(w + dw) ≈ Exp(w) Exp(Jr dw) with an error of order |dw|²")
def _(right_jacobian_so3):
    w = np.array([0.9, -1.2, 0.6])
    J = require_shape(right_jacobian_so3(w), (3, 3))
    dw = 1e-4 * np.array([0.48, 0.6, -0.64])
    leftover = np.linalg.norm(Log((Exp(w) @ Exp(J @ dw)).T @ Exp(w + dw)))
    if leftover > 1e-8:
        hint = hints.RIGHT_JACOBIAN_FORMULA_HINT
        if np.linalg.norm(Log((Exp(J @ dw) @ Exp(w)).T @ Exp(w + dw))) < 1e-8:
            hint = hints.LEFT_JACOBIAN_WORKS_ON_LEFT_HINT
        raise Mismatch(f"for |dw| = 1e-4 the leftover angle is {leftover:.1e} rad, expected below 1e-8", hint)


# Jr and Jr⁻¹ at w = θ u for θ = 0.97 · 10⁻ᵏ, to full precision, summed from their series (recomputed by
# tests/test_public_check_constants_lesson06.py); stored as numbers so that no formula sits on the page.
JR_AT_DECADES = {
    0.97: np.array([[0.9168875792316438, 0.2655182405171563, 0.21587154102693434],
                    [-0.3320081771318412, 0.8670201267706301, 0.2655182405171563],
                    [-0.08289166779756442, -0.3320081771318412, 0.9168875792316438]]),
    0.097: np.array([[0.9991292060622728, 0.03195967168036984, 0.01685062977791212],
                     [-0.032656306830551596, 0.9986067296996365, 0.03195967168036984],
                     [-0.015457359477548598, -0.032656306830551596, 0.9991292060622728]]),
    0.0097: np.array([[0.9999912880039487, 0.0032298231829645274, 0.0016236235875336145],
                      [-0.003236792779805608, 0.9999860608063178, 0.0032298231829645274],
                      [-0.0016096843938514533, -0.003236792779805608, 0.9999912880039487]]),
    0.00097: np.array([[0.9999999128796337, 0.0003232984598347977, 0.00016173635028367064],
                       [-0.0003233681561278151, 0.999999860607414, 0.0003232984598347977],
                       [-0.00016159695769763576, -0.0003233681561278151, 0.9999999128796337]]),
    9.7e-05: np.array([[0.9999999991287963, 3.233298482649999e-05, 1.6167363616953285e-05],
                       [-3.233368178946262e-05, 0.999999998606074, 3.233298482649999e-05],
                       [-1.6165969691028017e-05, -3.233368178946262e-05, 0.9999999991287963]]),
    9.7e-06: np.array([[0.999999999991288, 3.2333298484931666e-06, 1.6166736362836203e-06],
                       [-3.233336818122796e-06, 0.9999999999860607, 3.2333298484931666e-06],
                       [-1.616659697024361e-06, -3.233336818122796e-06, 0.999999999991288]]),
    9.7e-07: np.array([[0.9999999999999128, 3.2333329848515985e-07, 1.616667363629503e-07],
                       [-3.233333681814561e-07, 0.9999999999998606, 3.2333329848515985e-07],
                       [-1.616665969703577e-07, -3.233333681814561e-07, 0.9999999999999128]]),
    9.7e-08: np.array([[0.9999999999999991, 3.233333298485182e-08, 1.6166667363629615e-08],
                       [-3.233333368181479e-08, 0.9999999999999986, 3.233333298485182e-08],
                       [-1.616666596970369e-08, -3.233333368181479e-08, 0.9999999999999991]]),
    9.7e-09: np.array([[1.0, 3.233333329848518e-09, 1.6166666736362961e-09],
                       [-3.2333333368181476e-09, 1.0, 3.233333329848518e-09],
                       [-1.6166666596970368e-09, -3.2333333368181476e-09, 1.0]]),
}
JR_INV_AT_DECADES = {
    0.97: np.array([[0.9557410468012884, -0.341036914612818, -0.12625950410769735],
                    [0.3056297520538486, 0.9291856748820614, -0.341036914612818],
                    [0.19707382922563596, 0.3056297520538486, 0.9557410468012884]]),
    0.097: np.array([[0.9995643298232112, -0.03250760140404887, -0.015818130525235598],
                     [0.032159065262617796, 0.9993029277171379, -0.03250760140404887],
                     [0.016515202808097734, 0.032159065262617796, 0.9995643298232112]]),
    0.0097: np.array([[0.9999956439746505, -0.003235075743473132, -0.0016131818463870691],
                      [0.0032315909231935345, 0.9999930303594408, -0.003235075743473132],
                      [0.0016201514869462641, 0.0032315909231935345, 0.9999956439746505]]),
    0.00097: np.array([[0.9999999564398141, -0.00032335075740768065, -0.00016163181851797204],
                       [0.00032331590925898605, 0.9999999303037026, -0.00032335075740768065],
                       [0.0001617015148153613, 0.00032331590925898605, 0.9999999564398141]]),
    9.7e-05: np.array([[0.9999999995643981, -3.23335075740741e-05, -1.616631818518513e-05],
                       [3.2333159092592565e-05, 0.9999999993030371, -3.23335075740741e-05],
                       [1.61670151481482e-05, 3.2333159092592565e-05, 0.9999999995643981]]),
    9.7e-06: np.array([[0.9999999999956439, -3.233335075740741e-06, -1.6166631818518518e-06],
                       [3.233331590925926e-06, 0.9999999999930304, -3.233335075740741e-06],
                       [1.6166701514814816e-06, 3.233331590925926e-06, 0.9999999999956439]]),
    9.7e-07: np.array([[0.9999999999999565, -3.2333335075740744e-07, -1.6166663181851854e-07],
                       [3.2333331590925925e-07, 0.9999999999999303, -3.2333335075740744e-07],
                       [1.616667015148148e-07, 3.2333331590925925e-07, 0.9999999999999565]]),
    9.7e-08: np.array([[0.9999999999999996, -3.233333350757407e-08, -1.6166666318185185e-08],
                       [3.233333315909259e-08, 0.9999999999999993, -3.233333350757407e-08],
                       [1.6166667015148147e-08, 3.233333315909259e-08, 0.9999999999999996]]),
    9.7e-09: np.array([[1.0, -3.2333333350757405e-09, -1.6166666631818517e-09],
                       [3.2333333315909254e-09, 1.0, -3.2333333350757405e-09],
                       [1.6166666701514812e-09, 3.2333333315909254e-09, 1.0]]),
}


def _every_decade(function, name, expected_at, formula, closed_form, series, first_order):
    """Compare ``function(θ u)`` with ``expected[θ]`` to 1e-13 at every angle of DECADE_ANGLES.

    The first miss is reported. Below θ = 0.97 the errors at all the angles name the cause: a series too short
    for its threshold is off by more at larger angles, a closed form that cancels by more at smaller ones.
    """
    errors, identity = {}, {}
    for theta in DECADE_ANGLES:
        w = theta * DECADE_AXIS
        given = w.tolist() if theta == 0.097 else w                 # one of them as a plain list
        got = require_shape(function(given), (3, 3), f"{name} at θ = {theta:.2g}")
        expected = expected_at[theta]
        errors[theta] = np.max(np.abs(got - expected))
        identity[theta] = close(got, E, 1e-300)
        if theta == DECADE_ANGLES[0] and errors[theta] > 1e-13:
            raise Mismatch(f"{name} is off by {errors[theta]:.1e} at θ = {theta:.2g} (tolerance 1e-13)",
                           _series_hint(theta, single_precision_error(got, expected), formula, closed_form))
    failing = [theta for theta in DECADE_ANGLES if errors[theta] > 1e-13]
    if not failing:
        return
    theta = failing[0]
    seen = f"{name} is off by {errors[theta]:.1e} at θ = {theta:.2g} (tolerance 1e-13)"
    if identity[theta]:
        raise Mismatch(seen, f"returned I at θ = {theta:.2g}: the first-order term {first_order} is missing below your "
                       f"threshold; use the series there, {series}")
    if len(failing) > 1 and errors[failing[-1]] > errors[theta]:
        raise Mismatch(seen + f", and by more at smaller angles ({errors[failing[-1]]:.1e} at θ = {failing[-1]:.2g})",
                       "the closed form cancels at small angles (a difference of nearly equal terms keeps fewer "
                       f"digits as θ shrinks): below a small-angle threshold use the series, {series}")
    raise Mismatch(seen, _series_hint(theta, False, formula, closed_form))


@public_check("right_jacobian_so3", "exact to 1e-13 just below each power of ten, θ = 0.97 … 9.7e-9 (one as a list)")
def _(right_jacobian_so3):
    _every_decade(right_jacobian_so3, "right_jacobian_so3", JR_AT_DECADES,
                  "keep the θ² term of each coefficient's series (without it the error grows like θ³)",
                  hints.RIGHT_JACOBIAN_FORMULA_HINT,
                  "the Taylor series of a and b, each with its θ² term", "-[w]×/2")


# ---------------------------------------------------------------- right_jacobian_inv_so3
@public_check("right_jacobian_inv_so3", "Jr⁻¹(0) is the identity, with no NaN")
def _(right_jacobian_inv_so3):
    got = right_jacobian_inv_so3(np.zeros(3))
    problem = shape_problem(got, (3, 3))
    if problem:
        raise Mismatch(f"right_jacobian_inv_so3(0) {problem}",
                       "the closed form is 0/0 at θ = 0: use the series of the [w]×² coefficient below a small angle"
                       if problem == "returned NaN or inf values" else None)
    if not close(got, E, 1e-12):
        raise Mismatch(f"right_jacobian_inv_so3(0) returned {fmt(got)}")


# At w = (0.9, -1.2, 0.6): Jr(w) (the slips "Jr itself" and "Jr transposed") and I + [w]×/2 (first order only),
# stored as numbers (recomputed by the constants test).
JR_AT_W = np.array([[0.7368032415238339, 0.08225164099319576, 0.5592984197006408],
                    [-0.39808775116459516, 0.828922106990492, 0.25497584072787677],
                    [-0.4013803646149411, -0.4655332475088097, 0.6710040519047924]])
JR_INV_FIRST_ORDER_AT_W = np.array([[1.0, -0.3, -0.6], [0.3, 1.0, -0.45], [0.6, 0.45, 1.0]])


@public_check("right_jacobian_inv_so3", "first order: Log(Exp(w) Exp(v)) ≈ w + Jr⁻¹(w) v")
def _(right_jacobian_inv_so3):
    w = np.array([0.9, -1.2, 0.6])
    J = require_shape(right_jacobian_inv_so3(w), (3, 3))
    v = 1e-4 * np.array([0.48, 0.6, -0.64])
    error = np.linalg.norm(Log(Exp(w) @ Exp(v)) - w - J @ v)
    if error > 1e-8:
        hint = hints.RIGHT_JACOBIAN_INVERSE_FORMULA_HINT
        if np.linalg.norm(Log(Exp(v) @ Exp(w)) - w - J @ v) < 1e-8:
            hint = "this is the inverse of the left Jacobian (it works for Exp(v) Exp(w)): flip the sign of [w]×/2"
        elif close(J, JR_AT_W.T, 1e-9):
            hint = hints.JACOBIAN_TRANSPOSE_NOT_INVERSE_HINT
        elif close(J, JR_AT_W, 1e-9):
            hint = "that is Jr(w) itself, not its inverse"
        elif close(J, JR_INV_FIRST_ORDER_AT_W, 1e-12):
            hint = (hints.FIRST_ORDER_PART_ONLY_HINT)
        raise Mismatch(f"for |v| = 1e-4 the error is {error:.1e}, expected below 1e-8", hint)


# I + [w]×/2 at w = 1e-9 (0, 0.6, 0.8): Jr⁻¹ there to full precision (the [w]×² term is 1e-19).
JR_INV_TINY = np.array([[1.0, -4.0000000000000007e-10, 3e-10], [4.0000000000000007e-10, 1.0, 0.0], [-3e-10, 0.0, 1.0]])


@public_check("right_jacobian_inv_so3", "tiny angle |w| = 1e-9: Jr⁻¹ ≈ I + [w]×/2, finite")
def _(right_jacobian_inv_so3):
    w = 1e-9 * np.array([0.0, 0.6, 0.8])
    got = require_shape(right_jacobian_inv_so3(w), (3, 3))
    if not close(got, JR_INV_TINY, 1e-14):
        c = _wx_coefficient(got, w)
        seen = f"off by {np.max(np.abs(got - JR_INV_TINY)):.1e} at θ = 1e-9: the coefficient of [w]× is {c:.9g}"
        if abs(c + 0.5) < 1e-6:
            raise Mismatch(seen, "the [w]× term has the wrong sign: -[w]×/2 belongs to Jr; its inverse has +[w]×/2")
        raise Mismatch(seen, "the [w]×² coefficient is off at tiny angles: use its series (on the page) below a "
                       "small angle")


@public_check("right_jacobian_inv_so3", "exact to 1e-13 just below each power of ten, θ = 0.97 … 9.7e-9 "
              "(one as a list)")
def _(right_jacobian_inv_so3):
    _every_decade(right_jacobian_inv_so3, "right_jacobian_inv_so3", JR_INV_AT_DECADES,
                  "keep the θ² term of c's series (the one-term c = 1/12 is off by about θ⁴/720)",
                  hints.RIGHT_JACOBIAN_INVERSE_FORMULA_HINT, "the series of c on the page, with its θ² term", "+[w]×/2")
