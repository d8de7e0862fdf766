"""Grading a whole class: each student in a fork, resume what has not changed, write every
output atomically, and show progress.

May import: reports, similarity, grading, sandbox, authoring, lessons.
"""
