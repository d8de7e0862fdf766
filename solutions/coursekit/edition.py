"""Which edition a notebook runs in: the lab (a student's notebook) or the book (the reader's edition).

The book is built from the same masters with the reference answers in place,
so a legend that says "your log_so3" in the lab must say "the reference
log_so3" there. The book build sets ``COURSEKIT_EDITION=reader`` for the
kernels it runs; everywhere else the lab's wording is used.

Examples
--------
>>> answer_label("log_so3")                                   # doctest: +SKIP
'your log_so3'
"""

import os

__all__ = ["answer_label", "is_reader_edition"]

EDITION_VARIABLE = "COURSEKIT_EDITION"


def is_reader_edition():
    """True when the notebook runs for the book (``COURSEKIT_EDITION=reader``)."""
    return os.environ.get(EDITION_VARIABLE, "").strip().lower() == "reader"


def answer_label(name):
    """How a legend or title names the answer to exercise ``name``.

    Parameters
    ----------
    name : str
        The exercise, e.g. ``"log_so3"``.

    Returns
    -------
    str
        ``"your log_so3"`` in the lab, ``"the reference log_so3"`` in the book.
    """
    return f"the reference {name}" if is_reader_edition() else f"your {name}"
