"""The course's grader: release, sandboxed grading, reports.

Run ``python -m autograder --help`` for the commands.
"""
