"""Answer similarity across a class: each exercise's answers compared pairwise, with the reference
solution and with past terms, so an instructor sees which answers are worth a look. Changes no grade.

May import: grading, lessons.
"""
