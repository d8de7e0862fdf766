"""Hidden checks generated from each exercise's contract (``coursekit/exercise_contracts.json``, issue #43).

For every exercise with array parameters (:func:`coursekit.exercise_contracts.covered`), one check calls the
student's function with float arrays (the baseline), nested lists, tuples, integer arrays and read-only arrays of
small integer-valued samples; each result must equal the baseline's and have the exact type, dtype and shape the
docstring promises, and no argument may be written into (the wire keeps an array read-only, so a write raises in
the sandbox as it would in the student's notebook). It counts only when it fails, and then costs :data:`SHARE` of
the exercise (``suite.weigh_shares``): an answer that misses the exercise's point earns nothing more for keeping
the contract. It is the public check's line, graded: :func:`coursekit.exercise_contracts.contract_problem` makes
the same calls.

Each ``test_NN_contracts.py`` holds lesson NN's checks: ``test_contract = contract_tests("NN")``.
"""

import pytest
from autograder.sandbox.session import StudentError
from coursekit.exercise_contracts import FORMS, contract_of, contract_problem, covered

from .helpers import Wrong

SHARE = 0.2  # of the exercise's points, lost when the check fails; a passed check is left out of the grade


def exercises_of(lesson):
    """The covered exercises of ``lesson`` (``"01"``), in the contract file's order."""
    from coursekit.exercise_contracts import _contracts

    return [name for name, c in _contracts().items() if c["lesson"] == lesson and covered(name)]


def contract_tests(lesson):
    """A test function, parametrized over ``lesson``'s covered exercises; None (nothing to collect) if none."""
    names = exercises_of(lesson)
    if not names:
        return None

    @pytest.mark.parametrize(
        "name", [pytest.param(n, marks=pytest.mark.exercise(name=n, weight=0.0, share=SHARE), id=n) for n in names]
    )
    def test_contract(student, name):
        """keeps its docstring's contract with lists, tuples, integer and read-only arrays as input (type, dtype, shape)"""
        assert contract_of(name) is not None
        problem = contract_problem(name, getattr(student, name), forms=FORMS, reraise=(StudentError,))
        if problem is not None:
            raise Wrong(*problem)

    return test_contract
