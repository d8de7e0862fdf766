"""Only plain data crosses from the sandbox: the decoder builds nothing else."""

import numpy as np
import pytest

from autograder.sandbox.child.wire import Probe, WireError, decode, dumps, encode, loads


@pytest.mark.parametrize(
    "value",
    [
        None,
        True,
        3,
        -2.5,
        "text",
        [1, [2.0, "x"]],
        (1.0, (2, 3)),
        {"closure": True, "n": 3},
        np.eye(3),
        np.arange(6, dtype=np.int32).reshape(2, 3),
        np.array([1 + 2j]),
        np.zeros((0, 3)),
        float("nan"),
        float("inf"),
        complex(1, -1),
        np.float64(2.5),
        np.bool_(True),
    ],
)
def test_round_trip(value):
    back = loads(dumps(value))
    if isinstance(value, np.ndarray):
        assert type(back) is np.ndarray and back.dtype == value.dtype and np.array_equal(back, value)
    elif isinstance(value, float) and value != value:
        assert back != back
    else:
        assert back == value and type(back) is type(value.item() if isinstance(value, np.generic) else value)


def test_probe_round_trip_and_call():
    probe = loads(dumps(Probe("rotate_point_by", np.array([1.0, 0.0, 0.0]))))
    assert isinstance(probe, Probe) and probe.name == "rotate_point_by"
    assert np.allclose(probe(np.eye(3)), [1.0, 0.0, 0.0])


class Liar:
    def __eq__(self, other):
        return True


@pytest.mark.parametrize(
    "value", [Liar(), {1: "int key"}, np.array(["a"], dtype=object), {"a": Liar()}, type("MyList", (list,), {})([1])]
)
def test_encode_refuses_objects(value):
    with pytest.raises(WireError):
        encode(value)


@pytest.mark.parametrize(
    "data",
    [
        {"__reduce__": "os.system"},
        {"__ndarray__": "AAAA", "dtype": "|O", "shape": [1]},
        {"__ndarray__": "AAAA", "dtype": "<f8", "shape": [5]},
        {"__ndarray__": "not base64!", "dtype": "<f8", "shape": [1]},
        {"__ndarray__": "", "dtype": "<f8", "shape": [-1]},
        {"__tuple__": "abc"},
        {"__dict__": [[1, 2]]},
        {"__float__": "1e400"},
        {"unexpected": 1},
    ],
)
def test_decode_refuses_anything_else(data):
    with pytest.raises(WireError):
        decode(data)


def test_loads_refuses_bare_nan_and_garbage():
    for text in ["NaN", "[1, Infinity]", "{not json", "x" * 10]:
        with pytest.raises(WireError):
            loads(text)


def test_decoded_arrays_are_independent_copies():
    text = dumps(np.ones(3))
    a, b = loads(text), loads(text)
    a[0] = 5.0
    assert b[0] == 1.0 and a.flags.writeable


def test_a_read_only_array_arrives_read_only_and_a_writeable_one_writeable():
    """The hidden suite's read-only form reaches the student's function as it was sent: a write raises there."""
    frozen = np.arange(3.0)
    frozen.flags.writeable = False
    received = loads(dumps({"frozen": frozen, "free": np.arange(3.0)}))
    assert not received["frozen"].flags.writeable and received["free"].flags.writeable
    assert np.array_equal(received["frozen"], frozen)
    with pytest.raises(ValueError, match="read-only"):
        received["frozen"][0] = 1.0


def test_the_read_only_flag_is_strict():
    data = encode(np.ones(2))
    data["read_only"] = "yes"
    with pytest.raises(WireError):
        decode(data)
