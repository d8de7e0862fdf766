"""Every exercise's contract, as its docstring states it, and the check that an answer keeps it.

``exercise_contracts.json`` (next to this module) holds, for each exercise, what its docstring
promises: each parameter's kind and shape, each return's exact type, dtype and shape. It is written
from the masters by ``python -m autograder contracts``.

:func:`contract_problem` calls an answer with the forms of input the course's conventions admit
(float arrays, nested lists, tuples, integer arrays, read-only arrays) on small integer-valued
samples (a quarter turn, ``[1, 2, 3]``, a half-turn quaternion; where a rotation or a pose is a
parameter, the identity and half turns as well, the special values most answers treat apart) and says
what, if anything, breaks the contract: a list or a float32 array returned, an int64 array for integer input, an error on
tuples, a write into an argument, a result that depends on the form of the input. The check cells
show it as one line, and the hidden suite grades the same calls.

A ``bool`` return may be a Python ``bool`` or a ``numpy.bool_``; a ``float`` return a Python
``float`` or a numpy float scalar; an ``ndarray`` return is a float64 array.
"""

import json
from pathlib import Path

import numpy as np

__all__ = ["contract_of", "later_exercises", "contract_problem", "covered", "sample_arguments", "sample_sets", "FORMS", "REGIMES"]

DESCRIPTION = "keeps its docstring's contract (lists, tuples, integer and read-only input; return type, dtype, shape)"
FORMS = ("float arrays", "nested lists", "tuples", "integer arrays", "read-only arrays")
NOT_COVERED_KINDS = ("callable", "element", "list")  # such exercises are not called with other forms

_RZ = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]  # quarter turns about z, x and y: integer-valued rotations
_RX = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
_RY = [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]
_ROTATIONS = (_RZ, _RX, _RY)
_IDENTITY = ([[1, 0, 0], [0, 1, 0], [0, 0, 1]],)
_HALF_TURNS = ([[1, 0, 0], [0, -1, 0], [0, 0, -1]], [[-1, 0, 0], [0, 1, 0], [0, 0, -1]], [[-1, 0, 0], [0, -1, 0], [0, 0, 1]])
# Turns whose cosine is 0.6 and sine 0.8 (about 53°), about z, x and y: no special value at all (not integer-valued,
# so they are not sent as integer arrays).
_TURNS_345 = (
    [[0.6, -0.8, 0.0], [0.8, 0.6, 0.0], [0.0, 0.0, 1.0]],
    [[1.0, 0.0, 0.0], [0.0, 0.6, -0.8], [0.0, 0.8, 0.6]],
    [[0.6, 0.0, 0.8], [0.0, 1.0, 0.0], [-0.8, 0.0, 0.6]],
)
_QUATS = ([0, 0, 0, 1], [0, 1, 0, 0], [1, 0, 0, 0])  # w, x, y, z: half turns about z and x, the identity
_HALF = float(np.sqrt(0.5))
# The rotations (matrices and quaternions) each sample set draws from: quarter turns (the baseline), the special
# values of the angle that most answers treat apart (0 and π), the quarter turns about y and back first (pitch = ±90°,
# where z-y-x Euler angles lock) and a 53° turn with no special value (below 90°, where a branch on cos θ > 0 goes).
REGIMES = {
    "quarter turns": (_ROTATIONS, _QUATS),
    "the identity": (_IDENTITY, ([1, 0, 0, 0],)),
    "half turns": (_HALF_TURNS, ([0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1])),
    "a quarter turn about y first": ((_RY, _RZ, _RX), ([_HALF, 0.0, _HALF, 0.0], [_HALF, 0.0, -_HALF, 0.0])),
    "a quarter turn back about y first": (
        (np.array(_RY).T.tolist(), _RX, _RZ),
        ([_HALF, 0.0, -_HALF, 0.0], [_HALF, 0.0, _HALF, 0.0]),
    ),
    "a 53° turn": (_TURNS_345, ([float(np.sqrt(0.8)), 0.0, 0.0, float(np.sqrt(0.2))],)),
}
_VECTORS = ([1, 2, 3], [0, 1, 0], [1, 0, 0])
_POINTS = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 2, 3]]
_COVARIANCES = ("Sigma", "Sigma_left", "Rn", "S1", "S2")  # (n, n) names that are covariances, not rotations


def _pose(R, t):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, t
    return T


def _hat(w):
    x, y, z = w
    return [[0, -z, y], [z, 0, -x], [-y, x, 0]]


# Per-exercise samples where the name conventions do not give a valid (or interesting) one.
OVERRIDES = {
    "body_angular_velocity": {"R_dot": (np.array(_hat([1, 2, 3])) @ np.array(_RZ)).tolist()},  # dR/dt = [ω_w]× R
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


def later_exercises(exercise):
    """The exercises of ``exercise``'s lesson that come after it, in order (a tuple; empty when unknown).

    >>> later_exercises("right_jacobian_so3")[:2]
    ('right_jacobian_inv_so3', 'jacobian_point_to_body')
    """
    contracts = _contracts()
    if exercise not in contracts:
        return ()
    lesson = contracts[exercise]["lesson"]
    names = [name for name, contract in contracts.items() if contract["lesson"] == lesson]
    return tuple(names[names.index(exercise) + 1 :])


def _array_sample(name, shape, counters, regime="quarter turns"):
    """A valid sample for a parameter named ``name`` of ``shape`` (a list), or None; single rotations, poses
    and quaternions are drawn from ``REGIMES[regime]`` (stacks always from the quarter turns)."""
    rotations, quaternions = REGIMES[regime]
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
        return nth("rotation", rotations)
    if dims == (4, 4):
        return _pose(nth("rotation", rotations), [1, 2, 3]).tolist()
    if dims == (6, 6):
        return np.diag([1, 2, 3, 4, 5, 6]).tolist()
    if dims == (4,):
        return [1, 2, 3, 1] if name == "P_h" else nth("quaternion", quaternions)
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


def sample_arguments(exercise, regime="quarter turns"):
    """``(arguments, why_not)``: sample arguments (lists) of ``exercise``, its rotations drawn from
    ``REGIMES[regime]`` (integer-valued but for the 53° turn), or None and the reason."""
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
            value = OVERRIDES.get(exercise, {}).get(name) or _array_sample(
                name, param["shapes"][0], counters, regime
            )
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


# Per-exercise sample sets at the special values of a data parameter (not a rotation): {exercise: {regime: {name: value}}}
SPECIAL_SETS = {
    "quat_from_two_vectors": {
        "parallel vectors": {"a": [1, 2, 3], "b": [2, 4, 6]},
        "opposite vectors": {"a": [1, 2, 3], "b": [-1, -2, -3]},
    },
}


def sample_sets(exercise):
    """``[(regime, arguments), ...]``: the baseline's samples, then one set per other regime of :data:`REGIMES` that
    changes them (an exercise with a single rotation or pose among its parameters and no per-exercise sample).

    Examples
    --------
    >>> [regime for regime, _ in sample_sets("log_so3")][:3]
    ['quarter turns', 'the identity', 'half turns']
    >>> [regime for regime, _ in sample_sets("hat")]
    ['quarter turns']
    >>> [regime for regime, _ in sample_sets("quat_from_two_vectors")]
    ['quarter turns', 'parallel vectors', 'opposite vectors']
    """
    baseline, _ = sample_arguments(exercise)
    if baseline is None:
        return []
    sets = [("quarter turns", baseline)]
    if exercise not in OVERRIDES:
        for regime in list(REGIMES)[1:]:
            arguments, _ = sample_arguments(exercise, regime)
            if arguments != baseline:
                sets.append((regime, arguments))
    names = [p["name"] for p in contract_of(exercise)["params"]]
    for regime, values in SPECIAL_SETS.get(exercise, {}).items():
        arguments = list(baseline)
        for name, value in values.items():
            arguments[names.index(name)] = value
        sets.append((regime, arguments))
    return sets


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
    "special": "the docstring admits this input (the identity, a half turn, a pitch of ±90°, parallel or opposite "
    "vectors): follow what your answer does there, and keep it defined and of the promised type",
    "differs": "the result must not depend on the form of the input: convert each input once, "
    "x = np.array(x, dtype=float), and compute on that",
}


def _is_a_write(error):
    """Did a call with read-only arrays fail because the function wrote into one? numpy says "assignment destination
    is read-only" or "output array is read-only"; a library that merely refuses read-only buffers (scipy's Rotation:
    "buffer source array is read-only") wrote nothing. Through the sandbox the error arrives as the grader's
    StudentError, whose text names the student's exception ("... raised ValueError: ...")."""
    text = f"{type(error).__name__}: {error}"
    return "ValueError" in text and "is read-only" in text and "buffer" not in text


def contract_problem(exercise, function, forms=FORMS, reraise=()):
    """``(reason, hint)`` for the first way ``function`` breaks ``exercise``'s contract, or None when it keeps it
    (or the exercise is not covered: see :func:`sample_arguments`).

    ``function`` is called on each set of :func:`sample_sets` (quarter turns, then the identity and half turns
    where a rotation is a parameter), once per form of input in ``forms`` (the first is the baseline; the others
    must give the same result, up to 1e-9). A ``NotImplementedError`` from it propagates, and so does an error of
    the types in ``reraise`` raised by the first baseline call (the hidden suite's "not written", "timeout", ...).
    """
    sets = sample_sets(exercise)
    if not sets:
        return None
    for regime, arguments in sets:
        problem = _problem_with(exercise, function, arguments, regime, forms, reraise)
        if problem is not None:
            return problem
    return None


def _problem_with(exercise, function, arguments, regime, forms, reraise):
    contract = contract_of(exercise)
    params, returns = contract["params"], contract["returns"]
    baseline = None
    at = "" if regime == "quarter turns" else f" at {regime}"
    integer_valued = all(np.array_equal(np.round(a), a) for a in arguments if isinstance(a, list))
    for form in forms:
        if form == "integer arrays" and not integer_valued:
            continue  # a 53° turn has no integer form
        args = [_form(a, form) for a in arguments]
        where = f"with {form} as input{at}, {exercise}" if form != "float arrays" else f"{exercise}{at}"
        try:
            value = function(*args)
        except NotImplementedError:
            raise
        except reraise as error:
            if baseline is None and regime == "quarter turns":
                raise
            if baseline is None:
                return f"{where} failed: {str(error)[:100]}", HINTS["special"]
            if form == "read-only arrays":
                if _is_a_write(error):
                    return f"{exercise} writes into an argument (read-only input: {str(error)[:80]})", HINTS["read-only"]
                continue
            return f"{where} failed: {str(error)[:100]}", HINTS["raised"]
        except Exception as error:
            if form == "read-only arrays":
                if _is_a_write(error):
                    return f"{exercise} writes into an argument (read-only input raised: {error})", HINTS["read-only"]
                continue
            hint = HINTS["special"] if baseline is None and regime != "quarter turns" else HINTS["raised"]
            return f"{where} raised {type(error).__name__}: {str(error)[:80]}", hint
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
