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

from .captions import figure_caption

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


def _with_caption(printer):
    def print_with_caption(fig, **kwargs):
        caption = figure_caption(fig)
        return printer(fig, metadata={"Title": caption}, **kwargs) if caption else printer(fig, **kwargs)

    print_with_caption.adds_caption = True
    return print_with_caption


def _caption_every_png(shell):
    import importlib

    import matplotlib
    from matplotlib.figure import Figure

    backend = matplotlib.get_backend()
    if backend.startswith("module://"):  # load it now: the inline backend registers its PNG printer on import
        importlib.import_module(backend[len("module://"):])

    formatter = shell.display_formatter.formatters["image/png"]
    try:
        printer = formatter.lookup_by_type(Figure)
    except KeyError:
        return
    if not getattr(printer, "adds_caption", False):
        formatter.for_type(Figure, _with_caption(printer))


def install_caption_metadata():
    """In the book's kernels, write each figure's caption into its PNG (the ``Title`` text chunk).

    The book build reads it back as the image's alt text. The inline backend
    registers its PNG printer when it is loaded (and again if a cell asks for
    it), so the backend is selected and the wrapper put back before every cell. Does nothing in the lab.

    Returns
    -------
    bool
        True when installed.
    """
    if not is_reader_edition():
        return False
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    if shell is None or getattr(shell, "kernel", None) is None:
        return False
    shell.events.register("pre_run_cell", lambda *args: _caption_every_png(shell))
    return True
