"""Hidden checks for lesson 04, section 14: quat_power, the power q^t = Exp_q(t Log_q q) of a unit quaternion.

Oracles: the power written out here for q = [cos α, sin α u] built from a known α in [0, π] and axis u, and the
group laws of powers (q^s ⊗ q^t = q^(s+t), q^-1 = q*, q⁰ = 1), with a product written out here. Core idea (3 of
6 points): α read accurately over every decade from 1e-12 to π (tolerance 1e-15 + 1e-10 |tα|), so the classic
slip, α = arccos(w), earns at most half; q and -q have different powers (1 point). Every test calls quat_power
only.
"""

import numpy as np

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect, expect_array, expect_close, expect_same_with_lists, fmt

ANGLES = (1e-12, 1e-9, 1e-6, 1e-4, 1e-2, 0.3, 1.0, 2.0, 3.0, np.pi - 1e-6, np.pi - 1e-9)


def _unit(seed, count):
    v = np.random.default_rng(seed).normal(size=(count, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _quat(alpha, axis):
    return np.concatenate([[np.cos(alpha)], np.sin(alpha) * np.asarray(axis, dtype=float)])


def _qmul(p, q):
    pw, pv, qw, qv = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[pw * qw - pv @ qv], pw * qv + qw * pv + np.cross(pv, qv)])


def _first_explained(got, candidates, truth, floor=1e-12):
    """The hint of the first slip whose value accounts for ``got``; slips within 100 floors of the truth are
    indistinguishable from it on this input and are skipped."""
    for candidate, hint in candidates:
        candidate = np.asarray(candidate, dtype=float)
        if candidate.shape == np.shape(truth) and np.max(np.abs(candidate - truth)) < 100 * floor:
            continue
        if explains(got, candidate, truth, floor=floor):
            return hint
    return ""


def _power_hint(got, alpha, axis, t):
    truth = _quat(t * alpha, axis)
    return (
        _first_explained(
            got,
            [
                (_quat(2 * t * alpha, axis), hints.POWER_HALF_ANGLE_HINT),
                (_quat(t * (np.pi - alpha), -axis) if alpha > np.pi / 2 else truth, hints.POWER_SIGN_FLIP_HINT),
                (_quat(t * np.arccos(np.clip(np.cos(alpha), -1.0, 1.0)), axis), hints.POWER_ARCCOS_HINT),
                (
                    np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * np.sin(alpha) * axis]),
                    hints.POWER_UNIT_AXIS_HINT,
                ),
            ],
            truth,
            floor=1e-17,
        )
        or hints.POWER_DEFINITION_HINT
    )


@exercise("quat_power", weight=3)
def test_power_every_angle(student):
    """q^t for α at every decade from 1e-12 to π and t from -1.5 to 3.7, to 1e-15 + 1e-10 |tα|"""
    generic_first = sorted(ANGLES, key=lambda a: (a < 0.1, -a))  # 3, 2, 1, 0.3, then the decades down to 1e-12
    axes = _unit(9400, len(ANGLES))
    for alpha, axis in zip(generic_first, axes):
        q = _quat(alpha, axis)
        for t in (-1.5, 0.3, 0.5, 2.0, 3.7):
            got = expect_array(student.quat_power(q, t), (4,), f"quat_power(q, {t:g})")
            expected = _quat(t * alpha, axis)
            tol = 1e-15 + 1e-10 * abs(t * alpha)
            expect(
                np.max(np.abs(got - expected)) <= tol,
                f"quat_power(q, {t:g}) for α = {alpha:.3g} is off by {np.max(np.abs(got - expected)):.2g} "
                f"(tolerance {tol:.2g}): got {fmt(got, 6)}, expected {fmt(expected, 6)}",
                lambda: _power_hint(got, alpha, axis, t),
            )


@exercise("quat_power", weight=1)
def test_power_of_the_other_sign(student):
    """(−q)^t turns the other way: half-angle π − α about −u (q and −q have different powers), to 1e-12"""
    for alpha, axis in zip((0.2, 1.0, 2.5), _unit(9410, 3)):
        q = _quat(alpha, axis)
        got = expect_array(student.quat_power(-q, 0.5), (4,), "quat_power(-q, 0.5)")
        expected = _quat(0.5 * (np.pi - alpha), -axis)
        expect_close(
            got,
            expected,
            1e-12,
            f"quat_power(-q, 0.5) for α = {alpha:g}",
            lambda: (
                hints.POWER_SIGN_FLIP_HINT
                if np.allclose(np.abs(got @ _quat(0.5 * alpha, axis)), 1.0)
                else _power_hint(got, np.pi - alpha, -axis, 0.5)
            ),
        )


@exercise("quat_power", weight=1)
def test_power_laws(student):
    """q^s ⊗ q^t = q^(s+t), q^-1 = q*, q^0 = 1, and the identity to any power is the identity (to 1e-12)"""
    for alpha, axis in zip((0.4, 1.3, 2.9), _unit(9420, 3)):
        q = _quat(alpha, axis)
        a = expect_array(student.quat_power(q, 0.3), (4,), "quat_power(q, 0.3)")
        b = expect_array(student.quat_power(q, 0.9), (4,), "quat_power(q, 0.9)")
        c = expect_array(student.quat_power(q, 1.2), (4,), "quat_power(q, 1.2)")
        expect_close(_qmul(a, b), c, 1e-12, "q^0.3 ⊗ q^0.9 against q^1.2", lambda: _power_hint(c, alpha, axis, 1.2))
        inverse = expect_array(student.quat_power(q, -1.0), (4,), "quat_power(q, -1)")
        expect_close(
            inverse,
            q * [1.0, -1.0, -1.0, -1.0],
            1e-12,
            "quat_power(q, -1) against the conjugate",
            lambda: _power_hint(inverse, alpha, axis, -1.0),
        )
        zero = expect_array(student.quat_power(q, 0.0), (4,), "quat_power(q, 0)")
        expect_close(zero, [1.0, 0.0, 0.0, 0.0], 1e-15, "quat_power(q, 0)")
    for t in (0.5, -2.0, 7.3):
        identity = student.quat_power([1.0, 0.0, 0.0, 0.0], t)
        expect(
            np.shape(identity) != (4,) or np.all(np.isfinite(np.asarray(identity, dtype=float))),
            f"quat_power(1, {t:g}) returned NaN",
            hints.POWER_IDENTITY_HINT,
        )
        identity = expect_array(identity, (4,), f"quat_power(1, {t:g})")
        expect_close(
            identity, [1.0, 0.0, 0.0, 0.0], 1e-15, f"the identity to the power {t:g}", hints.POWER_IDENTITY_HINT
        )


@exercise("quat_power", weight=1)
def test_power_accepts_lists(student):
    """gives the same answer for a plain list as for an array"""
    q = _quat(1.1, _unit(9430, 1)[0])
    expect_same_with_lists(lambda q_: student.quat_power(q_, 0.7), (q,), (4,), "quat_power(q, 0.7)")
