"""Typical mistakes, one module per lesson (``lesson01.py``, ...).

Each module defines

- ``MISTAKES``: a list of :class:`Mistake`, each a wrong answer cell for one
  exercise, written the way students really get it wrong. The project's
  mutation tests put each into an otherwise correct submission and require
  that it loses points on its exercise and nowhere else.
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


def _modules():
    for info in pkgutil.iter_modules(__path__):
        if info.name.startswith("lesson"):
            yield importlib.import_module(f"{__name__}.{info.name}")


def all_mistakes():
    """Every :class:`Mistake` of every lesson, by name."""
    found = {}
    for module in _modules():
        for mistake in module.MISTAKES:
            if mistake.name in found:
                raise ValueError(f"mistake {mistake.name!r} defined twice")
            found[mistake.name] = mistake
    return found


def sample_assignments():
    """``{student_id: [mistake names]}`` merged over all lessons."""
    merged = {}
    for module in _modules():
        for student, names in getattr(module, "SAMPLE", {}).items():
            merged.setdefault(student, []).extend(names)
    return merged
