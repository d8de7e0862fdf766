"""The class roster: who is expected, and (optionally) their names, emails, sections and SIS ids.

Two formats are read:

- plain text, one student id per line (``#`` starts a comment);
- CSV with a header row naming at least ``id`` (or ``student_id``) and any of
  ``name``, ``email``, ``section``, ``sis_id``, ``canvas_id`` (case and spaces
  do not matter: ``SIS User ID`` is ``sis_id``).

Examples
--------
>>> [e.student_id for e in parse_roster("ada\\n# a comment\\nben\\n")]
['ada', 'ben']
>>> parse_roster("ID,Name,Section\\nada,Ada L.,A\\n")[0]
RosterEntry(student_id='ada', name='Ada L.', email='', section='A', sis_id='', canvas_id='')
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path

ALIASES = {
    "id": "student_id",
    "student_id": "student_id",
    "student": "student_id",
    "login": "student_id",
    "name": "name",
    "email": "email",
    "section": "section",
    "sis_id": "sis_id",
    "sis_user_id": "sis_id",
    "canvas_id": "canvas_id",
}


class RosterError(ValueError):
    """The roster cannot be read; the message says why."""


@dataclass(frozen=True)
class RosterEntry:
    student_id: str
    name: str = ""
    email: str = ""
    section: str = ""
    sis_id: str = ""
    canvas_id: str = ""


def _key(header):
    return ALIASES.get("_".join(header.strip().lower().split()))


def parse_roster(text: str) -> list[RosterEntry]:
    """Roster entries from the text of a roster file (see the module docstring)."""
    lines = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        return []
    header = next(csv.reader([lines[0]]))
    if len(header) > 1 or _key(header[0]) == "student_id":  # a CSV header (a lone "id" line is one too)
        keys = [_key(column) for column in header]
        if "student_id" not in keys:
            raise RosterError(f"the roster's header {header} has no id column (id or student_id)")
        entries = []
        for row in csv.reader(io.StringIO("\n".join(lines[1:]))):
            values = {key: value.strip() for key, value in zip(keys, row) if key}
            if values.get("student_id"):
                entries.append(RosterEntry(**values))
        return entries
    return [RosterEntry(line.strip()) for line in lines]


def read_roster(path: str | Path | None) -> list[RosterEntry]:
    """Read a roster file; ``None`` or ``""`` gives an empty roster."""
    if not path:
        return []
    try:
        return parse_roster(Path(path).read_text(encoding="utf-8-sig"))
    except OSError as error:
        raise RosterError(f"cannot read the roster {path}: {error.strerror}") from None
