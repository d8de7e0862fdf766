"""Gradebook exports for learning-management systems, one small module each.

An exporter is a function ``write(results, catalog, roster, missing="zero") -> str``
(the file's text) registered in :data:`EXPORTERS`. ``missing`` says what a lesson
that was not handed in becomes: ``"zero"`` (the default: 0 points) or ``"blank"``
(an empty cell, which LMSs leave ungraded); :func:`~autograder.reports.exports.missing.not_handed_in`
names those lessons. To add Moodle or Blackboard, copy :mod:`autograder.reports.exports.canvas`,
change the columns, and register it here; ``python -m autograder export --to NAME`` then offers it.
"""

from autograder.reports.exports import canvas

EXPORTERS = {"canvas": canvas.write}
