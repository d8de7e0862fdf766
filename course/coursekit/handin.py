"""The last cell of every lesson: is this notebook ready to hand in?

:func:`ready_to_hand_in` runs the public checks of every exercise of a lesson
at once, quietly, and prints one line per exercise and what is still to do,
like nbgrader's *Validate* button but with the course's own messages. When
something is left it ends with one red line, :class:`NotReadyYet`, naming
what to finish; that error is also how the cell, a grade cell worth the
notebook point, scores 0 in stock ``nbgrader autograde``.

Examples
--------
>>> ready_to_hand_in("01")                          # doctest: +SKIP
Lesson 01: ready to hand in?
  ✓ rot2d               3 of 3 public checks pass
  ✗ rot_x               not written yet
...
NotReadyYet: still to do in lesson 01: rot_x
"""

from .checking import _OneLine, checks_of_lesson, run_quietly


class NotReadyYet(_OneLine, AssertionError):
    """Raised by :func:`ready_to_hand_in` when some exercise does not pass its public checks yet."""


def _user_namespace():
    try:
        from IPython import get_ipython
    except ImportError:
        return {}
    shell = get_ipython()
    return shell.user_ns if shell is not None else {}


def ready_to_hand_in(lesson, namespace=None):
    """Print which exercises of ``lesson`` pass their public checks, and what is left to do.

    Parameters
    ----------
    lesson : str
        The lesson's number, e.g. ``"01"``.
    namespace : dict, optional
        Where the functions live (default: the notebook's).

    Returns
    -------
    None
        Nothing, so that a clean run shows no value under the cell.

    Raises
    ------
    NotReadyYet
        After the summary, when some exercise is still to finish (its message names them).
    """
    namespace = _user_namespace() if namespace is None else namespace
    names = checks_of_lesson(lesson)
    width = max([len(name) for name in names] + [8])
    print(f"Lesson {lesson}: ready to hand in?")
    unfinished = []
    for name in names:
        function = namespace.get(name)
        if not callable(function):
            passed, total, problem = 0, 0, "not defined: run its answer cell"
        else:
            passed, total, problem = run_quietly(name, function)
        if problem:
            unfinished.append(name)
            print(f"  ✗ {name:<{width}}  {problem}")
        else:
            print(f"  ✓ {name:<{width}}  {passed} of {total} public checks pass")
    if unfinished:
        print(f"{len(names) - len(unfinished)} of {len(names)} exercises pass their public checks. "
              f"Still to do: {', '.join(unfinished)}. Each one's check cell says more.")
        raise NotReadyYet(f"still to do in lesson {lesson}: {', '.join(unfinished)}")
    print(f"All {len(names)} exercises pass their public checks: ready to hand in. "
          "Save the notebook (Ctrl+S) and hand in this file; the hidden checks run when it is graded.")
