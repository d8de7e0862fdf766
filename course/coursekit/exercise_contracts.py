"""Every exercise's contract, as its docstring states it, and the check that an answer keeps it.

``exercise_contracts.json`` (next to this module) holds, for each exercise, what its docstring
promises: each parameter's kind and shape, each return's exact type, dtype and shape. It is written
from the masters by ``python -m autograder contracts``.

:func:`contract_problem` calls an answer with the forms of input the course's conventions admit
(float arrays, nested lists, tuples, integer arrays, read-only arrays) on small integer-valued
samples (a quarter turn, ``[1, 2, 3]``, a half-turn quaternion) and says what, if anything, breaks
the contract: a list or a float32 array returned, an int64 array for integer input, an error on
tuples, a write into an argument, a result that depends on the form of the input. The check cells
show it as one line, and the hidden suite grades the same calls.

A ``bool`` return may be a Python ``bool`` or a ``numpy.bool_``; a ``float`` return a Python
``float`` or a numpy float scalar; an ``ndarray`` return is a float64 array.
"""

import json
from pathlib import Path

import numpy as np

__all__ = ["contract_of", "contract_problem", "covered", "sample_arguments", "FORMS"]

DESCRIPTION = "keeps its docstring's contract (lists, tuples, integer and read-only input; return type, dtype, shape)"
FORMS = ("float arrays", "nested lists", "tuples", "integer arrays", "read-only arrays")
NOT_COVERED_KINDS = ("callable", "element", "list")  # such exercises are not called with other forms

_RZ = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]  # quarter turns about z, x and y: integer-valued rotations
_RX = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
_RY = [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]
_ROTATIONS = (_RZ, _RX, _RY)
_QUATS = ([0, 0, 0, 1], [0, 1, 0, 0], [1, 0, 0, 0])  # w, x, y, z: half turns about z and x, the identity
_VECTORS = ([1, 2, 3], [0, 1, 0], [1, 0, 0])
_POINTS = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 2, 3]]
_COVARIANCES = ("Sigma", "Sigma_left", "Rn", "S1", "S2")  # (n, n) names that are covariances, not rotations


def _pose(R, t):
    T = np.eye(4, dtype=int)
    T[:3, :3], T[:3, 3] = R, t
    return T


def _hat(w):
    x, y, z = w
    return [[0, -z, y], [z, 0, -x], [-y, x, 0]]


# Per-exercise samples where the name conventions do not give a valid (or interesting) one.
OVERRIDES = {
    "body_angular_velocity": {"R_dot": (np.array(_RZ) @ np.array(_hat([1, 2, 3]))).tolist()},
    "quat_from_axis_angle": {"u": [0, 0, 1]},
    "align_svd": {"Q": (np.array(_POINTS) @ np.array(_RZ).T).tolist()},
    "align_gauss_newton": {"Q": (np.array(_POINTS) @ np.array(_RZ).T).tolist()},
    "align_pose_gauss_newton": {"Q": (np.array(_POINTS) @ np.array(_RZ).T + [1, 2, 3]).tolist()},
    "align_pose_robust": {"Q": (np.array(_POINTS) @ np.array(_RZ).T + [1, 2, 3]).tolist()},
    "attitude_nees": {"P": np.diag([1, 2, 3]).tolist()},
    "filter_predict": {"P": np.diag([1, 2, 3]).tolist(), "Q": np.eye(3, dtype=int).tolist()},
    "filter_update": {"P": np.diag([1, 2, 3]).tolist(), "y": [0, 0, 1], "g_w": [0, 0, 1]},
    "rotated_point_covariance": {"Sigma": np.diag([1, 2, 3]).tolist()},
}
SCALARS = {
    "theta": 0.7,
    "a": 0.7,
    "yaw": 0.3,
    "pitch": 0.2,
    "roll": 0.1,
    "t": 0.3,
    "dt": 0.1,
    "k": 1.0,
    "n_terms": 20,
    "iters": 10,
    "tol": 1e-9,
}

# An ndarray means a float64 ndarray and a tuple a tuple, nothing else (issue 43: the right numbers as the wrong
# type are a wrong answer). True would accept nested lists of the promised shape for arrays and tuples.
LISTS_FOR_ARRAYS = False

_CONTRACTS = None


def _contracts():
    global _CONTRACTS
    if _CONTRACTS is None:
        path = Path(__file__).with_name("exercise_contracts.json")
        _CONTRACTS = json.loads(path.read_text(encoding="utf-8"))["exercises"] if path.exists() else {}
    return _CONTRACTS


def contract_of(exercise):
    """The contract of ``exercise`` (a dict: ``params``, ``returns``), or None."""
    return _contracts().get(exercise)


def _array_sample(name, shape, counters):
    """An integer-valued valid sample for a parameter named ``name`` of ``shape`` (a list), or None."""
    dims = tuple(d if isinstance(d, int) else None for d in shape)

    def nth(kind, options):
        i = counters.get(kind, 0)
        counters[kind] = i + 1
        return options[i % len(options)]

    if dims in ((3, 3), (None, None)):
        if name in _COVARIANCES:
            return np.diag([1, 2, 3]).tolist()
        if name in ("W", "A", "B"):
            return _hat(nth("vector", _VECTORS))
        return nth("rotation", _ROTATIONS)
    if dims == (4, 4):
        return _pose(nth("rotation", _ROTATIONS), [1, 2, 3]).tolist()
    if dims == (6, 6):
        return np.diag([1, 2, 3, 4, 5, 6]).tolist()
    if dims == (4,):
        return [1, 2, 3, 1] if name == "P_h" else nth("quaternion", _QUATS)
    if dims == (3,):
        return nth("vector", _VECTORS)
    if dims == (6,):
        return [1, 2, 3, 0, 0, 1]
    if dims == (None, 3):
        return _POINTS
    if dims == (None, 4):
        return [list(q) for q in _QUATS]
    if dims == (None, 3, 3):
        return [list(R) for R in _ROTATIONS]
    if dims == (None,):
        return [1, 2, 3]
    return None


def sample_arguments(exercise):
    """``(arguments, why_not)``: integer-valued sample arguments (lists) of ``exercise``, or None and the reason."""
    contract = contract_of(exercise)
    if contract is None:
        return None, "no contract"
    arguments, counters = [], {}
    for param in contract["params"]:
        name, kind = param["name"], param["kind"]
        if kind in NOT_COVERED_KINDS:
            return None, f"parameter {name} is a {kind}"
        if "default" in param:
            break  # optional parameters keep their defaults
        if kind == "array_like":
            if not param["shapes"]:
                return None, f"the docstring gives no shape for {name}"
            value = OVERRIDES.get(exercise, {}).get(name) or _array_sample(name, param["shapes"][0], counters)
            if value is None:
                return None, f"no sample for {name} of shape {param['shapes'][0]}"
            arguments.append(value)
        elif name in SCALARS:
            arguments.append(SCALARS[name] if kind == "float" else int(SCALARS[name]))
        else:
            return None, f"no sample for the {kind} {name}"
    return arguments, ""  # scalars only (rot_x(a)): the forms are all the same call, the return's type still counts


def covered(exercise):
    return sample_arguments(exercise)[0] is not None


def _tuples(value):
    return tuple(_tuples(v) for v in value) if isinstance(value, list) else value


def _read_only(value):
    array = np.array(value, dtype=float)
    array.setflags(write=False)
    return array


def _form(value, form):
    """``value`` (an integer-valued sample, as nested lists, or a scalar) in the input ``form``."""
    if not isinstance(value, list):
        return value
    return {
        "float arrays": lambda v: np.array(v, dtype=float),
        "nested lists": lambda v: np.array(v, dtype=float).tolist(),
        "tuples": lambda v: _tuples(np.array(v, dtype=float).tolist()),
        "integer arrays": lambda v: np.array(v, dtype=np.int64),
        "read-only arrays": _read_only,
    }[form](value)


def _type_name(value):
    if isinstance(value, np.ndarray):
        return f"{'an' if str(value.dtype)[0] in 'aeiou' else 'a'} {value.dtype} array of shape {value.shape}"
    module = type(value).__module__
    name = f"{'' if module == 'builtins' else module + '.'}{type(value).__name__}"
    return f"{'an' if name[0] in 'aeiou' else 'a'} {name}"


def _shape_promised(item, arguments, params):
    """The shape (tuple) the return ``item`` promises for these ``arguments``, or None (any)."""
    names = [p["name"] for p in params]
    if "shape_like" in item:
        return np.shape(arguments[names.index(item["shape_like"])])
    shapes = item["shapes"]
    choice = 0
    if len(shapes) > 1:  # follows the parameter with alternatives: the same alternative
        for param, arg in zip(params, arguments):
            if param["kind"] == "array_like" and param["shapes"] and len(param["shapes"]) == len(shapes):
                choice = next((i for i, s in enumerate(param["shapes"]) if len(s) == np.ndim(arg)), 0)
                break
    sizes = {}  # the letters of the parameters' shapes ("n", "N"), read off the arguments
    for param, arg in zip(params, arguments):
        for alternative in (param.get("shapes") or []) if param["kind"] == "array_like" else []:
            if len(alternative) == np.ndim(arg):
                for d, size in zip(alternative, np.shape(arg)):
                    if not isinstance(d, int):
                        sizes.setdefault(d, size)
    shape = [d if isinstance(d, int) else sizes.get(d) for d in shapes[choice]]
    return None if None in shape else tuple(shape)


def _type_problem(value, item, arguments, params, where):
    """What is wrong with ``value`` as the return ``item``; "" when it keeps the contract."""
    kind = item["type"]
    if kind == "ndarray":
        if isinstance(value, (list, tuple)) and LISTS_FOR_ARRAYS:
            try:  # nested lists of the right numbers, accepted as the array they spell
                value = np.array(value)
            except ValueError:
                return f"{where} returned a ragged {type(value).__name__}; the contract promises an array", "type"
            if value.dtype.kind not in "fiu":
                return f"{where} returned a list of {value.dtype}; the contract promises numbers", "type"
            value = value.astype(float)  # a list has no dtype: its numbers are what they are
        if not isinstance(value, np.ndarray):
            return f"{where} returned {_type_name(value)}; the contract promises a float64 numpy array", "type"
        if value.dtype != np.float64:
            return f"{where} returned {_type_name(value)}; the contract promises float64", "dtype"
        shape = _shape_promised(item, arguments, params)
        if shape is not None and value.shape != shape:
            return f"{where} returned an array of shape {value.shape}; the contract promises {shape}", "shape"
        return "", ""
    if kind == "float":
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (float, np.floating)):
            return f"{where} returned {_type_name(value)}; the contract promises a float", "type"
        return "", ""
    if kind == "int":
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            return f"{where} returned {_type_name(value)}; the contract promises an int", "type"
        return "", ""
    if kind == "bool":
        if not isinstance(value, (bool, np.bool_)):
            return f"{where} returned {_type_name(value)}; the contract promises a bool (True or False)", "type"
        return "", ""
    if kind == "dict":
        return (
            ("", "")
            if isinstance(value, dict)
            else (f"{where} returned {_type_name(value)}; the contract promises a dict", "type")
        )
    if kind == "tuple":
        items = item["items"]
        containers = (tuple, list) if LISTS_FOR_ARRAYS else tuple
        if not isinstance(value, containers) or len(value) != len(items):
            size = f" of {len(value)}" if isinstance(value, (tuple, list)) else ""
            return (
                f"{where} returned {_type_name(value)}{size}; the contract promises a tuple of {len(items)}",
                "type",
            )
        for i, (part, sub) in enumerate(zip(value, items)):
            label = sub.get("name") or f"item {i}"
            problem, what = _type_problem(part, sub, arguments, params, f"{where} (its {label})")
            if problem:
                return problem, what
        return "", ""
    return "", ""


def _same(value, baseline):
    try:
        if isinstance(baseline, (tuple, list)) and isinstance(value, (tuple, list)):  # item by item (ragged too)
            return len(value) == len(baseline) and all(_same(v, b) for v, b in zip(value, baseline))
        if isinstance(baseline, dict):
            return value == baseline
        a, b = np.asarray(value, dtype=float), np.asarray(baseline, dtype=float)
        return a.shape == b.shape and np.allclose(a, b, rtol=1e-9, atol=1e-9, equal_nan=True)
    except (TypeError, ValueError):
        return False


HINTS = {
    "type": "return the type the docstring promises: a numpy array, a float or a bool, or a tuple of them; a list is "
    "not an array (wrap the result: np.array(result, dtype=float))",
    "dtype": "with integer input the result must still be float64: convert each input once, "
    "x = np.array(x, dtype=float), and compute on that",
    "dtype32": "keep the result in float64, numpy's default: no dtype=np.float32 and no .astype(np.float32)",
    "shape": "keep the shape the docstring promises (no extra axis, no flattening)",
    "raised": "the conventions admit nested lists, tuples and integer arrays as input: convert each input once, "
    "x = np.array(x, dtype=float), and compute on that",
    "read-only": "never write into an argument you were given: make your own array (np.array(x, dtype=float) copies) "
    "and change that",
    "differs": "the result must not depend on the form of the input: convert each input once, "
    "x = np.array(x, dtype=float), and compute on that",
}


def contract_problem(exercise, function, forms=FORMS, reraise=()):
    """``(reason, hint)`` for the first way ``function`` breaks ``exercise``'s contract, or None when it keeps it
    (or the exercise is not covered: see :func:`sample_arguments`).

    ``function`` is called once per form of input in ``forms`` (the first is the baseline; the others must give
    the same result, up to 1e-9). A ``NotImplementedError`` from it propagates, and so does an error of the
    types in ``reraise`` raised by the baseline call (the hidden suite's "not written", "timeout", ...).
    """
    arguments, _ = sample_arguments(exercise)
    if arguments is None:
        return None
    contract = contract_of(exercise)
    params, returns = contract["params"], contract["returns"]
    baseline = None
    for form in forms:
        args = [_form(a, form) for a in arguments]
        where = f"with {form} as input, {exercise}" if form != "float arrays" else exercise
        try:
            value = function(*args)
        except NotImplementedError:
            raise
        except reraise as error:
            if baseline is None:
                raise
            return f"{where} failed: {str(error)[:100]}", HINTS["raised"]
        except Exception as error:
            if form == "read-only arrays":
                if isinstance(error, ValueError) and "is read-only" in str(error) and "buffer" not in str(error):
                    return f"{exercise} writes into an argument (read-only input raised: {error})", HINTS["read-only"]
                continue  # another error: a library that refuses read-only buffers (scipy's Rotation), not a write
            return f"{where} raised {type(error).__name__}: {str(error)[:80]}", HINTS["raised"]
        problem, what = _type_problem(value, returns, args, params, where)
        if problem:
            if what == "dtype" and ("float32" in problem or "float16" in problem):
                what = "dtype32"
            return problem, HINTS[what]
        if baseline is None:
            baseline = value
        elif not _same(value, baseline):
            return f"{where} returned another result than with float arrays", HINTS["differs"]
    return None
