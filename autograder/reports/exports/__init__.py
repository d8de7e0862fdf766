"""Gradebook exports for learning-management systems, one small module each.

An exporter is a function ``write(results, catalog, roster, missing="zero") -> str``
(the file's text) registered as a plugin of kind ``"exporter"``
(:func:`autograder.reports.plugins.register`). ``missing`` says what a lesson
that was not handed in becomes: ``"zero"`` (the default: 0 points) or ``"blank"``
(an empty cell, which LMSs leave ungraded); :func:`~autograder.reports.exports.missing.not_handed_in`
names those lessons. To add Moodle or Blackboard, copy :mod:`autograder.reports.exports.canvas`,
change the columns and the name in ``@register("exporter", "canvas")``, and import the module here;
``python -m autograder export --to NAME`` then offers it. :data:`EXPORTERS` is the live view
``{name: write}`` of every registered exporter (one registered later included).
"""

from autograder.reports.exports import canvas  # noqa: F401  (registers "canvas")
from autograder.reports.plugins import Registered

EXPORTERS = Registered("exporter")
