"""Tools for authors: normalise the masters and release course/, record demonstration outputs,
build the book, the students' hand-out and the sample class.

May import: lessons, mistakes.
"""
