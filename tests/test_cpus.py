"""One CPU per grading slot (autograder/sandbox/cpus.py): concurrent graders keep to distinct CPUs, a lone
grader is never pinned, and pinning for a block leaves the process as it was."""

import os

import pytest

from autograder.sandbox import cpus
from autograder.sandbox.forking import fork_each

ALLOWED = sorted(os.sched_getaffinity(0))
needs_two = pytest.mark.skipif(len(ALLOWED) < 2, reason="this machine lets this process use one CPU only")


def test_a_lone_grader_is_never_pinned():
    assert cpus.cpu_of_slot(0, jobs=1) is None


@needs_two
def test_concurrent_slots_get_distinct_cpus_of_those_allowed():
    chosen = [cpus.cpu_of_slot(slot, jobs=2) for slot in range(2)]
    assert chosen[0] != chosen[1] and set(chosen) <= set(ALLOWED)


@needs_two
def test_two_batches_start_counting_from_the_cpu_their_ids_pick():
    assert cpus.cpu_of_slot(0, jobs=2, batch=0) != cpus.cpu_of_slot(0, jobs=2, batch=1)


@needs_two
def test_pinned_holds_within_the_block_and_restores_after():
    before = os.sched_getaffinity(0)
    with cpus.pinned(ALLOWED[1]):
        assert os.sched_getaffinity(0) == {ALLOWED[1]}
    assert os.sched_getaffinity(0) == before


@needs_two
def test_each_forked_grader_keeps_to_its_slots_cpu(tmp_path):
    def note(item, _slot):
        (tmp_path / f"{item}.txt").write_text(",".join(map(str, sorted(os.sched_getaffinity(0)))))

    outcomes = {}
    fork_each(note, ["a", "b"], jobs=2, on_done=outcomes.__setitem__)
    assert outcomes == {"a": None, "b": None}
    seen = [(tmp_path / f"{item}.txt").read_text() for item in "ab"]
    assert seen == [str(cpus.cpu_of_slot(slot, jobs=2)) for slot in range(2)], seen
    assert os.sched_getaffinity(0) == set(ALLOWED), "the parent must stay free"
