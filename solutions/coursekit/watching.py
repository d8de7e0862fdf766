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

import builtins
import copy
import dis
import functools
import gc
import inspect
import signal
import sys
import threading
import types
import weakref
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
        return (
            isinstance(after, np.ndarray)
            and before.shape == after.shape
            and before.dtype == after.dtype
            and before.tobytes() == after.tobytes()
        )
    if isinstance(before, (list, tuple)):
        return (
            type(after) is type(before)
            and len(after) == len(before)
            and all(_same(b, a) for b, a in zip(before, after))
        )
    if isinstance(before, dict):
        return (
            isinstance(after, dict) and list(after) == list(before) and all(_same(before[k], after[k]) for k in before)
        )
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


_STDLIB = frozenset(getattr(sys, "stdlib_module_names", ()))
# numpy's functions that call a function they are handed: a library function handed to them is a call
# of the notebook's (``np.vectorize(expm)``); np.frompyfunc is C: what it is handed is judged by name
_TAKES_CALLBACKS = frozenset({"vectorize.__init__", "apply_along_axis", "apply_over_axes", "piecewise", "fromfunction"})


def _spontaneous(code):
    """True for code the interpreter runs on its own while notebook code runs, which the notebook never called:
    a finaliser (``__del__``, ``weakref.finalize``), a garbage-collector callback (``gc.callbacks``; hypothesis
    registers one) or a signal handler (the grader's alarm). Its frame's caller is whatever notebook frame the
    collection or the signal happened to interrupt. Asked only of a call about to be noted, so it may be slow."""
    if code.co_name == "__del__" or code is _FINALIZE_CODE:
        return True
    handlers = list(gc.callbacks)
    if threading.current_thread() is threading.main_thread():  # handlers run in the main thread only
        handlers += [signal.getsignal(number) for number in signal.valid_signals()]
    return any(getattr(getattr(handler, "__func__", handler), "__code__", None) is code for handler in handlers)


_FINALIZE_CODE = weakref.finalize.__call__.__code__


class _Tracer:
    """A profile hook that notes what notebook code calls while the watched call runs.

    Notebook code is the watched function's module (its globals; any ``__main__`` code when it has
    none): the student's function, its helpers, lambdas and classes. A call counts when notebook code
    makes it directly, or hands the callee to a built-in (``sorted(key=...)``, ``functools.reduce``) or
    to one of numpy's functions that call back (``np.vectorize``, ``np.apply_along_axis``: the handed
    function is judged when numpy is called); calls that a library makes inside itself are free, and so
    are functions the caller handed in as arguments (a check's own function, a grader's probe). A call
    is noted when its target is on the exercise's ``forbidden`` list, or when there is an
    ``allowance`` and the target's module is outside it (a method counts as the module of its
    object's type), or when it is one of the student's own functions that the allowance names as
    doing the exercise's job. A callback is noted only when its module is outside the allowance *and*
    outside the standard library; ``print`` and what it writes to are free. Threads started during
    the call are watched too (``threading.setprofile``), though starting one already leaves the
    allowance (``threading``). A ufunc or an f2py routine makes no profile event when called; those are
    judged where notebook code names them (:func:`_check_unreported`) and, fetched by a computed name, through
    the stand-ins that take their place (:func:`_put_stand_ins`). The tracer switched off
    (``sys.setprofile``) is seen as ``tampered``.
    """

    def __init__(self, forbidden, allowance=None, callables=(), main=None):
        self.prefixes = tuple(forbidden)
        # the notebook's namespace: the watched function's globals (in the sandbox the worker's own module
        # is also named __main__, so the name alone cannot tell notebook code); None: any __main__
        self.main = main
        self.allowance = allowance
        self.modules = tuple(allowance.modules) if allowance is not None else ()
        self.own = frozenset(allowance.own) if allowance is not None else frozenset()
        self.codes = set(callables)  # code of functions handed in as arguments: the caller's own
        self.used = []
        self.verdicts = {"__main__": True}
        self.in_c = []  # (frame, C function) of the C calls notebook code is inside of
        # while the garbage collector runs: the frame it interrupted, [] otherwise (see collection_callbacks)
        self.interrupted = []

    def allowed(self, module):
        verdict = self.verdicts.get(module)
        if verdict is None:
            verdict = (
                self.allowance is None
                or module.startswith("namedtuple_")  # the constructor of a named tuple (numpy's SVDResult)
                or any(module == prefix or module.startswith(prefix + ".") for prefix in self.modules)
            )
            self.verdicts[module] = verdict
        return verdict

    def note(self, full_name):
        if full_name not in self.used and len(self.used) < 3:
            self.used.append(full_name)

    def is_main(self, namespace):
        return namespace is self.main if self.main is not None else namespace.get("__name__") == "__main__"

    def _check(self, module, qualname, indirect=False, code=None):
        if module == "__main__":
            if qualname.rpartition(".")[2] in self.own:
                self.note(f"your {qualname.rpartition('.')[2]}")
            return
        full_name = f"{module}.{qualname}"
        if (full_name + ".").startswith(self.prefixes) or (
            not self.allowed(module) and not (indirect and module.partition(".")[0] in _STDLIB)
        ):
            if code is None or not _spontaneous(code):
                self.note(full_name)

    def collection_callbacks(self):
        """Two ``gc.callbacks`` entries, one to go first and one last, that mark the collector's work: what it
        calls from the frame it interrupted (a finaliser, a weak reference's callback, the closing of a
        suspended generator, another ``gc.callbacks`` entry) is the interpreter's call, not the answer's;
        what a notebook finaliser calls in turn has a notebook caller and is judged as usual."""
        interrupted = self.interrupted

        def opening(phase, info):
            if phase == "start":
                interrupted[:] = [sys._getframe(1)]

        def closing(phase, info):
            if phase == "stop":
                interrupted.clear()

        return opening, closing

    def make_hook(self):
        """The profile function: a closure, so that the events it ignores (most of them) cost little.
        Each frame's globals are classified once: notebook code, numpy, or anything else."""
        kinds = {}  # id(globals) -> 1 notebook code, 0 anything else
        codes, in_c, check, main, interrupted = self.codes, self.in_c, self._check, self.main, self.interrupted

        def kind_of(namespace):
            name = namespace.get("__name__") or ""
            if (namespace is main) if main is not None else name == "__main__":
                kind = 1
            else:
                kind = 0
            kinds[id(namespace)] = kind
            return kind

        def hook(frame, event, arg):
            if event == "call":
                caller = frame.f_back
                if caller is None:
                    return
                namespace = caller.f_globals
                kind = kinds.get(id(namespace))
                if kind is None:
                    kind = kind_of(namespace)
                if kind == 0 or frame.f_code in codes:
                    return
                if interrupted and interrupted[0] is caller:
                    return  # run by the garbage collector; what a notebook finaliser calls is still judged
                module = frame.f_globals.get("__name__") or ""
                if in_c and in_c[-1][0] is caller:  # called back by a C function of notebook code
                    if in_c[-1][1] is not print:
                        check(module, _qualname(frame.f_code), True, frame.f_code)
                else:
                    qualname = _qualname(frame.f_code)
                    check(module, qualname, False, frame.f_code)
                    if qualname in _TAKES_CALLBACKS and module.startswith("numpy"):
                        for value in frame.f_locals.values():  # the function numpy will call back
                            if callable(value) and not isinstance(value, type):
                                target = getattr(value, "__func__", value)
                                check(
                                    getattr(target, "__module__", None) or "", getattr(target, "__qualname__", ""), True
                                )
            elif event == "c_call":
                namespace = frame.f_globals
                kind = kinds.get(id(namespace))
                if kind is None:
                    kind = kind_of(namespace)
                if kind == 1:
                    in_c.append((frame, arg))
                    module = getattr(arg, "__module__", None)
                    if module is None:  # a method: it belongs to its object's type's module
                        module = getattr(type(getattr(arg, "__self__", None)), "__module__", None) or ""
                    check(module, getattr(arg, "__qualname__", ""))
            elif in_c and (event == "c_return" or event == "c_exception") and in_c[-1][0] is frame:
                in_c.pop()

        return hook


# Callables whose calls sys.setprofile reports: Python code ("call") and C functions and method descriptors
# ("c_call"). Anything else is called without an event: a ufunc (numpy.linalg._umath_linalg.inv, a
# scipy.special function, one that np.frompyfunc made), an f2py routine (scipy.linalg.lapack.dgesv).
_REPORTED_KINDS = (
    type,
    types.FunctionType,
    types.MethodType,
    types.BuiltinFunctionType,
    types.MethodDescriptorType,
    types.ClassMethodDescriptorType,
    types.WrapperDescriptorType,
    types.MethodWrapperType,
    functools.partial,
)
_MISSING = object()


def _unreported(value):
    """True for a callable that ``sys.setprofile`` cannot see called (a ufunc, an f2py routine).

    >>> _unreported(np.sqrt), _unreported(np.linalg.norm), _unreported(len)
    (True, False, False)
    """
    if not callable(value) or isinstance(value, _REPORTED_KINDS):
        return False
    # looked up statically: no __getattr__ of the notebook's own objects runs while the watch is not yet on
    if inspect.getattr_static(value, "_implementation", None) is not None:  # numpy's dispatchers run Python code
        return False
    return not isinstance(inspect.getattr_static(type(value), "__call__", None), types.FunctionType)  # np.vectorize


_CHAINS = {}  # code object -> the names it loads: (global, attribute, attribute, ...) tuples, and its nested code


def _chains(code):
    """The global names ``code`` loads, each with the attributes read from it straight after
    (``np.linalg._umath_linalg.inv`` → ``("np", "linalg", "_umath_linalg", "inv")``), and its nested code."""
    cached = _CHAINS.get(code)
    if cached is None:
        chains, chain = [], None
        for instruction in dis.get_instructions(code):
            if instruction.opname in ("LOAD_GLOBAL", "LOAD_NAME"):
                chain = [instruction.argval]
                chains.append(chain)
            elif instruction.opname in ("LOAD_ATTR", "LOAD_METHOD") and chain is not None:
                chain.append(instruction.argval)
            else:
                chain = None
        nested = tuple(const for const in code.co_consts if isinstance(const, types.CodeType))
        cached = _CHAINS[code] = (tuple(map(tuple, chains)), nested)
    return cached


_HOMES = {}  # id(callable) -> (callable, the modules that hold it under its name)
_HEAP_TYPE = 1 << 9  # Py_TPFLAGS_HEAPTYPE: the type was made by a class statement, not written in C


def _homes(value):
    """The names of the loaded modules that hold ``value`` under its own name."""
    cached = _HOMES.get(id(value))
    if cached is None or cached[0] is not value:
        # a class written in Python (the notebook's own, say) could run code to answer __name__: not looked at
        name = None if type(value).__flags__ & _HEAP_TYPE else getattr(value, "__name__", None)
        found = []
        if isinstance(name, str):
            for module_name, module in list(sys.modules.items()):
                if getattr(module, "__dict__", {}).get(name) is value:
                    found.append(module_name)
        cached = _HOMES[id(value)] = (value, tuple(found))
    return cached[1]


def _check_unreported(function, tracer, limit=64):
    """Note the callables outside the allowance that ``sys.setprofile`` would not see called, wherever the
    notebook code that ``function`` can reach names them.

    The profile hook sees every Python function and C function that notebook code calls, but no event
    marks the call of a ufunc or an f2py routine (``numpy.linalg._umath_linalg.inv``, the kernel under
    ``np.linalg.inv``). So these are judged where the code names them: a global or a closure's value, a
    default, an item of a list, tuple, set or dict held there, or an attribute chain read from a module
    (``np.linalg._umath_linalg.inv``, resolved from the modules' own dictionaries, so no code runs); a kernel
    fetched by a computed name is left to its stand-in (:func:`_put_stand_ins`). Reachable code is ``function``'s, its nested functions',
    and that of the notebook functions and classes it names, transitively (at most ``limit`` code
    objects). A name in a branch that never runs counts too: the answer names a tool it may not use.
    """
    namespace = tracer.main if tracer.main is not None else getattr(function, "__globals__", None)
    if not isinstance(namespace, dict):
        return
    start = getattr(inspect.unwrap(function), "__func__", function)
    queue, done = [start], set()

    def consider(value, module=None, attribute=None):
        if isinstance(value, types.FunctionType) and value.__globals__ is namespace:
            queue.append(value)
        elif isinstance(value, type) and getattr(value, "__module__", None) == namespace.get("__name__"):
            queue.extend(v for v in vars(value).values() if isinstance(v, types.FunctionType))
        elif isinstance(value, _Visible):  # a kernel's stand-in, named: judged as the kernel would be
            tracer._check(module or type(value).__module__, attribute or type(value).__name__)
        elif type(value) in (list, tuple, set, frozenset, dict):  # kernels stored where no name shows them
            for item in _contents(value):
                consider(item)
        elif _unreported(value):
            if module is not None:
                tracer._check(module, attribute)
                return
            known = _KERNELS["stand_ins"].get(id(value))
            if known is not None and known[0] is value:  # a kernel kept from before its modules got its stand-in
                tracer._check(type(known[1]).__module__, type(known[1]).__name__)
                return
            homes = _homes(value)
            cleared = [home for home in homes if tracer.allowed(home) and not (home + ".").startswith(tracer.prefixes)]
            if homes and not cleared:
                tracer._check(homes[0], value.__name__)

    while queue and len(done) < limit:
        function = queue.pop()
        code = getattr(function, "__code__", None)
        if code is None or code in done:
            continue
        for cell in function.__closure__ or ():
            try:
                consider(cell.cell_contents)
            except ValueError:  # an empty cell
                pass
        for value in list(function.__defaults__ or ()) + list((function.__kwdefaults__ or {}).values()):
            consider(value)
        codes = [code]
        while codes:
            code = codes.pop()
            if code in done:
                continue
            done.add(code)
            chains, nested = _chains(code)
            codes.extend(nested)
            for chain in chains:
                value = namespace.get(chain[0], _MISSING)
                if value is _MISSING:
                    continue  # a builtin: reported when called
                consider(value)
                for attribute in chain[1:]:
                    if not isinstance(value, types.ModuleType):
                        break
                    module, value = value.__name__, vars(value).get(attribute, _MISSING)
                    if value is _MISSING:
                        break
                    consider(value, module, attribute)


# --- kernels fetched by a computed name ---------------------------------------------------------------------
# A ufunc or an f2py routine that notebook code reaches by a computed name (``getattr(np.linalg, "_umath" +
# "_linalg").inv``, ``vars(scipy)["special"].cosm1``) is named nowhere in its code, so _check_unreported cannot
# judge it, and no profile event marks its call. So before a watched call runs, each such kernel that only
# modules the call may not use hold (outside the allowance, or forbidden) is replaced there by a _Visible
# stand-in: calling it runs a Python frame of that module's name, which the profile hook judges like any other
# call. The stand-ins stay (putting them back would cost a millisecond a call where scipy is loaded); library
# code that uses a kernel goes on working, since calls and attributes are passed on, and is free as always:
# its caller is not notebook code. Kernels stored before the call, where no name shows them, are looked for in
# containers (_contents).
_MODULE_DICT = types.ModuleType.__dict__["__dict__"]  # a module's namespace, read without running any code
_TYPE_NAME = type.__dict__["__name__"]  # a type's own name, read without running a metaclass's code
_KERNELS = {"modules": -1, "holders": {}, "done": set(), "stand_ins": {}}


def _is_kernel(value):
    """A ufunc or an f2py routine (checked by exact type: no code of ``value`` runs).

    >>> _is_kernel(np.sqrt), _is_kernel(np.linalg.norm), _is_kernel(len)
    (True, False, False)
    """
    kind = type(value)
    return kind is np.ufunc or (not kind.__flags__ & _HEAP_TYPE and _TYPE_NAME.__get__(kind, type) == "fortran")


def _kernel_holders():
    """``{id(kernel): (kernel, [(module namespace, module name, attribute), ...])}`` over the loaded modules,
    built again when a module has been loaded since (a few milliseconds)."""
    if _KERNELS["modules"] != len(sys.modules):
        holders = {}
        for name, module in list(sys.modules.items()):
            if not isinstance(name, str) or not isinstance(module, types.ModuleType):
                continue
            namespace = _MODULE_DICT.__get__(module)
            for attribute, value in list(namespace.items()) if isinstance(namespace, dict) else ():
                if isinstance(attribute, str) and _is_kernel(value):
                    holders.setdefault(id(value), (value, []))[1].append((namespace, name, attribute))
        _KERNELS.update(modules=len(sys.modules), holders=holders, done=set())
    return _KERNELS["holders"]


class _Visible:
    """A kernel's stand-in: a Python callable, so that its calls make a profile event. Each kernel gets a
    subclass whose ``__call__`` is a frame of the kernel's module and name."""

    __slots__ = ("_kernel",)

    def __getattr__(self, name):
        return getattr(object.__getattribute__(self, "_kernel"), name)

    def __setattr__(self, name, value):  # scipy labels its LAPACK routines (func.dtype = ...)
        setattr(object.__getattribute__(self, "_kernel"), name, value)

    def __delattr__(self, name):
        delattr(object.__getattribute__(self, "_kernel"), name)

    def __repr__(self):
        return repr(object.__getattribute__(self, "_kernel"))


def _stand_in(kernel, module_name, attribute):
    """The :class:`_Visible` stand-in of ``kernel``, made once per kernel."""
    cached = _KERNELS["stand_ins"].get(id(kernel))
    if cached is None or cached[0] is not kernel:

        def call(self, *args, **kwargs):
            return kernel(*args, **kwargs)

        names = {"co_name": attribute}
        if hasattr(call.__code__, "co_qualname"):  # Python 3.11+
            names["co_qualname"] = attribute
        namespace = {"__name__": module_name, "__builtins__": builtins}  # the frame's module, as the hook reads it
        call = types.FunctionType(call.__code__.replace(**names), namespace, attribute, None, call.__closure__)
        kind = type(attribute, (_Visible,), {"__slots__": (), "__call__": call, "__module__": module_name})
        stand_in = object.__new__(kind)
        object.__setattr__(stand_in, "_kernel", kernel)
        cached = _KERNELS["stand_ins"][id(kernel)] = (kernel, stand_in)
    return cached[1]


def _put_stand_ins(tracer):
    """Put in place the stand-ins of the kernels that only modules ``tracer``'s call may not use hold (once per
    allowance and set of loaded modules)."""
    holders = _kernel_holders()
    key = (tracer.modules, tracer.prefixes, tracer.allowance is None)
    if key in _KERNELS["done"]:
        return
    for kernel, places in holders.values():
        shut = [
            place
            for place in places
            if not tracer.allowed(place[1]) or f"{place[1]}.{place[2]}.".startswith(tracer.prefixes)
        ]
        if shut and len(shut) == len(places):
            shown = min(shut, key=lambda place: (place[1].count("._"), len(place[1])))
            stand_in = _stand_in(kernel, shown[1], shown[2])
            for namespace, _, attribute in shut:
                if namespace.get(attribute) is kernel:
                    namespace[attribute] = stand_in
    _KERNELS["done"].add(key)


def _contents(value, depth=0):
    """The values inside plain containers (lists, tuples, sets, dicts' values; at most 2 levels, 256 items each),
    read by exact type so that no code of the notebook runs."""
    if depth >= 2 or type(value) not in (list, tuple, set, frozenset, dict):
        return []
    items = list(value.values() if type(value) is dict else value)[:256]
    found = []
    for item in items:
        found.append(item)
        found += _contents(item, depth + 1)
    return found


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
    # numpy's public functions are C dispatchers (numpy >= 1.25): their frames are the implementation's,
    # in the module the code lives in (numpy.linalg._linalg), whatever __module__ says
    target = getattr(target, "_implementation", target)
    module = getattr(target, "__globals__", {}).get("__name__") or getattr(target, "__module__", module_name)
    return f"{module}.{getattr(target, '__qualname__', attribute)}."


def _callable_codes(values, depth=0):
    """The code objects of the functions among ``values`` (inside lists, tuples and dicts too)."""
    codes = set()
    for value in values:
        if isinstance(value, (list, tuple)) and depth < 2:
            codes |= _callable_codes(value, depth + 1)
        elif isinstance(value, dict) and depth < 2:
            codes |= _callable_codes(value.values(), depth + 1)
        elif callable(value) and not isinstance(value, (type, np.ndarray)):
            while isinstance(value, functools.partial):
                value = value.func
            for target in (value, getattr(type(value), "__call__", None)):
                code = getattr(getattr(target, "__func__", target), "__code__", None)
                if code is not None:
                    codes.add(code)
    return codes


def _namespace_of(function):
    """The globals of the notebook code ``function`` is (``None`` when it is not a Python function)."""
    try:
        function = inspect.unwrap(function)
    except ValueError:
        return None
    namespace = getattr(getattr(function, "__func__", function), "__globals__", None)
    return namespace if isinstance(namespace, dict) and namespace.get("__name__") == "__main__" else None


class _ImportGuard:
    """``builtins.__import__`` while a call runs: an import made from notebook code of a module
    outside the allowance is noted (so the call's result is refused, with the line that names the
    import, rather than ending in an error that says nothing about the rule); every import goes on."""

    def __init__(self, tracer, original):
        self.tracer, self.original = tracer, original

    def __call__(self, name, globals=None, locals=None, fromlist=(), level=0):
        if level == 0 and globals is not None and self.tracer.is_main(globals):
            names = [f"{name}.{item}" for item in fromlist or () if item != "*"] or [name]
            if name and (
                not any(self.tracer.allowed(full) for full in [name] + names)
                or any((full + ".").startswith(self.tracer.prefixes) for full in [name] + names)
            ):
                self.tracer.note(f"import {name}")  # the call's result is refused; the import goes on
        return self.original(name, globals, locals, fromlist, level)


def watch_call(function, args=(), kwargs=None, forbidden=()):
    """Call ``function(*args, **kwargs)``; return ``(value, Watched)``.

    Parameters
    ----------
    function : callable
    args : tuple
    kwargs : dict, optional
    forbidden : sequence of str
        Modules (``"coursekit.lie"``) and functions (``"scipy.linalg.expm"``) that the exercise must
        not hand its work to, and ``"allowance:EXERCISE"`` (see :func:`coursekit.contracts.guard_for`):
        then only what :func:`coursekit.contracts.allowance_for` allows may be called or imported.
        Only calls made from notebook code (the ``__main__`` module) count, so a library that uses
        anything internally is fine; functions handed in as arguments are the caller's own.

    Exceptions raised by ``function`` propagate unchanged.
    """
    kwargs = dict(kwargs or {})
    before = [snapshot(v) for v in list(args) + list(kwargs.values())]
    seen = Watched()
    tracer = guard = None
    try:
        plain = inspect.unwrap(function)
    except ValueError:  # a cycle of __wrapped__
        plain = function
    elsewhere = getattr(getattr(plain, "__func__", plain), "__globals__", {}).get("__name__", "__main__")
    if forbidden and elsewhere == "__main__":  # a function that is not notebook code has nothing to watch
        allowance = None
        names = []
        for name in forbidden:
            if str(name).startswith("allowance:"):
                from .contracts import allowance_for

                allowance = allowance_for(*str(name).split(":")[1:])
            else:
                names.append(name)
        tracer = _Tracer(
            sorted({_resolve(name) for name in names}),
            allowance,
            _callable_codes(list(args) + list(kwargs.values())),
            _namespace_of(function),
        )
        if allowance is not None:
            guard = _ImportGuard(tracer, builtins.__import__)
            tracer.codes.add(_ImportGuard.__call__.__code__)
            builtins.__import__ = guard
        _check_unreported(function, tracer)
        _put_stand_ins(tracer)
        hook = tracer.make_hook()
        opening, closing = tracer.collection_callbacks()
        gc.callbacks.insert(0, opening)
        gc.callbacks.append(closing)
        sys.setprofile(hook)
        threading.setprofile(hook)
    try:
        value = function(*args, **kwargs)
    finally:
        if tracer is not None:
            seen.tampered = sys.getprofile() is not hook
            sys.setprofile(None)
            threading.setprofile(None)
            for callback in (opening, closing):
                if callback in gc.callbacks:
                    gc.callbacks.remove(callback)
            if guard is not None:
                seen.tampered = seen.tampered or builtins.__import__ is not guard
                builtins.__import__ = guard.original
            seen.used = list(tracer.used)
        seen.changed = changed_arguments(function, args, kwargs, before)
    return value, seen
