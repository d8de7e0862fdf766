import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "solutions"))  # coursekit, as the notebooks import it
os.environ.setdefault("MPLBACKEND", "Agg")
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


# The slowest test files, slowest first (from the durations printed at the end of a CI run).
# Each grades whole classes or drives a browser; started first, they overlap instead of
# forming a tail on one worker. Every other file follows in collection order; that puts
# test_student_floor_grading.py, which waits for .ci/run's background floor run, near the end.
SLOWEST_FILES_FIRST = (
    "test_integrations.py",  # stock nbgrader: generate_assignment and autograde
    "test_sample_class.py",  # the sample class with nbval
    "test_sample_class_limits.py",  # the same in limits mode
    "test_cluster.py",  # a real Dask cluster
    "test_hostile_class.py",  # a class of hostile students, twice
    "test_as_ordinary_user.py",  # the walls' tests again as nobody
    "test_browser.py",  # JupyterLab in Chromium
    "test_speed_verdicts.py",  # the benchmark class against its golden gradebook
    "test_book.py",  # Sphinx builds the book
    "test_accessibility.py",  # axe-core in Chromium
    "test_adversarial.py",  # the adversarial corpus in one batch
    "test_notebook_hygiene.py",  # every lesson run top to bottom
)


def pytest_collection_modifyitems(config, items):
    """Put the files of ``SLOWEST_FILES_FIRST`` at the front, in that order (a stable sort)."""
    rank = {name: position for position, name in enumerate(SLOWEST_FILES_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))
