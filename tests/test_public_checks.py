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
