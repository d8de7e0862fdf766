"""Lesson 08's Gauss-Newton explorer steps through the student's own function and never solves it itself.

Oracles: with the reference ``align_gauss_newton`` the static figure plots the
start and 8 iterates and ends at the closed-form minimum (scipy's
``align_vectors``); with the released stub it says to write the exercise
first; with a function that raises, it names the error; and the hand-out's
explorers module has no least-squares solve or SVD of its own.
"""

import matplotlib
import numpy as np
import pytest

matplotlib.use("agg")
import matplotlib.pyplot as plt  # noqa: E402

from autograder.lessons.paths import COURSE  # noqa: E402
from coursekit.explorers import explore_gauss_newton  # noqa: E402
from support import THIS_COURSE


def _draw(function, monkeypatch):
    plt.close("all")
    monkeypatch.setattr(plt, "show", lambda *args, **kwargs: None)
    explore_gauss_newton(function, figure="2b")
    cost_axes = plt.gcf().axes[1]
    return cost_axes.get_title(), cost_axes.lines[0].get_ydata()


def test_it_plots_the_students_iterations(monkeypatch):
    title, costs = _draw(THIS_COURSE.reference.align_gauss_newton, monkeypatch)
    assert len(costs) == 9 and costs[-1] < 1e-2 * costs[0]
    assert title.startswith("cost ")


@pytest.mark.parametrize(
    "error, words",
    [
        (NotImplementedError("not written"), "write align_gauss_newton"),
        (ValueError("shapes"), "raised ValueError: shapes"),
    ],
)
def test_it_says_what_stops_it(monkeypatch, error, words):
    def broken(P, Q, R0, iters=10):
        raise error

    title, costs = _draw(broken, monkeypatch)
    assert words in title and len(costs) == 1


def test_the_hand_out_explorers_solve_nothing_themselves():
    source = (COURSE / "coursekit" / "explorers.py").read_text(encoding="utf-8")
    assert "lstsq" not in source and "linalg.svd" not in source and np.linalg.solve.__name__ + "(" not in source


def test_the_gimbal_title_says_the_angle_its_slider_shows(monkeypatch):
    """Pitch moves in steps of 0.5°: at 88.5 the title must not round to 88 while the slider says 88.5."""
    from coursekit import explorers

    captured = {}
    monkeypatch.setattr(
        explorers, "_explore", lambda draw, controls, *args, **kwargs: captured.update(draw=draw, controls=controls)
    )
    explorers.explore_gimbal(figure="5")
    plt.close("all")
    fig = plt.figure()
    captured["draw"](fig, yaw=-12.0, pitch=88.5, roll=20.0)
    title = fig.axes[0].get_title()
    plt.close(fig)
    for value in (-12.0, 88.5, 20.0):
        readout = format(value, explorers.READOUT_FORMAT)  # what the slider prints
        assert f"{readout}°" in title, (readout, title)
    assert captured["controls"]["pitch"][3] == 0.5
