"""The notebooks run: nbval passes on solutions/, and course/ fails only where a stub is.

Each notebook runs in its own ``pytest --nbval-lax`` process, with the Agg
backend as in grading. In solutions/, every cell must run and every cell
tagged ``nbval-check-output`` must reproduce its recorded output. In course/,
the stubs raise ``NotImplementedError`` (their check cells ``NotWrittenYet``)
and nothing else may go wrong.
"""

import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from autograder.lessons.paths import COURSE, PROJECT_ROOT, SOLUTIONS
from support import THIS_COURSE

MASTERS = sorted(p.name for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb"))


def _nbval(path, junit):
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONHASHSEED="0")
    env.pop("PYTEST_DISABLE_PLUGIN_AUTOLOAD", None)
    return subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "--nbval-lax",
            "-p",
            "no:cacheprovider",
            "-q",
            "-o",
            "addopts=",
            "--nbval-cell-timeout=120",
            f"--junitxml={junit}",
            str(path),
        ],
        cwd=PROJECT_ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )


def _failures(junit):
    root = ET.parse(junit).getroot()
    found = []
    for case in root.iter("testcase"):
        for failure in list(case.findall("failure")) + list(case.findall("error")):
            found.append((case.get("name"), (failure.get("message") or "") + (failure.text or "")))
    return found


@pytest.mark.parametrize("name", MASTERS)
def test_solutions_pass_nbval(name, tmp_path):
    result = _nbval(SOLUTIONS / name, tmp_path / "junit.xml")
    failures = _failures(tmp_path / "junit.xml")
    assert result.returncode == 0 and not failures, [(cell, text[-600:]) for cell, text in failures][:3]


@pytest.mark.parametrize("name", MASTERS)
def test_course_fails_only_with_not_implemented(name, tmp_path):
    _nbval(COURSE / name, tmp_path / "junit.xml")
    failures = _failures(tmp_path / "junit.xml")
    has_exercises = bool(THIS_COURSE.catalog.lesson(name[:2]).exercises)
    assert bool(failures) == has_exercises, f"{name}: stubs should fail (and only stubs)"
    # a stub raises the first; its check cell the second; the hand-in cell the third
    stubs = ("NotImplementedError", "NotWrittenYet", "NotReadyYet")
    other = [(cell, text[-400:]) for cell, text in failures if not any(word in text for word in stubs)]
    assert not other, other[:3]
