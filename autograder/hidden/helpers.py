"""What hidden tests are written with: marks, failures with hints, comparisons.

Every hidden test names the exercise it grades and, through its docstring's
first line, what it checks — that line is what the student reads. When a
check fails it raises :class:`Wrong` with one line on what was seen and,
where a mistake is recognisable, a hint::

    @exercise("rot_z", weight=2)
    def test_rot_z_matches_scipy(student):
        \"\"\"agrees with scipy for 20 random angles\"\"\"
        for angle in angles(seed=1):
            got = expect_array(student.rot_z(angle), (3, 3), "rot_z")
            expect_close(got, Rotation.from_euler("z", angle).as_matrix(), 1e-9,
                         f"rot_z({angle:.3f})", hint=rotation_hint(got, ...))

A test may call student functions of its own exercise only; inputs and
expected values come from the reference (``ref``), scipy, or the test itself,
so one wrong exercise never costs points elsewhere.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from autograder.sandbox.child.wire import Probe  # noqa: F401  (callable arguments, by name)
from autograder.sandbox.session import StudentError
from autograder.grading.hidden_api import Wrong, exercise, expect, expect_close, fmt  # noqa: F401  (for the tests)
from coursekit.diagnose import LISTS_HINT, shape_problem
from coursekit.diagnose import ALLCLOSE_HINT, rotation_hint, rotation_problem  # noqa: F401  (for the tests)


def expect_array(value, shape, what):
    """``value`` as a float array of ``shape``, or :class:`Wrong` saying why not."""
    problem = shape_problem(value, shape)
    if problem:
        raise Wrong(f"{what} {problem}")
    return np.asarray(value, dtype=float)


def expect_same_with_lists(function, args, shape, what, lists=None, **kwargs):
    """``function`` gives the same answer for plain lists as for arrays (whether or not it is right).

    The hint blames lists only when lists are the difference: a wrong answer
    that is wrong either way loses its points in the checks of its values.
    ``lists`` replaces the default plain-list form of ``args`` (e.g. integers).
    """
    arrays = [np.array(a, dtype=float) for a in args]
    with_arrays = expect_array(function(*arrays, **kwargs), shape, f"{what} with arrays")
    try:
        with_lists = function(*(lists if lists is not None else [a.tolist() for a in arrays]), **kwargs)
    except StudentError as error:
        if error.kind != "exception":
            raise
        raise Wrong(f"{what} with lists: {error}", LISTS_HINT) from None
    with_lists = expect_array(with_lists, shape, f"{what} with lists")
    expect_close(with_lists, with_arrays, 1e-12, f"{what} with lists, compared with arrays", LISTS_HINT)


def expect_bool(value, what):
    """``value`` as a Python bool, or :class:`Wrong` if it is not a boolean."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise Wrong(
        f"{what} returned {value!r} ({type(value).__name__}), not True or False",
        "return a bool: wrap numpy's result in bool(...)",
    )


def random_rotations(count, seed):
    """``count`` uniformly random rotation matrices, shape (count, 3, 3), seeded."""
    return Rotation.random(count, random_state=seed).as_matrix()


def random_angles(count, seed, low=-2 * np.pi, high=2 * np.pi):
    """``count`` seeded random angles in [low, high)."""
    return np.random.default_rng(seed).uniform(low, high, count)
