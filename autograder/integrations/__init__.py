"""Other tools around the grader: stock nbgrader (a course, its gradebook), Gradescope's bundle
and container run, and grading on a Dask cluster.

May import: batch, reports, grading, sandbox, authoring, lessons.
"""
