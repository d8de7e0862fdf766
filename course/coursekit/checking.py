"""The visible check cells: run a few public checks on one exercise.

Every exercise in the course is followed by a locked cell such as::

    check("rot_z", rot_z)

:func:`check` runs the public checks registered for that exercise (see the
modules in :mod:`coursekit.checks`) and prints one line per check. A failed
check prints what is wrong and a hint. Public checks test properties (shapes,
orthogonality, a quarter turn about an axis); the hidden checks that grade
your work are more thorough and run only when your notebook is graded, so a
clean run here is encouraging, not a guarantee.

When a check fails the cell raises :class:`CheckFailed`, and an exercise that
is not written yet raises :class:`NotWrittenYet` (a ``NotImplementedError``):
that is how the course's notebooks also work as ordinary nbgrader
assignments. Both errors show as one red line in Jupyter, not a traceback
(IPython prints what ``_render_traceback_`` returns): the lines printed just
above already say what is wrong.
"""

import functools
import traceback

from .contracts import CHANGED_HINT, delegated_hint, guard_for, refusal
from .watching import snapshot, watch_call

# Crashes whose message says what went wrong in a way a student may not read at once: (words, hint).
CRASH_HINTS = (
    ("truth value of an array with more than one element is ambiguous",
     "an if, and, or or met a whole array: a comparison of two arrays gives one True or False per entry; reduce "
     "it to one verdict first (np.all, or compare the largest entry of the difference)"),
)


def crash_hint(message):
    """The hint for a crash whose message (``"ValueError: The truth value ..."``) is a known one, else ""."""
    return next((hint for words, hint in CRASH_HINTS if words in str(message)), "")



__all__ = ["check", "public_check", "Mismatch", "CheckFailed", "NotWrittenYet", "registered_exercises",
           "checks_of_lesson"]

_REGISTRY = {}
_LESSON_OF = {}  # exercise -> lesson number ("01"), from the checks module that registered it


class Mismatch(Exception):
    """Raised by a public check: one line on what is wrong, and a hint.

    Parameters
    ----------
    reason : str
        What the check saw, e.g. ``"rot_z(pi/2) sends x to [0, -1, 0]"``.
    hint : str, optional
        A likely cause, e.g. ``"looks like the transpose"``.
    """

    def __init__(self, reason, hint=None):
        super().__init__(reason)
        self.reason = reason
        self.hint = hint


RED, RESET = "\x1b[0;31m", "\x1b[0m"


class _OneLine:
    """Shown by IPython as one red line instead of a traceback into coursekit."""

    def _render_traceback_(self):
        return [f"{RED}{type(self).__name__}{RESET}: {self}"]


class CheckFailed(_OneLine, AssertionError):
    """Raised by :func:`check` when at least one public check failed."""


class NotWrittenYet(_OneLine, NotImplementedError):
    """Raised by :func:`check` for an exercise that still raises ``NotImplementedError``."""


def public_check(exercise, description):
    """Register a public check for ``exercise``.

    The decorated function receives the student's function and returns
    nothing when the property holds, or raises :class:`Mismatch`.

    Examples
    --------
    >>> @public_check("double", "doubles 2 to 4")
    ... def _(double):
    ...     if double(2) != 4:
    ...         raise Mismatch(f"double(2) returned {double(2)!r}")
    """

    def register(function):
        _REGISTRY.setdefault(exercise, []).append((description, function))
        # "lesson03" or "lesson03_body_rates" (a section added to a lesson later): the lesson is "03"
        _LESSON_OF[exercise] = function.__module__.rpartition(".")[2].removeprefix("lesson")[:2]
        return function

    return register


def registered_exercises():
    """Names of the exercises that have public checks, sorted."""
    _load_check_modules()
    return sorted(_REGISTRY)


def checks_of_lesson(lesson):
    """Names of the exercises of ``lesson`` (``"01"``) that have public checks, in the order registered."""
    _load_check_modules()
    return [name for name in _REGISTRY if _LESSON_OF.get(name) == lesson]


def run_quietly(exercise, function):
    """``(passed, total, first problem or "")`` for ``exercise``'s public checks, printing nothing."""
    _load_check_modules()
    checks = _REGISTRY.get(exercise, [])
    passed, problem = 0, ""
    function = _Watched(exercise, function)
    for description, run in checks:
        try:
            run(function)
        except NotImplementedError:
            return 0, len(checks), "not written yet"
        except Mismatch as mismatch:
            problem = problem or f"{description}: {_one_line(mismatch.reason, 90)}"
        except Exception as error:
            problem = problem or f"{description}: raised {type(error).__name__}"
        else:
            passed += 1
    contract = _contract_line(exercise, function.function) if passed or problem else None
    if contract is not None:
        passed += contract[0]
        problem = problem or ("" if contract[0] else contract[1].strip().removeprefix("✗ ").split("\n")[0])
    broken = function.broken_promises()
    if broken and not problem:
        problem = f"{broken[0][0]}: {_one_line(broken[0][1], 90)}"
    return passed, len(checks) + (contract is not None) + len(broken), problem


def _contract_line(exercise, function):
    """``(passed, line)`` for the contract check of :mod:`coursekit.exercise_contracts`; None if not covered."""
    from .exercise_contracts import DESCRIPTION, contract_problem, covered

    if not covered(exercise):
        return None
    problem = contract_problem(exercise, function)
    if problem is None:
        return True, f"  ✓ {DESCRIPTION}"
    reason, hint = problem
    return False, f"  ✗ {DESCRIPTION}: {_one_line(reason)}\n      hint: {_one_line(hint)}"


class _Watched:
    """The student's function as the checks call it: each call gets copies of its arguments and is
    watched (:func:`coursekit.watching.watch_call`) for arguments changed in place and for calls
    into the library functions that do the exercise's job (:mod:`coursekit.contracts`)."""

    def __init__(self, exercise, function):
        functools.update_wrapper(self, function)
        self.exercise, self.function = exercise, function
        self.forbidden = guard_for(exercise, _LESSON_OF.get(exercise, ""))  # its allowance (coursekit.contracts)
        self.changed, self.used = [], []

    def __call__(self, *args, **kwargs):
        args = tuple(snapshot(a) for a in args)  # the check's own data stays as it was
        kwargs = {name: snapshot(value) for name, value in kwargs.items()}
        value, seen = watch_call(self.function, args, kwargs, self.forbidden)
        self.changed += [name for name in seen.changed if name not in self.changed]
        self.used += [name for name in seen.used + (["sys.setprofile"] if seen.tampered else [])
                      if name not in self.used]
        return value

    def broken_promises(self):
        """``(description, reason, hint)`` for each contract the calls so far broke (none: ``[]``)."""
        broken = []
        if self.used:
            broken.append(("is your own implementation",
                           refusal(self.exercise, self.used, _LESSON_OF.get(self.exercise, "")),
                           delegated_hint(self.used)))
        if self.changed:
            broken.append(("leaves its arguments unchanged",
                           f"{self.exercise} changes its argument{'s' if len(self.changed) > 1 else ''} "
                           f"{', '.join(self.changed)} in place", CHANGED_HINT))
        return broken


def _load_check_modules():
    from . import checks  # noqa: F401  (importing registers every lesson's checks)


def _one_line(text, limit=200):
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _where_in_student_code(error):
    """The last line of the traceback that is not inside coursekit."""
    frames = traceback.extract_tb(error.__traceback__)
    for frame in reversed(frames):
        if "coursekit" not in frame.filename.replace("\\", "/"):
            return f" (line {frame.lineno} of your {frame.name})"
    return ""


def _stop_the_cell(error):
    # The check cell ends with an error so that nbgrader counts the check as failed; Run All stops here.
    raise error from None


def check(exercise, function):
    """Run the public checks of ``exercise`` on ``function`` and report.

    Parameters
    ----------
    exercise : str
        The exercise's name, e.g. ``"rot_z"``.
    function : callable
        Your implementation.

    Raises
    ------
    NotImplementedError
        If the exercise still raises it (the stub has not been replaced).
    CheckFailed
        If any public check failed; the printed lines say which and why.
    """
    __tracebackhide__ = True
    _load_check_modules()
    checks = _REGISTRY.get(exercise)
    if not checks:
        from .checks import IMPORT_ERRORS

        broken = "; ".join(f"{name}: {why}" for name, why in IMPORT_ERRORS.items())
        raise KeyError(f"no public checks are registered for {exercise!r}"
                       + (f" (a checks module failed to import: {broken})" if broken else ""))
    passed, failed = 0, 0
    lines = []
    function = _Watched(exercise, function)
    for description, run in checks:
        try:
            run(function)
        except NotImplementedError:
            print(
                f"{exercise}: not written yet. Replace the line "
                "`raise NotImplementedError(...)` with your code, then run this cell again."
            )
            _stop_the_cell(NotWrittenYet(
                f"{exercise} is not written yet: write {exercise} next"))
        except Mismatch as mismatch:
            failed += 1
            line = f"  ✗ {description}: {_one_line(mismatch.reason)}"
            if mismatch.hint:
                line += f"\n      hint: {_one_line(mismatch.hint)}"
            lines.append(line)
        except Exception as error:  # the student's code crashed: report, do not explode
            failed += 1
            line = f"  ✗ {description}: raised {type(error).__name__}: {_one_line(error, 120)}"
            line += _where_in_student_code(error)
            hint = crash_hint(error)
            lines.append(line + (f"\n      hint: {_one_line(hint)}" if hint else ""))
        else:
            passed += 1
            lines.append(f"  ✓ {description}")
    contract = _contract_line(exercise, function.function)  # one line: the docstring's contract (issue #43)
    if contract is not None:
        ok, line = contract
        passed, failed = passed + ok, failed + (not ok)
        lines.append(line)
    for description, reason, hint in function.broken_promises():
        failed += 1
        lines.append(f"  ✗ {description}: {reason}\n      hint: {_one_line(hint)}")
    print(f"{exercise}: public checks")
    print("\n".join(lines))
    total = passed + failed
    if failed:
        print(f"{passed} of {total} public checks passed. Fix the ✗ lines above and run this cell again.")
        _stop_the_cell(CheckFailed(f"{failed} of {total} public checks failed for {exercise}: "
                                   "fix the ✗ lines above"))
    passed_text = "The public check passed" if total == 1 else f"All {total} public checks passed"
    print(f"{passed_text}. The hidden checks run when your notebook is graded.")
