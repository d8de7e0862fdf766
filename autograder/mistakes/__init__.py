"""Typical mistakes and correct alternatives, one module per lesson (``lesson01.py``, ...).

Each module defines

- ``MISTAKES``: a list of :class:`Mistake`, each a wrong answer cell for one
  exercise, written the way students really get it wrong. The project's
  mutation tests put each into an otherwise correct submission and require
  that it loses points on its exercise and nowhere else, that it fails at
  least one public check, and that it gets the hint meant for it (``hint``,
  a substring of the hidden feedback; ``public_hint``, of the check cell's
  output) while no other mistake's hint fires for it.
- ``ALTERNATIVES``: a list of :class:`Alternative`, correct answers written
  differently from the reference (other formulas, lists instead of arrays,
  the other valid branch at a singularity); each must get full marks in the
  hidden suite and pass every public check.
- ``SAMPLE``: which sample-class students make which of these mistakes,
  ``{student_id: [mistake name, ...]}``.
"""

import importlib
import pkgutil
from dataclasses import dataclass


@dataclass(frozen=True)
class Mistake:
    name: str
    exercise: str
    description: str
    source: str
    kind: str = "mistake"  # "mistake": a wrong answer; "fault": crashes, hangs, exits
    hint: str = ""  # a substring of the hint the hidden feedback must give it
    public_hint: str = ""  # a substring of the hint the public check cell must print for it
    classic: bool = False  # misses the exercise's core idea: may earn at most half of its points


@dataclass(frozen=True)
class Alternative:
    name: str
    exercise: str
    description: str
    source: str


def _modules():
    for info in pkgutil.iter_modules(__path__):
        if info.name.startswith("lesson"):
            yield importlib.import_module(f"{__name__}.{info.name}")


def _collect(attribute):
    found = {}
    for module in _modules():
        for item in getattr(module, attribute, []):
            if item.name in found:
                raise ValueError(f"{attribute[:-1].lower()} {item.name!r} defined twice")
            found[item.name] = item
    return found


def all_mistakes():
    """Every :class:`Mistake` of every lesson, by name."""
    return _collect("MISTAKES")


def all_alternatives():
    """Every :class:`Alternative` of every lesson, by name."""
    return _collect("ALTERNATIVES")


def sample_assignments():
    """``{student_id: [mistake names]}`` merged over all lessons."""
    merged = {}
    for module in _modules():
        for student, names in getattr(module, "SAMPLE", {}).items():
            merged.setdefault(student, []).extend(names)
    return merged
