"""Fixtures of the hidden suite: ``student`` (the proxy) and ``ref`` (the reference)."""

import pytest

from autograder.grading import suite


@pytest.fixture
def student():
    """The student's exercise functions, called in their sandbox."""
    return suite.CONTEXT.student


@pytest.fixture
def ref():
    """The reference solutions, executed from the masters in this process."""
    return suite.CONTEXT.reference
