"""What a call of your function did besides returning a value.

Two promises every exercise's docstring makes are not visible in the value a
function returns:

- **its arguments are left unchanged**: ``rotate_point(R, p)`` must not
  overwrite ``p`` (a later cell that reuses ``p`` would print wrong values);
- **it is your own implementation**: where an exercise asks you to write a
  map (``exp_so3``, ``quat_multiply``), calling the library version of it
  (:mod:`coursekit.lie`, scipy's ``Rotation``) answers a different question.

:func:`watch_call` calls a function and reports both. The visible checks use
it, and so does the grader's sandbox, so the two always agree.

Examples
--------
>>> import numpy as np
>>> def normalise_in_place(q):
...     q /= np.linalg.norm(q)
...     return q
>>> value, seen = watch_call(normalise_in_place, (np.array([2.0, 0.0, 0.0, 0.0]),))
>>> seen.changed
['q']
"""

import copy
import inspect
import sys
import threading
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Watched", "watch_call", "snapshot", "changed_arguments"]


@dataclass
class Watched:
    """What :func:`watch_call` saw.

    Attributes
    ----------
    changed : list of str
        Names of the arguments the call changed in place (positions as ``"argument 2"`` when the
        function's signature cannot be read).
    used : list of str
        Library functions from the forbidden list that the function called directly, as
        ``"module.qualname"`` (at most three).
    tampered : bool
        The function switched the watching off (``sys.setprofile``) while it ran.
    """

    changed: list = field(default_factory=list)
    used: list = field(default_factory=list)
    tampered: bool = False


def snapshot(values):
    """A deep copy of plain data (arrays, lists, tuples, dicts, numbers); other objects are kept as is."""
    if isinstance(values, np.ndarray):
        return values.copy()
    if isinstance(values, (list, tuple, dict)):
        try:
            return copy.deepcopy(values)
        except Exception:  # an object that cannot be copied: nothing to compare it with
            return values
    return values


def _same(before, after):
    """Bit for bit the same plain data (a NaN equals itself; -0.0 differs from 0.0)."""
    if isinstance(before, np.ndarray):
        return (isinstance(after, np.ndarray) and before.shape == after.shape and before.dtype == after.dtype
                and before.tobytes() == after.tobytes())
    if isinstance(before, (list, tuple)):
        return (type(after) is type(before) and len(after) == len(before)
                and all(_same(b, a) for b, a in zip(before, after)))
    if isinstance(before, dict):
        return (isinstance(after, dict) and list(after) == list(before)
                and all(_same(before[k], after[k]) for k in before))
    return True  # numbers, strings and other objects cannot be changed in place (or are not ours to judge)


def _labels(function, count, keywords):
    try:
        names = list(inspect.signature(function).parameters)
    except (TypeError, ValueError):
        names = []
    positional = [names[i] if i < len(names) else f"argument {i + 1}" for i in range(count)]
    return positional + list(keywords)


def changed_arguments(function, args, kwargs, before):
    """Names of the arguments of ``function(*args, **kwargs)`` that differ from their ``before`` copies."""
    values = list(args) + list(kwargs.values())
    changed = [i for i, (old, new) in enumerate(zip(before, values)) if not _same(old, new)]
    if not changed:
        return []
    labels = _labels(function, len(args), kwargs)  # read the signature only when there is something to name
    return [labels[i] for i in changed]


def _qualname(code):
    """``code``'s qualified name (``"Rotation.from_matrix"``). Before Python 3.11 a code object has
    only its plain name (``"from_matrix"``), which is enough here: every function that
    ``coursekit.contracts.FORBIDDEN`` names one by one lives at the top of its module, and a module
    entry matches on the module's name alone.

    >>> def f(): pass
    >>> _qualname(f.__code__)
    'f'
    """
    return getattr(code, "co_qualname", code.co_name)


class _Tracer:
    """A profile hook that notes calls into forbidden functions made directly from notebook code."""

    def __init__(self, forbidden):
        self.prefixes = tuple(forbidden)
        self.used = []

    def _note(self, caller, full_name):
        if caller.f_globals.get("__name__") != "__main__":
            return  # called by a library or a check, not by the notebook's own code
        if (full_name + ".").startswith(self.prefixes) and full_name not in self.used and len(self.used) < 3:
            self.used.append(full_name)

    def __call__(self, frame, event, arg):
        if event == "call" and frame.f_back is not None:
            self._note(frame.f_back, f"{frame.f_globals.get('__name__', '')}.{_qualname(frame.f_code)}")
        elif event == "c_call":
            module = getattr(arg, "__module__", None) or ""
            self._note(frame, f"{module}.{getattr(arg, '__qualname__', '')}")


def _resolve(name):
    """``"scipy.linalg.expm"`` → the prefix that its frames carry (``"scipy.linalg._matfuncs.expm."``);
    a module or package name is its own prefix (``"coursekit.lie."``)."""
    if name in sys.modules:
        return name + "."
    module_name, _, attribute = name.rpartition(".")
    module = sys.modules.get(module_name)
    if module is None:
        try:
            module = __import__(module_name, fromlist=[attribute])
        except ImportError:
            return name + "."
    target = getattr(module, attribute, None)
    if target is None:
        return name + "."
    if inspect.ismodule(target):
        return target.__name__ + "."
    target = getattr(target, "__func__", target)
    return f"{getattr(target, '__module__', module_name)}.{getattr(target, '__qualname__', attribute)}."


def watch_call(function, args=(), kwargs=None, forbidden=()):
    """Call ``function(*args, **kwargs)``; return ``(value, Watched)``.

    Parameters
    ----------
    function : callable
    args : tuple
    kwargs : dict, optional
    forbidden : sequence of str
        Modules (``"coursekit.lie"``) and functions (``"scipy.linalg.expm"``) that the exercise must
        not hand its work to. Only calls made directly from notebook code (the ``__main__`` module)
        count, so a library that uses them internally is fine.

    Exceptions raised by ``function`` propagate unchanged.
    """
    kwargs = dict(kwargs or {})
    before = [snapshot(v) for v in list(args) + list(kwargs.values())]
    seen = Watched()
    tracer = None
    if forbidden:
        tracer = _Tracer(sorted({_resolve(name) for name in forbidden}))
        sys.setprofile(tracer)
        threading.setprofile(tracer)
    try:
        value = function(*args, **kwargs)
    finally:
        if tracer is not None:
            seen.tampered = sys.getprofile() is not tracer
            sys.setprofile(None)
            threading.setprofile(None)
            seen.used = list(tracer.used)
        seen.changed = changed_arguments(function, args, kwargs, before)
    return value, seen
