"""Gradebook exports for learning-management systems, one small module each.

An exporter is a function ``write(results, catalog, roster) -> str`` (the
file's text) registered in :data:`EXPORTERS`. To add Moodle or Blackboard,
copy :mod:`autograder.reports.exports.canvas`, change the columns, and register it
here; ``python -m autograder export --to NAME`` then offers it.
"""

from autograder.reports.exports import canvas

EXPORTERS = {"canvas": canvas.write}
