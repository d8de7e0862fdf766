"""Hidden checks for lesson 09, section 6: filter_update, the attitude filter's correction with a measured direction.

The error state is the right perturbation, R_true = R Exp(ε); the measurement is y = R_trueᵀ g_w + v, v ~ N(0, Rn).
Oracles: the definitions, with scipy's Exp and Log. Log(Rᵀ R_new) must be the minimiser of the linearised MAP cost
|ε|²_{P⁻¹} + |y - Rᵀ g_w - H ε|²_{Rn⁻¹} and P_new the inverse of half its Hessian, both to 1e-11 relative, with H the exact
derivative of (R Exp(ε))ᵀ g_w at ε = 0 (tests/test_hidden_oracles_lesson09.py holds it against central differences):
the docstring's linearisation is exact, and a Jacobian taken by the lesson's central differences (good to about
3e-10) does not pass (values alone cannot tell an accurate numerical Jacobian from an exact one: a high-order
stencil with a tuned step (8th order, h = 0.02) reaches about 1e-13 and passes), nor does float32 storage anywhere.
Attitudes at every angle from 1e-12 to π, with gravity (9.80665 m/s²) or a unit star direction; lists and nested
tuples are accepted. Core idea (3 of 6 points): the measurement Jacobian of the right error. A filter run on a
seeded trajectory (the reference's prediction, the student's update) must be consistent: over 40 independent runs
its average NEES at the end lies in the two-sided 99 % χ² band. Every test calls filter_update only.
"""

from functools import lru_cache

import numpy as np
from coursekit import hints
from scipy.spatial.transform import Rotation
from scipy.stats import chi2

from .helpers import Wrong, exercise, expect, expect_array, expect_close, expect_same_with_lists

DECADES = (0.7, 2.0, 1e-12, 1e-9, 1e-6, 1e-3, 1e-2, 0.1, 3.0, np.pi - 1e-9)


def _skew(v):
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(R).as_rotvec()


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
    """``a`` as nested tuples of floats (array_like, as the docstring allows)."""
    return tuple(_tuples(x) for x in a) if np.ndim(a) else float(a)


def _first(got, candidates, truth, tol):
    for candidate, hint in candidates:
        if np.max(np.abs(candidate - truth)) > 10 * tol and np.max(np.abs(got - candidate)) <= tol:
            return hint
    return ""


# ---------------------------------------------------------------- filter_update
def measurement_jacobian(R, g_w):
    """H = d/dε (R Exp(ε))ᵀ g_w at ε = 0, exact: Exp(-ε) b ≈ b - ε × b = b + [b]× ε with b = Rᵀ g_w."""
    return _skew(R.T @ g_w)


EXACT = 1e-11  # relative; a measurement Jacobian by central differences leaves about 3e-10
FINITE_DIFFERENCES_HINT = hints.UPDATE_FINITE_DIFFERENCES_HINT


def _map(R, P, y, g_w, Rn):
    H = measurement_jacobian(R, g_w)
    information = np.linalg.inv(P) + H.T @ np.linalg.solve(Rn, H)
    return np.linalg.solve(information, H.T @ np.linalg.solve(Rn, y - R.T @ g_w)), np.linalg.inv(information), H


def _update_hint(step, R, P, y, g_w, Rn, truth, tol):
    def kalman(H):
        K = np.linalg.solve(H @ P @ H.T + Rn, H @ P).T
        return K @ (y - R.T @ g_w)

    g_b = R.T @ g_w
    return _first(
        step,
        [
            (kalman(-_skew(g_b)), hints.UPDATE_SIGN_HINT),
            (kalman(_skew(g_w)), "the measurement Jacobian must depend on the attitude R"),
            (
                kalman(R.T @ _skew(g_w)),
                "that measurement Jacobian belongs to a left (world-frame) error; this one is on the right",
            ),
            (
                np.linalg.solve(_skew(g_b) @ P @ _skew(g_b).T + Rn, _skew(g_b) @ P).T @ y,
                "the gain multiplies the innovation y - Rᵀ g_w, not the measurement y itself",
            ),
        ],
        truth,
        tol,
    )


def _update_cases(seed):
    rng = np.random.default_rng(seed)
    for angle in DECADES:
        R = _exp(angle * _unit(rng))
        g_w = rng.choice([9.80665, 1.0]) * _unit(rng)  # gravity, or a unit star direction
        P = _covariance(rng, float(rng.choice([1e-4, 1e-2])))
        Rn = _covariance(rng, 1e-3) * np.linalg.norm(g_w) ** 2
        y = _exp(0.05 * rng.normal(size=3)).T @ R.T @ g_w + rng.multivariate_normal(np.zeros(3), Rn)
        yield R, P, y, g_w, Rn


@exercise("filter_update", weight=3)
def test_update_is_the_map_minimiser(student):
    """the correction minimises the linearised MAP cost, to 1e-11, for attitudes at every angle from 1e-12 to π"""
    for R, P, y, g_w, Rn in _update_cases(9200):
        R_new, _ = _pair(student.filter_update(R, P, y, g_w, Rn), "filter_update")
        truth, _, _ = _map(R, P, y, g_w, Rn)
        got = _log(R.T @ R_new)
        tol = EXACT * max(1e-6, np.max(np.abs(truth)))
        hint = _update_hint(got, R, P, y, g_w, Rn, truth, 200 * tol)
        if not hint and np.max(np.abs(_log(R_new @ R.T) - truth)) <= 200 * tol:
            hint = hints.UPDATE_WRONG_SIDE_HINT
        if not hint and np.max(np.abs(got - truth)) <= 1e-7 * max(1e-6, np.max(np.abs(truth))):
            hint = FINITE_DIFFERENCES_HINT
        expect_close(
            got, truth, tol, f"filter_update's correction at an attitude of {_log(R).dot(_log(R)) ** 0.5:.3g} rad", hint
        )


@exercise("filter_update", weight=1)
def test_update_covariance(student):
    """P_new is the inverse of half the Hessian of the linearised MAP cost, to 1e-11 of max |P_new|"""
    for R, P, y, g_w, Rn in _update_cases(9210):
        _, P_new = _pair(student.filter_update(R, P, y, g_w, Rn), "filter_update")
        _, truth, _ = _map(R, P, y, g_w, Rn)
        hint = "a measurement adds information: P_new must shrink" if np.max(np.abs(P_new - P)) < 1e-15 else ""
        if not hint and np.max(np.abs(P_new - truth)) <= 1e-7 * np.max(np.abs(truth)):
            hint = FINITE_DIFFERENCES_HINT
        expect_close(P_new, truth, EXACT * np.max(np.abs(truth)), "filter_update's P_new", hint)


def _trajectory(seed, steps=400, dt=0.01):
    rng = np.random.default_rng(seed)
    phases, amplitudes = rng.uniform(0, 2 * np.pi, 3), rng.uniform(0.5, 2.0, 3)
    times = dt * np.arange(steps)
    return amplitudes * np.sin(times[:, None] * np.array([1.3, 0.7, 2.1]) + phases), dt


GRAVITY_W = np.array([0.0, 0.0, 9.80665])
GYRO_Q, GRAVITY_RN = np.diag([0.02, 0.03, 0.025]) ** 2, np.diag([0.3, 0.2, 0.4]) ** 2


@lru_cache(maxsize=1)
def _consistency_runs(runs=40, steps=60):
    """The seeded runs of the consistency test: each run's start (estimate, covariance), step dt, gyro samples,
    gravity readings (by step) and final truth. None of it depends on the student, so it is drawn once per grader
    process, in the order the test has always drawn it (the same numbers, bit for bit)."""
    rng = np.random.default_rng(9230)
    drawn = []
    for run in range(runs):
        omegas, dt = _trajectory(9231 + run, steps=steps)
        P = np.diag([0.1, 0.1, 0.1]) ** 2
        R_true = _exp(rng.normal(size=3))
        R = R_true @ _exp(-rng.multivariate_normal(np.zeros(3), P))
        samples, readings = [], {}
        for k, omega in enumerate(omegas):
            R_true = R_true @ _exp(omega * dt)
            samples.append(omega + rng.multivariate_normal(np.zeros(3), GYRO_Q))
            if k % 5 == 4:
                readings[k] = R_true.T @ GRAVITY_W + rng.multivariate_normal(np.zeros(3), GRAVITY_RN)
        for array in (R, P, R_true, *samples, *readings.values()):
            array.setflags(write=False)  # shared by every student of the process
        drawn.append((R, P, dt, tuple(samples), readings, R_true))
    return tuple(drawn)


@exercise("filter_update", weight=1)
def test_update_filter_is_consistent(student, ref):
    """runs of the filter on seeded trajectories end with an average NEES in the 99 % χ² band"""
    # The NEES test averages over independent runs at one time: within one run the errors are correlated (the
    # yaw error, which gravity cannot see, is one draw carried along), so a time average has no χ² law.
    runs, nees = _consistency_runs(), []
    for R, P, dt, samples, readings, R_true in runs:
        for k, sample in enumerate(samples):
            R, P = ref.filter_predict(R, P, sample, dt, GYRO_Q)
            if k in readings:
                R, P = _pair(student.filter_update(R, P, readings[k], GRAVITY_W, GRAVITY_RN), "filter_update")
                expect(np.all(np.isfinite(P)), "filter_update returned a covariance that is not finite")
        e = _log(R.T @ R_true)
        nees.append(float(e @ np.linalg.solve(P, e)))
    count = len(runs)
    low, high = chi2.ppf(0.005, 3 * count) / count, chi2.ppf(0.995, 3 * count) / count
    average = float(np.mean(nees))
    expect(
        low <= average <= high,
        f"the average NEES over {count} runs is {average:.3g}, outside the 99 % band [{low:.3g}, {high:.3g}]",
        "over-confident (too large) or over-cautious (too small): compare P_new with the inverse of half the MAP cost's Hessian",
    )


@exercise("filter_update", weight=1)
def test_update_accepts_lists(student):
    """gives the same answer for plain lists and for nested tuples as for arrays"""
    args = next(_update_cases(9240))
    expect_same_with_lists(
        lambda *a: np.vstack(student.filter_update(*a)), args, (6, 3), "filter_update(R, P, y, g_w, Rn)"
    )
    expect_same_with_lists(
        lambda *a: np.vstack(student.filter_update(*a)),
        args,
        (6, 3),
        "filter_update(...) given tuples",
        lists=[_tuples(a) for a in args],
    )
