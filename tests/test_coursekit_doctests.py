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


@pytest.fixture(autouse=True)
def _no_example_check_left_registered():
    """An example that registers a public check (``checking.public_check``'s "double") must not leave it behind for
    the tests that read the registry later in this process (tests/test_public_claims.py)."""
    yield
    from coursekit import checking

    for exercise, checks in list(checking._REGISTRY.items()):
        kept = [(text, f) for text, f in checks if not f.__code__.co_filename.startswith("<doctest")]
        if kept:
            checking._REGISTRY[exercise] = kept
        else:
            del checking._REGISTRY[exercise]


@pytest.mark.parametrize("name", MODULES)
def test_every_docstring_example_runs(name):
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in finder.find(module, name, globs={"np": np, **vars(module)}):
        runner.run(test)
    results = runner.summarize(verbose=False)
    assert results.failed == 0, f"{name}: {results.failed} of {results.attempted} docstring examples failed (above)"
