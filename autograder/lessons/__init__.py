"""The course as the grader reads it: where files live, the roles of a notebook's cells,
the catalog of lessons and exercises, the reference answers taken from the masters; reading
notebook files defensively, and showing a student's text safely (``untrusted_text``).

May import: nothing else in autograder.
"""
