import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "solutions"))  # coursekit, as the notebooks import it
os.environ.setdefault("MPLBACKEND", "Agg")


@pytest.hookimpl(tryfirst=True)
def pytest_cmdline_main(config):
    """Two workers, one test file each (module fixtures such as a graded class are built once),
    unless the command line says otherwise (``-n 0``, ``-n 4``, ``-p no:xdist``)."""
    if hasattr(config, "workerinput") or not config.pluginmanager.hasplugin("xdist"):
        return
    if config.option.numprocesses is None:
        config.option.numprocesses = "auto"
        config.option.dist = "loadfile"
