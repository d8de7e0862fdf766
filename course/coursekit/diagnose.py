"""Name the likely mistake behind a wrong answer.

These helpers compare what a function returned with what was expected and
return a short human sentence, or ``None`` when nothing recognisable is
wrong. The public checks in the notebooks and the hidden grading suite use
the same sentences, so a student reads the same hint in both places.
"""

import numpy as np

__all__ = [
    "as_float_array",
    "shape_problem",
    "rotation_problem",
    "rotation_hint",
    "rotation_vector_hint",
    "pose_problem",
    "close",
    "explains",
    "same_rotation_quat",
    "quaternion_hint",
    "ALLCLOSE_HINT",
    "LISTS_HINT",
    "jacobian_error_allowed",
    "JACOBIAN_STEP_HINT",
]

# Said only when an answer differs between lists and arrays (the function compared with itself).
LISTS_HINT = "convert the inputs with np.asarray(..., dtype=float) (lists have no .T and @ does not work on them)"

# np.allclose(x, y, atol=tol) passes when |x - y| <= atol + rtol·|y| with rtol = 1e-5 by default.
ALLCLOSE_HINT = ("np.allclose(x, y, atol=tol) keeps its default rtol=1e-5, which swamps tol: "
                 "compare np.max(np.abs(x - y)) <= tol (or pass rtol=0)")


def close(a, b, tol=1e-9):
    """True when ``a`` and ``b`` have the same shape and agree to ``tol`` (max abs)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= tol))


def as_float_array(value):
    """Convert ``value`` to a float array, or return ``None`` if it is not numeric.

    Examples
    --------
    >>> as_float_array([1, 2, 3]).dtype
    dtype('float64')
    >>> as_float_array("abc") is None
    True
    """
    if value is None:
        return None
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return array


def shape_problem(value, shape):
    """Describe why ``value`` is not a finite float array of ``shape``, or return None.

    Examples
    --------
    >>> shape_problem(np.eye(3), (3, 3)) is None
    True
    >>> shape_problem(None, (3, 3))
    'returned None: did you forget the return statement?'
    """
    if value is None:
        return "returned None: did you forget the return statement?"
    if np.iscomplexobj(value):
        return "returned complex numbers: the answer is real (take np.real(...) where np.linalg.eig made them)"
    array = as_float_array(value)
    if array is None:
        return f"returned {type(value).__name__}, not an array of numbers"
    if array.shape != tuple(shape):
        want = "×".join(map(str, shape)) if shape else "a scalar"
        got = "×".join(map(str, array.shape)) if array.shape else "a scalar"
        return f"returned shape {got}, expected {want}"
    if not np.all(np.isfinite(array)):
        return "returned NaN or inf values"
    return None


def rotation_problem(R, tol=1e-6):
    """Describe why a 3×3 (or 2×2) array is not a rotation matrix, or return None.

    Examples
    --------
    >>> rotation_problem(np.diag([1.0, 1.0, -1.0]))
    'det = -1.000: a reflection, not a rotation (a right-handed frame needs det = +1)'
    """
    R = np.asarray(R, dtype=float)
    n = R.shape[0]
    error = np.max(np.abs(R.T @ R - np.eye(n)))
    if error > tol:
        return f"columns are not orthonormal (max |RᵀR - I| = {error:.2g})"
    det = np.linalg.det(R)
    if det < 0:
        return f"det = {det:.3f}: a reflection, not a rotation (a right-handed frame needs det = +1)"
    return None


def rotation_hint(got, expected, tol=1e-6, degrees_version=None):
    """Guess why a rotation matrix ``got`` differs from ``expected``.

    Parameters
    ----------
    got, expected : array_like, shape (n, n)
    tol : float
        Agreement tolerance, max abs.
    degrees_version : array_like, optional
        What a solution that treated the angle as degrees would return.

    Returns
    -------
    str or None
        A hint such as ``"looks like the transpose (the inverse rotation)"``.

    Examples
    --------
    >>> c, s = np.cos(0.3), np.sin(0.3)
    >>> R = np.array([[c, -s], [s, c]])
    >>> rotation_hint(R.T, R)
    'looks like the transpose (the inverse rotation): check the signs of the sine terms'
    """
    got = np.asarray(got, dtype=float)
    expected = np.asarray(expected, dtype=float)
    if got.shape != expected.shape:
        return None
    if close(got, expected.T, tol):
        return "looks like the transpose (the inverse rotation): check the signs of the sine terms"
    if degrees_version is not None and close(got, degrees_version, tol):
        return "looks like the angle was taken in degrees: the course works in radians (np.cos takes radians)"
    if np.linalg.det(got) < 0 and close(got.T @ got, np.eye(len(got)), tol):
        return "det < 0: a reflection, not a rotation; check the signs"
    if close(got, -expected, tol):
        return "every entry has the wrong sign"
    return None


def pose_problem(T, tol=1e-6):
    """Describe why a 4×4 array is not a pose [[R, t], [0, 0, 0, 1]], or return None.

    Examples
    --------
    >>> pose_problem(np.eye(4)) is None
    True
    >>> pose_problem(np.diag([1.0, 1.0, 1.0, 2.0]))
    'the bottom row is [0.0, 0.0, 0.0, 2.0], expected [0, 0, 0, 1]'
    """
    T = np.asarray(T, dtype=float)
    bottom = T[3]
    if not close(bottom, [0.0, 0.0, 0.0, 1.0], tol):
        shown = ", ".join(f"{x:.3g}" if abs(x - round(x)) > 1e-9 else f"{round(x):.1f}" for x in bottom + 0.0)
        hint = " (the translation ended up in the bottom row: it belongs in the last column)" \
            if not close(bottom[:3], 0.0 * bottom[:3], tol) and close(T[:3, 3], [0.0, 0.0, 0.0], tol) else ""
        return f"the bottom row is [{shown}], expected [0, 0, 0, 1]{hint}"
    problem = rotation_problem(T[:3, :3], tol)
    if problem:
        return f"the top-left 3×3 block is not a rotation: {problem}"
    return None


def explains(got, candidate, truth, floor=1e-15):
    """True when ``candidate`` (what a known slip returns) accounts for ``got``'s error from ``truth``.

    ``got`` must be much closer to the candidate than the candidate is to the
    truth: within a thousandth of that distance, plus a rounding ``floor``. So a
    hint never fires where the slip and the right answer agree.

    Examples
    --------
    >>> R = np.eye(3)
    >>> explains(-R, -R, R), explains(R, -R, R)
    (True, False)
    """
    got, candidate, truth = (np.asarray(x, dtype=float) for x in (got, candidate, truth))
    if got.shape != candidate.shape or not np.all(np.isfinite(candidate)):
        return False
    gap = float(np.max(np.abs(candidate - truth)))
    return gap > 0.0 and float(np.max(np.abs(got - candidate))) <= 1e-3 * gap + floor


def same_rotation_quat(a, b, tol=1e-9):
    """True when quaternions ``a`` and ``b`` are equal or opposite within ``tol``: one rotation.

    Examples
    --------
    >>> same_rotation_quat([0.0, 1.0, 0.0, 0.0], [0.0, -1.0, 0.0, 0.0])
    True
    """
    return close(a, b, tol) or close(a, -np.asarray(b, dtype=float), tol)


def quaternion_hint(got, expected, tol=1e-6):
    """Guess why a scalar-first quaternion ``got`` differs from ``expected``, or return None.

    Recognises the scalar-last layout, the conjugate (the inverse rotation)
    and the opposite sign, each up to the sign of the whole quaternion where
    that is the same rotation.

    Examples
    --------
    >>> quaternion_hint([0.0, 0.0, 0.6, 0.8], [0.8, 0.0, 0.0, 0.6])
    'looks like scalar-last order [x, y, z, w]: this course stores [w, x, y, z]'
    """
    got = as_float_array(got)
    expected = as_float_array(expected)
    if got is None or expected is None or got.shape != (4,) or expected.shape != (4,):
        return None
    if same_rotation_quat(got, expected, tol):
        return "q and -q are the same rotation, but here the sign matters" if not close(got, expected, tol) else None
    if same_rotation_quat(got, np.roll(expected, -1), tol):
        return "looks like scalar-last order [x, y, z, w]: this course stores [w, x, y, z]"
    if same_rotation_quat(got, expected * [1.0, -1.0, -1.0, -1.0], tol):
        return "looks like the conjugate (the inverse rotation): check the signs of the vector part"
    return None


def rotation_vector_hint(got, expected):
    """Guess why a rotation vector ``got`` (shape (3,)) differs from ``expected``, or return None.

    Recognises NaN (a division by sin θ = 0), a zero vector where a rotation
    was expected (the axis lost at θ = 0 or θ = π), the opposite rotation (the
    axis sign) and an angle in degrees. Comparisons are relative to |expected|.

    Examples
    --------
    >>> rotation_vector_hint([0.0, 0.0, -1.0], [0.0, 0.0, 1.0])
    'the opposite rotation: check the sign of the axis against a small positive turn about z'
    """
    got = as_float_array(got)
    expected = as_float_array(expected)
    if got is None or expected is None or got.shape != (3,) or expected.shape != (3,):
        return None
    angle = float(np.linalg.norm(expected))
    if not np.all(np.isfinite(got)):
        if angle > 3.0:
            return ("NaN or inf near θ = π: sin θ → 0 there, or rounding pushed (tr R - 1)/2 below -1 "
                    "(clip it before arccos, and take the axis from (R + Rᵀ)/2)")
        if angle < 1e-3:
            return "NaN or inf at a tiny angle: a division by sin θ ≈ 0; treat θ ≈ 0 with the series θ/sin θ ≈ 1"
        return "NaN or inf: arccos of a trace that rounding pushed just outside [-1, 1]? clip it first"
    if angle == 0.0:
        return None
    if np.linalg.norm(got) <= 1e-3 * angle:
        if angle > 3.0:
            return ("returned (almost) zero near θ = π, where R - Rᵀ vanishes: "
                    "take the axis from the symmetric part (R + Rᵀ)/2 there")
        if np.arccos(np.clip(np.cos(angle), -1.0, 1.0)) == 0.0:  # cos θ rounds to 1: arccos really gives 0 here
            return ("returned (almost) zero for a small rotation: arccos rounds tiny angles to 0; "
                    "find the angle from numbers that keep it at that size")
        return "returned (almost) zero for a rotation that is not zero: check how the angle and the axis are found"
    if np.linalg.norm(got + expected) <= 1e-3 * angle:
        return "the opposite rotation: check the sign of the axis against a small positive turn about z"
    if np.linalg.norm(got - np.rad2deg(expected)) <= 1e-3 * np.rad2deg(angle):
        return "looks like the angle is in degrees: the course works in radians"
    return None


# ---------------------------------------------------------------- numerical Jacobians
JACOBIAN_STEP_HINT = ("any forward or central scheme at least as accurate as the lecture's rule is right: forward "
                      "steps near √ε·max(1, |x_j|) ≈ 1e-8 (the bottom of the V-curve), the lecture's "
                      "δ_j = max(|1e-4 x_j|, 1e-6), or central differences; much larger steps are biased and much "
                      "smaller ones drown in rounding")


def jacobian_error_allowed(lecture_error, exact):
    """The largest error a numerical Jacobian may have, the rule of the course.

    ``lecture_error`` is how far forward differences with the lecture's steps
    δ_j = max(|1e-4 x_j|, 1e-6) are from the ``exact`` Jacobian at the same
    point. Allowed: twice that, plus 1e-8·(1 + max|J|) for rounding. A √ε forward
    step and central differences pass; a step far from the V-curve's bottom
    (1e-2, or 1e-13) does not.

    Examples
    --------
    >>> round(jacobian_error_allowed(1e-6, np.eye(2)), 12)
    2.02e-06
    """
    exact = np.asarray(exact, dtype=float)
    return 2.0 * float(lecture_error) + 1e-8 * (1.0 + float(np.max(np.abs(exact))))


# --- lessons 01-04 ---
FLOAT32_HINT = ("the error is the size of float32 rounding (single precision keeps about 7 digits): keep every array "
                "in float64, numpy's default (no dtype=np.float32)")
SERIES_HINT = ("exact at unit-size angles but not at small ones: a truncated series (sin θ ≈ θ, cos θ ≈ 1 - θ²/2) "
               "is off by its first dropped term, which peaks at the largest angle it is used for; np.sin and "
               "np.cos are accurate at every angle")


def float32_rounding(got, expected):
    """True when ``got`` is off from ``expected`` by what float32 rounding makes, and by more than float64's.

    The error must lie between 1e-11 and 8 float32 epsilons (about 1e-6) of
    the values' size (at least 1): float64 arithmetic stays far below that
    window, and a wrong formula far above it.

    Examples
    --------
    >>> R = np.array([[0.6, -0.8], [0.8, 0.6]])
    >>> float32_rounding(R.astype(np.float32), R), float32_rounding(R, R)
    (True, False)
    """
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if got.shape != expected.shape or not np.all(np.isfinite(got)):
        return False
    scale = max(1.0, float(np.max(np.abs(expected), initial=0.0)))
    error = float(np.max(np.abs(got - expected), initial=0.0))
    return 1e-11 * scale < error <= 8 * float(np.finfo(np.float32).eps) * scale


# --- lessons 05-09 (FLOAT32_HINT above) ---
def single_precision_error(got, expected):
    """True when ``got`` misses ``expected`` as a computation carried out in float32 does: 1e-9 … 1e-5 of the
    largest entry (several roundings compound, so the window reaches above :func:`float32_rounding`'s).

    A float64 answer is off by about 1e-16 of that size; a slip in a formula, by
    far more than 1e-5 at a generic input.

    Examples
    --------
    >>> x = np.array([0.3, -1.7, 2.9])
    >>> single_precision_error(x.astype(np.float32), x), single_precision_error(x + 1e-15, x)
    (True, False)
    """
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if got.shape != expected.shape or not np.all(np.isfinite(got)):
        return False
    size = max(1.0, float(np.max(np.abs(expected)))) if expected.size else 1.0
    error = float(np.max(np.abs(got - expected))) if got.size else 0.0
    return 1e-9 * size <= error <= 1e-5 * size
