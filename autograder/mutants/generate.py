"""The mutants of every reference answer: each operator's edits, one edit per mutant, duplicates dropped.

A mutant is a whole answer cell (the reference's, with one edit made), so it is
graded exactly as a student's cell would be. Its ``key`` (exercise and a hash
of its source) stays the same from run to run while the reference answer
does not change; :mod:`autograder.mutants.equivalent` lists mutants by key.

Examples
--------
>>> found = mutants_of(course, "rot_z")    # doctest: +SKIP
>>> found[0].key, found[0].family          # doctest: +SKIP
('rot_z.1f0c9a2e', 'sign')
"""

from __future__ import annotations

import ast
import hashlib
from dataclasses import dataclass
from functools import lru_cache

from autograder.lessons.course import Course
from autograder.lessons.reference import answer_sources
from autograder.mutants import operators


@dataclass(frozen=True)
class Mutant:
    exercise: str
    lesson: str
    family: str
    description: str
    source: str

    @property
    def key(self) -> str:
        return key_of(self.exercise, self.source)


def key_of(exercise: str, source: str) -> str:
    """``"exercise.hash"``: names a mutant by what it is (its normalised source), not by how it was made."""
    normalised = ast.unparse(ast.parse(source))
    return f"{exercise}.{hashlib.sha1(normalised.encode('utf-8')).hexdigest()[:8]}"


def _globals_of(setup_source):
    """Names that a lesson's setup cell binds (``np``, ``check``, ``Exp``...)."""
    names = set()
    for node in ast.walk(ast.parse(setup_source)):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names.update((alias.asname or alias.name).split(".")[0] for alias in node.names)
    return names


@lru_cache(maxsize=None)
def mutants_of(course: Course, exercise: str) -> tuple[Mutant, ...]:
    """Every distinct mutant of ``exercise``'s reference answer, in operator order (a tuple)."""
    catalog = course.catalog
    lesson = catalog.exercise(exercise).lesson
    reference = answer_sources(course.solutions)[exercise]
    tree = ast.parse(reference)
    seen = {ast.unparse(tree)}
    found = []
    for edit in operators.edits(tree, exercise, _globals_of(catalog.lesson(lesson).setup_source)):
        try:
            source = operators.apply(tree, edit)
            compile(source, f"<mutant of {exercise}>", "exec")
        except (SyntaxError, ValueError, TypeError):
            continue  # an edit that makes no valid Python (e.g. a swap inside a starred call)
        if source in seen:
            continue
        seen.add(source)
        found.append(Mutant(exercise, lesson, edit.family, operators.describe(edit), source))
    delegation = operators.DELEGATIONS.get(exercise)
    if delegation is not None:
        found.append(Mutant(exercise, lesson, "delegation", "the library's version called instead", delegation))
    return tuple(found)


def all_mutants(course: Course, exercises: list[str] | None = None, lessons: list[str] | None = None) -> list[Mutant]:
    """The mutants of every graded exercise of the catalog (or of the ones named), lesson by lesson."""
    found = []
    for lesson in course.catalog.graded_lessons:
        if lessons and lesson.number not in lessons:
            continue
        for exercise in lesson.exercises:
            if exercises and exercise.name not in exercises:
                continue
            found.extend(mutants_of(course, exercise.name))
    return found
