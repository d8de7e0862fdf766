"""Running untrusted code: bubblewrap (or limits-only) sandboxes, the worker session that calls
student functions, cgroup and process-tree limits, and forks that may die without hurting us.

May import: lessons.
"""
