"""The numbers stored in the public checks of lesson 06, recomputed from each slip's definition.

The public checks are shipped to students, so they carry the values of the usual slips at their fixed inputs
as literals instead of the formulas (some slips are one constant away from an answer). This test keeps every
literal honest: it recomputes each one here and requires agreement to about 1e-12 (relative).
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson06 as checks
from coursekit.lie import Exp, Log, quat_product, skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run

R, D = checks.R_SAMPLE, checks.D_SAMPLE
P = np.array([0.5, -1.0, 2.0])  # the point of the first-order check of jacobian_rotate_point
W_INV = np.array([0.9, -1.2, 0.6])  # the w of the first-order check of right_jacobian_inv_so3


def same(stored, computed, rel=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    assert np.max(np.abs(stored - computed)) <= rel * max(1.0, np.max(np.abs(computed))), (stored, computed)


def jr_closed_form(w):
    w = np.asarray(w, dtype=float)
    theta, W = np.linalg.norm(w), skew(w)
    return np.eye(3) - (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W


@pytest.mark.parametrize(
    "name, slip",
    [
        ("EXP_D_R_AT_SAMPLE", lambda: Exp(D) @ R),
        ("R_EXP_D_AT_SAMPLE", lambda: R @ Exp(D)),
        ("R_EXP_MINUS_D_AT_SAMPLE", lambda: R @ Exp(-D)),
        ("EXP_MINUS_D_R_AT_SAMPLE", lambda: Exp(-D) @ R),
        ("RT_EXP_D_AT_SAMPLE", lambda: R.T @ Exp(D)),
        ("EXP_D_RT_AT_SAMPLE", lambda: Exp(D) @ R.T),
        ("JRP_AT_GENERIC", lambda: -R @ skew(checks.P_GENERIC)),
        ("JR_AT_W", lambda: jr_closed_form(W_INV)),
        ("JR_INV_FIRST_ORDER_AT_W", lambda: np.eye(3) + 0.5 * skew(W_INV)),
        ("JR_INV_TINY", lambda: np.eye(3) + 0.5 * skew(1e-9 * np.array([0.0, 0.6, 0.8]))),
        (
            "QUAT_NOT_NORMALISED",
            lambda: quat_product(
                [np.cos(0.4), np.sin(0.4), 0.0, 0.0], np.concatenate([[1.0], np.array([0.6, -0.8, 0.5]) / 2.0])
            ),
        ),
    ],
)
def test_stored_slip_matches_its_definition(name, slip):
    same(getattr(checks, name), slip())


def test_boxplus_slips_at_the_quarter_turns_are_the_products_they_name():
    QX, QZ, d = checks.QUARTER_TURN_X, checks.QUARTER_TURN_Z, checks.QUARTER_D
    same(Exp(d), QZ)
    right = [value for value, _ in checks.RIGHT_SLIPS_AT_QUARTER]
    left = [value for value, _ in checks.LEFT_SLIPS_AT_QUARTER]
    same(right[0], Exp(d) @ QX)
    same(right[2], QX @ Exp(-d))
    same(right[3], QX.T @ Exp(d))
    same(left[0], QX @ Exp(d))
    same(left[2], Exp(-d) @ QX)
    same(left[3], Exp(d) @ QX.T)


@pytest.mark.parametrize(
    "table, truth",
    [
        ("RIGHT_SLIPS_AT_SAMPLE", lambda: R @ Exp(D)),
        ("LEFT_SLIPS_AT_SAMPLE", lambda: Exp(D) @ R),
        ("RIGHT_SLIPS_AT_QUARTER", lambda: checks.QUARTER_TURN_X @ checks.QUARTER_TURN_Z),
        ("LEFT_SLIPS_AT_QUARTER", lambda: checks.QUARTER_TURN_Z @ checks.QUARTER_TURN_X),
    ],
)
def test_no_boxplus_slip_is_the_right_answer(table, truth):
    for value, hint in getattr(checks, table):
        assert np.max(np.abs(np.asarray(value) - truth())) > 1e-3, hint


def test_jr_at_w_is_the_jacobian_measured_by_central_differences():
    h = 1e-6
    measured = np.column_stack(
        [(Log(Exp(W_INV).T @ Exp(W_INV + h * e)) - Log(Exp(W_INV).T @ Exp(W_INV - h * e))) / (2 * h) for e in np.eye(3)]
    )
    assert np.max(np.abs(checks.JR_AT_W - measured)) < 1e-8


@pytest.mark.parametrize("theta", [1e-9, 1e-6])
def test_tiny_angle_series(theta):
    w = theta * np.array([0.6, 0.0, 0.8])
    same(checks.JR_TINY[theta], np.eye(3) - 0.5 * skew(w) + skew(w) @ skew(w) / 6.0)


def _jr(a, b):
    """Jr = I - a(θ) [w]× + b(θ) [w]×² with the coefficients given as functions of θ (0 at w = 0)."""

    def right_jacobian_so3(w):
        w = np.asarray(w, dtype=float)
        theta = np.linalg.norm(w)
        W = skew(w)
        return np.eye(3) - a(theta) * W + b(theta) * W @ W

    return right_jacobian_so3


def test_a_closed_form_that_cancels_is_told_by_its_lost_digits():
    """The slip's value is stored nowhere: the check sees the [w]× coefficient miss its limit by more as θ shrinks.
    The naive closed form is named; the series, the reference's half-angle form, and slips with other causes (the
    identity, the left Jacobian, the swapped coefficients) are not."""
    u = np.array([0.6, 0.0, 0.8])
    naive = _jr(lambda t: (1.0 - np.cos(t)) / t**2, lambda t: (t - np.sin(t)) / t**3)
    assert checks._loses_digits(naive, u)
    quiet = [
        _jr(lambda t: 0.5 - t**2 / 24 + t**4 / 720, lambda t: 1 / 6 - t**2 / 120),
        _jr(lambda t: 0.5 * (np.sin(t / 2) / (t / 2)) ** 2, lambda t: 1 / 6),
        _jr(lambda t: 0.0, lambda t: 0.0),
        _jr(lambda t: -0.5, lambda t: 1 / 6),
        _jr(lambda t: 1 / 6, lambda t: 0.5),
    ]
    assert not any(checks._loses_digits(f, u) for f in quiet)


def test_the_boxplus_fixture_of_numerical_jacobian_is_the_right_perturbation():
    d = np.array([0.1, -0.2, 0.3])
    plus_R = (Rotation.from_matrix(R) * Rotation.from_rotvec(d)).as_matrix()
    same(plus_R, R @ Exp(d))


def test_fixed_step_is_read_off_the_moves_of_the_students_function():
    """The step hint watches the student's own function: a fixed forward step of 1e-12 is named, the lecture's
    relative steps and central differences are not."""

    def fixed(h):
        def numerical_jacobian(f, x, boxplus=None):
            x = np.asarray(x, dtype=float)
            f0 = np.asarray(f(x), dtype=float)
            return np.column_stack([(np.asarray(f(x + h * e), dtype=float) - f0) / h for e in np.eye(x.size)])

        return numerical_jacobian

    def central(f, x, boxplus=None):
        x = np.asarray(x, dtype=float)
        return np.column_stack(
            [(np.asarray(f(x + 1e-6 * e)) - np.asarray(f(x - 1e-6 * e))) / 2e-6 for e in np.eye(x.size)]
        )

    x = np.array([1.2, -3.0, 2.5])
    for h in (1e-2, 1e-12, 1e-15):
        steps = checks._steps_taken(fixed(h), checks._wavy, x)
        assert checks._fixed_step_taken(steps, x, 3) == h
    assert checks._fixed_step_taken(checks._steps_taken(central, checks._wavy, x), x, 3) is None
    assert checks._fixed_step_taken(checks._steps_taken(fixed(1e-6), checks._wavy, x), x, 3) is None


def jr_series(w, terms=40):
    """Jr(w) = Σ (-[w]×)^k / (k + 1)!, summed far past convergence: no branch, no cancellation."""
    W = skew(w)
    total, term, factorial = np.zeros((3, 3)), np.eye(3), 1.0
    for k in range(terms):
        total = total + term / factorial
        term = -term @ W
        factorial *= k + 2
    return total


@pytest.mark.parametrize("theta", checks.DECADE_ANGLES)
def test_jr_and_its_inverse_at_every_decade(theta):
    """Jr and Jr⁻¹ at θ u are the branch-free series' to 1e-15, and, where the closed forms keep their digits
    (θ ≥ 0.01), I - a [w]× + b [w]×² and I + [w]×/2 + c [w]×² with the closed-form coefficients."""
    w = theta * checks.DECADE_AXIS
    W = skew(w)
    exact = jr_series(w)
    assert np.max(np.abs(checks.JR_AT_DECADES[theta] - exact)) <= 1e-15
    assert np.max(np.abs(checks.JR_INV_AT_DECADES[theta] - np.linalg.inv(exact))) <= 1e-15
    if theta >= 0.01:
        a, b = (1 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
        c = (1 - 0.5 * theta / np.tan(0.5 * theta)) / theta**2
        same(checks.JR_AT_DECADES[theta], np.eye(3) - a * W + b * W @ W, rel=1e-10)
        same(checks.JR_INV_AT_DECADES[theta], np.eye(3) + 0.5 * W + c * W @ W, rel=1e-9)
    assert set(checks.JR_AT_DECADES) == set(checks.JR_INV_AT_DECADES) == set(checks.DECADE_ANGLES)


def test_lecture_error_at_zero_is_the_floor_steps_error():
    x = np.zeros(3)
    f0 = checks._wavy(x)
    lecture = np.column_stack([(checks._wavy(x + 1e-6 * e) - f0) / 1e-6 for e in np.eye(3)])
    stored = dict((tuple(p), e) for p, e in checks._LECTURE_ERRORS)[(0.0, 0.0, 0.0)]
    assert abs(np.max(np.abs(lecture - checks._wavy_jacobian(x))) - stored) <= 1e-9
