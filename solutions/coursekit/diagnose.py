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
    "close",
]


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
    if np.linalg.det(got) < 0:
        return "det < 0: a reflection, not a rotation; check the signs"
    if close(got, -expected, tol):
        return "every entry has the wrong sign"
    return None
