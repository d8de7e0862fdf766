"""Hidden checks for lesson 02: each exercise keeps its docstring's contract (see :mod:`.contract_forms`)."""

from .contract_forms import contract_tests

test_contract = contract_tests("02")
