"""Deterministic printing of numbers and arrays.

The demonstration cells of the lessons print their results through
:func:`show`, so that the text is the same on every machine: values are
rounded to a fixed number of decimals and negative zeros are printed as
zeros. The grader compares these printed lines with the reference notebook,
so two correct answers that differ by 1e-16 print the same thing.
"""

import numpy as np

__all__ = ["show", "format_value"]


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
