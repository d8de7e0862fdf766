"""The visible check cells: fast, friendly, and honest about hidden checks."""

import time

import pytest

from support import THIS_COURSE

EXERCISES = [e.name for e in THIS_COURSE.catalog.exercises]


@pytest.fixture(scope="module")
def kit():
    import coursekit
    from coursekit.checking import registered_exercises
    from coursekit.checks import IMPORT_ERRORS

    assert not IMPORT_ERRORS, IMPORT_ERRORS
    return coursekit, registered_exercises()


@pytest.mark.parametrize("name", EXERCISES)
def test_reference_passes_the_public_checks_quickly(name, kit, capsys):
    coursekit, registered = kit
    assert name in registered, f"no public checks for {name}"
    started = time.perf_counter()
    coursekit.check(name, getattr(THIS_COURSE.reference, name))
    elapsed = time.perf_counter() - started
    out = capsys.readouterr().out
    assert elapsed < 0.5, f"check cell for {name} took {elapsed:.2f} s"
    assert "The hidden checks run when your notebook is graded" in out
    assert "✗" not in out


@pytest.mark.parametrize("name", EXERCISES)
def test_a_stub_is_reported_as_not_written(name, kit, capsys):
    coursekit, _ = kit

    def stub(*args, **kwargs):
        raise NotImplementedError("this exercise is not written yet")

    with pytest.raises(NotImplementedError):
        coursekit.check(name, stub)
    assert "not written yet" in capsys.readouterr().out


def test_a_wrong_answer_gets_a_hint(kit, capsys):
    coursekit, _ = kit
    import numpy as np
    from coursekit.checking import CheckFailed

    def rot_z_transposed(a):
        c, s = np.cos(a), np.sin(a)
        return np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])

    with pytest.raises(CheckFailed):
        coursekit.check("rot_z", rot_z_transposed)
    out = capsys.readouterr().out
    assert "✗" in out and "transpose" in out and "hidden checks" not in out.lower().replace("the hidden checks run", "")


def test_a_crashing_answer_is_reported_not_raised_raw(kit, capsys):
    coursekit, _ = kit
    from coursekit.checking import CheckFailed

    with pytest.raises(CheckFailed):
        coursekit.check("rot_x", lambda a: 1 / 0)
    assert "raised ZeroDivisionError" in capsys.readouterr().out


FINITE_DIFFERENCE_POINT_JACOBIAN = """
from coursekit.lie import ExpSE3

def jacobian_transform_point(T, p):
    T, p_h = np.asarray(T, dtype=float), np.append(np.asarray(p, dtype=float), 1.0)
    h = 1e-6
    columns = [((T @ ExpSE3(h * e) @ p_h) - (T @ ExpSE3(-h * e) @ p_h))[:3] / (2 * h) for e in np.eye(6)]
    return np.column_stack(columns)
"""


def test_an_inexact_derivative_is_a_cross_in_the_check_cell_and_a_loss_when_graded(tmp_path):
    """A ✓ predicts the hidden grade: central differences come within 1e-9 of jacobian_transform_point's exact
    answer, which the hidden suite holds to 1e-12 |p|; the check cell must say ✗, and say it is close but inexact."""
    from public_runner import run_public_checks
    from support import build_submission, grade

    passed, printed = run_public_checks(THIS_COURSE, "jacobian_transform_point", FINITE_DIFFERENCE_POINT_JACOBIAN)
    assert not passed
    assert "✗ exact to rounding" in printed and "close, but not exact" in printed, printed
    folder = build_submission(
        tmp_path / "student", {"jacobian_transform_point": FINITE_DIFFERENCE_POINT_JACOBIAN}, lessons=("07",)
    )
    [graded] = [e for e in grade(folder, lessons=("07",)).exercises if e.name == "jacobian_transform_point"]
    assert graded.points < graded.max_points
