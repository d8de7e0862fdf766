"""The names a course's hidden tests are written with: the grader's side of the contract.

Every hidden test names the exercise it grades (:func:`exercise`) and, through
its docstring's first line, what it checks: that line is what the student
reads. It asks for the fixtures ``student`` (the student's functions, called in
their sandbox) and ``ref`` (the reference answers, run in the grader). When a
check fails it raises :class:`Wrong` with one line on what was seen and, where
a mistake is recognisable, a hint; any other exception fails the check with its
own message.

Nothing here imports a course: any course's suite can use it. Example, a whole
hidden test::

    from autograder.grading.hidden_api import exercise, expect_close

    @exercise("double", weight=2)
    def test_double_of_three(student, ref):
        \"\"\"doubles 3\"\"\"
        expect_close(student.double(3.0), ref.double(3.0), 1e-12, "double(3)", hint="multiply by 2")
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import pytest

if TYPE_CHECKING:
    from numpy.typing import ArrayLike


class Wrong(AssertionError):
    """A failed hidden check: ``reason`` is what was seen, ``hint`` a likely cause."""

    def __init__(self, reason, hint=""):
        super().__init__(reason)
        self.reason = reason
        self.hint = hint or ""


def exercise(name: str, weight: float = 1.0) -> pytest.MarkDecorator:
    """Mark a test as grading exercise ``name`` with relative ``weight``."""
    return pytest.mark.exercise(name=name, weight=float(weight))


def fmt(value: object, digits: int = 4) -> str:
    """Short text for a value in a failure message; tiny numbers keep their significant digits.

    Examples
    --------
    >>> fmt([1.0, 2.5e-9, -0.0])
    '[1, 2.5e-09, 0]'
    """
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return repr(value)[:120]
    text = np.array2string(
        array + 0.0,
        separator=", ",
        threshold=20,
        max_line_width=1000,
        formatter={"float_kind": lambda x: f"{x:.{digits}g}"},
    )
    return " ".join(text.split())


def expect(condition: object, reason: str, hint: str = "") -> None:
    """Raise :class:`Wrong` unless ``condition``."""
    if not condition:
        raise Wrong(reason, hint)


def expect_close(
    got: ArrayLike, expected: ArrayLike, tol: float, what: str, hint: str = "", scale: float = 1.0
) -> None:
    """Raise :class:`Wrong` unless ``got`` matches ``expected`` entrywise within ``tol · max(1, scale)``.

    ``scale`` is the size of the inputs (e.g. |ρ| of a pose), so the tolerance
    is relative to them; the message gives the size of the error.
    """
    got = np.asarray(got, dtype=float)
    expected = np.asarray(expected, dtype=float)
    if got.shape != expected.shape:
        raise Wrong(f"{what}: shape {got.shape}, expected {expected.shape}", hint)
    tol = tol * max(1.0, float(scale))
    error = float(np.max(np.abs(got - expected))) if got.size else 0.0
    if not error <= tol:
        raise Wrong(
            f"{what} is off by {error:.2g} (tolerance {tol:.2g}): got {fmt(got, 6)}, expected {fmt(expected, 6)}", hint
        )
