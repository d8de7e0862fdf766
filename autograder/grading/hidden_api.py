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

import contextlib
import contextvars
from collections.abc import Callable, Iterator
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


# per thread (a context variable): a grader thread recording the reference never relaxes another thread's grading
_NOT_ENFORCED = contextvars.ContextVar("checks_not_enforced", default=False)


@contextlib.contextmanager
def checks_not_enforced() -> Iterator[None]:
    """While inside, :func:`fail` (so :func:`expect`, :func:`expect_close` and the checks built on
    :func:`fail`) returns instead of raising, so a test runs on past a failed check.

    Only the grader's second recording of the reference uses it (answers nudged by 1e-14, which a check
    as tight as the nudge rejects; :func:`autograder.grading.suite.transcripts_for`): it needs every call
    the test would make, not a verdict. A ``raise Wrong`` written in a test still stops it.
    """
    token = _NOT_ENFORCED.set(True)
    try:
        yield
    finally:
        _NOT_ENFORCED.reset(token)


def fail(reason: str, hint: str | Callable[[], str] = "") -> None:
    """Raise :class:`Wrong` (``hint`` called first when it is a function), except under
    :func:`checks_not_enforced`."""
    if _NOT_ENFORCED.get():
        return
    raise Wrong(reason, hint() if callable(hint) else hint)


def expect(condition: object, reason: str, hint: str | Callable[[], str] = "") -> None:
    """Raise :class:`Wrong` unless ``condition``.

    ``hint`` may be a function of no arguments, called only on a failure: naming a slip can cost more
    than the check, and a passing answer should not pay for it.
    """
    if not condition:
        fail(reason, hint)


def expect_close(
    got: ArrayLike, expected: ArrayLike, tol: float, what: str, hint: str | Callable[[], str] = "", scale: float = 1.0
) -> None:
    """Raise :class:`Wrong` unless ``got`` matches ``expected`` entrywise within ``tol · max(1, scale)``.

    ``scale`` is the size of the inputs (e.g. |ρ| of a pose), so the tolerance
    is relative to them; the message gives the size of the error. ``hint`` as for :func:`expect`.
    """
    got = np.asarray(got, dtype=float)
    expected = np.asarray(expected, dtype=float)
    if got.shape != expected.shape:
        fail(f"{what}: shape {got.shape}, expected {expected.shape}", hint)
        return
    tol = tol * max(1.0, float(scale))
    error = float(np.max(np.abs(got - expected))) if got.size else 0.0
    if not error <= tol:
        fail(
            f"{what} is off by {error:.2g} (tolerance {tol:.2g}): got {fmt(got, 6)}, expected {fmt(expected, 6)}", hint
        )
