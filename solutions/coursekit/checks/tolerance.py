"""A tolerance read as its docstring defines it: calls just below, at and just above the boundary.

Three exercises take ``tol`` with one meaning: two values are equal when the largest entry of their
absolute difference is **at most** ``tol`` (``is_rotation_matrix``: of MᵀM - I; ``commutes``: of
op(a, b) - op(b, a); ``check_group_axioms``: of each pair it compares). Calls two decades apart
(tol = 1e-5 against a difference of 4e-7) cannot tell that reading from another one: a factor on
``tol``, a squared difference, a norm instead of the largest entry, a relative tolerance or ``<`` for
``<=`` all give the same verdicts there. So the checks build inputs whose difference ``gap`` is exact
in binary and ask at three tolerances: 0.1 % below ``gap`` (not equal), exactly ``gap`` (equal) and
0.1 % above (equal), at several decades of ``gap``. Both suites use :func:`boundary_problem`, so
they say the same thing.

Examples
--------
>>> gap = 2.0**-18
>>> boundary_problem(lambda tol: gap <= tol, gap, "max |a - b|", "equal") is None
True
>>> boundary_problem(lambda tol: gap < tol, gap, "max |a - b|", "equal")[0]
'with tol equal to max |a - b| = 3.815e-06, equal returned False (expected True)'
"""

__all__ = ["BELOW", "ABOVE", "GAP_EXPONENTS", "boundary_problem", "AT_HINT", "BELOW_HINT", "ABOVE_HINT"]

BELOW, ABOVE = 1.0 - 2.0**-10, 1.0 + 2.0**-10  # 0.1 % either side of the boundary
GAP_EXPONENTS = (8, 14, 20, 26)  # gaps of 2^-k: from about 4e-3 down to 1.5e-8, every second decade or so

AT_HINT = ("tol is the largest difference still accepted (\"at most tol\"): a difference equal to tol must pass; "
           "look for a factor on tol, a norm over all entries instead of the largest one, or a strict comparison")
BELOW_HINT = ("a difference a little larger than tol was accepted: compare the largest entry of the absolute "
              "difference itself with tol, with no factor, square, norm or relative part")
ABOVE_HINT = ("a difference a little smaller than tol was rejected: compare the largest entry of the absolute "
              "difference itself with tol, with no factor, square or norm")


def boundary_problem(verdict, gap, what, name):
    """``None`` if ``verdict(tol)`` reads ``tol`` as "at most tol" around ``gap``, else ``(reason, hint)``.

    The hint is empty when the answer does not follow ``tol`` at all (the same verdict a thousand times
    above and below ``gap``): that slip is not about the boundary.

    Parameters
    ----------
    verdict : callable
        ``verdict(tol)`` is the answer's True/False ("equal", "a rotation", "commute") for an input whose
        compared difference is ``gap``.
    gap : float
        The largest entry of the absolute difference the answer should compare, exact in binary.
    what : str
        How the reason names that difference, e.g. ``"max |MᵀM - I|"``.
    name : str
        How the reason names the call, e.g. ``"is_rotation_matrix(diag(1 + 2^-20, 1, 1), tol)"``.
    """
    for tol, expected, hint, where in (
        (gap * BELOW, False, BELOW_HINT, "0.1 % below"),
        (gap, True, AT_HINT, "equal to"),
        (gap * ABOVE, True, ABOVE_HINT, "0.1 % above"),
    ):
        if bool(verdict(tol)) != expected:
            reason = f"with tol {where} {what} = {gap:.4g}, {name} returned {not expected} (expected {expected})"
            # the hints are for a tolerance read another way; an answer that does not follow tol at all (== or a
            # fixed number) fails here too, and the checks of its own slip name it
            follows_tol = bool(verdict(gap * 2.0**10)) and not bool(verdict(gap * 2.0**-10))
            return reason, hint if follows_tol else ""
    return None
