"""Named functions that hidden tests pass to student functions taking callables.

A test writes ``student.commutes(A, B, Probe("matmul"))``; the name travels
over the wire and the sandbox rebuilds the callable here, so no code ever
crosses. Fixed parameters travel too: ``Probe("rotate_point_by", p)`` becomes
``lambda R: rotate_point_by(p, R)``.

This file is copied into every sandbox, so it imports only numpy, and lazily
scipy (for the exponential map) and the course's ``coursekit`` (copied beside it).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # for the annotations only: importing numpy.typing costs every sandbox 10 ms
    from numpy.typing import ArrayLike

_ROTATION_TOL = 1e-9


def _exp(w):
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


# ---------------------------------------------------------------- binary operations
def matmul(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    return np.asarray(a, dtype=float) @ np.asarray(b, dtype=float)


def add(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    return np.asarray(a, dtype=float) + np.asarray(b, dtype=float)


def multiply(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    return np.asarray(a, dtype=float) * np.asarray(b, dtype=float)


def quat_multiply(p: ArrayLike, q: ArrayLike) -> np.ndarray:
    """The Hamilton product, the course's own (``coursekit.lie.quat_product``, in the sandbox beside this file)."""
    from coursekit.lie import quat_product

    return quat_product(p, q)


def cross(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    return np.cross(np.asarray(a, dtype=float), np.asarray(b, dtype=float))


def second(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """a ∘ b = b: associative, every element a left identity, no two-sided identity."""
    return np.array(b, dtype=float)


def first(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """a ∘ b = a: associative, every element a right identity, no two-sided identity."""
    return np.array(a, dtype=float)


# ---------------------------------------------------------------- inverses
def transpose(a: ArrayLike) -> np.ndarray:
    return np.asarray(a, dtype=float).T.copy()


def matrix_inverse(a: ArrayLike) -> np.ndarray:
    return np.linalg.inv(np.asarray(a, dtype=float))


def negate(a: ArrayLike) -> np.ndarray:
    return -np.asarray(a, dtype=float)


def reciprocal(a: ArrayLike) -> np.ndarray | float:
    a = np.asarray(a, dtype=float)
    with np.errstate(divide="ignore"):
        return 1.0 / a


def quat_conjugate(q: ArrayLike) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    return np.array([q[0], -q[1], -q[2], -q[3]])


def constant(value: ArrayLike, a: ArrayLike) -> np.ndarray:
    """Probe("constant", e) is the map a ↦ e (a one-sided "inverse" for ``second``)."""
    return np.array(value, dtype=float)


# ---------------------------------------------------------------- membership tests
def is_rotation(M: ArrayLike) -> bool:
    M = np.asarray(M, dtype=float)
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.all(np.isfinite(M)):
        return False
    error = np.max(np.abs(M.T @ M - np.eye(M.shape[0])))
    return bool(error <= _ROTATION_TOL and np.linalg.det(M) > 0)


def is_orthogonal(M: ArrayLike) -> bool:
    M = np.asarray(M, dtype=float)
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.all(np.isfinite(M)):
        return False
    return bool(np.max(np.abs(M.T @ M - np.eye(M.shape[0]))) <= _ROTATION_TOL)


def is_rotation_within(tol: float, M: ArrayLike) -> bool:
    """Probe("is_rotation_within", tol): a rotation test with a looser tolerance."""
    M = np.asarray(M, dtype=float)
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.all(np.isfinite(M)):
        return False
    return bool(np.max(np.abs(M.T @ M - np.eye(M.shape[0]))) <= tol and np.linalg.det(M) > 0)


def is_reflection(M: ArrayLike) -> bool:
    """Orthogonal with det = -1."""
    return is_orthogonal(M) and bool(np.linalg.det(np.asarray(M, dtype=float)) < 0)


def is_finite(x: ArrayLike) -> bool:
    return bool(np.all(np.isfinite(np.asarray(x, dtype=float))))


def is_nonzero(x: ArrayLike) -> bool:
    x = np.asarray(x, dtype=float)
    return bool(np.all(np.isfinite(x)) and np.all(x != 0))


def is_unit_quaternion(q: ArrayLike) -> bool:
    q = np.asarray(q, dtype=float)
    return bool(q.shape == (4,) and abs(np.linalg.norm(q) - 1.0) <= _ROTATION_TOL)


# ---------------------------------------------------------------- perturbations (x ⊞ δ)
def vector_add(x: ArrayLike, d: ArrayLike) -> np.ndarray:
    return np.asarray(x, dtype=float) + np.asarray(d, dtype=float)


def so3_plus_right(R: ArrayLike, d: ArrayLike) -> np.ndarray:
    return np.asarray(R, dtype=float) @ _exp(d)


def so3_plus_left(R: ArrayLike, d: ArrayLike) -> np.ndarray:
    return _exp(d) @ np.asarray(R, dtype=float)


def quat_plus_right(q: ArrayLike, d: ArrayLike) -> np.ndarray:
    d = np.asarray(d, dtype=float)
    angle = np.linalg.norm(d)
    if angle < 1e-12:
        dq = np.concatenate([[1.0], d / 2.0])
    else:
        dq = np.concatenate([[np.cos(angle / 2.0)], np.sin(angle / 2.0) * d / angle])
    out = quat_multiply(q, dq)
    return out / np.linalg.norm(out)


# ---------------------------------------------------------------- functions to differentiate
def rotate_point_by(p: ArrayLike, R: ArrayLike) -> np.ndarray:
    """f(R) = R p."""
    return np.asarray(R, dtype=float) @ np.asarray(p, dtype=float)


def unrotate_point_by(p: ArrayLike, R: ArrayLike) -> np.ndarray:
    """f(R) = Rᵀ p."""
    return np.asarray(R, dtype=float).T @ np.asarray(p, dtype=float)


def smooth_vector_function(x: ArrayLike) -> np.ndarray:
    """A fixed nonlinear map R^3 → R^2 with an easy analytic Jacobian."""
    x = np.asarray(x, dtype=float)
    return np.array([x[0] ** 2 * x[1] + np.sin(x[2]), np.exp(0.5 * x[0]) - x[1] * x[2]])


def smooth_vector_function_jacobian(x: ArrayLike) -> np.ndarray:
    x = np.asarray(x, dtype=float)
    return np.array([[2 * x[0] * x[1], x[0] ** 2, np.cos(x[2])], [0.5 * np.exp(0.5 * x[0]), -x[2], -x[1]]])


def quat_rotate_point_by(p: ArrayLike, q: ArrayLike) -> np.ndarray:
    """f(q) = vector part of q ⊗ [0, p] ⊗ q*."""
    pure = np.concatenate([[0.0], np.asarray(p, dtype=float)])
    return quat_multiply(quat_multiply(q, pure), quat_conjugate(q))[1:]


def identity_function(x: ArrayLike) -> np.ndarray:
    return np.asarray(x, dtype=float).copy()


_PROBES = {
    name: value
    for name, value in globals().items()
    if callable(value) and not name.startswith("_") and value.__module__ == __name__
}


def names() -> list[str]:
    """The names a test may use, sorted."""
    return sorted(_PROBES)


def resolve(name: str, args: tuple = ()) -> Callable:
    """The callable for ``Probe(name, *args)``: the probe with ``args`` bound first."""
    if name not in _PROBES:
        raise KeyError(f"unknown probe {name!r}")
    function = _PROBES[name]
    return functools.partial(function, *args) if args else function
