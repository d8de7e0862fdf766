"""How a notebook shows an exercise that is not written yet.

A stub is an answer cell's ``raise NotImplementedError(...)``. Any cell that
reaches one (a worked example, a figure, a demonstration, a check) ends in
one line naming the exercise to write first, never in a traceback through
numpy, matplotlib or ``coursekit``. Importing ``coursekit`` (the setup cell
does) installs the handler in the IPython kernel; outside a kernel nothing
changes.

Examples
--------
>>> def rot_x(angle):
...     raise NotImplementedError("this exercise is not written yet")
>>> try:
...     rot_x(0.3)
... except NotImplementedError as error:
...     print(stub_message(error, defined_in_a_cell=lambda filename: True))
rot_x is not written yet: write rot_x (its exercise is above this cell), run its cell, then run this cell again
"""

import traceback

__all__ = ["stub_message", "install_stub_handler"]

RED, RESET = "\x1b[0;31m", "\x1b[0m"


def stub_message(error, defined_in_a_cell):
    """One line for a ``NotImplementedError`` raised by a stub, or None for any other error.

    The stub is the innermost frame of the traceback: a named function whose
    code was typed in a notebook cell. A ``NotImplementedError`` raised inside
    a library (numpy, scipy, matplotlib, ``coursekit``) is not a stub.

    Parameters
    ----------
    error : BaseException
        The error, with its traceback.
    defined_in_a_cell : callable
        ``defined_in_a_cell(filename) -> bool``: whether code of that file name
        was typed in a cell of this notebook.

    Returns
    -------
    str or None
        ``"rot_x is not written yet: write rot_x ..."``, or None.
    """
    if not isinstance(error, NotImplementedError):
        return None
    frames = traceback.extract_tb(error.__traceback__)
    if not frames:
        return None
    innermost = frames[-1]
    name = innermost.name
    if not name.isidentifier() or not defined_in_a_cell(innermost.filename):
        return None
    return (f"{name} is not written yet: write {name} (its exercise is above this cell), run its cell, "
            "then run this cell again")


def _typed_in_a_cell(shell):
    """``defined_in_a_cell`` for a live kernel: the file names IPython gave the cells it ran."""
    known = getattr(getattr(shell, "compile", None), "_filename_map", None)

    def defined_in_a_cell(filename):
        if isinstance(known, dict) and filename in known:
            return True
        return filename.startswith("<ipython-input-") or "/ipykernel_" in filename.replace("\\", "/")

    return defined_in_a_cell


def _show_stub_in_one_line(shell, etype, value, tb, tb_offset=None):
    """IPython's handler for ``NotImplementedError``: a stub gets :func:`stub_message` in one red line;
    any other error (including coursekit's own one-line errors) is shown as IPython would."""
    message = None if hasattr(value, "_render_traceback_") else stub_message(value, _typed_in_a_cell(shell))
    if message is None:
        shell.showtraceback((etype, value, tb), tb_offset=tb_offset)
        return None
    lines = [f"{RED}{etype.__name__}{RESET}: {message}"]
    shell._showtraceback(etype, value, lines)
    return None


def _kernel_shell():
    try:
        from IPython import get_ipython
    except ImportError:
        return None
    shell = get_ipython()
    return shell if shell is not None and getattr(shell, "kernel", None) is not None else None


def install_stub_handler():
    """Show every stub reached by a notebook cell as one line (:func:`stub_message`).

    Does nothing outside an IPython kernel, or when the notebook installed a
    custom exception handler of its own.

    Returns
    -------
    bool
        True when the handler is in place.
    """
    shell = _kernel_shell()
    if shell is None:
        return False
    if shell.custom_exceptions not in ((), (NotImplementedError,)):
        return False
    shell.set_custom_exc((NotImplementedError,), _show_stub_in_one_line)
    return True
