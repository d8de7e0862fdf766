"""The course's grader: release, sandboxed grading, reports.

Run ``python -m autograder --help`` for the commands.
"""

# The oldest Python the pinned requirements install on (soupsieve 4.1.2 asks for 3.11.5);
# README.md and the Gradescope setup.sh state it, tests/test_environment.py keeps them honest.
MINIMUM_PYTHON = "3.11.5"
