"""Lateness an instructor can trust, and feedback and a class report worth forwarding (issue 28, items 3 and 4).

One small class (lessons 01 and 02), graded once by the real command as an instructor types it, with a
course config whose due date has passed and no ``timestamp.txt``: every notebook's time is the moment
this test wrote it, as after a copy. Then ``status``, and one more grading with ``--ignore-mtimes``.

- ``ana``: every answer right;  ``bo``: the untouched release;  ``cy``: lesson 01 damaged by a text editor;
  ``dan``: one typical mistake;  ``eve``: lesson 01 only, right, with nbgrader's ``timestamp.txt`` before
  the due date;  ``zoe``: on the roster, handed in nothing.
"""

import csv
import re
import subprocess
import sys

import pytest

from autograder.lessons.catalog import load_catalog
from autograder.lessons.paths import PROJECT_ROOT
from support import STUB, build_submission, mistakes

CATALOG = load_catalog()
FIRST, SECOND = CATALOG.lesson("01"), CATALOG.lesson("02")
LESSONS = (FIRST.number, SECOND.number)
MISTAKE = mistakes()["rot_z_transposed"]
CONFIG = f'''timezone = "Europe/Berlin"
[late_policy]
penalty_per_day = 0.1
max_penalty = 0.3
[lessons."{FIRST.number}"]
due = 2026-01-15T23:59:00
[lessons."{SECOND.number}"]
due = 2026-01-20T12:00:00
'''


def _run(*args):
    return subprocess.run([sys.executable, "-m", "autograder", *args], cwd=PROJECT_ROOT, capture_output=True,
                          text=True, timeout=900)


def _rows(out):
    with open(out / "grades.csv", newline="", encoding="utf-8") as handle:
        return {row["student_id"]: row for row in csv.DictReader(handle)}


def build_class(root):
    """The class of this module's docstring, in ``root``; returns the roster file."""
    build_submission(root / "ana", lessons=LESSONS)
    build_submission(root / "bo", default=STUB, lessons=LESSONS)
    cy = build_submission(root / "cy", lessons=LESSONS)
    damaged = cy / FIRST.filename
    damaged.write_text(damaged.read_text(encoding="utf-8")[:-200], encoding="utf-8")  # cut short: not JSON
    build_submission(root / "dan", {MISTAKE.exercise: MISTAKE.source}, lessons=LESSONS)
    eve = build_submission(root / "eve", lessons=(FIRST.number,))
    (eve / "timestamp.txt").write_text("2026-01-15 20:00:00.000000 UTC", encoding="utf-8")
    roster = root.parent / "roster.csv"
    roster.write_text("id\nana\nbo\ncy\ndan\neve\nzoe\n", encoding="utf-8")
    return roster


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """``(out, grade's run, status's run, the class folder, the config file)``: one grading for the module."""
    root = tmp_path_factory.mktemp("forwarded")
    roster = build_class(root / "class")
    config = root / "course.toml"
    config.write_text(CONFIG, encoding="utf-8")
    out = root / "out"
    run = _run("grade", str(root / "class"), "--out", str(out), "--lessons", *LESSONS, "--roster", str(roster),
               "--config", str(config))
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    status = _run("status", "--out", str(out), "--roster", str(roster))
    assert status.returncode == 0, status.stdout[-2000:] + status.stderr[-2000:]
    return out, run, status, root / "class", config, roster
