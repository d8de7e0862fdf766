"""Public checks for lesson 07, section 10: the adjoint of a pose and three Jacobians.

The checks use a quarter turn and a shift written out by hand, the defining identities
(T Exp(ξ) T⁻¹ = Exp(Ad_T ξ), Exp(ξ + dξ) ≈ Exp(ξ) Exp(J dξ)), central differences of those definitions
(computed here with the course's ``ExpSE3`` and ``LogSE3``), and exact identities a true Jacobian of Exp
satisfies (J(-ξ) = Ad_Exp(ξ) J(ξ) and J(ξ) ξ = ξ). A slip is named by a property seen at run time: a pure shift
[rho, 0] that comes out with a spin, a pure spin [0, phi] whose translation part is missing, of the wrong sign, or the
same when the pose's rotation changes; columns that pass once their sign is flipped; agreement with the Jacobian of
the other perturbation. No expected matrix is stored.
"""

import numpy as np
from scipy.linalg import expm

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import AdSE3, Exp, ExpSE3, LogSE3, skew
from .common import central_differences, fmt, off_by, require_same_with_lists, require_shape, require_unchanged_inputs

# A quarter turn about z (x goes to y) and a shift, written out.
QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
SHIFT = np.array([1.0, 2.0, 3.0])
T_QUARTER = np.array([[0.0, -1.0, 0.0, 1.0],
                      [1.0, 0.0, 0.0, 2.0],
                      [0.0, 0.0, 1.0, 3.0],
                      [0.0, 0.0, 0.0, 1.0]])


# ---------------------------------------------------------------- adjoint_se3
XI = np.array([0.3, -0.2, 0.5, 0.2, 0.4, -0.3])
# Two more twists for the defining identity: a pure shift and a pure spin of their own.
XI_SHIFT = np.array([-0.6, 0.1, 0.4, 0.0, 0.0, 0.0])
XI_SPIN = np.array([0.0, 0.0, 0.0, 0.5, -0.1, 0.7])
# The same shift as T_QUARTER without the turn, and the same turn without the shift.
T_SHIFT = np.array([[1.0, 0.0, 0.0, 1.0],
                    [0.0, 1.0, 0.0, 2.0],
                    [0.0, 0.0, 1.0, 3.0],
                    [0.0, 0.0, 0.0, 1.0]])
T_TURN = np.array([[0.0, -1.0, 0.0, 0.0],
                   [1.0, 0.0, 0.0, 0.0],
                   [0.0, 0.0, 1.0, 0.0],
                   [0.0, 0.0, 0.0, 1.0]])
ADJOINT_HINT = hints.ADJOINT_DEFINITION_HINT
SPIN_FROM_SHIFT_HINT = hints.ADJOINT_SPIN_FROM_SHIFT_HINT
SPIN_WITHOUT_SHIFT_HINT = hints.ADJOINT_SPIN_WITHOUT_SHIFT_HINT
COUPLING_WITHOUT_R_HINT = hints.ADJOINT_COUPLING_WITHOUT_R_HINT
COUPLING_SIGN_HINT = hints.ADJOINT_SPIN_SHIFT_SIGN_HINT
COUPLING_ORDER_HINT = hints.ADJOINT_COUPLING_IDENTITY_HINT


def _twist_matrix(xi):
    M = np.zeros((4, 4))
    M[:3, :3], M[:3, 3] = skew(xi[3:]), xi[:3]
    return M


def _adjoint_hint(adjoint_se3, T, Ad):
    """Which twist Ad carries wrongly at the pose T, told from what Ad does to a pure shift [rho, 0] and a pure spin
    [0, phi] (compared with coursekit.lie's AdSE3) and from the student's adjoint of T_SHIFT (the same t, no turn)."""
    shift, spin = np.concatenate([XI[:3], np.zeros(3)]), np.concatenate([np.zeros(3), XI[3:]])
    from_shift, from_spin = Ad @ shift, Ad @ spin
    want_shift, want_spin = AdSE3(T) @ shift, AdSE3(T) @ spin
    if not close(from_shift[3:], np.zeros(3), 1e-9):          # a shift can never come out with a spin
        return SPIN_FROM_SHIFT_HINT
    if not close(from_shift[:3], want_shift[:3], 1e-9) or not close(from_spin[3:], want_spin[3:], 1e-9):
        return ADJOINT_HINT
    moved, want = from_spin[:3], want_spin[:3]                 # where a pure spin moves the world's origin
    if close(moved, want, 1e-9):
        return ADJOINT_HINT
    if close(moved, np.zeros(3), 1e-9):
        return SPIN_WITHOUT_SHIFT_HINT
    if close(moved, -want, 1e-9):
        return COUPLING_SIGN_HINT
    if not close(T[:3, :3], np.eye(3), 1e-12):
        unturned = require_shape(adjoint_se3(T_SHIFT), (6, 6), "adjoint_se3(T) for a shift without a turn")
        if close((unturned @ spin)[:3], moved, 1e-9):
            return COUPLING_WITHOUT_R_HINT
    return COUPLING_ORDER_HINT


def _require_defining_identity(adjoint_se3, T, twists, what, tol=1e-9):
    """Mismatch unless Exp(Ad_T ξ) = T Exp(ξ) T⁻¹ for each twist ξ, with the hint of _adjoint_hint."""
    Ad = require_shape(adjoint_se3(T), (6, 6), what)
    for xi in twists:
        conjugated = T @ expm(_twist_matrix(xi)) @ np.linalg.inv(T)
        got = expm(_twist_matrix(Ad @ xi))
        if not close(got, conjugated, tol):
            raise Mismatch(f"{what}: Exp(Ad_T ξ) misses T Exp(ξ) T⁻¹ at ξ = {fmt(xi)} ({off_by(got, conjugated)})",
                           _adjoint_hint(adjoint_se3, T, Ad))


@public_check("adjoint_se3", "T Exp(ξ) T⁻¹ = Exp(Ad_T ξ) for three twists at a quarter turn about z and a shift of "
              "(1, 2, 3)")
def _(adjoint_se3):
    _require_defining_identity(adjoint_se3, T_QUARTER, (XI, XI_SHIFT, XI_SPIN), "adjoint_se3(T)")


@public_check("adjoint_se3", "pure motions: the same identity at a pure turn and at a pure shift, to 1e-12; and a "
              "pure shift ξ = [ρ, 0] gains no spin")
def _(adjoint_se3):
    _require_defining_identity(adjoint_se3, T_TURN, (XI, XI_SHIFT, XI_SPIN), "adjoint_se3 of a pure turn", 1e-12)
    _require_defining_identity(adjoint_se3, T_SHIFT, (XI, XI_SHIFT, XI_SPIN), "adjoint_se3 of a pure shift", 1e-12)
    Ad = require_shape(adjoint_se3(T_QUARTER), (6, 6), "adjoint_se3(T)")
    spin = (Ad @ XI_SHIFT)[3:]
    if not close(spin, np.zeros(3), 1e-12):
        raise Mismatch(f"Ad_T [ρ, 0] has the spin part {fmt(spin)}", SPIN_FROM_SHIFT_HINT)


@public_check("adjoint_se3", "Ad(T1 T2) = Ad(T1) Ad(T2), and Ad(I) = I")
def _(adjoint_se3):
    T2 = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, -1.0], [0.0, 1.0, 0.0, 0.5], [0.0, 0.0, 0.0, 1.0]])
    identity = require_shape(adjoint_se3(np.eye(4)), (6, 6), "adjoint_se3(I)")
    if not close(identity, np.eye(6), 1e-12):
        raise Mismatch(f"Ad(I) is not the 6×6 identity ({off_by(identity, np.eye(6))})",
                       "conjugating by the identity changes nothing")
    product = require_shape(adjoint_se3(T_QUARTER @ T2), (6, 6), "adjoint_se3(T1 T2)")
    separate = require_shape(adjoint_se3(T_QUARTER), (6, 6), "adjoint_se3(T1)") @ \
        require_shape(adjoint_se3(T2), (6, 6), "adjoint_se3(T2)")
    if not close(product, separate, 1e-9):
        raise Mismatch(f"Ad(T1 T2) differs from Ad(T1) Ad(T2) ({off_by(product, separate)})",
                       "conjugating by T1 T2 is conjugating by T2, then by T1: the adjoint must respect that")


@public_check("adjoint_se3", "accepts plain lists and leaves its input unchanged")
def _(adjoint_se3):
    require_same_with_lists(adjoint_se3, (T_QUARTER,), (6, 6), "adjoint_se3(T)")
    require_unchanged_inputs(adjoint_se3, (T_QUARTER,), "adjoint_se3")


# ---------------------------------------------------------------- jacobian_transform_point
POINT = np.array([1.0, -2.0, 0.5])
POINT_ROTATION_FIRST_HINT = "xi = [rho, phi]: the first three columns are for the translation rho, the last three for phi"
POINT_TRANSLATION_HINT = ("the rho block is off: for a small shift, T Exp([rho, 0]) p - T p must equal J [rho, 0] "
                          "to first order; try rho along one axis at a pose that turns")
POINT_LEFT_HINT = ("that is the Jacobian of a left (world-frame) perturbation; here xi perturbs T on the right, "
                   "in the body frame")
POINT_SIGN_HINT = hints.SIGN_ROTATION_BLOCK_PHI_HINT
POINT_WORLD_ROTATION_HINT = ("the phi block turns the point about the world's axes, as a perturbation on the left "
                             "would; for T Exp(xi) the turn is about the body's axes (lesson 06, section 6, makes the "
                             "same distinction for a rotated point)")


def _point_hint(J, numeric, T, p):
    """Which block of J fails, told by comparing J's blocks with central differences at run time."""
    p_h = np.append(p, 1.0)
    shift_block, turn_block = numeric[:, :3], numeric[:, 3:]
    if close(J[:, :3], turn_block, 1e-6) and close(J[:, 3:], shift_block, 1e-6):
        return POINT_ROTATION_FIRST_HINT
    if close(J[:, 3:], turn_block, 1e-6):
        return POINT_TRANSLATION_HINT
    if close(J[:, :3], shift_block, 1e-6) and close(J[:, 3:], -turn_block, 1e-6):
        return POINT_SIGN_HINT
    if close(J, central_differences(lambda xi: (ExpSE3(xi) @ T @ p_h)[:3], 6), 1e-6):
        return POINT_LEFT_HINT
    world_turn = central_differences(lambda phi: Exp(phi) @ T[:3, :3] @ p, 3)
    if close(J[:, :3], shift_block, 1e-6) and close(J[:, 3:], world_turn, 1e-6):
        return POINT_WORLD_ROTATION_HINT
    return "expand T (I + ξ^) [p; 1] and collect the terms in rho and phi"


@public_check("jacobian_transform_point", "matches finite differences of T Exp(ξ) p (quarter turn, shift (1, 2, 3))")
def _(jacobian_transform_point):
    J = require_shape(jacobian_transform_point(T_QUARTER, POINT), (3, 6), "jacobian_transform_point(T, p)")
    numeric = central_differences(lambda xi: (T_QUARTER @ ExpSE3(xi) @ np.append(POINT, 1.0))[:3], 6)
    if not close(J, numeric, 1e-6):
        raise Mismatch(f"disagrees with finite differences ({off_by(J, numeric)})",
                       _point_hint(J, numeric, T_QUARTER, POINT))


def _exact_point_jacobian(T, p):
    """The derivative of T Exp(ξ) [p; 1] at ξ = 0, exact to rounding: the complex-step derivative
    Im f(i h e_j) / h, which subtracts nothing and so takes h = 1e-30, through scipy's matrix exponential."""
    p_h = np.append(np.asarray(p, dtype=float), 1.0)
    columns = []
    for e in np.eye(6):
        twist = np.zeros((4, 4), dtype=complex)
        twist[:3, :3], twist[:3, 3] = skew(e[3:]) * 1e-30j, e[:3] * 1e-30j
        columns.append(np.imag(T @ expm(twist) @ p_h)[:3] / 1e-30)
    return np.column_stack(columns)


@public_check("jacobian_transform_point", "exact to rounding, 1e-12 max(1, |p|), which finite differences are not "
              "(|p| = 1 m and 1 km)")
def _(jacobian_transform_point):
    for size in (1.0, 1e3):
        p = size * POINT / np.linalg.norm(POINT)
        J = require_shape(jacobian_transform_point(T_QUARTER, p), (3, 6), "jacobian_transform_point(T, p)")
        exact = _exact_point_jacobian(T_QUARTER, p)
        tol = 1e-12 * max(1.0, size)
        if close(J, exact, tol):
            continue
        if close(J, exact, 1e-5 * max(1.0, size)):
            hint = ("close, but not exact: a finite-difference or truncated estimate; the blocks of the derivative "
                    "can be written out exactly")
        else:
            numeric = central_differences(lambda xi: (T_QUARTER @ ExpSE3(xi) @ np.append(p, 1.0))[:3], 6)
            hint = _point_hint(J, numeric, T_QUARTER, p)
        raise Mismatch(f"for |p| = {size:g} m it is off by {np.max(np.abs(J - exact)):.2g} (tolerance {tol:.2g})", hint)


@public_check("jacobian_transform_point", "accepts plain lists and leaves its inputs unchanged")
def _(jacobian_transform_point):
    require_same_with_lists(jacobian_transform_point, (T_QUARTER, POINT), (3, 6), "jacobian_transform_point(T, p)")
    require_unchanged_inputs(jacobian_transform_point, (T_QUARTER, POINT), "jacobian_transform_point")


# ---------------------------------------------------------------- right_jacobian_se3
# A twist of about 1 rad with |rho| ≈ 2 m; one tiny turn; one of 3.08 rad with |rho| ≈ 37 m.
XI_MODERATE = np.array([0.8, -1.5, 1.1, 0.6, -0.3, 0.7])
XI_TINY = np.array([0.5, 0.2, -0.4, 3e-7, -2e-7, 6e-7])
XI_LARGE = np.array([30.0, -20.0, 10.0, 1.5, 2.0, -1.8])
JR_NO_COUPLING_HINT = hints.JR_SE3_NO_COUPLING_HINT
JR_SIGN_HINT = hints.JR_SE3_COUPLING_SIGN_HINT
JR_LEFT_HINT = ("that is the left Jacobian, Exp(ξ + dξ) ≈ Exp(J dξ) Exp(ξ); here the small step goes on the right: "
                "carry the nudge felt at instant s to the end of the motion, Exp(-s ξ)")
JR_INVERSE_HINT = "that is the inverse of the Jacobian of Exp (the Jacobian of Log); return J itself"
JR_SERIES_HINT = ("exact at a tiny angle but not at {angle}: a series cut off after a few terms; near π its terms "
                  "shrink slowly, so sum many more (or use a closed form or a quadrature rule)")
JR_DIFFERENCES_HINT = hints.JR_SE3_DIFFERENCES_HINT


def _numeric_jr(xi):
    base_inverse = np.linalg.inv(ExpSE3(xi))
    return central_differences(lambda d: LogSE3(base_inverse @ ExpSE3(xi + d)), 6)


def _jr(right_jacobian_se3, xi, what="right_jacobian_se3(xi)"):
    return require_shape(right_jacobian_se3(xi), (6, 6), what)


@public_check("right_jacobian_se3", "matches central differences of Log(Exp(ξ)⁻¹ Exp(ξ + dξ)) at θ ≈ 1 (|ρ| ≈ 2 m)")
def _(right_jacobian_se3):
    xi = XI_MODERATE
    J = _jr(right_jacobian_se3, xi)
    numeric = _numeric_jr(xi)
    scale = 1.0 + np.linalg.norm(xi[:3])
    if close(J, numeric, 1e-7 * scale):
        return
    hint = "compare Exp(ξ + dξ) with Exp(ξ) Exp(J dξ) for a small dξ: J must make them agree to first order"
    if close(J[:3, 3:], np.zeros((3, 3)), 1e-12):
        hint = JR_NO_COUPLING_HINT
    elif (close(J[:3, :3], numeric[:3, :3], 1e-6) and close(J[3:], numeric[3:], 1e-6)
          and close(J[:3, 3:], -numeric[:3, 3:], 1e-6 * scale)):
        hint = JR_SIGN_HINT
    elif close(J @ numeric, np.eye(6), 1e-6 * scale):
        hint = JR_INVERSE_HINT
    elif close(_jr(right_jacobian_se3, -xi, "right_jacobian_se3(-xi)"), numeric, 1e-6 * scale):
        hint = JR_LEFT_HINT
    raise Mismatch(f"J disagrees with finite differences of its definition ({off_by(J, numeric)})", hint)


@public_check("right_jacobian_se3", "exact identities of the true Jacobian, to 1e-11 (1 + |ρ|): J(-ξ) = Ad_Exp(ξ) J(ξ) "
              "and J(ξ) ξ = ξ, at θ = 7e-7, 1 and 3.08 (|ρ| up to 37 m)")
def _(right_jacobian_se3):
    tiny_passed = False
    for xi in (XI_TINY, XI_MODERATE, XI_LARGE):
        scale = 1.0 + np.linalg.norm(xi[:3])
        angle = f"θ = {np.linalg.norm(xi[3:]):.3g}"
        J = _jr(right_jacobian_se3, xi)
        J_minus = _jr(right_jacobian_se3, -xi, "right_jacobian_se3(-xi)")
        flipped = AdSE3(ExpSE3(xi)) @ J
        errors = [np.max(np.abs(J_minus - flipped)), np.max(np.abs(J @ xi - xi))]
        error = max(errors) / scale
        if error <= 1e-11:
            tiny_passed = tiny_passed or xi is XI_TINY
            continue
        if tiny_passed and error > 1e-5:
            hint = JR_SERIES_HINT.format(angle=angle)
        elif error < 1e-5:
            hint = JR_DIFFERENCES_HINT.format(error=f"off by {error * scale:.2g}")
        else:
            hint = ("J(-ξ) = Ad_Exp(ξ) J(ξ) says the left and right Jacobians are one matrix seen from the two ends "
                    "of the motion; compare your J with central differences of its definition, part by part")
        which = "J(-ξ) ≠ Ad_Exp(ξ) J(ξ)" if errors[0] >= errors[1] else "J(ξ) ξ ≠ ξ"
        raise Mismatch(f"{which} at {angle}, |ρ| = {np.linalg.norm(xi[:3]):.3g} m ({error * scale:.2g})", hint)


@public_check("right_jacobian_se3", "J(0) = I, accepts plain lists and leaves its input unchanged")
def _(right_jacobian_se3):
    J0 = _jr(right_jacobian_se3, np.zeros(6), "right_jacobian_se3(0)")
    if not close(J0, np.eye(6), 1e-14):
        raise Mismatch(f"J(0) is not the identity ({off_by(J0, np.eye(6))})",
                       "at ξ = 0 the motion is not bent at all: Exp(dξ) = Exp(0) Exp(dξ)")
    require_same_with_lists(right_jacobian_se3, (XI_MODERATE,), (6, 6), "right_jacobian_se3(xi)")
    require_unchanged_inputs(right_jacobian_se3, (XI_MODERATE,), "right_jacobian_se3")
