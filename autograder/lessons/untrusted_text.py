"""Text that came from a student, made safe for the place it is shown.

Student ids (folder names), notebook names, messages of their code and what it
printed reach the instructor's terminal, the gradebook CSV, HTML pages and file
names. Any of them may hold control characters (an ESC sequence rewrites a
terminal, a newline forges a row of a table), bidirectional overrides, lone
surrogates (a folder name that is not UTF-8, text that no encoder accepts), or
be megabytes long. Every place that shows such text goes through this module:

- :func:`one_line` for a terminal or a CSV cell: one line, every control or
  format character shown as a Python escape (``\\x1b``, ``\\n``, ``\\u202e``),
  bounded with a note of what was cut;
- :func:`html_text` for a page: HTML-escaped, encodable, bounded (line breaks kept);
- :func:`csv_cell`: :func:`one_line`, then :func:`spreadsheet_safe`;
- :func:`safe_name` for a file name: bounded, portable and collision-free.

Examples
--------
>>> one_line("ada\\x1b[2J\\nzed 12 / 12 graded")
'ada\\\\x1b[2J\\\\nzed 12 / 12 graded'
>>> csv_cell("=HYPERLINK(1)")
"'=HYPERLINK(1)"
>>> safe_name("../etc/passwd")
'..%2Fetc%2Fpasswd'
"""

from __future__ import annotations

import hashlib
import html
import unicodedata

LINE_LIMIT = 300  # characters of one line on the terminal or in a CSV cell
HTML_LIMIT = 20_000  # characters of one piece of student text on a page
NAME_LIMIT = 120  # characters of a file name made from a student id (NAME_MAX is 255 bytes)
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
_UNSAFE_CATEGORIES = {"Cc", "Cf", "Cs", "Zl", "Zp"}  # controls, format (bidi), surrogates, line separators
_KEPT_IN_HTML = {"\n", "\t"}


def _escape_char(char):
    code = ord(char)
    if char in "\n\r\t":
        return {"\n": "\\n", "\r": "\\r", "\t": "\\t"}[char]
    if code < 0x100:
        return f"\\x{code:02x}"
    return f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"


def _unsafe(char, kept=()):
    return char not in kept and unicodedata.category(char) in _UNSAFE_CATEGORIES


def _bounded(text, limit):
    if limit is None or len(text) <= limit:
        return text
    return f"{text[:limit]}… ({len(text) - limit:,} more characters not shown)"


def encodable(text: str) -> str:
    """``text`` as a ``str`` that any UTF-8 writer accepts: lone surrogates become ``\\udcff`` escapes.

    Examples
    --------
    >>> encodable("caf\\udce9")
    'caf\\\\udce9'
    """
    text = str(text)
    if text.isascii():
        return text
    return "".join(_escape_char(c) if unicodedata.category(c) == "Cs" else c for c in text)


def one_line(text: object, limit: int = LINE_LIMIT) -> str:
    """``text`` on one line, every control, format or separator character escaped, at most ``limit``
    characters (then a note says how many more there were); ``limit=None`` keeps it all.

    Examples
    --------
    >>> one_line("two\\nlines")
    'two\\\\nlines'
    >>> one_line("x" * 10, limit=4)
    'xxxx… (6 more characters not shown)'
    """
    text = str(text)
    clipped = text[:limit] if limit is not None else text
    shown = "".join(_escape_char(c) if _unsafe(c) else c for c in clipped)
    if limit is not None and len(text) > limit:
        return f"{shown}… ({len(text) - limit:,} more characters not shown)"
    return shown


def html_text(text: object, limit: int = HTML_LIMIT) -> str:
    """``text`` escaped for an HTML page: entities for ``<>&"'``, line breaks and tabs kept, other
    control and format characters shown as escapes, lone surrogates made encodable, at most ``limit``
    characters.

    Examples
    --------
    >>> html_text("<script>\\x1b")
    '&lt;script&gt;\\\\x1b'
    """
    text = _bounded(str(text), limit)
    shown = "".join(_escape_char(c) if _unsafe(c, _KEPT_IN_HTML) else c for c in text)
    return html.escape(shown, quote=True)


def spreadsheet_safe(text: str) -> str:
    """``text`` with a leading apostrophe if a spreadsheet would evaluate it as a formula.

    Examples
    --------
    >>> spreadsheet_safe("=1+1"), spreadsheet_safe("ada")
    ("'=1+1", 'ada')
    """
    text = str(text)
    return "'" + text if text.startswith(FORMULA_STARTS) else text


def csv_cell(text: object, limit: int = LINE_LIMIT) -> str:
    """A gradebook cell: :func:`one_line` (at most ``limit`` characters), then :func:`spreadsheet_safe`."""
    return spreadsheet_safe(one_line(text, limit))


def safe_name(student_id: str, limit: int = NAME_LIMIT) -> str:
    """A file name for a student id: bounded, portable, and different for different ids.

    Letters, digits and ``._-`` are kept, every other character becomes the ``%XX`` escapes of its
    UTF-8 bytes (lone surrogates included), so distinct ids give distinct names. A name longer than
    ``limit`` is cut and ends with ``~`` and 32 hex digits of the id's SHA-256 (``~`` never appears
    otherwise), so it stays distinct too and leaves room under NAME_MAX for suffixes.

    Examples
    --------
    >>> safe_name("=cmd|' /C calc'!A0")
    '%3Dcmd%7C%27%20%2FC%20calc%27%21A0'
    >>> len(safe_name("x" * 250))
    120
    """
    pieces = []
    for char in str(student_id):
        if char.isascii() and (char.isalnum() or char in "._-"):
            pieces.append(char)
        else:
            pieces.append("".join(f"%{b:02X}" for b in char.encode("utf-8", "surrogatepass")))
    name = "".join(pieces)
    if name in ("", ".", ".."):
        name = f"%{name}"
    if len(name) > limit:
        digest = hashlib.sha256(str(student_id).encode("utf-8", "surrogatepass")).hexdigest()[:32]
        name = f"{name[: limit - len(digest) - 1]}~{digest}"
    return name
