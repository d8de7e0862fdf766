"""Public checks for the start page's practice function, ``unit_vector`` (not graded)."""

import numpy as np

from ..checking import Mismatch, public_check
from ..diagnose import close, shape_problem


@public_check("unit_vector", "returns a vector of length 1")
def _(unit_vector):
    got = unit_vector([3.0, 4.0, 0.0])
    problem = shape_problem(got, (3,))
    if problem:
        raise Mismatch(problem)
    length = float(np.linalg.norm(got))
    if abs(length - 1.0) > 1e-12:
        hint = "it looks divided by the squared length: use np.linalg.norm(v), not v @ v" \
            if close(got, np.array([3.0, 4.0, 0.0]) / 25.0, 1e-12) else None
        raise Mismatch(f"unit_vector([3, 4, 0]) has length {length:.4g}", hint)


@public_check("unit_vector", "keeps the direction of the input")
def _(unit_vector):
    got = np.asarray(unit_vector([0.0, -2.0, 0.0]), dtype=float)
    if got.shape != (3,) or not np.all(np.isfinite(got)):
        return  # the first check names the shape problem
    along = float(got @ [0.0, -1.0, 0.0])
    if along <= 0 or not close(got, [0.0, -along, 0.0], 1e-12 * max(along, 1.0)):
        raise Mismatch(f"unit_vector([0, -2, 0]) returned {np.round(got, 4)}, which does not point along -y",
                       "divide by the length, keep the sign")
