"""One budget for every byte a student can make the grader keep, applied where the data is produced.

A student controls much of the text a grading keeps: the error their answer cell raises, what it
prints, the reasons a check gives (which quote the student's values), the names of their notebooks and
files, and the answers the similarity stage compares. Every such string is cut here to
:data:`STRING_CHARS` characters with a visible ``… (N bytes more)`` marker, every list of notes to
:data:`LIST_ITEMS` items with ``and N more``, and one :class:`StudentBudget` per student spends at most
:data:`TEXT_BYTES` bytes (as saved: ASCII JSON) on all of them together; what is past the budget is
replaced by its marker. The answers kept for the similarity stage have a budget of their own,
:data:`ANSWERS_BYTES`. So a student's saved result is at most :data:`RESULT_BYTES`, their feedback page
at most :data:`PAGE_BYTES`, and everything the grader keeps for one student (saved result, feedback
page, Gradescope JSON) at most :data:`STUDENT_BYTES`; readers of saved results read at most
:data:`RESULT_BYTES` of a file (:func:`read_capped`), so ``status``, ``export`` and the batch parent
hold a bounded summary per student.

Examples
--------
>>> cut("x" * 10, 4)
'xxxx… (6 bytes more)'
>>> cut_list(["a", "b", "c"], 2)
['a', 'b', 'and 1 more']
>>> budget = StudentBudget(60)
>>> budget.text("y" * 100)[:6], budget.text("z" * 100)[:3]
('yyyyyy', '… (')
"""

from __future__ import annotations

import json
import os
from dataclasses import fields, is_dataclass
from pathlib import Path

STRING_CHARS = 4_000  # characters of one student-controlled string (a note, a reason, printed output)
LIST_ITEMS = 50  # items of one list of notes, problems, failures or skipped entries
TEXT_BYTES = 1 << 20  # bytes (ASCII JSON) of all the student-controlled text of one result together
ANSWERS_BYTES = 2 << 20  # bytes (ASCII JSON) of the answers kept for the similarity stage
RESULT_BYTES = 4 << 20  # a saved result (OUT/students/<id>.json), the fingerprint's parts included
PAGE_BYTES = 4 << 20  # a feedback page (OUT/feedback/<id>.html)
GRADESCOPE_BYTES = 4 << 20  # a Gradescope JSON (OUT/results/<id>.json)
STUDENT_BYTES = RESULT_BYTES + PAGE_BYTES + GRADESCOPE_BYTES  # everything the grader keeps for one student

MARK = "… ({} bytes more)"


def _cost(text: str) -> int:
    """Bytes ``text`` takes in a saved result (ASCII JSON, quotes included)."""
    return len(json.dumps(text))


def _utf8_len(text: str) -> int:
    return len(text.encode("utf-8", "surrogatepass"))


def cut(text: object, limit: int = STRING_CHARS) -> str:
    """``text`` (made a string) cut to ``limit`` characters, followed by ``… (N bytes more)`` when cut.

    >>> cut("short")
    'short'
    """
    text = text if isinstance(text, str) else str(text)
    if len(text) <= limit:
        return text
    return text[:limit] + MARK.format(_utf8_len(text[limit:]))


def cut_list(items: list, count: int = LIST_ITEMS) -> list:
    """The first ``count`` of ``items`` and, when there were more, ``"and N more"``.

    >>> cut_list(["a"], 2)
    ['a']
    """
    items = list(items)
    if len(items) <= count:
        return items
    return items[:count] + [f"and {len(items) - count} more"]


class StudentBudget:
    """The bytes one student's text may still take: each :meth:`text` spends from one total.

    >>> StudentBudget(1000).text("ok")
    'ok'
    """

    def __init__(self, total: int = TEXT_BYTES) -> None:
        self.left = total

    def text(self, value: object, limit: int = STRING_CHARS) -> str:
        """``value`` cut to ``limit`` characters and to what is left of the budget (then spent)."""
        text = cut(value, limit)
        cost = _cost(text)
        if cost > self.left:  # keep what fits (past the budget, only the marker: bounded by the count of strings)
            whole = value if isinstance(value, str) else str(value)
            keep = max(0, min(limit, self.left - 40))
            text = cut(whole, keep)
            while keep and _cost(text) > self.left:
                keep //= 2
                text = cut(whole, keep)
            cost = _cost(text)
        self.left -= cost
        return text

    def texts(self, values: list, count: int = LIST_ITEMS) -> list:
        """A list of strings, each through :meth:`text`, capped at ``count`` items with ``and N more``."""
        return [self.text(v) for v in cut_list(values, count)]


_TEXT_FIELDS = {  # the student-controlled strings and lists of strings of each part of a result
    "StudentResult": (("reason",), ("problems", "skipped")),  # the id is a folder name: bounded by NAME_MAX
    "LessonResult": (("reason", "notebook"), ()),
    "ExerciseResult": ((), ("notes",)),
    "CheckResult": (("reason", "printed"), ()),
    "NotebookRun": ((), ("failures",)),
}


def fit_result(result: object, budget: StudentBudget | None = None) -> object:
    """Bound, in place, every student-controlled string and list of ``result`` (a
    :class:`~autograder.grading.results.StudentResult`) with one :class:`StudentBudget`; return it.

    Points, weights and statuses are untouched: this changes no grade. The answers kept for the similarity
    stage are bounded where they are made (:data:`ANSWERS_BYTES`).

    >>> from autograder.grading.results import StudentResult
    >>> fit_result(StudentResult("ada", "graded", problems=["p"] * 60)).problems[-1]
    'and 10 more'
    """
    budget = budget or StudentBudget()
    pending = [result]
    while pending:
        item = pending.pop(0)
        if not is_dataclass(item):
            continue
        strings, lists = _TEXT_FIELDS.get(type(item).__name__, ((), ()))
        for name in strings:
            value = getattr(item, name, "")
            if isinstance(value, str) and value:
                setattr(item, name, budget.text(value))
        for name in lists:
            value = getattr(item, name, None)
            if isinstance(value, list):
                setattr(item, name, budget.texts(value))
        for each in fields(item):
            value = getattr(item, each.name)
            if is_dataclass(value):
                pending.append(value)
            elif isinstance(value, list):
                pending.extend(v for v in value if is_dataclass(v))
    return result


class TooLarge(ValueError):
    """A file the grader wrote is larger than it can be: it is not read."""


def read_capped(path: str | Path, cap: int = RESULT_BYTES) -> str:
    """The text of ``path`` (never a link), refused with :class:`TooLarge` past ``cap`` bytes; at most
    ``cap + 1`` bytes are ever read.

    >>> read_capped("OUT/students/ada.json")                  # doctest: +SKIP
    '{...}'
    """
    descriptor = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_CLOEXEC | os.O_NONBLOCK)
    with open(descriptor, "rb") as handle:
        data = handle.read(cap + 1)
    if len(data) > cap:
        raise TooLarge(f"{path} is larger than {cap} bytes")
    return data.decode("utf-8", errors="backslashreplace")
