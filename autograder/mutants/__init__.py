"""Mutation testing of the reference answers: AST operators that model students' slips, each mutant
graded by the hidden suite and by the public checks, and a table of what each suite kills.

May import: grading, sandbox, lessons.
"""
