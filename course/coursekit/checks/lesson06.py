"""Public checks for lesson 06: perturbations and Jacobians.

The checks use quarter turns written out by hand, the library maps of
:mod:`coursekit.lie`, and properties any correct answer has: results that stay
rotations, round trips, and first-order expansions whose remainder shrinks
like the square of the step.
"""

import numpy as np

from ..checking import Mismatch, public_check
from ..diagnose import JACOBIAN_STEP_HINT, close, jacobian_error_allowed, rotation_problem, shape_problem
from ..lie import Exp, Log, quat_product, skew
from .common import fmt, off_by, require_shape

# A quarter turn about z (x goes to y) and about x (y goes to z), written out.
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
E = np.eye(3)
# A generic attitude and a generic small rotation vector.
R_SAMPLE = Exp([0.4, -0.7, 1.1])
D_SAMPLE = np.array([0.2, -0.3, 0.25])


def _first_order_hint(R):
    if close(R, R_SAMPLE @ (E + skew(D_SAMPLE)), 1e-9):
        return "looks like R (I + [δ]×), the first-order approximation: use Exp(δ), which stays a rotation"
    return None


# ---------------------------------------------------------------- boxplus_right
@public_check("boxplus_right", "returns a rotation, and δ = 0 leaves R unchanged")
def _(boxplus_right):
    got = require_shape(boxplus_right(R_SAMPLE, D_SAMPLE), (3, 3))
    problem = rotation_problem(got)
    if problem:
        raise Mismatch(problem, _first_order_hint(got))
    same = require_shape(boxplus_right(R_SAMPLE, np.zeros(3)), (3, 3))
    if not close(same, R_SAMPLE, 1e-12):
        raise Mismatch("boxplus_right(R, 0) differs from R", "Exp(0) is the identity: nothing should move")


@public_check("boxplus_right", "turns about the body's own axis: R ⊞ (0, 0, π/2) keeps the body z axis")
def _(boxplus_right):
    got = require_shape(boxplus_right(QUARTER_TURN_X, [0.0, 0.0, np.pi / 2]), (3, 3))
    expected = QUARTER_TURN_X @ QUARTER_TURN_Z
    if close(got, expected, 1e-9):
        return
    if rotation_problem(got):
        raise Mismatch(f"R ⊞ (0, 0, π/2) is not a rotation: {rotation_problem(got)}",
                       "R (I + [δ]×) is only a first-order approximation: use R @ Exp(δ)")
    if close(got, QUARTER_TURN_Z @ QUARTER_TURN_X, 1e-9):
        raise Mismatch("turned about the world z axis instead of the body's z axis",
                       "that is the left perturbation Exp(δ) R; the right one is R @ Exp(δ)")
    raise Mismatch(f"R ⊞ δ moved the body z axis from {fmt(QUARTER_TURN_X[:, 2])} to {fmt(got[:, 2])}",
                   "the right perturbation is R @ Exp(δ)")


# ---------------------------------------------------------------- boxplus_left
@public_check("boxplus_left", "returns a rotation, and δ = 0 leaves R unchanged")
def _(boxplus_left):
    got = require_shape(boxplus_left(R_SAMPLE, D_SAMPLE), (3, 3))
    problem = rotation_problem(got)
    if problem:
        raise Mismatch(problem, "use Exp(δ), which is always a rotation")
    same = require_shape(boxplus_left(R_SAMPLE, np.zeros(3)), (3, 3))
    if not close(same, R_SAMPLE, 1e-12):
        raise Mismatch("boxplus_left(R, 0) differs from R", "Exp(0) is the identity: nothing should move")


@public_check("boxplus_left", "turns about the world axis: (0, 0, π/2) sends the body z axis from -y to x")
def _(boxplus_left):
    got = require_shape(boxplus_left(QUARTER_TURN_X, [0.0, 0.0, np.pi / 2]), (3, 3))
    expected = QUARTER_TURN_Z @ QUARTER_TURN_X
    if close(got, expected, 1e-9):
        return
    if close(got, QUARTER_TURN_X @ QUARTER_TURN_Z, 1e-9):
        raise Mismatch("turned about the body's z axis instead of the world z axis",
                       "that is the right perturbation R Exp(δ); the left one is Exp(δ) @ R")
    raise Mismatch(f"the body z axis went to {fmt(got[:, 2])}, expected [1, 0, 0]",
                   "the left perturbation is Exp(δ) @ R")


# ---------------------------------------------------------------- boxminus
@public_check("boxminus", "R ⊟ R is zero, shape (3,)")
def _(boxminus):
    got = require_shape(boxminus(R_SAMPLE, R_SAMPLE), (3,))
    if not close(got, np.zeros(3), 1e-9):
        raise Mismatch(f"boxminus(R, R) returned {fmt(got)}", "the difference of a rotation with itself is 0")


@public_check("boxminus", "a quarter turn about the body's z axis: (R Q_z) ⊟ R = (0, 0, π/2)")
def _(boxminus):
    got = require_shape(boxminus(R_SAMPLE @ QUARTER_TURN_Z, R_SAMPLE), (3,))
    if close(got, [0.0, 0.0, np.pi / 2], 1e-9):
        return
    if close(got, [0.0, 0.0, -np.pi / 2], 1e-9):
        raise Mismatch(f"got {fmt(got)}, the step back",
                       "arguments swapped? boxminus(R_a, R_b) = Log(R_bᵀ R_a), the step from R_b to R_a")
    raise Mismatch(f"got {fmt(got)}, expected [0, 0, 1.571]",
                   "boxminus(R_a, R_b) = Log(R_bᵀ R_a): the body-frame step from R_b to R_a")


@public_check("boxminus", "round trip: R_b Exp(R_a ⊟ R_b) = R_a")
def _(boxminus):
    R_b = Exp([-0.5, 0.2, 0.9])
    got = require_shape(boxminus(R_SAMPLE, R_b), (3,))
    if close(R_b @ Exp(got), R_SAMPLE, 1e-9):
        return
    if close(Exp(got) @ R_b, R_SAMPLE, 1e-9):
        raise Mismatch("Exp(δ) R_b gives R_a, but R_b Exp(δ) does not",
                       "that is the left difference Log(R_a R_bᵀ); use Log(R_bᵀ R_a)")
    raise Mismatch("R_b @ Exp(boxminus(R_a, R_b)) is not R_a", "boxminus(R_a, R_b) = Log(R_bᵀ R_a)")


# ---------------------------------------------------------------- quat_boxplus
@public_check("quat_boxplus", "identity ⊞ (0, 0, π/2) is the quarter turn [cos 45°, 0, 0, sin 45°]")
def _(quat_boxplus):
    got = require_shape(quat_boxplus([1.0, 0.0, 0.0, 0.0], [0.0, 0.0, np.pi / 2]), (4,))
    half = np.sqrt(0.5)
    if close(got, [half, 0.0, 0.0, half], 1e-9) or close(got, [-half, 0.0, 0.0, -half], 1e-9):
        return
    if close(np.abs(got), [0.0, 0.0, 0.0, 1.0], 1e-9):
        raise Mismatch(f"got {fmt(got)}: a half turn", "a quaternion holds the half angle: cos(|δ|/2), sin(|δ|/2) u")
    if close(got, [1.0, 0.0, 0.0, np.pi / 4], 1e-9):
        raise Mismatch(f"got {fmt(got)}: the shortcut [1, δ/2] without normalising",
                       "use the exact Exp_q(δ), or at least divide by the norm")
    if close(got, [0.0, 0.0, half, half], 1e-9) or close(got, [half, half, 0.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(got)}", "scalar first: [w, x, y, z]")
    raise Mismatch(f"got {fmt(got)}, expected [0.707, 0, 0, 0.707]")


@public_check("quat_boxplus", "the result has unit norm, even for a large δ")
def _(quat_boxplus):
    q = np.array([np.cos(0.4), np.sin(0.4), 0.0, 0.0])
    got = require_shape(quat_boxplus(q, [0.6, -0.8, 0.5]), (4,))
    norm = np.linalg.norm(got)
    if abs(norm - 1.0) > 1e-9:
        raise Mismatch(f"|q ⊞ δ| = {norm:.6f}",
                       "q ⊗ [1, δ/2] is not a unit quaternion: use the exact Exp_q(δ) or normalise")


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
        if close(np.abs(got), np.abs(quat_product(exp_z, q)), 1e-9):
            raise Mismatch("got Exp_q(δ) ⊗ q", "the right perturbation multiplies on the right: q ⊗ Exp_q(δ)")
        raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)}")
    same = require_shape(quat_boxplus(q, np.zeros(3)), (4,))
    if not (close(same, q, 1e-12) or close(same, -q, 1e-12)):
        raise Mismatch(f"quat_boxplus(q, 0) returned {fmt(same)}",
                       "δ/|δ| is 0/0 at δ = 0: use [1, δ/2] below a tiny angle")


# ---------------------------------------------------------------- numerical_jacobian
def _polynomial(x):
    return np.array([x[0] * x[1], x[2] ** 2])


@public_check("numerical_jacobian", "shape (len(f(x)), n) and the slopes of a small polynomial")
def _(numerical_jacobian):
    got = numerical_jacobian(_polynomial, np.array([1.0, 2.0, 3.0]))
    if np.shape(got) == (3, 2):
        raise Mismatch("returned shape 3×2 for f: R³ → R²: the Jacobian is transposed",
                       "row i is output f_i, column j is input x_j: shape (len(f(x)), n)")
    got = require_shape(got, (2, 3))
    expected = np.array([[2.0, 1.0, 0.0], [0.0, 0.0, 6.0]])
    if not close(got, expected, 1e-3):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from the slopes",
                       "column j: (f(x + δ_j e_j) - f(x)) / δ_j, e.g. with δ_j = max(|1e-4 x_j|, 1e-6)")


def _wavy(x):
    return np.array([np.sin(x[0]) * x[1], np.exp(0.5 * x[2]) + x[0] * x[1]])


def _wavy_jacobian(x):
    return np.array([[np.cos(x[0]) * x[1], np.sin(x[0]), 0.0], [x[1], x[0], 0.5 * np.exp(0.5 * x[2])]])


# How far the lecture's forward steps land from _wavy_jacobian at these points, measured once
# (numbers, not the rule's code: the public checks never carry an answer).
_LECTURE_ERRORS = ((np.array([1.2, -3.0, 2.5]), 1.68e-4), (np.array([0.0, 0.5, -1.0]), 7.58e-6))


@public_check("numerical_jacobian", "at least as accurate as the lecture's forward steps δ_j = max(|1e-4 x_j|, 1e-6)")
def _(numerical_jacobian):
    for x, lecture_error in _LECTURE_ERRORS:
        got = require_shape(numerical_jacobian(_wavy, x), (2, 3))
        exact = _wavy_jacobian(x)
        allowed = jacobian_error_allowed(lecture_error, exact)
        error = np.max(np.abs(got - exact))
        if error > allowed:
            raise Mismatch(f"at x = {fmt(x)} the Jacobian is off by {error:.2g}, more than the {allowed:.2g} allowed "
                           "(twice the error of the lecture's forward steps)", JACOBIAN_STEP_HINT)


@public_check("numerical_jacobian", "works where x_j = 0 (the floor 1e-6 of the step rule)")
def _(numerical_jacobian):
    got = require_shape(numerical_jacobian(np.sin, np.zeros(3)), (3, 3))
    if not close(got, E, 1e-5):
        raise Mismatch(f"the Jacobian of sin at 0 came out as {fmt(got)}, expected the identity",
                       "at x_j = 0 the relative step 1e-4·|x_j| is 0: keep the floor, max(..., 1e-6)")


@public_check("numerical_jacobian", "with a boxplus: 3 columns, one per turning direction of δ")
def _(numerical_jacobian):
    def rotate_x_axis(R):
        return np.asarray(R, dtype=float) @ E[0]

    def plus(R, d):
        return np.asarray(R, dtype=float) @ Exp(d)

    got = numerical_jacobian(rotate_x_axis, np.eye(3), plus)
    if shape_problem(got, (3, 3)) and np.asarray(got).shape == (3, 9):
        raise Mismatch("got 9 columns: the 9 entries of the matrix were perturbed",
                       "with a boxplus, perturb the 3-vector δ in boxplus(x, δ), starting from δ = 0")
    got = require_shape(got, (3, 3))
    # Turning about z moves x towards y, about y towards -z, about x not at all.
    expected = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    if not close(got, expected, 1e-4):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)} from the turning directions",
                       "column j: (f(boxplus(x, h e_j)) - f(x)) / h with a small h (e.g. 1e-6)")


# ---------------------------------------------------------------- jacobian_rotate_point
@public_check("jacobian_rotate_point", "R = I, p = x: turning about z moves x towards y, about y towards -z")
def _(jacobian_rotate_point):
    got = require_shape(jacobian_rotate_point(np.eye(3), [1.0, 0.0, 0.0]), (3, 3))
    expected = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    if not close(got, expected, 1e-12):     # antisymmetric here: a sign slip and a transpose look alike
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)}; expected {fmt(expected)}")


@public_check("jacobian_rotate_point", "first order: R Exp(δ) p - R p - J δ shrinks like |δ|²")
def _(jacobian_rotate_point):
    p = np.array([0.5, -1.0, 2.0])
    J = require_shape(jacobian_rotate_point(R_SAMPLE, p), (3, 3))
    direction = np.array([2.0, -1.0, 2.0]) / 3.0
    for size in (1e-3, 1e-4):
        d = size * direction
        remainder = np.linalg.norm(R_SAMPLE @ Exp(d) @ p - R_SAMPLE @ p - J @ d)
        if remainder > 2.0 * np.linalg.norm(p) * size**2:
            hint = "d(R Exp(δ) p)/dδ = -R [p]×"
            if close(J, -skew(R_SAMPLE @ p), 1e-9):
                hint = "that is -[R p]×, the Jacobian of the left perturbation; the right one is -R [p]×"
            elif close(J, R_SAMPLE @ skew(p), 1e-9):
                hint = "the sign is flipped: R [δ]× p = -R [p]× δ"
            elif close(J, (-R_SAMPLE @ skew(p)).T, 1e-9):
                hint = "that is the transpose of -R [p]×: row i is output i, column j is δ_j"
            raise Mismatch(f"for |δ| = {size:g} the remainder is {remainder:.1e}, not of order |δ|²", hint)


# ---------------------------------------------------------------- right_jacobian_so3
@public_check("right_jacobian_so3", "Jr(0) is the identity, with no NaN")
def _(right_jacobian_so3):
    got = right_jacobian_so3(np.zeros(3))
    problem = shape_problem(got, (3, 3))
    if problem:
        raise Mismatch(f"right_jacobian_so3(0) {problem}",
                       "the closed form is 0/0 at θ = 0: use the Taylor series below a small angle")
    if not close(got, E, 1e-12):
        raise Mismatch(f"right_jacobian_so3(0) returned {fmt(got)}")


@public_check("right_jacobian_so3", "tiny angle |w| = 1e-9: Jr ≈ I - [w]×/2 to full precision")
def _(right_jacobian_so3):
    w = 1e-9 * np.array([0.6, 0.0, 0.8])
    got = require_shape(right_jacobian_so3(w), (3, 3))
    expected = E - 0.5 * skew(w)
    if close(got, E + 0.5 * skew(w), 1e-14):
        raise Mismatch("got I + [w]×/2: the sign of the [w]× term is flipped",
                       "that is the left Jacobian; Jr = I - a [w]× + b [w]×²")
    if not close(got, expected, 1e-14):
        raise Mismatch(f"off by {np.max(np.abs(got - expected)):.1e} at θ = 1e-9",
                       "(1 - cos θ)/θ² loses its digits at tiny θ: use the series 1/2 - θ²/24 below a threshold")


@public_check("right_jacobian_so3", "first order: Exp(w + dw) ≈ Exp(w) Exp(Jr dw) with an error of order |dw|²")
def _(right_jacobian_so3):
    w = np.array([0.9, -1.2, 0.6])
    J = require_shape(right_jacobian_so3(w), (3, 3))
    dw = 1e-4 * np.array([0.48, 0.6, -0.64])
    leftover = np.linalg.norm(Log((Exp(w) @ Exp(J @ dw)).T @ Exp(w + dw)))
    if leftover > 1e-8:
        hint = "Jr = I - (1 - cos θ)/θ² [w]× + (θ - sin θ)/θ³ [w]×²"
        if np.linalg.norm(Log((Exp(J @ dw) @ Exp(w)).T @ Exp(w + dw))) < 1e-8:
            hint = "this J works on the left, Exp(J dw) Exp(w): it is the left Jacobian; flip the sign of the [w]× term"
        raise Mismatch(f"for |dw| = 1e-4 the leftover angle is {leftover:.1e} rad, expected below 1e-8", hint)


# ---------------------------------------------------------------- right_jacobian_inv_so3
@public_check("right_jacobian_inv_so3", "Jr⁻¹(0) is the identity, with no NaN")
def _(right_jacobian_inv_so3):
    got = right_jacobian_inv_so3(np.zeros(3))
    problem = shape_problem(got, (3, 3))
    if problem:
        raise Mismatch(f"right_jacobian_inv_so3(0) {problem}",
                       "the closed form is 0/0 at θ = 0: use the series 1/12 + θ²/720 below a small angle")
    if not close(got, E, 1e-12):
        raise Mismatch(f"right_jacobian_inv_so3(0) returned {fmt(got)}")


@public_check("right_jacobian_inv_so3", "first order: Log(Exp(w) Exp(v)) ≈ w + Jr⁻¹(w) v")
def _(right_jacobian_inv_so3):
    w = np.array([0.9, -1.2, 0.6])
    J = require_shape(right_jacobian_inv_so3(w), (3, 3))
    v = 1e-4 * np.array([0.48, 0.6, -0.64])
    error = np.linalg.norm(Log(Exp(w) @ Exp(v)) - w - J @ v)
    if error > 1e-8:
        hint = "Jr⁻¹ = I + [w]×/2 + (1/θ² - (1 + cos θ)/(2θ sin θ)) [w]×²"
        if np.linalg.norm(Log(Exp(v) @ Exp(w)) - w - J @ v) < 1e-8:
            hint = "this is the inverse of the left Jacobian (it works for Exp(v) Exp(w)): flip the sign of [w]×/2"
        raise Mismatch(f"for |v| = 1e-4 the error is {error:.1e}, expected below 1e-8", hint)


@public_check("right_jacobian_inv_so3", "tiny angle |w| = 1e-9: Jr⁻¹ ≈ I + [w]×/2, finite")
def _(right_jacobian_inv_so3):
    w = 1e-9 * np.array([0.0, 0.6, 0.8])
    got = require_shape(right_jacobian_inv_so3(w), (3, 3))
    if not close(got, E + 0.5 * skew(w), 1e-14):
        raise Mismatch(f"off by {np.max(np.abs(got - E - 0.5 * skew(w))):.1e} at θ = 1e-9",
                       "use the series of the [w]×² coefficient (1/12 + θ²/720) below a small angle")
