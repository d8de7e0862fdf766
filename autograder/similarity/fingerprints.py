"""Fingerprints of answers and how much two of them share, with copydetect.

copydetect (PyPI, maintained) tokenises Python with Pygments and replaces every
name by one letter, drops comments, docstrings' whitespace and layout, hashes
the k-grams of what is left and keeps a winnowed subset (Schleimer, Wilkerson
and Aiken 2003, the method of MOSS). Fingerprints that also occur in the
released stub are removed (copydetect's boilerplate), so the signature and
docstring every student was given never count; the stub's docstring, when an
answer still holds it unchanged, is cut before tokenising (it is most of the
text, and most of the time). So renamed identifiers,
rewritten comments and docstrings and reformatting change nothing; reordered
independent lines and inserted dead code change only the k-grams that cross
them.

The score of a pair is the share of the smaller answer's fingerprints that
the other answer also has (what MOSS reports for the shorter file), computed
for all pairs of an exercise at once as a sparse product; copydetect's own
``compare_files`` finds the matching spans of the pairs that are shown.

Examples
--------
>>> stub = "def f(x):\\n    raise NotImplementedError\\n"
>>> a = fingerprint("def f(x):\\n    y = x * 2\\n    return y + 1  # add\\n", stub)
>>> b = fingerprint("def f(value):\\n    twice = value * 2\\n    return twice + 1\\n", stub)
>>> round(float(shared_share([a, b])[0, 1]), 2)
1.0
"""

from __future__ import annotations

import ast
import io
import warnings
from functools import lru_cache

import numpy as np
from copydetect import CodeFingerprint, compare_files
from copydetect.utils import filter_code, get_document_fingerprints, get_token_coverage, highlight_overlap
from markupsafe import escape
from scipy import sparse

K = 12  # characters of normalised code per k-gram (a name is one character)
# copydetect hashes k-grams with Python's hash(), salted per process: with a window above 1, winnowing
# would keep other k-grams in each run and a report would change between runs. Answers are a few hundred
# characters, so every k-gram is kept (window 1): the same class gives the same scores every time.
WINDOW = 1
MARK_OPEN, MARK_CLOSE = "<mark>", "</mark>"


def fingerprint(source: str, boilerplate_source: str = "") -> CodeFingerprint | None:
    """copydetect's :class:`CodeFingerprint` of ``source`` without the fingerprints of ``boilerplate_source``.

    Parameters
    ----------
    source : str
        An answer cell.
    boilerplate_source : str
        The released stub of the same exercise.

    Returns
    -------
    copydetect.CodeFingerprint
        ``hashes`` (a set), ``token_coverage`` (normalised characters not in the stub) and the spans.
    """
    normalised = getattr(source, "normalised", None)  # tokenised already, in the student's grading process
    source, boilerplate = _without_stub_docstring(str(source), boilerplate_source)
    if normalised is not None:
        return _from_normalised(source, normalised, boilerplate)
    return _fingerprint(source, boilerplate)


def normalised(source: str, boilerplate_source: str = "") -> tuple[str, list[int]]:
    """``(code, offsets)``: ``source`` tokenised and normalised as :func:`fingerprint` does it (the stub's
    docstring cut, names as one letter), with copydetect's offsets flattened; what a student's grading
    process keeps so that the similarity stage never tokenises a student's text itself.

    >>> normalised("def f(x):\n    return x\n")[0]
    'deff(V):returnV'
    """
    source, _ = _without_stub_docstring(source, boilerplate_source)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        code, offsets = filter_code(source, "answer.py", "python")
    return code, [int(value) for value in np.asarray(offsets, dtype=np.int64).ravel()]


class _Normalised(CodeFingerprint):
    """A :class:`CodeFingerprint` made from code tokenised elsewhere (:func:`normalised`): only hashing."""

    def __init__(self, raw_code, code, offsets, boilerplate):
        hashes, idx = get_document_fingerprints(code, K, WINDOW, boilerplate)
        self.filename, self.raw_code, self.filtered_code = "answer.py", raw_code, code
        self.offsets = np.asarray(offsets, dtype=np.int64).reshape(-1, 2) if offsets else np.array([])
        self.hashes, self.hash_idx, self.k = hashes, idx, K
        self.token_coverage = get_token_coverage(idx, K, len(code))


def _from_normalised(raw_code, normalised, boilerplate):
    code, offsets = normalised
    return _Normalised(raw_code, code, offsets, boilerplate)


def longest_coverage(source: str, boilerplate_source: str = "") -> int:
    """An upper bound of ``fingerprint(source, boilerplate_source).token_coverage``, without tokenising.

    Tokenising drops whitespace and comments and writes a name or a string as one character, so the
    normalised code is never longer than the answer's characters outside whitespace (the stub's docstring
    cut as :func:`fingerprint` cuts it). An answer whose bound is below the length worth comparing is
    left out before it costs a tokenisation.

    >>> longest_coverage("def f(x):\\n    return x.T\\n")
    17
    """
    source, _ = _without_stub_docstring(source, boilerplate_source)
    return len("".join(source.split()))


def _without_stub_docstring(source, boilerplate_source):
    """``(source, the stub's sorted fingerprints)``, the stub's docstring cut from ``source`` when it is there
    as released (most of a stub's text; tokenising it is most of the time)."""
    if not boilerplate_source:
        return source, []
    boilerplate, docstring = _boilerplate(boilerplate_source)
    if docstring and docstring in source:
        source = source.replace(docstring, "", 1)
    return source, boilerplate


@lru_cache(maxsize=512)
def _boilerplate(stub):
    """The stub's fingerprints (sorted, as copydetect wants them) and its docstring's lines as released."""
    hashes = np.array(sorted(_fingerprint(stub, []).hashes), dtype=np.int64)
    docstring = ""
    try:
        function = ast.parse(stub).body[0]
        first = function.body[0]
        if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
            docstring = "\n".join(stub.splitlines()[first.lineno - 1 : first.end_lineno]) + "\n"
    except (SyntaxError, IndexError, AttributeError):
        pass
    return hashes, docstring


def _fingerprint(source, boilerplate):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return CodeFingerprint(
            "answer.py", K, WINDOW, boilerplate=boilerplate, language="python", fp=io.StringIO(source)
        )


def shared_counts(fingerprints: list[CodeFingerprint]) -> tuple[np.ndarray, np.ndarray]:
    """``(C, sizes)``: ``C[i, j]`` fingerprints that answers i and j both have, shape (n, n), and each
    answer's number of fingerprints, shape (n,).

    One sparse product for all pairs: the answers × fingerprints incidence matrix times its transpose.

    >>> a = fingerprint("def f(x):\\n    y = x * 2\\n    return y + 1\\n")
    >>> counts, sizes = shared_counts([a, a])
    >>> counts.shape, bool(counts[0, 1] == sizes[0])
    ((2, 2), True)
    """
    n = len(fingerprints)
    sizes = np.array([len(fp.hashes) for fp in fingerprints], dtype=np.int64)
    hashes = np.fromiter((value for fp in fingerprints for value in fp.hashes), dtype=np.int64, count=int(sizes.sum()))
    _, columns = np.unique(hashes, return_inverse=True)
    columns = columns.ravel()
    incidence = sparse.csr_matrix(
        (np.ones(len(columns), dtype=np.int32), (np.repeat(np.arange(n), sizes), columns)),
        shape=(n, max(int(columns.max(initial=0)) + 1, 1)),
    )
    return (incidence @ incidence.T).toarray(), sizes


def share_of_smaller(counts: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """``counts[i, j] / min(sizes[i], sizes[j])`` (0 where an answer has no fingerprint), shape (n, n)."""
    smaller = np.minimum.outer(sizes, sizes).astype(float)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(smaller > 0, counts.astype(float) / np.where(smaller > 0, smaller, 1), 0.0)


def shared_share(fingerprints: list[CodeFingerprint]) -> np.ndarray:
    """``S[i, j]``: share of the smaller of answers i and j's fingerprints that both have, shape (n, n).

    The diagonal is 1 for an answer with fingerprints; an answer without any shares nothing.

    >>> a = fingerprint("def f(x):\\n    y = x * 2\\n    return y + 1\\n")
    >>> shared_share([a, a]).tolist()
    [[1.0, 1.0], [1.0, 1.0]]
    """
    return share_of_smaller(*shared_counts(fingerprints))


def highlighted(first: CodeFingerprint, second: CodeFingerprint, limit: int = 6000) -> tuple[str, str]:
    """Both answers as escaped HTML with the spans they share in ``<mark>``; ``limit`` characters each."""
    _, _, (slices_first, slices_second) = compare_files(first, second)
    return _marked(first.raw_code, slices_first, limit), _marked(second.raw_code, slices_second, limit)


def _marked(code, slices, limit):
    code = code[:limit]
    slices = np.asarray(slices, dtype=int).reshape(2, -1) if np.size(slices) else np.zeros((2, 0), dtype=int)
    slices = np.minimum(slices[:, slices[0] < len(code)], len(code))
    if slices.shape[1] == 0:
        return str(escape(code))
    return highlight_overlap(code, slices, MARK_OPEN, MARK_CLOSE, escape_html=True)[0]
