"""Is lateness taken from file times that a copy has reset? One warning an instructor cannot miss.

Without nbgrader's ``timestamp.txt``, when a lesson was handed in is its notebook's modification time
(:mod:`autograder.reports.lateness`). Copying or downloading a class without keeping those times
(``cp`` without ``-p``, unzipping some archives, an LMS download) sets them all to the moment of the
copy, which can make every student late. Two signs give a copy away, for a lesson with a due date:

- many students' notebooks (at least :data:`LEAST` and at least half of those timed by their files)
  were modified within :data:`WINDOW_SECONDS` of each other;
- every student timed by their file is after the due date (at least two students).

Only the saved results are read (each lesson records where its time came from and its late note), so
``grade``, ``status`` and the class report all say the same thing.

Examples
--------
>>> copied_times_warning(results)                                                   # doctest: +SKIP
'late penalties may be wrong. Without timestamp.txt, ... (lesson 01: 4 of 4 students' notebooks modified ...'
"""

from __future__ import annotations

from datetime import datetime

from autograder.grading.results import StudentResult

WINDOW_SECONDS = 60
LEAST = 3  # students modified within the window before it looks like a copy
OPTION = "--ignore-mtimes"


def _file_timed(results):
    """``{lesson number: [(student id, moment, late?)]}`` for lessons with a due date timed by their file."""
    timed = {}
    for result in results:
        for lesson in result.lessons:
            if lesson.due and lesson.submitted_from == "file time" and lesson.submitted_at:
                try:
                    moment = datetime.fromisoformat(lesson.submitted_at)
                except ValueError:
                    continue
                timed.setdefault(lesson.number, []).append((result.student_id, moment, bool(lesson.late_note)))
    return timed


def _largest_bunch(moments):
    """The largest number of ``moments`` (sorted datetimes) within :data:`WINDOW_SECONDS` of each other."""
    best, start = 0, 0
    for end, moment in enumerate(moments):
        while (moment - moments[start]).total_seconds() > WINDOW_SECONDS:
            start += 1
        best = max(best, end - start + 1)
    return best


def copy_signs(results: list[StudentResult]) -> list[str]:
    """One sentence per lesson whose file times look like a copy; ``[]`` when none does."""
    signs = []
    for number, entries in sorted(_file_timed(results).items()):
        count = len(entries)
        bunch = _largest_bunch(sorted(moment for _, moment, _ in entries))
        late = sum(1 for *_, is_late in entries if is_late)
        found = []
        if bunch >= LEAST and 2 * bunch >= count:
            found.append(f"{bunch} of {count} students' notebooks modified within one minute")
        if count >= 2 and late == count:
            found.append(f"all {count} after the due date")
        if found:
            signs.append(f"lesson {number}: " + ", ".join(found))
    return signs


def copied_times_warning(results: list[StudentResult]) -> str:
    """The warning to show (terminal, ``status``, class report), or ``""`` when the file times look genuine."""
    signs = copy_signs(results)
    if not signs:
        return ""
    return (
        "late penalties may be wrong. Without timestamp.txt, a lesson's hand-in time is its notebook's "
        "modification time, and these look like a copy (" + "; ".join(signs) + "): copying or downloading a "
        f"class resets them. Grade again with {OPTION} to take no lateness from file times, or keep the "
        "original times (cp -p, rsync -t, nbgrader's timestamp.txt)."
    )
