"""Running untrusted code: bubblewrap (or limits-only) sandboxes, the worker session that calls
student functions, warm slots whose zygote forks each student's worker, cgroup and process-tree
limits, and forks that may die without hurting us.

May import: lessons.
"""
