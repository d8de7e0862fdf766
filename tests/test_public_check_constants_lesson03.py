"""Lesson 03's public checks store what each typical slip returns at their fixed inputs as literals.

The public check module is shipped to students, so it must not compute an
exercise's answer (nor the answer with one changed constant): no hat, no
partial sums of the exponential series, no Rodrigues, no atan2 log, no
eigenvector picking. Its hints compare the student's answer with stored
values instead; this file recomputes every stored value from the slip's
definition, so a literal can never silently go stale.
"""

import inspect
import io
import re
import tokenize

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson03 as L

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run

RTOL = 1e-12


def _hat(w):
    x, y, z = np.asarray(w, dtype=float)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _partial(W, first, last, factorial=True):
    """Σ W^k / k! (or Σ W^k) for k = first … last."""
    term, total = np.eye(len(W)), np.zeros_like(W)
    for k in range(last + 1):
        if k >= first:
            total = total + term
        term = term @ W / (k + 1 if factorial else 1)
    return total


def _entrywise(W, n):
    return sum(W**k / np.prod(np.arange(1, k + 1)) for k in range(n))


def _rodrigues_swapped(w):
    theta = np.linalg.norm(w)
    K = _hat(np.asarray(w) / theta)
    return np.eye(3) + (1 - np.cos(theta)) * K + np.sin(theta) * K @ K


def _rodrigues_unnormalised(w):
    theta = np.linalg.norm(w)
    W = _hat(w)
    return np.eye(3) + np.sin(theta) * W + (1 - np.cos(theta)) * W @ W


def _log_parts(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    c = 0.5 * (np.trace(R) - 1.0)
    return a, float(np.arctan2(np.linalg.norm(a), c)), float(np.arccos(np.clip(c, -1.0, 1.0)))


def _no_branch(R):
    a, theta, theta_acos = _log_parts(R)
    return [t / np.sin(t) * a for t in (theta, theta_acos) if np.sin(t) != 0.0]


def _column_slips(R, expected):
    """What a near-π log that always reads its axis from one fixed column of B = (R + Rᵀ)/2 - cos θ I returns
    (each non-zero column, signed by vee(R - Rᵀ)'s direction, here expected · sin θ, with either sign of
    ``expected``: at exactly π both signs are right), and whether some column of B is (nearly) zero there."""
    R = np.asarray(R, dtype=float)
    B = 0.5 * (R + R.T) - 0.5 * (np.trace(R) - 1.0) * np.eye(3)
    diagonal = np.diag(B)
    angle = float(np.linalg.norm(expected))
    logs = []
    for sign in (1.0, -1.0):
        a = sign * expected * np.sin(angle) / angle
        for j in range(3):
            norm = np.sqrt(B[:, j] @ B[:, j])
            if norm > 0.0:
                u = B[:, j] / norm
                log = angle * u * (1.0 if u @ a >= 0.0 else -1.0)
                if not any(np.array_equal(log, seen) for seen in logs):
                    logs.append(log)
    return {"weak_column": bool(np.min(diagonal) <= 1e-8 * np.max(diagonal)), "column_logs": logs}


def _unit(v):
    v = np.real(np.asarray(v))
    return v / np.linalg.norm(v)


def _eigen_row_lines(R):
    """Every line a row of eig's vector matrix can give, whatever LAPACK's kernel chooses: the real eigenvalue listed
    first or last (a complex pair stays together), each column's sign its own (the pair shares one)."""
    values, vectors = np.linalg.eig(R)
    k = int(np.argmin(np.abs(values - 1.0)))
    real, pair = np.real(vectors[:, k]), np.real(vectors[:, (k + 1) % 3])
    rows = []
    for flip in (1.0, -1.0):
        rows.append([real[0], flip * pair[0], flip * pair[0]])  # real eigenvalue first: row 0
        rows.append([flip * pair[2], flip * pair[2], real[2]])  # real eigenvalue last: row 2
    return np.array([_unit(row) for row in rows])


def _eigen_slips(R, keys):
    """What each axis_from_eigen slip returns for R (the module keeps those that differ from the axis)."""
    values, vectors = np.linalg.eig(R)
    sym_values, sym_vectors = np.linalg.eigh(R)
    slips = {
        "row": _eigen_row_lines(R),
        "first": _unit(vectors[:, 0]),
        "first_eigenvalue": complex(values[0]),
        "svd_of_R": np.linalg.svd(R)[2][-1],
        "eigh": sym_vectors[:, int(np.argmin(np.abs(sym_values - 1.0)))],
    }
    return {key: slips[key] for key in keys}


def _log_inputs():
    return {
        "quarter": L.QUARTER_TURN_Z,
        "tiny_1e-08": _exp(1e-8 * L.AXIS_221),
        "tiny_0.001": _exp(1e-3 * L.AXIS_221),
        "half_z": L.HALF_TURN_Z,
        "half_diagonal": L.HALF_TURN_DIAGONAL,
        "below_pi": _exp((np.pi - 1e-6) * L.AXIS_BELOW_PI),
    }


def _near_pi_logs():
    """The rotation vector each near-π check expects (the half turns' with the axis's own sign)."""
    return {
        "half_z": np.pi * np.array([0.0, 0.0, 1.0]),
        "half_diagonal": np.pi * L.DIAGONAL,
        "below_pi": (np.pi - 1e-6) * L.AXIS_BELOW_PI,
    }


def expected_constants():
    """Every literal of the public module, recomputed from its definition."""
    w, W, Q = L.W_SAMPLE, L.SKEW_SAMPLE, np.array([[0.0, -np.pi / 2, 0.0], [np.pi / 2, 0.0, 0.0], [0.0, 0.0, 0.0]])
    x, y, z = w
    log_slips = {}
    for name, R in _log_inputs().items():
        a, _, theta_acos = _log_parts(R)
        slips = {"arccos_angle": theta_acos}
        if name.startswith("tiny"):
            slips["sin_angle_axis"] = a
        if name in ("half_z", "half_diagonal", "below_pi"):
            slips["no_branch"] = _no_branch(R)
            slips.update(_column_slips(R, _near_pi_logs()[name]))
        log_slips[name] = slips
    return {
        "SKEW_SAMPLE": _hat(w),
        "HAT_SYMMETRIC_AT_W": np.array([[0.0, z, y], [z, 0.0, x], [y, x, 0.0]]),
        "HAT_PERMUTED_AT_W": [_hat(w[list(order)]) for order in L.PERMUTATIONS],
        "E_X_HAT": _hat([1.0, 0.0, 0.0]),
        "E_Y_HAT": _hat([0.0, 1.0, 0.0]),
        "E_Z_HAT": _hat([0.0, 0.0, 1.0]),
        "BRACKET_2X2": L.A_2X2 @ L.B_2X2 - L.B_2X2 @ L.A_2X2,
        "BRACKET_SLIPS": {
            "e_x, e_y": {
                "anticommutator": L.E_X_HAT @ L.E_Y_HAT + L.E_Y_HAT @ L.E_X_HAT,
                "entrywise": L.E_X_HAT * L.E_Y_HAT - L.E_Y_HAT * L.E_X_HAT,
                "AB": L.E_X_HAT @ L.E_Y_HAT,
                "BA": L.E_Y_HAT @ L.E_X_HAT,
            },
            "2x2": {
                "anticommutator": L.A_2X2 @ L.B_2X2 + L.B_2X2 @ L.A_2X2,
                "entrywise": L.A_2X2 * L.B_2X2 - L.B_2X2 * L.A_2X2,
                "AB": L.A_2X2 @ L.B_2X2,
                "BA": L.B_2X2 @ L.A_2X2,
            },
        },
        "SERIES_AT_SKEW": {n: _partial(W, 0, n - 1) for n in (1, 2, 3, 4)},
        "SERIES_ENTRYWISE_AT_SKEW": {n: _entrywise(W, n) for n in (1, 2, 3)},
        "SERIES_NO_FACTORIAL_AT_SKEW": {n: _partial(W, 0, n - 1, factorial=False) for n in (1, 2, 3)},
        "QUARTER_W": Q,
        "SERIES_ENTRYWISE_QUARTER_30": _entrywise(Q, 30),
        "SERIES_NO_FACTORIAL_QUARTER_30": _partial(Q, 0, 29, factorial=False),
        "EXP_SLIPS": {
            name: {"swapped": _rodrigues_swapped(v), "unnormalised": _rodrigues_unnormalised(v)}
            for name, v in (("quarter", [0.0, 0.0, np.pi / 2]), ("sample", w), ("tiny", [0.0, 0.0, 1e-8]))
        },
        "LOG_SLIPS": log_slips,
        "EIGEN_SLIPS": {
            "two_rad": _eigen_slips(_exp(2.0 * L.AXIS_221), ("row", "svd_of_R", "eigh")),
            "half_z": _eigen_slips(L.HALF_TURN_Z, ("first", "first_eigenvalue")),
        },
    }


def _assert_same(got, want, where):
    if isinstance(want, bool):
        assert isinstance(got, bool) and got == want, f"{where}: {got!r} != {want!r}"
        return
    if isinstance(want, dict):
        assert isinstance(got, dict) and set(got) == set(want), f"{where}: keys {sorted(got)} != {sorted(want)}"
        for key in want:
            _assert_same(got[key], want[key], f"{where}[{key!r}]")
        return
    if isinstance(want, list):
        assert len(got) == len(want), f"{where}: {len(got)} items, expected {len(want)}"
        for i, (g, w) in enumerate(zip(got, want)):
            _assert_same(g, w, f"{where}[{i}]")
        return
    got, want = np.asarray(got), np.asarray(want)
    assert got.shape == want.shape, f"{where}: shape {got.shape} != {want.shape}"
    scale = max(1.0, float(np.max(np.abs(want)))) if want.size else 1.0
    assert np.max(np.abs(got - want), initial=0.0) <= RTOL * scale, f"{where}: {got!r} != {want!r}"


def _same_lines(got, want, where):
    """The same set of lines (each row up to its sign): LAPACK picks eigenvector signs and orders per kernel."""
    got, want = np.atleast_2d(got), np.atleast_2d(want)
    assert got.shape == want.shape, f"{where}: shape {got.shape} != {want.shape}"
    for rows, others in ((got, want), (want, got)):
        for row in rows:
            apart = np.minimum(np.max(np.abs(others - row), axis=1), np.max(np.abs(others + row), axis=1))
            assert np.min(apart) <= 1e-12, f"{where}: {row!r} is not one of {others!r}"


@pytest.mark.parametrize("name", sorted(expected_constants()))
def test_public_literal_matches_its_definition(name):
    stored, want = getattr(L, name), expected_constants()[name]
    if name == "EIGEN_SLIPS":  # axes are lines, and LAPACK's signs and order vary by kernel: compared as lines
        for key in ("row", "svd_of_R", "eigh"):
            _same_lines(stored["two_rad"][key], want["two_rad"][key], f"{name}[two_rad][{key}]")
        _same_lines(stored["half_z"]["first"], want["half_z"]["first"], f"{name}[half_z][first]")
        _assert_same(stored["half_z"]["first_eigenvalue"], want["half_z"]["first_eigenvalue"], name)
        assert set(stored["two_rad"]) == set(want["two_rad"]) and set(stored["half_z"]) == set(want["half_z"])
        return
    _assert_same(stored, want, name)


def test_fixed_inputs_are_what_the_literals_assume():
    assert np.array_equal(L.AXIS_221, np.array([2.0, -1.0, 2.0]) / 3.0)
    assert np.array_equal(L.R_TWO_RAD, _exp(2.0 * L.AXIS_221))
    assert np.array_equal(L.HALF_TURN_DIAGONAL, 2.0 * np.outer(L.DIAGONAL, L.DIAGONAL) - np.eye(3))


def _code_only(source):
    """The module's code without its strings and comments (hint texts may name formulas)."""
    tokens = tokenize.generate_tokens(io.StringIO(source).readline)
    return " ".join(
        t.string
        for t in tokens
        if t.type not in (tokenize.STRING, tokenize.COMMENT) and not (t.type == getattr(tokenize, "FSTRING_MIDDLE", -1))
    )


def test_the_module_computes_no_answer():
    """No hat, series sum, Rodrigues, atan2 or arccos angle, eigen or SVD pick in the shipped code."""
    code = _code_only(inspect.getsource(L))
    banned = [
        r"\b_skew\b",
        r"\b_partial\b",
        r"\b_log_parts\b",
        r"\bnp \. (arctan2|arccos|cos|tan)\b",
        r"\bnp \. linalg \. (eig|eigh|svd|matrix_power)\b",
        r"\b(E_X_HAT|E_Y_HAT|A_2X2|B_2X2) @",
        r"@ (E_X_HAT|E_Y_HAT|A_2X2|B_2X2)\b",
        r"\b(SKEW_SAMPLE|QUARTER_W|term) @",
        r"@ (SKEW_SAMPLE|QUARTER_W)\b",
        r"\*\* k\b",
        r"\b(column_logs|weak_column|_symmetric_part)\b",
        r"\bR \+ R \. T\b",
    ]
    found = [pattern for pattern in banned if re.search(pattern, code)]
    assert not found, f"the public lesson 03 checks compute something they must only store: {found}"


def test_bracket_of_generic_hats_is_the_hat_of_the_cross_product():
    assert np.allclose(L.HAT_V_SAMPLE, _hat(L.V_SAMPLE), rtol=0, atol=1e-15)
    assert np.allclose(L.HAT_W_CROSS_V, _hat(np.cross(L.W_SAMPLE, L.V_SAMPLE)), rtol=0, atol=1e-15)
    assert np.allclose(
        L.SKEW_SAMPLE @ L.HAT_V_SAMPLE - L.HAT_V_SAMPLE @ L.SKEW_SAMPLE, L.HAT_W_CROSS_V, rtol=0, atol=1e-14
    )
