"""Hidden checks for lesson 09, section 6: filter_predict and attitude_nees.

The error state is the right perturbation, R_true = R Exp(ε). Oracles: the definitions, with scipy's Exp and Log.

- filter_predict: R_new = R Exp(ω Δt) to 1e-12; P_new the first-order covariance of ε' with
  R_new Exp(ε') = R Exp(ε) Exp((ω - n) Δt), n ~ N(0, Q), to 2e-12 of max |P_new|, for steps |ω Δt| at every decade
  from 1e-12 to π (and just below 1e-6, 1e-3, 0.1), and the step that does not turn (ω = 0: P + dt² Q) to 1e-14.
  The oracle is exact: the old error crosses the step as Exp(-ω Δt), the noise enters through ∫₀¹ Exp(-s ω Δt) ds Δt,
  that integral read off scipy's matrix exponential of a 6 × 6 block matrix (no closed form);
  tests/test_hidden_oracles_lesson09.py holds it against central differences of the definition. First-order
  Jacobians taken by the lesson's central differences (they miss it at the larger steps) do not pass (a high-order
  stencil with a tuned step can pass: values alone cannot tell an accurate numerical Jacobian from an exact one),
  nor does a closed form of J_r that loses its digits just above its small-step branch; the central differences
  still name the usual slips.
  Core idea (3 of 6 points): the old error crosses the step's turn and the noise enters through the step. Lists
  and nested tuples are accepted.
- attitude_nees: εᵀ P⁻¹ ε with ε = Log(R_estᵀ R_true), to 1e-9 relative, for errors at every decade from 1e-12 to
  π - 1e-9 (core, 3 of 5 points).
Every test calls its own exercise's student function only.
"""

import numpy as np
from coursekit import hints
from scipy.spatial.transform import Rotation
from scipy.stats import chi2

from .helpers import Wrong, exercise, expect, expect_array, expect_close, expect_same_with_lists, random_rotations

DECADES = (0.7, 2.0, 1e-12, 1e-9, 1e-6, 1e-3, 1e-2, 0.1, 3.0, np.pi - 1e-9)


def _skew(v):
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(R).as_rotvec()


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _unit(rng):
    v = rng.normal(size=3)
    return v / np.linalg.norm(v)


def _covariance(rng, size):
    A = rng.normal(size=(3, 3))
    return size * (A @ A.T + 0.3 * np.eye(3))


def _pair(value, what):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Wrong(f"{what} returned {type(value).__name__}, not a pair (R_new, P_new)", "return both: R_new, P_new")
    return expect_array(value[0], (3, 3), f"{what}'s R_new"), expect_array(value[1], (3, 3), f"{what}'s P_new")


def _tuples(a):
    """``a`` as nested tuples of floats (array_like, as the docstrings allow)."""
    return tuple(_tuples(x) for x in a) if np.ndim(a) else float(a)


def _first(got, candidates, truth, tol):
    for candidate, hint in candidates:
        if np.max(np.abs(candidate - truth)) > 10 * tol and np.max(np.abs(got - candidate)) <= tol:
            return hint
    return ""


# ---------------------------------------------------------------- filter_predict
def _predict_jacobians(R, omega, dt):
    R_new = R @ _exp(omega * dt)
    J = _central(lambda x: _log(R_new.T @ R @ _exp(x[:3]) @ _exp((omega - x[3:]) * dt)), 6, h=1e-5 * max(1.0, dt))
    return J[:, :3], J[:, 3:]


def _predict_hint(P_new, R, P, omega, dt, Q, truth, tol):
    F, G = _predict_jacobians(R, omega, dt)
    return _first(
        P_new,
        [
            (
                P + G @ Q @ G.T,
                "P was not carried across the step: P_new is right when the step does not turn, and wrong when it does",
            ),
            (F.T @ P @ F + G @ Q @ G.T, "the error crosses the step's turn the wrong way round"),
            (F @ P @ F.T + dt * dt * Q, hints.PREDICT_NOISE_SHORT_STEP_HINT),
            (
                F @ P @ F.T + G @ Q @ G.T / dt,
                "Q is in (rad/s)² and P in rad²: check the units of the noise's part",
            ),
            (F @ P @ F.T, "the gyro noise must add to P"),
            (F @ P @ F.T + G.T @ Q @ G, hints.PREDICT_NOISE_OLD_AXES_HINT),
        ],
        truth,
        tol,
    )


def exact_predict_covariance(R, P, omega, dt, Q):
    """P_new to rounding: F = Exp(ω Δt)ᵀ and G = J_r(ω Δt) Δt, J_r = ∫₀¹ Exp(-s ω Δt) ds from a block exponential."""
    from scipy.linalg import expm

    phi = np.asarray(omega, dtype=float) * dt
    block = np.zeros((6, 6))
    block[:3, :3] = -_skew(phi)
    block[:3, 3:] = np.eye(3)
    F, G = _exp(phi).T, expm(block)[:3, 3:] * dt
    return F @ P @ F.T + G @ Q @ G.T


EXACT = 2e-12  # of max |P_new|; Jacobians by central differences leave 7e-12 to 6e-10 (steps of 1e-5 to 1e-6)
PREDICT_ROUNDING_HINT = hints.PREDICT_FINITE_DIFFERENCES_HINT
PREDICT_CANCELS_HINT = hints.PREDICT_CANCELS_HINT


# every decade, and just below 1e-6, 1e-3 and 0.1, where a small-step branch may switch
PREDICT_STEPS = DECADES + (9.9e-7, 9.9e-4, 9.9e-2)


def _predict_cases(seed):
    rng = np.random.default_rng(seed)
    for step in PREDICT_STEPS:
        dt = float(rng.choice([0.005, 0.01, 0.1, 0.5]))
        omega = step / dt * _unit(rng)
        yield _exp(rng.uniform(0.2, 3.0) * _unit(rng)), _covariance(rng, 1e-3), omega, dt, _covariance(rng, 1e-2)
    # just above and just below every decade where a small-step branch may end, with a long step and a small P, so
    # that the noise term, which carries J_r, is most of P_new (a closed form that cancels above a branch shows, and
    # a series too short for the steps below it)
    for step in (1.01e-9, 1.01e-8, 1.01e-7, 1.01e-6, 1.01e-5, 1.01e-4, 1.01e-3, 9.9e-4, 9.9e-3, 9.9e-2):
        omega = step / 0.5 * _unit(rng)
        yield _exp(rng.uniform(0.2, 3.0) * _unit(rng)), _covariance(rng, 1e-9), omega, 0.5, _covariance(rng, 1e-2)


@exercise("filter_predict", weight=3)
def test_predict_covariance_first_order(student):
    """P_new is the first-order covariance of the new error, to 2e-12, for steps |ω Δt| from 1e-12 to π"""
    for R, P, omega, dt, Q in _predict_cases(9100):
        _, P_new = _pair(student.filter_predict(R, P, omega, dt, Q), "filter_predict")
        truth = exact_predict_covariance(R, P, omega, dt, Q)
        scale = np.max(np.abs(truth))
        if np.max(np.abs(P_new - truth)) <= EXACT * scale:
            continue
        near = np.max(np.abs(P_new - truth)) <= 1e-7 * scale
        expect_close(
            P_new,
            truth,
            EXACT * scale,
            f"filter_predict's P_new for a step of {np.linalg.norm(omega * dt):.3g} rad",
            lambda: (
                (PREDICT_CANCELS_HINT if np.linalg.norm(omega * dt) < 1e-2 else PREDICT_ROUNDING_HINT)
                if near
                else _predict_hint(P_new, R, P, omega, dt, Q, truth, 1e-7 * scale)
            ),
        )


@exercise("filter_predict", weight=1)
def test_predict_attitude(student):
    """R_new = R Exp(ω Δt) to 1e-12 for steps from 1e-12 to π"""
    for R, P, omega, dt, Q in _predict_cases(9110):
        R_new, _ = _pair(student.filter_predict(R, P, omega, dt, Q), "filter_predict")
        truth = R @ _exp(omega * dt)
        hint = ""
        if np.max(np.abs(R_new - _exp(omega * dt) @ R)) < 1e-12:
            hint = "that is the step on the world side: a gyro measures body rates, so the step goes on the right of R"
        expect_close(
            R_new, truth, 1e-12, f"filter_predict's R_new for a step of {np.linalg.norm(omega * dt):.3g} rad", hint
        )


@exercise("filter_predict", weight=1)
def test_predict_no_turn(student):
    """with ω = 0: R_new = R, and P_new is P plus one step's gyro noise, to 1e-14 (generic R, P, Q)"""
    rng = np.random.default_rng(9130)
    for dt in (0.005, 0.1, 0.5):
        R, P, Q = _exp(rng.uniform(0.2, 3.0) * _unit(rng)), _covariance(rng, 1e-3), _covariance(rng, 1e-2)
        R_new, P_new = _pair(student.filter_predict(R, P, np.zeros(3), dt, Q), "filter_predict")
        expect_close(R_new, R, 1e-14, f"filter_predict's R_new with ω = 0 (dt = {dt:g})", hints.PREDICT_NO_TURN_R_HINT)
        truth = P + dt * dt * Q
        expect_close(
            P_new,
            truth,
            1e-14 * np.max(np.abs(truth)),
            f"filter_predict's P_new with ω = 0 (dt = {dt:g})",
            hints.PREDICT_NO_TURN_P_HINT,
        )


@exercise("filter_predict", weight=1)
def test_predict_accepts_lists(student):
    """gives the same answer for plain lists and for nested tuples as for arrays"""
    rng = np.random.default_rng(9120)
    args = (random_rotations(1, 9121)[0], _covariance(rng, 1e-3), [0.3, -1.0, 2.0], 0.05, _covariance(rng, 1e-2))
    expect_same_with_lists(
        lambda *a: np.vstack(student.filter_predict(*a)), args, (6, 3), "filter_predict(R, P, omega_meas, dt, Q)"
    )
    expect_same_with_lists(
        lambda *a: np.vstack(student.filter_predict(*a)),
        args,
        (6, 3),
        "filter_predict(...) given tuples",
        lists=[_tuples(a) for a in args],
    )


# ---------------------------------------------------------------- attitude_nees
def _nees_hint(got, R_true, R_est, P, truth):
    e = _log(R_est.T @ R_true)
    w = _log(R_true @ R_est.T)
    d = _log(R_true) - _log(R_est)
    candidates = [
        (w @ np.linalg.solve(P, w), "that is a turn in world axes, Log(R_true R_estᵀ)"),
        (e @ P @ e, "the NEES uses P's inverse"),
        (truth / 3.0, hints.NEES_NOT_DIVIDED_HINT),
        (np.sqrt(truth), "that is the Mahalanobis distance; the NEES is its square"),
        (d @ np.linalg.solve(P, d), "rotation vectors do not subtract"),
        (float(e @ (e / np.diag(P))), "the off-diagonal entries of P count too"),
    ]
    for value, hint in candidates:
        if abs(value - truth) > 1e-6 * truth and abs(got - value) <= 1e-9 * max(truth, value):
            return hint
    return ""


@exercise("attitude_nees", weight=3)
def test_nees_definition(student):
    """equals εᵀ P⁻¹ ε, ε = Log(R_estᵀ R_true), to 1e-9 relative (and Log's rounding) for errors from 1e-12 to π - 1e-9 rad"""
    rng = np.random.default_rng(9300)
    for angle in DECADES:
        R_est = _exp(rng.uniform(0.1, 3.0) * _unit(rng))
        P = _covariance(rng, float(rng.choice([1e-6, 1e-2, 1.0])))
        e = angle * _unit(rng)
        R_true = R_est @ _exp(e)
        truth = float(e @ np.linalg.solve(P, e))
        value = expect_array(student.attitude_nees(R_true, R_est, P), (), "attitude_nees(R_true, R_est, P)")
        expect_close(
            float(value),
            truth,
            1e-9 * truth + 1e-14 * np.linalg.norm(np.linalg.solve(P, e)),  # and Log's rounding, 5e-15 rad
            f"attitude_nees for an error of {angle:.3g} rad",
            lambda: _nees_hint(float(value), R_true, R_est, P, truth),
        )


@exercise("attitude_nees", weight=1)
def test_nees_chi_square(student):
    """errors drawn from N(0, P) give an average NEES in the 99 % χ² band (400 draws)"""
    rng = np.random.default_rng(9310)
    P = _covariance(rng, 1e-2)
    values = []
    for _ in range(400):
        R_est = _exp(rng.uniform(0.1, 3.0) * _unit(rng))
        R_true = R_est @ _exp(rng.multivariate_normal(np.zeros(3), P))
        values.append(float(expect_array(student.attitude_nees(R_true, R_est, P), (), "attitude_nees")))
    low, high = chi2.ppf(0.005, 1200) / 400, chi2.ppf(0.995, 1200) / 400
    average = float(np.mean(values))
    expect(
        low <= average <= high,
        f"the average NEES is {average:.3g}, outside the 99 % χ² band [{low:.3g}, {high:.3g}]",
        "for a consistent error the NEES averages the dimension, 3",
    )


@exercise("attitude_nees", weight=1)
def test_nees_accepts_lists(student):
    """gives the same answer for plain lists and for nested tuples as for arrays"""
    R = random_rotations(2, 9320)
    args = (R[0], R[1], np.diag([0.1, 0.2, 0.3]))
    expect_same_with_lists(student.attitude_nees, args, (), "attitude_nees")
    expect_same_with_lists(
        student.attitude_nees, args, (), "attitude_nees given tuples", lists=[_tuples(a) for a in args]
    )
