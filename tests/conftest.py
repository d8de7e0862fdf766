import os
import sys
import zlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "solutions"))  # coursekit, as the notebooks import it
os.environ["MPLBACKEND"] = "Agg"  # whatever the shell set: the tests draw off screen (the kernels set their own)
# As autograder/cli.py does: jsonschema's rfc3987_syntax builds a grammar at import (seconds per process)
# for a string format no notebook schema uses.
sys.modules.setdefault("rfc3987_syntax", None)


@pytest.hookimpl(tryfirst=True)
def pytest_cmdline_main(config):
    """Two workers, one test file each (module fixtures such as a graded class are built once),
    unless the command line says otherwise (``-n 0``, ``-n 4``, ``-p no:xdist``)."""
    if hasattr(config, "workerinput") or not config.pluginmanager.hasplugin("xdist"):
        return
    if config.option.numprocesses is None:
        config.option.numprocesses = "auto"
        config.option.dist = "loadfile"
        # Hand out the files in the order below, not xdist's "most tests first": the heavy files
        # have few tests, and sent last they left one worker grading alone for ten minutes.
        config.option.loadscopereorder = False


# Files of many independent tests and no costly module fixture, and the number of work units each is cut into
# (by a hash of the test's id, so a unit's tests stay put as tests are added): whole, test_mutations.py (330
# mistakes, each graded in a sandbox) was one unit of several minutes on one worker while the other ran out of work.
SPLIT_FILES = {"test_mutations.py": 3, "test_alternatives.py": 2}


def _unit(nodeid):
    """The work unit of a test under ``--dist loadfile``: its file, or a part of a file of ``SPLIT_FILES``."""
    path = nodeid.split("::", 1)[0]
    parts = SPLIT_FILES.get(path.rsplit("/", 1)[-1])
    return f"{path}@{zlib.crc32(nodeid.encode()) % parts}" if parts else path


@pytest.hookimpl(optionalhook=True)  # xdist's hook: unknown with -p no:xdist
def pytest_xdist_make_scheduler(config, log):
    """``--dist loadfile``, with the files of ``SPLIT_FILES`` handed out in parts."""
    if config.option.dist != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class SplitFileScheduling(LoadFileScheduling):
        def _split_scope(self, nodeid):
            return _unit(nodeid)

    return SplitFileScheduling(config, log)


# The slowest work units, slowest first (from the durations printed at the end of a CI run, and per file
# with -p no:xdist). Each grades whole classes, drives a browser or runs every lesson; started first, they
# overlap instead of forming a tail on one worker (a worker takes its next unit when its current one has
# two tests left, so a unit of two tests or fewer runs beside the next one on the same worker). Every other
# file follows in collection order. test_student_floor_grading.py builds a floor venv of its own (a couple of
# minutes) unless .ci/run's background floor run is there to wait for ($STUDENT_FLOOR_OUT): early without
# it, last with it.
SLOWEST_FILES_FIRST = (
    "test_integrations.py",  # stock nbgrader: generate_assignment and autograde
    "test_sample_class.py",  # the sample class with nbval
    "test_sample_class_limits.py",  # the same in limits mode
    "test_hostile_class.py",  # a class of hostile students, twice
    "test_as_ordinary_user.py",  # the walls' tests again as nobody
    "test_cluster.py",  # a real Dask cluster
    "test_browser.py",  # JupyterLab in Chromium
    "test_mutations.py",  # every typical mistake graded (in parts, SPLIT_FILES)
    "test_book.py",  # Sphinx builds the book
    "test_speed_verdicts.py",  # the benchmark class against its golden gradebook
    "test_student_floor_grading.py",  # a floor venv and two lessons run in it (unless .ci/run's floor run)
    "test_notebooks.py",  # nbval on every lesson, solved and released
    "test_accessibility.py",  # axe-core in Chromium
    "test_adversarial.py",  # the adversarial corpus in one batch
    "test_notebook_hygiene.py",  # every lesson run top to bottom
    "test_alternatives.py",  # every correct alternative graded (in parts)
)
LAST_FILES = ("test_student_floor_grading.py",)  # when $STUDENT_FLOOR_OUT names .ci/run's background floor run

# `pytest tests -m quick`: every stage once, in about 3 minutes on 2 cores (README, "Tests"). Test ids or their
# beginnings; the suite stops with a usage error when one of them matches no test (renamed or removed).
QUICK = (
    # the course as the grader reads it, and its release
    "tests/test_catalog.py::",
    "tests/test_coursekit_doctests.py::",
    "tests/test_release.py::test_course_is_in_sync_with_solutions",
    "tests/test_release.py::test_no_solution_code_in_course",
    "tests/test_release.py::test_released_answers_are_stubs_and_checks_are_locked",
    "tests/test_handout.py::",
    # the sandbox
    "tests/test_sandbox.py::test_values_come_back_as_plain_data",
    "tests/test_sandbox.py::test_an_endless_loop_times_out_and_is_not_called_again",
    "tests/test_sandbox.py::test_project_files_are_out_of_reach",
    "tests/test_sandbox.py::test_no_network",
    # grading: lesson 01's reference and stubs through the hidden suite, its public checks, its mistakes
    "tests/test_reference_and_stubs.py::test_reference_answers_score_full_marks[lesson01]",
    "tests/test_reference_and_stubs.py::test_released_stubs_score_zero[lesson01]",
    "tests/test_public_checks.py::",
    "tests/test_mutations.py::test_mistake_fails_a_public_check[lesson01-",
    "tests/test_mutations.py::test_mistake_costs_points_on_its_exercise_only[lesson01-rot_z_",
    "tests/test_suite_runner.py::test_answers_equal_to_the_references_bit_for_bit_are_passed_without_running",
    "tests/test_notebook_stage_walls.py::test_the_same_answer_without_its_flaw_keeps_the_point",  # nbval stage
    "tests/test_notebooks.py::test_solutions_pass_nbval[01_frames_and_rotations.ipynb]",  # the lesson runs
    "tests/test_transcript_cache.py::test_the_file_name_follows_the_kernel_and_the_content",
    # reports and a batch
    "tests/test_attention.py::",
    "tests/test_batch.py::test_rerun_skips_unchanged_and_regrades_changed",
    "tests/test_batch.py::test_formulas_are_escaped",
    "tests/test_batch.py::test_unsafe_ids_make_safe_file_names",
    "tests/test_batch.py::test_class_report_contents",
    "tests/test_batch.py::test_progress_draws_at_once_and_on_a_terminal_only",
    # similarity
    "tests/test_similarity.py::test_the_stub_never_counts_and_short_answers_are_not_compared",
    "tests/test_similarity.py::test_one_pass_finds_what_pairwise_scoring_finds",
    "tests/test_similarity.py::test_two_short_standard_answers_are_not_a_finding",
    # integrations: the Gradescope bundle grades the reference
    "tests/test_integrations.py::test_gradescope_setup_runs_the_canary",
    "tests/test_integrations.py::test_gradescope_reference_full_marks[None]",
    # the records that stand in for .ci/run's network and floor runs; the code's own rules
    "tests/test_student_resolution.py::test_the_recorded_matrix_is_of_the_current_list",
    "tests/test_architecture.py::",
    "tests/test_lint.py::",
)


@pytest.fixture(scope="module")
def warm_slot():
    """One warm slot per test module (and worker): its zygote forks each student's sandbox, as in a class run."""
    from support import started_warm_slot

    with started_warm_slot() as slot:
        yield slot


@pytest.hookimpl(tryfirst=True)  # before pytest's own -m selection reads the marks
def pytest_collection_modifyitems(config, items):
    """Mark the tests of ``QUICK``; put the files of ``SLOWEST_FILES_FIRST`` at the front, in that order, and
    those of ``LAST_FILES`` at the end when .ci/run's floor run is beside the suite (a stable sort)."""
    matched = set()
    for item in items:
        for prefix in QUICK:
            if item.nodeid.startswith(prefix):
                item.add_marker(pytest.mark.quick)
                matched.add(prefix)
    if config.getoption("markexpr") == "quick" and not config.getoption("keyword") and len(items) > 1000:
        missing = [prefix for prefix in QUICK if prefix not in matched]
        if missing:
            raise pytest.UsageError(f"tests/conftest.py's QUICK names tests that are not there: {missing}")
    last = LAST_FILES if os.environ.get("STUDENT_FLOOR_OUT") else ()
    rank = {name: position for position, name in enumerate(name for name in SLOWEST_FILES_FIRST if name not in last)}
    rank.update({name: len(SLOWEST_FILES_FIRST) + 1 for name in last})
    items.sort(key=lambda item: rank.get(item.path.name, len(SLOWEST_FILES_FIRST)))
