"""What graded results become: feedback pages, the class report, the gradebook CSV, late
penalties, rosters, Gradescope's results.json and LMS exports.

May import: grading, sandbox, lessons.
"""
