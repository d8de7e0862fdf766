"""What graded results become: feedback pages, the class report, the gradebook CSV, late
penalties, rosters, Gradescope's results.json and LMS exports; ``plugins`` finds the exporters and the
late-policy rules by name.

May import: grading, sandbox, lessons.
"""
