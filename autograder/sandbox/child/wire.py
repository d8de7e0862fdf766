"""Plain-data messages between the grader and the sandbox: JSON lines, no pickle.

This file is copied into every sandbox, so it imports only the standard
library and numpy. The grader decodes everything that comes out of a sandbox
with :func:`decode`, which builds nothing but ``None``, ``bool``, ``int``,
``float``, ``complex``, ``str``, ``list``, ``tuple``, ``dict`` (string keys),
plain ``numpy.ndarray`` of a numeric dtype (read-only when the sender's was), :class:`Probe` and :class:`Callback`. Whatever a
student's object does in its ``__eq__`` or ``__array__`` stays in the sandbox.

Examples
--------
>>> import numpy as np
>>> text = dumps({"R": np.eye(2), "angle": (0.5, float("nan"))})
>>> value = loads(text)
>>> value["R"].shape, type(value["angle"])
((2, 2), <class 'tuple'>)
"""

from __future__ import annotations

import base64
import json
import math

import numpy as np

ALLOWED_DTYPES = frozenset(
    ["|b1", "|i1", "<i2", "<i4", "<i8", "|u1", "<u2", "<u4", "<u8", "<f2", "<f4", "<f8", "<c8", "<c16"]
)
MAX_ELEMENTS = 5_000_000
MAX_DEPTH = 32
MAX_LINE_BYTES = 64 * 1024 * 1024
MAX_NODES = 200_000


class WireError(ValueError):
    """A message that is not plain data of the kinds listed in the module docstring."""


class Probe:
    """A callable argument, sent by name and rebuilt from :mod:`probes` on each side.

    Examples
    --------
    >>> Probe("matmul")
    Probe('matmul')
    """

    def __init__(self, name, *args):
        self.name = name
        self.args = args

    def __repr__(self):
        inner = ", ".join([repr(self.name)] + [repr(a) for a in self.args])
        return f"Probe({inner})"

    def __call__(self, *args, **kwargs):
        return _resolve_probe(self)(*args, **kwargs)


class Callback:
    """A callable argument that stays with its sender: the receiver may call it, and each call is a
    round trip to the sender (the notebook stage passes its own functions this way). ``label`` is
    only for messages.

    Examples
    --------
    >>> Callback("matmul")
    Callback('matmul')
    """

    def __init__(self, label=""):
        self.label = str(label)[:80]

    def __repr__(self):
        return f"Callback({self.label!r})"


def _resolve_probe(probe):
    try:
        from . import probes  # inside the grader: autograder.sandbox.child.probes
    except ImportError:
        import probes  # inside the sandbox: a plain module next to this file
    return probes.resolve(probe.name, probe.args)


def _encode_float(x):
    if math.isfinite(x):
        return x
    return {"__float__": "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")}


def encode(value: object, depth: int = 0, budget: list[int] | None = None) -> object:
    """Turn ``value`` into JSON-ready data, or raise :class:`WireError`.

    At most :data:`MAX_NODES` items of lists, tuples and dicts in all, counted before they are walked,
    so six million empty lists are refused at once rather than encoded for seconds.
    """
    if depth > MAX_DEPTH:
        raise WireError("nested too deeply")
    if budget is None:
        budget = [MAX_NODES]
    if type(value) in (list, tuple, dict):
        budget[0] -= len(value)
        if budget[0] < 0:
            raise WireError(f"more than {MAX_NODES} items in lists, tuples and dicts")
    kind = type(value)
    if value is None or kind is bool or kind is str:
        return value
    if kind is int:
        return value
    if kind is float:
        return _encode_float(value)
    if kind is complex:
        return {"__complex__": [_encode_float(value.real), _encode_float(value.imag)]}
    if isinstance(value, np.generic) and value.dtype.kind in "biufc":
        return encode(value.item(), depth + 1, budget)
    if isinstance(value, np.ndarray):
        array = np.ascontiguousarray(np.asarray(value).view(np.ndarray))
        if array.dtype.kind not in "biufc":
            raise WireError(f"an array of dtype {array.dtype} (only numbers can be graded)")
        array = array.astype(array.dtype.newbyteorder("<"), copy=False)
        if array.size > MAX_ELEMENTS:
            raise WireError(f"an array of {array.size} elements (limit {MAX_ELEMENTS})")
        data = {
            "__ndarray__": base64.b64encode(array.tobytes()).decode("ascii"),
            "dtype": array.dtype.str,
            "shape": list(array.shape),
        }
        if not value.flags.writeable:
            data["read_only"] = True  # the other side sees it read-only too: a write fails there as it would here
        return data
    if kind is list:
        return [encode(v, depth + 1, budget) for v in value]
    if kind is tuple:
        return {"__tuple__": [encode(v, depth + 1, budget) for v in value]}
    if kind is dict:
        items = []
        for key, item in value.items():
            if type(key) is not str:
                raise WireError(f"a dict with a {type(key).__name__} key (only str keys)")
            items.append([key, encode(item, depth + 1, budget)])
        return {"__dict__": items}
    if kind is Probe:
        return {"__probe__": value.name, "args": [encode(a, depth + 1, budget) for a in value.args]}
    if kind is Callback:
        return {"__callback__": value.label}
    raise WireError(f"a {kind.__name__} object")


def _decode_float(x):
    if isinstance(x, dict) and set(x) == {"__float__"} and x["__float__"] in ("nan", "inf", "-inf"):
        return float(x["__float__"])
    if type(x) in (int, float):
        return float(x)
    raise WireError("bad float")


def decode(data: object, depth: int = 0) -> object:
    """Rebuild plain values from JSON data made by :func:`encode`; strict."""
    if depth > MAX_DEPTH:
        raise WireError("nested too deeply")
    kind = type(data)
    if data is None or kind in (bool, int, float, str):
        return data
    if kind is list:
        return [decode(v, depth + 1) for v in data]
    if kind is not dict or len(data) == 0:
        raise WireError(f"unexpected {kind.__name__}")
    keys = set(data)
    if keys == {"__float__"}:
        return _decode_float(data)
    if keys == {"__complex__"}:
        pair = data["__complex__"]
        if type(pair) is not list or len(pair) != 2:
            raise WireError("bad complex")
        return complex(_decode_float(pair[0]), _decode_float(pair[1]))
    if keys == {"__tuple__"}:
        if type(data["__tuple__"]) is not list:
            raise WireError("bad tuple")
        return tuple(decode(v, depth + 1) for v in data["__tuple__"])
    if keys == {"__dict__"}:
        result = {}
        for pair in data["__dict__"]:
            if type(pair) is not list or len(pair) != 2 or type(pair[0]) is not str:
                raise WireError("bad dict item")
            result[pair[0]] = decode(pair[1], depth + 1)
        return result
    if keys == {"__ndarray__", "dtype", "shape"}:
        return _decode_array(data)
    if keys == {"__ndarray__", "dtype", "shape", "read_only"}:
        if data["read_only"] is not True:
            raise WireError("bad read_only flag")
        array = _decode_array(data)
        array.flags.writeable = False
        return array
    if keys == {"__callback__"}:
        if type(data["__callback__"]) is not str:
            raise WireError("bad callback")
        return Callback(data["__callback__"])
    if keys == {"__probe__", "args"}:
        if type(data["__probe__"]) is not str or type(data["args"]) is not list:
            raise WireError("bad probe")
        return Probe(data["__probe__"], *[decode(a, depth + 1) for a in data["args"]])
    raise WireError(f"unexpected object with keys {sorted(keys)[:4]}")


def _decode_array(data):
    dtype, shape, payload = data["dtype"], data["shape"], data["__ndarray__"]
    if type(dtype) is not str or dtype not in ALLOWED_DTYPES:
        raise WireError(f"array dtype {dtype!r} is not allowed")
    if type(shape) is not list or len(shape) > 8 or not all(type(n) is int and 0 <= n for n in shape):
        raise WireError("bad array shape")
    count = math.prod(shape)
    if count > MAX_ELEMENTS:
        raise WireError("array too large")
    if type(payload) is not str:
        raise WireError("bad array data")
    try:
        raw = base64.b64decode(payload, validate=True)
    except ValueError:
        raise WireError("bad array data") from None
    dt = np.dtype(dtype)
    if len(raw) != count * dt.itemsize:
        raise WireError("array data does not match its shape")
    return np.frombuffer(raw, dtype=dt).reshape(shape).copy()


def dumps(value: object) -> str:
    """One message line (no trailing newline)."""
    return json.dumps(encode(value), allow_nan=False, separators=(",", ":"))


def loads(text: str, max_bytes: int = MAX_LINE_BYTES) -> object:
    """Decode one message line; raises :class:`WireError` on anything but plain data.

    Its size and its number of JSON values (at most :data:`MAX_NODES`, counted from its brackets and
    commas before anything is parsed) are bounded, so no line can make the decoder build more than a
    few tens of MB, however it is nested.
    """
    if len(text) > max_bytes:
        raise WireError("message too large")
    if text.count("[") + text.count("{") + text.count(",") > MAX_NODES:
        raise WireError(f"message with more than {MAX_NODES} values")
    try:
        data = json.loads(text, parse_constant=_reject_constant)
    except (ValueError, RecursionError) as error:
        raise WireError(f"not JSON: {error}") from None
    return decode(data)


def _reject_constant(name):
    raise WireError(f"bare {name} in JSON")
