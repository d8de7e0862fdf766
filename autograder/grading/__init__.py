"""Grading one student: match notebooks to lessons, extract the answers, run the hidden suite and
nbval in the sandbox, score them; plus the canary and the grader's fingerprint.

May import: sandbox, lessons.
"""
