"""The fixtures every course's hidden tests ask for: ``student`` (the proxy) and ``ref`` (the reference).

The grader loads this module as a pytest plugin (``-p``), so a course's hidden folder needs no conftest.
"""

import pytest

from autograder.grading import suite


@pytest.fixture
def student() -> object:
    """The student's exercise functions, called in their sandbox."""
    return suite.CONTEXT.student


@pytest.fixture
def ref() -> object:
    """The reference solutions, executed from the masters in this process."""
    return suite.CONTEXT.reference
