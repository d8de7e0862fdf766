"""The course as the grader reads it: where files live, the roles of a notebook's cells,
the catalog of lessons and exercises, and the reference answers taken from the masters.

May import: nothing else in autograder.
"""
