"""Public checks for lesson 07: poses and rigid-body transformations.

The checks use poses written out by hand (a quarter turn about z and a shift
by (1, 2, 3)), definitional facts (a pose times its inverse is the identity,
a pure translation has V = I), and the values of the exponential map and of
the usual slips at the checks' fixed inputs, stored as numbers (worked out
once; ``tests/test_public_check_constants_lesson07.py`` recomputes them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import FLOAT32_HINT, close, single_precision_error
from ..lie import Exp
from .common import fmt, off_by, require_pose, require_same_with_lists, require_shape
from .lesson01 import SQUARE_BATCH_HINT
from .lesson06 import DECADE_ANGLES, DECADE_AXIS

# A quarter turn about z (x goes to y) followed by a shift of (1, 2, 3) m, written out.
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
SHIFT = np.array([1.0, 2.0, 3.0])
T_QUARTER = np.array([[0.0, -1.0, 0.0, 1.0],
                      [1.0, 0.0, 0.0, 2.0],
                      [0.0, 0.0, 1.0, 3.0],
                      [0.0, 0.0, 0.0, 1.0]])
# A quarter turn about x (y goes to z) with a shift of (0, -1, 0.5) m.
T_QUARTER_X = np.array([[1.0, 0.0, 0.0, 0.0],
                        [0.0, 0.0, -1.0, -1.0],
                        [0.0, 1.0, 0.0, 0.5],
                        [0.0, 0.0, 0.0, 1.0]])


MIRROR_HINT = "xi = [rho, phi]: translation part first (xi[:3]), rotation part last (xi[3:])"
FORGETS_V_HINT = hints.EXP_SE3_TRANSLATION_IS_RHO_HINT
V_SERIES_HINT = ("the pose is off: compare it with expm of the 4×4 twist matrix ξ^ at this xi, and your closed form of "
                 "V with the first terms of its series on the page")
SERIES_NAN_HINT_V = ("NaN or inf: the closed forms of V's coefficients divide 0 by 0 at θ = 0; "
                     "below θ = 1e-2 use their Taylor series, each with its θ² term")
SERIES_HINT_C = (hints.SMALL_ANGLE_SERIES_HINT)


def _first_match(got, candidates):
    """The (reason, hint) of the first candidate (a mistake's value computed from the inputs) that got equals."""
    for candidate, reason, hint in candidates:
        if close(got, candidate, 1e-9):
            return reason, hint
    return None


# A generic pose and generic points: none of their numbers is exact in float32, so an answer that drops to
# single precision anywhere shows an error of about 1e-8 instead of 1e-16.
R_GENERIC = Exp([0.4, -0.7, 1.1])
T_GENERIC = np.vstack([np.column_stack([R_GENERIC, [0.3, -1.7, 2.9]]), [0.0, 0.0, 0.0, 1.0]])
T_GENERIC_2 = np.vstack([np.column_stack([Exp([-1.3, 0.2, 0.6]), [-2.1, 0.7, 1.3]]), [0.0, 0.0, 0.0, 1.0]])
P_GENERIC = np.array([[0.3, -1.1, 2.7], [1.9, 0.6, -0.4], [-2.2, 1.3, 0.1], [0.7, 0.7, -3.1]])


def require_exact(got, expected, what, tol=1e-12, hint=None):
    """:class:`Mismatch` unless ``got`` matches ``expected`` to ``tol`` (times its size); float32 named as such."""
    got = np.asarray(got, dtype=float)
    size = max(1.0, float(np.max(np.abs(expected))))
    if got.shape == np.shape(expected) and np.max(np.abs(got - expected)) <= tol * size:
        return
    raise Mismatch(f"{what} is {off_by(got, expected)} from the exact value (tolerance {tol * size:.1g})",
                   FLOAT32_HINT if single_precision_error(got, expected) else hint)


# ---------------------------------------------------------------- make_pose
# [[Qᵀ, t]] for the quarter turn Q and t = (1, 2, 3), written out: the slip "copies Rᵀ".
MAKE_POSE_R_TRANSPOSED = np.array([[0.0, 1.0, 0.0, 1.0], [-1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0],
                                   [0.0, 0.0, 0.0, 1.0]])
# t = (1, 2, 3) in the bottom row under the quarter turn, written out: the slip "t in the bottom row".
MAKE_POSE_T_IN_BOTTOM_ROW = np.array([[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0],
                                      [1.0, 2.0, 3.0, 1.0]])


@public_check("make_pose", "puts R top-left, t in the last column and [0, 0, 0, 1] below")
def _(make_pose):
    T = require_shape(make_pose(QUARTER_TURN_Z, SHIFT), (4, 4))
    if close(T, T_QUARTER, 1e-12):
        return
    no_one = T_QUARTER.copy()
    no_one[3, 3] = 0.0
    found = _first_match(T, [
        (T_QUARTER.T, "got the transpose of the pose matrix", "t goes in the last column (T[:3, 3]), not the bottom row"),
        (MAKE_POSE_T_IN_BOTTOM_ROW, "t ended up in the bottom row", "t goes in the last column (T[:3, 3]), not the bottom row"),
        (MAKE_POSE_R_TRANSPOSED, "the top-left 3×3 block is Rᵀ", "copy R itself, not its transpose"),
        (no_one, "the bottom row is [0, 0, 0, 0], expected [0, 0, 0, 1]",
         "T[3, 3] must be 1: start from np.eye(4), not np.zeros((4, 4))"),
    ])
    if found:
        raise Mismatch(*found)
    raise Mismatch(f"got {fmt(T)}, expected {fmt(T_QUARTER)} ({off_by(T, T_QUARTER)})",
                   "T = [[R, t], [0, 0, 0, 1]]: R in T[:3, :3], t in T[:3, 3]")


@public_check("make_pose", "accepts plain lists")
def _(make_pose):
    require_same_with_lists(make_pose, (QUARTER_TURN_Z, SHIFT), (4, 4), "make_pose")


@public_check("make_pose", "a generic R and t come back with every digit (float64 kept)")
def _(make_pose):
    got = require_shape(make_pose(R_GENERIC, T_GENERIC[:3, 3]), (4, 4), "make_pose(R, t)")
    require_exact(got, T_GENERIC, "make_pose(R, t)", tol=0.0, hint="T = [[R, t], [0, 0, 0, 1]], copied exactly")


# ---------------------------------------------------------------- to_homogeneous / from_homogeneous
@public_check("to_homogeneous", "appends a 1 to one point: shape (3,) → (4,)")
def _(to_homogeneous):
    got = to_homogeneous([1.0, 2.0, 3.0])
    if np.shape(got) == (1, 4):
        raise Mismatch("returned shape 1×4, expected 4",
                       "one point of shape (3,) became a batch of shape (1, 4): append along the last axis, "
                       "np.concatenate([P, ones], axis=-1), so (3,) gives (4,)")
    got = require_shape(got, (4,))
    if close(got, [1.0, 2.0, 3.0, 0.0], 1e-12):
        raise Mismatch("appended a 0", "a 0 marks a direction; points get a 1")
    if close(got, [1.0, 1.0, 2.0, 3.0], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [1, 2, 3, 1]", "the 1 goes last: [x, y, z] becomes [x, y, z, 1]")
    if not close(got, [1.0, 2.0, 3.0, 1.0], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [1, 2, 3, 1]")


@public_check("to_homogeneous", "appends a 1 to every row: shape (N, 3) → (N, 4)")
def _(to_homogeneous):
    P = np.array([[1.0, 2.0, 3.0], [-4.0, 0.5, 0.0]])
    got = to_homogeneous(P)
    if np.shape(got) == (3, 3):
        raise Mismatch("returned shape 3×3: a row of ones was added below the points",
                       "append a column: the new coordinate belongs to every point (axis=-1)")
    got = require_shape(got, (2, 4))
    if close(got, [[1.0, 2.0, 3.0, 0.0], [-4.0, 0.5, 0.0, 0.0]], 1e-12):
        raise Mismatch(f"got {fmt(got)}", "a 0 marks a direction; points get a 1")
    if close(got, [[1.0, 1.0, 2.0, 3.0], [1.0, -4.0, 0.5, 0.0]], 1e-12):
        raise Mismatch(f"got {fmt(got)}", "the 1 goes last: [x, y, z] becomes [x, y, z, 1]")
    if not close(got, [[1.0, 2.0, 3.0, 1.0], [-4.0, 0.5, 0.0, 1.0]], 1e-12):
        raise Mismatch(f"got {fmt(got)}", "each row should be the point followed by a 1")


@public_check("to_homogeneous", "generic rows come back with every digit, a 1 appended (float64 kept)")
def _(to_homogeneous):
    got = require_shape(to_homogeneous(P_GENERIC), (4, 4), "to_homogeneous(P) for 4 points")
    require_exact(got, np.column_stack([P_GENERIC, np.ones(4)]), "to_homogeneous(P)", tol=0.0,
                  hint="each row [x, y, z] becomes [x, y, z, 1], copied exactly")


@public_check("from_homogeneous", "divides by the last coordinate: [2, 4, 6, 2] → [1, 2, 3]")
def _(from_homogeneous):
    P_h = np.array([2.0, 4.0, 6.0, 2.0])
    got = require_shape(from_homogeneous(P_h.tolist()), (3,))
    if close(got, [1.0, 2.0, 3.0], 1e-12):
        return
    found = _dehomogeneous_mistake(got, DEHOMOGENEOUS_SLIPS_ONE)
    raise Mismatch(f"got {fmt(got)}, expected [1, 2, 3]", found or "[x, y, z, w] is the point [x/w, y/w, z/w]")


_NO_DIVIDE = "divide by the last coordinate before dropping it: [x, y, z, w] is [x/w, y/w, z/w]"
_DIVIDES_FIRST = hints.DIVIDED_FIRST_COORDINATE_X_HINT
_MULTIPLIES = hints.MULTIPLIED_LAST_COORDINATE_DIVIDE_HINT
# The slips at the checks' points, written out: [2, 4, 6, 2] and the rows of P_h in the second check.
DEHOMOGENEOUS_SLIPS_ONE = [([2.0, 4.0, 6.0], _NO_DIVIDE), ([2.0, 3.0, 1.0], _DIVIDES_FIRST),
                           ([4.0, 8.0, 12.0], _MULTIPLIES)]
DEHOMOGENEOUS_SLIPS_ROWS = [([[2.0, 4.0, 6.0], [1.0, -1.0, 0.5], [3.0, 0.0, 0.0]], _NO_DIVIDE),
                            ([[2.0, 3.0, 1.0], [-1.0, 0.5, 0.5], [0.0, 0.0, 1.0 / 3.0]], _DIVIDES_FIRST),
                            ([[4.0, 8.0, 12.0], [0.5, -0.5, 0.25], [3.0, 0.0, 0.0]], _MULTIPLIES)]


def _dehomogeneous_mistake(got, slips):
    found = _first_match(got, [(value, "", hint) for value, hint in slips])
    return found[1] if found else None


@public_check("from_homogeneous", "works on rows: shape (N, 4) → (N, 3)")
def _(from_homogeneous):
    P_h = np.array([[2.0, 4.0, 6.0, 2.0], [1.0, -1.0, 0.5, 0.5], [3.0, 0.0, 0.0, 1.0]])
    expected = np.array([[1.0, 2.0, 3.0], [2.0, -2.0, 1.0], [3.0, 0.0, 0.0]])
    single_ok = close(from_homogeneous(P_h[0].copy()), expected[0], 1e-12)
    single_only = ("works for one point only (P_h[:3] / P_h[3] indexes rows): index the last axis, "
                   "P_h[..., :3] / P_h[..., 3:]")
    try:
        got = from_homogeneous(P_h.copy())
    except IndexError as error:
        if single_ok:
            raise Mismatch(f"rows of shape (3, 4) raised IndexError: {error}", single_only) from None
        raise
    if single_ok and np.shape(got) == (3, 4) and close(got, P_h[:3] / P_h[3:4], 1e-12):
        raise Mismatch("returned shape 3×4, expected 3×3", single_only)
    got = require_shape(got, (3, 3))
    if not close(got, expected, 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)}",
                       _dehomogeneous_mistake(got, DEHOMOGENEOUS_SLIPS_ROWS) or
                       "divide each row by its own last coordinate (P_h[..., -1:] keeps the shape)")


@public_check("from_homogeneous", "generic rows with a last coordinate of 0.7 are divided to 1e-15 (float64 kept)")
def _(from_homogeneous):
    P_h = 0.7 * np.column_stack([P_GENERIC, np.ones(4)])
    got = require_shape(from_homogeneous(P_h), (4, 3), "from_homogeneous(P_h) for 4 points")
    require_exact(got, P_GENERIC, "from_homogeneous(P_h)", tol=1e-15,
                  hint="divide the first three coordinates of each row by its last one")


# ---------------------------------------------------------------- transform_points
@public_check("transform_points", "turns and shifts N points (shape (N, 3)): p_a = R p_b + t")
def _(transform_points):
    P = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 2.0, -1.0]])
    got = require_shape(transform_points(T_QUARTER, P), (3, 3))
    expected = np.array([[1.0, 3.0, 3.0], [1.0, 2.0, 3.0], [-1.0, 2.0, 2.0]])
    if close(got, expected, 1e-12):
        return
    found = _transform_mistake(got, TRANSFORM_SLIPS + [COLUMNS_SLIP])
    if found:
        raise Mismatch(*found)
    raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)} ({off_by(got, expected)})",
                   hints.TRANSFORM_ROWS_FORMULA_HINT)


_MULTIPLIED_BY_T = ("the points were multiplied by T instead of T.T",
                    hints.HOMOGENEOUS_ROWS_TRANSPOSE_HINT)
# The slips of transform_points(T_QUARTER, P) for P = [[1, 0, 0], [0, 0, 0], [0, 2, -1]], written out (each row
# is the slip for that one point; the constants test recomputes them).
TRANSFORM_SLIPS = [
    ([[0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [-2.0, 0.0, -1.0]],             # R p, no shift
     "the points were turned but not shifted", "the translation is missing: add t = T[:3, 3]"),
    ([[1.0, 1.0, 3.0], [1.0, 2.0, 3.0], [3.0, 2.0, 2.0]],              # P @ R + t
     "the points were turned the wrong way", "for rows use P @ R.T (or P_h @ T.T), not P @ R"),
    ([[0.0, -1.0, 0.0], [0.0, 0.0, 0.0], [2.0, 0.0, -1.0]], *_MULTIPLIED_BY_T),    # (P_h @ T)[:, :3]
    ([[0.0, -0.5, 0.0], [0.0, 0.0, 0.0], [1.0, 0.0, -0.5]], *_MULTIPLIED_BY_T),    # P_h @ T, divided by its w
    ([[-2.0, 2.0, 3.0], [-2.0, 1.0, 3.0], [-4.0, 1.0, 2.0]],           # R (p + t)
     "the points were shifted, then turned", "rotate first, then shift: R p + t"),
]
# R P + t, the points taken as columns: a batch of 3 points is square, and shape[0] == 3 does not tell it from one point
COLUMNS_SLIP = ([[1.0, 1.0, 1.0], [3.0, 2.0, 2.0], [3.0, 5.0, 2.0]], "the 3 points (shape (3, 3)) were read as columns",
                SQUARE_BATCH_HINT)


def _transform_mistake(got, slips, row=None):
    """The (reason, hint) of the slip ``got`` is; ``row`` picks one point's row of the stored slips."""
    return _first_match(got, [(np.asarray(value)[row] if row is not None else value, reason, hint)
                              for value, reason, hint in slips])


@public_check("transform_points", "accepts a single point of shape (3,)")
def _(transform_points):
    got = require_shape(transform_points(T_QUARTER, [1.0, 0.0, 0.0]), (3,))
    if not close(got, [1.0, 3.0, 3.0], 1e-12):
        found = _transform_mistake(got, TRANSFORM_SLIPS, row=0)      # the point [1, 0, 0] is P's first row
        raise Mismatch(f"got {fmt(got)} for the point [1, 0, 0], expected [1, 3, 3]",
                       found[1] if found else "p_a = R p_b + t")


@public_check("transform_points", "a generic pose moves 4 generic points to 1e-12 (float64 kept)")
def _(transform_points):
    got = require_shape(transform_points(T_GENERIC, P_GENERIC), (4, 3), "transform_points(T, P) for 4 points")
    require_exact(got, P_GENERIC @ R_GENERIC.T + T_GENERIC[:3, 3], "transform_points(T, P)",
                  hint="p_a = R p_b + t for every row")


# ---------------------------------------------------------------- pose_compose
@public_check("transform_points", "accepts plain lists")
def _(transform_points):
    require_same_with_lists(transform_points, (T_QUARTER_X, [[0.5, -1.0, 2.0], [1.0, 0.0, 0.0]]), (2, 3),
                            "transform_points")


# The slips of pose_compose(T_QUARTER, T_QUARTER_X), written out (the constants test recomputes them).
COMPOSE_SLIPS = [
    (np.array([[0.0, -1.0, 0.0, 1.0], [0.0, 0.0, -1.0, -4.0], [1.0, 0.0, 0.0, 2.5], [0.0, 0.0, 0.0, 1.0]]),      # T_bc T_ab
     "the two poses are multiplied in the wrong order",
     "the order is reversed: inner letters must match, T_ac = T_ab @ T_bc"),
    (np.array([[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, -2.0], [0.0, 0.0, 0.0, 1.5], [0.0, 0.0, 0.0, 1.0]]),        # entry by entry
     "the poses were multiplied entry by entry", "* multiplies entry by entry: use the matrix product @"),
    (np.array([[0.0, 0.0, 1.0, 1.0], [1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 3.5], [0.0, 0.0, 0.0, 1.0]]),         # t_ab + t_bc
     "the translations were added", "t_bc must be turned by R_ab first: t_ac = R_ab t_bc + t_ab"),
    (np.array([[0.0, 0.0, -1.0, -1.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.5], [1.0, 3.0, -2.0, 0.5]]),
     "T_ab was transposed", hints.TRANSPOSES_T_AB_T_HINT),                # T_abᵀ T_bc
]


@public_check("pose_compose", "T_ac = T_ab T_bc: one step equals two steps for a point of c")
def _(pose_compose):
    T_ac = require_shape(pose_compose(T_QUARTER, T_QUARTER_X), (4, 4))
    p_c = np.array([0.3, -1.2, 2.0, 1.0])
    if close(T_ac @ p_c, T_QUARTER @ (T_QUARTER_X @ p_c), 1e-12):
        return
    found = _first_match(T_ac, COMPOSE_SLIPS)
    if found:
        raise Mismatch(*found)
    raise Mismatch(f"pose_compose(T_ab, T_bc) @ p differs from T_ab @ (T_bc @ p) "
                   f"({off_by(T_ac @ p_c, T_QUARTER @ (T_QUARTER_X @ p_c))})", "T_ac = T_ab @ T_bc")


@public_check("pose_compose", "two generic poses compose to 1e-12 (float64 kept)")
def _(pose_compose):
    got = require_shape(pose_compose(T_GENERIC, T_GENERIC_2), (4, 4), "pose_compose(T_ab, T_bc)")
    require_exact(got, T_GENERIC @ T_GENERIC_2, "pose_compose(T_ab, T_bc)", hint="T_ac = T_ab @ T_bc")


# ---------------------------------------------------------------- pose_inverse
@public_check("pose_inverse", "a pose times its inverse is the identity")
def _(pose_inverse):
    got = require_shape(pose_inverse(T_QUARTER), (4, 4))
    if close(T_QUARTER @ got, np.eye(4), 1e-12):
        return
    found = _inverse_mistake(got, T_QUARTER)
    if found:
        raise Mismatch(*found)
    require_pose(got)
    raise Mismatch(f"T @ pose_inverse(T) is not the identity ({off_by(T_QUARTER @ got, np.eye(4))})",
                   hints.INVERSE_R_T_RT_HINT)


def _inverse_mistake(got, T):
    """The (reason, hint) of a usual slip that ``got``, a wrong inverse of T, shows, told from its blocks at run time
    (its rotation block undoes R or is R, its translation is -t or t), or None."""
    got = np.asarray(got, dtype=float)
    R, t = T[:3, :3], T[:3, 3]
    if close(got, T.T, 1e-9):
        return ("returned the transpose of T",
                "the plain transpose of T is not its inverse (a pose is not orthogonal): it puts t in the bottom row "
                "and never undoes the shift")
    undoes_turn = close(got[:3, :3] @ R, np.eye(3), 1e-9)
    if undoes_turn and close(got[:3, 3], -t, 1e-9):
        return f"the translation of the inverse is -t = {fmt(-t)}", hints.INVERSE_TRANSLATION_FRAME_HINT
    if undoes_turn and close(got[:3, 3], t, 1e-9):
        return "the translation of the inverse is t itself", hints.KEPT_T_UNCHANGED_INVERSE_HINT
    if close(got[:3, :3], R, 1e-9):
        return "the rotation block of the inverse is R", hints.ROTATION_BLOCK_INVERSE_RT_HINT
    return None


@public_check("pose_inverse", "takes a point back: T_ba (T_ab p) = p")
def _(pose_inverse):
    got = require_shape(pose_inverse(T_QUARTER_X), (4, 4))
    p = np.array([0.7, 0.1, -2.0, 1.0])
    if not close(got @ (T_QUARTER_X @ p), p, 1e-12):
        found = _inverse_mistake(got, T_QUARTER_X)
        raise Mismatch(f"got {fmt((got @ (T_QUARTER_X @ p))[:3])} back instead of {fmt(p[:3])}",
                       found[1] if found else hints.INVERSE_R_T_RT_HINT)


@public_check("pose_inverse", "a generic pose: T T⁻¹ = I to 1e-12 (float64 kept), and plain lists are accepted")
def _(pose_inverse):
    got = require_shape(pose_inverse(T_GENERIC), (4, 4), "pose_inverse(T)")
    require_exact(T_GENERIC @ got, np.eye(4), "T @ pose_inverse(T)",
                  hint="T T⁻¹ must be I to rounding: build the blocks of the inverse from R and t directly, in float64")
    require_same_with_lists(pose_inverse, (T_GENERIC,), (4, 4), "pose_inverse(T)")


# ---------------------------------------------------------------- exp_se3
# Poses of the checks' twists, worked out once and stored as numbers (tests/test_public_check_constants_lesson07.py
# recomputes each from the exponential map and from scipy's expm of the 4×4 twist matrix).
# xi = [0, 0, π/2, 1, 0, 0], the mirror of [1, 0, 0, 0, 0, π/2]: a turn of 1 rad about x.
EXP_MIRRORED_QUARTER = np.array([[1.0, 0.0, 0.0, 0.0],
                                 [0.0, 0.5403023058681398, -0.8414709848078965, -0.72209144937841],
                                 [0.0, 0.8414709848078965, 0.5403023058681398, 1.321779532040728],
                                 [0.0, 0.0, 0.0, 1.0]])
# rho = (30, -40, 0), phi = angle (2, -1, 2)/3 (see _tiny_twist): the pose, and the pose of the mirrored twist.
EXP_TINY = {
    1e-9: np.array([[1.0, -6.666666667777779e-10, -3.3333333311111114e-10, 30.000000013333334],
                    [6.666666665555556e-10, 1.0, -6.666666667777779e-10, -39.99999999],
                    [3.333333335555556e-10, 6.666666665555556e-10, 1.0, -8.333333329629632e-09],
                    [0.0, 0.0, 0.0, 1.0]]),
    1e-6: np.array([[0.9999999999997222, -6.666667777776666e-07, -3.3333311111105554e-07, 30.00001333333204],
                    [6.666665555554444e-07, 0.9999999999995556, -6.666667777776666e-07, -39.99998999999519],
                    [3.333335555555e-07, 6.666665555554444e-07, 0.9999999999997222, -8.333329629628936e-06],
                    [0.0, 0.0, 0.0, 1.0]])}
EXP_TINY_MIRRORED = {
    1e-9: np.array([[0.9775782582349525, -0.01681630632378563, 0.20989988296314305, 3.982269717508283e-10],
                    [-0.01681630632378563, 0.9873877702571608, 0.15742491222235727, -5.346631045202122e-10],
                    [-0.20989988296314305, -0.15742491222235727, 0.9649660284921133, -3.264771572666467e-12],
                    [0.0, 0.0, 0.0, 1.0]]),
    1e-6: np.array([[0.9775782582349525, -0.01681630632378563, 0.20989988296314305, 3.982269717508282e-07],
                    [-0.01681630632378563, 0.9873877702571608, 0.15742491222235727, -5.34663104520212e-07],
                    [-0.20989988296314305, -0.15742491222235727, 0.9649660284921133, -3.264771572666466e-09],
                    [0.0, 0.0, 0.0, 1.0]])}


@public_check("exp_se3", "a twist with phi = 0 is a pure translation by rho")
def _(exp_se3):
    T = exp_se3([1.0, 2.0, 3.0, 0.0, 0.0, 0.0])
    if np.shape(T) == (4, 4) and not np.all(np.isfinite(np.asarray(T, dtype=float))):
        raise Mismatch("returned NaN or inf at phi = 0", SERIES_NAN_HINT_V)
    T = require_shape(T, (4, 4))
    if close(T[:3, :3], Exp([1.0, 2.0, 3.0]), 1e-9):          # rho = (1, 2, 3) used as the rotation vector
        raise Mismatch("rho was used as the rotation vector", MIRROR_HINT)
    expected = np.array([[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]])
    if not close(T, expected, 1e-12):
        raise Mismatch(f"got translation {fmt(T[:3, 3])} and a non-identity rotation block")


@public_check("exp_se3", "xi = [0, 0, 0, 0, 0, π/2] is a quarter turn about z")
def _(exp_se3):
    xi = np.array([0.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
    T = require_shape(exp_se3(xi), (4, 4))
    expected = np.array([[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    if not close(T, expected, 1e-12):
        mirrored = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, np.pi / 2],
                             [0.0, 0.0, 0.0, 1.0]])       # [phi, rho] read as [rho, phi]: a shift by (0, 0, π/2)
        if close(T, mirrored, 1e-9):
            raise Mismatch(f"got {fmt(T)}: phi was used as the translation", MIRROR_HINT)
        raise Mismatch(f"got {fmt(T)} ({off_by(T, expected)})", "the rotation block is Exp(phi) with phi = xi[3:]")


@public_check("exp_se3", "xi = [1, 0, 0, 0, 0, π/2]: a quarter turn about z, shifted by V(phi) rho = (2/π, 2/π, 0)")
def _(exp_se3):
    xi = np.array([1.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
    T = require_shape(exp_se3(xi), (4, 4))
    expected = np.array([[0.0, -1.0, 0.0, 2.0 / np.pi], [1.0, 0.0, 0.0, 2.0 / np.pi], [0.0, 0.0, 1.0, 0.0],
                         [0.0, 0.0, 0.0, 1.0]])
    if close(T, expected, 1e-9):
        return
    if close(T[:3, 3], xi[:3], 1e-9):
        raise Mismatch(f"the translation equals rho = {fmt(xi[:3])}, expected {fmt(expected[:3, 3])}", FORGETS_V_HINT)
    if close(T, EXP_MIRRORED_QUARTER, 1e-9):
        raise Mismatch(f"got translation {fmt(T[:3, 3])}, expected {fmt(expected[:3, 3])}", MIRROR_HINT)
    raise Mismatch(f"got translation {fmt(T[:3, 3])}, expected {fmt(expected[:3, 3])} ({off_by(T, expected)})",
                   V_SERIES_HINT)


def _tiny_twist(angle):
    """rho of length 50 and a rotation part of length ``angle``."""
    return np.array([30.0, -40.0, 0.0]), angle * np.array([2.0, -1.0, 2.0]) / 3.0


@public_check("exp_se3", "tiny rotation parts keep their accuracy: |phi| = 1e-9 and 1e-6 with |rho| = 50")
def _(exp_se3):
    failures = []
    for angle in (1e-9, 1e-6):
        rho, phi = _tiny_twist(angle)
        xi = np.concatenate([rho, phi])
        T = require_shape(exp_se3(xi), (4, 4), f"exp_se3 at |phi| = {angle:g}",
                          nan_hint=lambda _: SERIES_NAN_HINT_V)
        expected = EXP_TINY[angle]
        if not close(T, expected, 1e-12 * 50.0):
            failures.append((angle, T, expected, xi))
    if not failures:
        return
    # At |phi| = 1e-9 a V whose coefficients round to 0 is I exactly, like a forgotten V: look at every failure.
    is_rho = [close(T[:3, 3], xi[:3], 1e-3 * np.max(np.abs(expected[:3, 3] - xi[:3]))) for _, T, expected, xi in failures]
    angle, T, expected, xi = failures[0]
    if close(T, EXP_TINY_MIRRORED[angle], 1e-9):
        hint = MIRROR_HINT
    elif all(is_rho):
        hint = FORGETS_V_HINT
    else:
        hint = hints.V_SERIES_TINY_ANGLE_HINT
    raise Mismatch(f"at |phi| = {angle:g}, |rho| = 50 the pose is {off_by(T, expected)} (allowed 5e-11)", hint)


RHO_DECADES = np.array([30.0, -20.0, 35.0])             # |rho| = 50.2
# The translation of exp_se3([RHO_DECADES, θ u]) at each angle of DECADE_ANGLES, to full precision (recomputed by
# tests/test_public_check_constants_lesson07.py independently of this module).
TRANSLATION_AT_DECADES = {
    0.97: np.array([31.245582546671383, -20.995141519512355, 33.256846693572435]),
    0.097: np.array([30.085994736765016, -20.156315182650943, 34.83584767190952]),
    0.0097: np.array([30.008135541929768, -20.016114267930618, 34.98380732410492]),
    0.00097: np.array([30.00080885599215, -20.00161614381771, 34.998383072098996]),
    9.7e-05: np.array([30.000080838560493, -20.000161661439314, 34.999838330719854]),
    9.7e-06: np.array([30.000008083385605, -20.000016166614394, 34.9999838333072]),
    9.7e-07: np.array([30.000000808333855, -20.000001616666143, 34.99999838333307]),
    9.7e-08: np.array([30.00000008083334, -20.000000161666662, 34.99999983833333]),
    9.7e-09: np.array([30.000000008083337, -20.000000016166666, 34.999999983833334]),
}


def _decade_pose(theta):
    """The twist [rho, θ u] at an angle of DECADE_ANGLES and its pose, from the stored translations."""
    phi = theta * DECADE_AXIS
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = TRANSLATION_AT_DECADES[theta]
    return np.concatenate([RHO_DECADES, phi]), T


def _decade_hint(theta, errors, single, what):
    """Name the cause of a miss at every decade: float32 at θ = 0.97, a cancelling closed form (errors grow as θ
    shrinks), or a series too short for its threshold (errors grow with θ)."""
    if theta == DECADE_ANGLES[0]:
        return FLOAT32_HINT if single else what
    failing = [t for t in DECADE_ANGLES if errors[t] > 0]
    if len(failing) > 1 and errors[failing[-1]] > errors[failing[0]]:
        return ("the closed form cancels at small angles (it keeps fewer digits as θ shrinks): below θ = 1e-2 use "
                "the series of the coefficients")
    return (f"below your small-angle threshold the series is too short for θ = {theta:.2g}: keep its θ² and θ⁴ "
            "terms, or move the threshold down")


def _decade_misses(answer, tol):
    """``({θ: error above tol, else 0}, (θ, error, single precision?) of the first miss or None)`` over
    ``DECADE_ANGLES``; ``answer(θ)`` returns ``(got, expected)``."""
    errors, first = {}, None
    for theta in DECADE_ANGLES:
        got, expected = answer(theta)
        error = np.max(np.abs(got - expected))
        errors[theta] = error if error > tol else 0.0
        if error > tol and first is None:
            first = (theta, error, single_precision_error(got, expected))
    return errors, first


@public_check("exp_se3", "exact to 5e-14 |rho| just below each power of ten, |phi| = 0.97 … 9.7e-9, |rho| = 50")
def _(exp_se3):
    tol = 5e-14 * np.linalg.norm(RHO_DECADES)

    def answer(theta):
        xi, expected = _decade_pose(theta)
        return require_shape(exp_se3(xi), (4, 4), f"exp_se3 at |phi| = {theta:.2g}",
                             nan_hint=lambda _: SERIES_NAN_HINT_V), expected

    errors, first = _decade_misses(answer, tol)
    if first:
        theta, error, single = first
        raise Mismatch(f"at |phi| = {theta:.2g}, |rho| = 50 the pose is off by {error:.1e} (tolerance {tol:.1g})",
                       _decade_hint(theta, errors, single, V_SERIES_HINT))


# ---------------------------------------------------------------- log_se3
@public_check("log_se3", "log_se3(I) = 0 (no NaN at zero angle)")
def _(log_se3):
    xi = log_se3(np.eye(4))
    if np.shape(xi) == (6,) and not np.all(np.isfinite(np.asarray(xi, dtype=float))):
        raise Mismatch("returned NaN or inf for the identity", SERIES_HINT_C)
    xi = require_shape(xi, (6,))
    if not close(xi, np.zeros(6), 1e-12):
        raise Mismatch(f"got {fmt(xi)}")


@public_check("log_se3", "a pure translation gives xi = [t, 0, 0, 0]")
def _(log_se3):
    T = np.array([[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]])
    xi = require_shape(log_se3(T), (6,))
    if close(xi, [0.0, 0.0, 0.0, 1.0, 2.0, 3.0], 1e-12):
        raise Mismatch("got [0, 0, 0, 1, 2, 3]", MIRROR_HINT)
    if not close(xi, [1.0, 2.0, 3.0, 0.0, 0.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(xi)}, expected [1, 2, 3, 0, 0, 0]")


@public_check("log_se3", "tiny rotation parts keep their accuracy: |phi| = 1e-9 and 1e-6 with |rho| = 50")
def _(log_se3):
    for angle in (1e-9, 1e-6):
        rho, phi = _tiny_twist(angle)
        xi = np.concatenate([rho, phi])
        T = EXP_TINY[angle]
        got = require_shape(log_se3(T), (6,), f"log_se3 at |phi| = {angle:g}", nan_hint=lambda _: SERIES_HINT_C)
        if not close(got, xi, 1e-11 * 50.0):
            raise Mismatch(f"at |phi| = {angle:g}, |rho| = 50 the twist is {off_by(got, xi)} (allowed 5e-10)",
                           _log_mistake(got, T, xi) or SERIES_HINT_C)


# The twists of the two hand-written poses, worked out by hand: phi = Log(R) is a quarter turn, and
# rho = V(phi)⁻¹ t with V = (2/π) [[1, -1], [1, 1]] in the plane of the turn and 1 along its axis.
LOG_T_QUARTER = np.array([0.75 * np.pi, 0.25 * np.pi, 3.0, 0.0, 0.0, 0.5 * np.pi])
LOG_T_QUARTER_X = np.array([0.0, -0.125 * np.pi, 0.375 * np.pi, 0.5 * np.pi, 0.0, 0.0])
# rho with c(θ) = 1/12 at every angle, (I - W/2 + W²/12) t, for the same two poses (recomputed by the tests).
RHO_C_CONSTANT = {"T_QUARTER": np.array([2.3651795684388683, 0.8033683198904951, 3.0]),
                  "T_QUARTER_X": np.array([0.0, -0.40168415994524753, 1.1825897842194342])}


@public_check("log_se3", "two quarter-turn poses: phi = Log(R) and rho = V(phi)⁻¹ t, as worked out by hand")
def _(log_se3):
    for name, T, expected in (("T_QUARTER", T_QUARTER, LOG_T_QUARTER), ("T_QUARTER_X", T_QUARTER_X, LOG_T_QUARTER_X)):
        xi = require_shape(log_se3(T), (6,))
        if close(xi[:3], T[:3, 3], 1e-9):
            raise Mismatch(f"rho equals t = {fmt(T[:3, 3])} although T rotates", FORGETS_V_INV_HINT)
        if close(np.concatenate([xi[3:], xi[:3]]), expected, 1e-9):
            raise Mismatch("rho and phi are swapped", MIRROR_HINT)
        if not close(xi, expected, 1e-9):
            raise Mismatch(f"log_se3(T) for T = {fmt(T)} is {fmt(xi)}, expected {fmt(expected)} ({off_by(xi, expected)})",
                           _log_mistake(xi, T, expected, RHO_C_CONSTANT[name]) or
                           "xi = [V(phi)⁻¹ t, phi] with phi = Log(R)")


FORGETS_V_INV_HINT = "rho = V(phi)⁻¹ t, not t itself: the translation must be undone through V"


def _log_mistake(got, T, xi, rho_c_constant=None):
    """The mistake behind the twist ``got`` of T (``xi``: the right twist; ``rho_c_constant``: the stored rho
    of the slip c = 1/12), or None."""
    if close(np.concatenate([got[3:], got[:3]]), xi, 1e-6):
        return MIRROR_HINT
    gap = np.max(np.abs(T[:3, 3] - xi[:3]))
    if gap > 0.0 and close(got[:3], T[:3, 3], 1e-3 * gap):
        return FORGETS_V_INV_HINT
    if rho_c_constant is not None and close(got[3:], xi[3:], 1e-9) and close(got[:3], rho_c_constant, 1e-9):
        return (hints.SERIES_VALUE_AT_ZERO_ONLY_HINT)
    return None


@public_check("log_se3", "exact to 5e-14 |rho| just below each power of ten, |phi| = 0.97 … 9.7e-9, |rho| = 50; "
              "plain lists accepted")
def _(log_se3):
    tol = 5e-14 * np.linalg.norm(RHO_DECADES)

    def answer(theta):
        xi, T = _decade_pose(theta)
        return require_shape(log_se3(T), (6,), f"log_se3 at |phi| = {theta:.2g}",
                             nan_hint=lambda _: SERIES_HINT_C), xi

    errors, first = _decade_misses(answer, tol)
    if first:
        theta, error, single = first
        raise Mismatch(f"at |phi| = {theta:.2g}, |rho| = 50 the twist is off by {error:.1e} (tolerance {tol:.1g})",
                       _decade_hint(theta, errors, single, "xi = [V(phi)⁻¹ t, phi] with phi = Log(R): "
                                    "compare your V⁻¹ with the page, term by term"))
    require_same_with_lists(log_se3, (_decade_pose(0.97)[1],), (6,), "log_se3(T)")
