"""Every example in ``coursekit``'s docstrings runs and prints what it says.

Students open these modules (the start page tells them they may), and the course's style is a docstring
with an example; an example that no longer matches its function teaches the wrong thing. Oracle: the
standard library's doctest, on each module of the master ``solutions/coursekit`` (the hand-out's copy is
checked equal to it by tests/test_release.py), with ``np`` as the lessons import it and matplotlib drawing
off screen.
"""

import doctest
import importlib

import matplotlib
import numpy as np
import pytest

from autograder.lessons.paths import SOLUTIONS

matplotlib.use("Agg")

MODULES = sorted(
    "coursekit." + ".".join(path.relative_to(SOLUTIONS / "coursekit").with_suffix("").parts)
    for path in (SOLUTIONS / "coursekit").rglob("*.py")
    if path.name != "__init__.py"
)


def test_the_modules_are_found():
    assert "coursekit.lie" in MODULES and "coursekit.checks.tolerance" in MODULES


@pytest.mark.parametrize("name", MODULES)
def test_every_docstring_example_runs(name):
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in finder.find(module, name, globs={"np": np, **vars(module)}):
        runner.run(test)
    results = runner.summarize(verbose=False)
    assert results.failed == 0, f"{name}: {results.failed} of {results.attempted} docstring examples failed (above)"
