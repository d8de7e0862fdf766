"""Deterministic printing of numbers and arrays.

The demonstration cells of the lessons print their results through
:func:`show`, so that the text is the same on every machine: values are
rounded to a fixed number of decimals and negative zeros are printed as
zeros. The grader compares these printed lines with the reference notebook,
so two correct answers that differ by 1e-16 print the same thing.

It also decides how a notebook shows an exercise that is not written yet:
any cell that calls a stub (a worked example, a figure, a check) ends in
one line naming the exercise, never a traceback (:func:`stub_message`,
installed in the kernel when ``coursekit`` is imported).
"""

import traceback

import numpy as np

__all__ = ["show", "format_value", "stub_message"]

RED, RESET = "\x1b[0;31m", "\x1b[0m"


def _is_vector(items):
    """A tuple of floats is a vector written differently: it prints like the array it stands for."""
    return bool(items) and all(isinstance(v, (float, np.floating)) for v in items)


def format_value(value, digits=4):
    """Return a stable text form of a number, array, tuple or dict.

    Parameters
    ----------
    value : float, int, bool, array_like, tuple, list or dict
        What to format. Arrays of any shape are accepted; a list or a tuple of
        floats prints exactly like the array it stands for, so a correct answer
        returned as a list or a tuple shows what the reference shows.
    digits : int
        Decimals kept after rounding.

    Returns
    -------
    str

    Examples
    --------
    >>> format_value(np.array([1e-17, -0.0, 0.5]))
    '[0.0000 0.0000 0.5000]'
    >>> format_value((1.0, -2e-20))          # a vector returned as a tuple prints as the array would
    '[1.0000 0.0000]'
    >>> format_value((np.array([0.0, 0.0, 1.0]), 0.5))
    '([0.0000 0.0000 1.0000], 0.5)'
    """
    if isinstance(value, dict):
        inner = ", ".join(f"{k!r}: {format_value(v, digits)}" for k, v in value.items())
        return "{" + inner + "}"
    if isinstance(value, tuple) and not _is_vector(value):
        return "(" + ", ".join(format_value(v, digits) for v in value) + ")"
    if isinstance(value, (bool, np.bool_, str)) or value is None:
        return str(value)
    array = np.asarray(value)
    if array.dtype.kind in "iu":
        return np.array2string(array) if array.ndim else str(int(array))
    rounded = np.round(array.astype(float), digits) + 0.0  # + 0.0 turns -0.0 into 0.0
    if rounded.ndim == 0:
        return repr(float(rounded))
    with np.printoptions(precision=digits, floatmode="fixed", suppress=True):
        return np.array2string(rounded, separator=" ")


class _Shown:
    """Text shown as a notebook *display* output (not a print), with a plain-text repr."""

    def __init__(self, text):
        self.text = text

    def __repr__(self):
        return self.text


def _in_a_kernel():
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and getattr(shell, "kernel", None) is not None


def show(label, value, digits=4):
    """Show ``label = value`` with :func:`format_value`.

    In a notebook the line is a display output rather than printed text: the
    grader compares these outputs with the reference notebook and ignores
    anything your own code prints, so a debugging print never costs a point.

    Parameters
    ----------
    label : str
        A short name for what is shown, such as ``"p_w"``.
    value : number, array_like, tuple or dict
    digits : int
        Decimals kept after rounding.

    Examples
    --------
    >>> show("p_w", [1.0, 2.0, -0.0])
    p_w = [1.0000 2.0000 0.0000]
    """
    text = format_value(value, digits)
    line = f"{label} =\n{text}" if "\n" in text else f"{label} = {text}"
    if _in_a_kernel():
        from IPython.display import display

        display(_Shown(line))
    else:
        print(line)


def stub_message(error):
    """One line for a ``NotImplementedError`` raised by an unwritten exercise, or None for any other.

    The stub is the function whose body raised it: the innermost frame of the
    traceback, when that frame is a function outside ``coursekit``.

    Parameters
    ----------
    error : NotImplementedError
        The error, with its traceback.

    Returns
    -------
    str or None

    Examples
    --------
    >>> def rot_x(a):
    ...     raise NotImplementedError("this exercise is not written yet")
    >>> try:
    ...     rot_x(0.3)
    ... except NotImplementedError as error:
    ...     print(stub_message(error))
    this cell needs rot_x, which is not written yet: write rot_x (its exercise is above), run its cell, then run this cell again
    """
    frames = traceback.extract_tb(error.__traceback__)
    if not frames:
        return None
    innermost = frames[-1]
    name = innermost.name
    if not name.isidentifier() or "coursekit" in innermost.filename.replace("\\", "/").split("/"):
        return None
    return (f"this cell needs {name}, which is not written yet: write {name} (its exercise is above), "
            "run its cell, then run this cell again")


def _show_stub_in_one_line(shell, etype, value, tb, tb_offset=None):
    """IPython's handler for ``NotImplementedError``: errors that render themselves keep their own line,
    an unwritten exercise gets :func:`stub_message`, anything else its usual traceback."""
    render = getattr(value, "_render_traceback_", None)
    if render is not None:
        lines = render()
    else:
        message = stub_message(value)
        lines = ([f"{RED}{etype.__name__}{RESET}: {message}"] if message is not None else
                 shell.InteractiveTB.structured_traceback(etype, value, tb, tb_offset=tb_offset))
    shell._showtraceback(etype, value, lines)
    return lines


def install_stub_handler():
    """Show every ``NotImplementedError`` that reaches a notebook cell through :func:`stub_message`.

    Does nothing outside an IPython kernel, or when another custom handler is installed.
    Returns True when the handler is in place.
    """
    if not _in_a_kernel():
        return False
    from IPython import get_ipython

    shell = get_ipython()
    if shell.custom_exceptions not in ((), (NotImplementedError,)):
        return False
    shell.set_custom_exc((NotImplementedError,), _show_stub_in_one_line)
    return True


install_stub_handler()
