"""The feeder stands between the grader and the student's process (autograder/sandbox/child/feeder.py).

Oracles, each with a cold sandbox and with a worker forked from a warm slot:

- a batch's later calls are nowhere in the student's process while an earlier one runs: its memory
  (every string and bytes object) and its socket hold the call it is running and nothing ahead;
- a reply line far over the limit, written straight into the socket, costs that call ("longer than")
  and the grader's memory grows by less than 64 MiB; so does an answer of six million lists;
- ``/sandbox/probes.py`` is empty for student code, and a probe passed as an argument still works;
- the feeder is PID 1 of the student's namespaces: killing it from inside changes nothing.
"""

import resource

import numpy as np
import pytest

from autograder.grading.transcripts import call_text
from autograder.sandbox import launcher, warm
from autograder.sandbox.child.wire import Probe
from autograder.sandbox.session import LessonProgram, StudentError, StudentSandbox
from support import THIS_COURSE

pytestmark = pytest.mark.skipif(
    launcher.isolation()[0] != "namespaces", reason=f"the feeder lives in namespaces ({launcher.isolation()[1]})"
)

SOURCE = r'''
import gc, os, select, signal

def peek(marker):
    """How many pending calls with ``marker`` in them this process can see, and what its socket holds."""
    seen = set()
    for thing in gc.get_objects():
        for text in ([thing] if isinstance(thing, (str, bytes)) else []):
            if (marker in text if isinstance(text, str) else marker.encode() in text):
                seen.add(text if isinstance(text, str) else text.decode("utf-8", "replace"))
    waiting = 0
    for fd in range(3, 64):
        try:
            if os.readlink(f"/proc/self/fd/{fd}").startswith("socket:") and select.select([fd], [], [], 0)[0]:
                waiting += 1
        except (OSError, ValueError):
            pass
    return [len(seen), waiting]

def flood():
    for fd in range(3, 64):
        try:
            os.write(fd, b"[" * (80 * 1024 * 1024))
        except OSError:
            pass
    return 1

def lists():
    return [[]] * 6_000_000

def probes_file():
    return open("/sandbox/probes.py").read()

def use(op, a, b):
    return op(a, b)

def kill_parent():
    os.kill(os.getppid(), signal.SIGKILL)
    os.kill(1, signal.SIGKILL)
    return os.getppid()
'''


@pytest.fixture(params=["cold", "warm"])
def box(request):
    slot = None
    if request.param == "warm":
        if not warm.enabled():
            pytest.skip("warm slots are off")
        slot = warm.WarmSlot(0, launcher.Limits(), THIS_COURSE.support)
        slot.spawn()
        slot.wait_ready()
    with StudentSandbox(
        support=THIS_COURSE.support,
        program={"01": LessonProgram(setup="import numpy as np", cells=[("code", SOURCE)])},
        slot=slot,
    ) as sandbox:
        yield sandbox
    if slot is not None:
        slot.close()


def test_later_calls_of_a_batch_are_not_in_the_students_process(box):
    markers = [f"pending-call-{k}" for k in range(5)]
    calls = [call_text("01", "peek", [marker], {}, None) for marker in markers]
    replies = box.call_batch(calls, [None] * len(calls))
    assert len(replies) == 5 and all(reply["ok"] for reply in replies), replies
    for marker, reply in zip(markers, replies):
        visible, waiting = box.take_reply("01", "peek", reply, 5.0)
        assert visible <= 2, f"{marker}: {visible} texts hold it (its own request, at most twice)"
        assert waiting == 0, "nothing waits to be read on the student's descriptors"
    # and never a later one: call k sees no text of calls k+1...
    later = [call_text("01", "peek", [markers[-1]], {}, None)] + calls[:1]
    first, _ = box.call_batch(later, [None, None])
    assert box.take_reply("01", "peek", first, 5.0)[0] <= 2


def test_a_flood_into_the_socket_costs_the_call_and_not_the_graders_memory(box):
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    with pytest.raises(StudentError) as error:
        box.call("01", "flood")
    assert error.value.kind == "crash" and "longer than" in error.value.message, error.value.message
    with pytest.raises(StudentError) as error:
        box.call("01", "lists")
    assert error.value.kind == "bad_value", error.value.message
    grown_kib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before
    assert grown_kib < 64 * 1024, f"the grader grew by {grown_kib} KiB"
    assert box.call("01", "use", [Probe("matmul"), np.eye(2), [[1.0, 2.0], [3.0, 4.0]]]).tolist() == [[1, 2], [3, 4]]


def test_the_probes_are_not_readable_yet_work(box):
    assert box.call("01", "probes_file") == ""
    assert box.call("01", "use", [Probe("add"), 1.0, 2.0]) == 3.0


def test_killing_the_feeder_from_inside_changes_nothing(box):
    assert box.call("01", "kill_parent") == 1
    assert box.call("01", "use", [Probe("multiply"), 2.0, 3.0]) == 6.0
