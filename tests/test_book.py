"""The book: the solved lessons as a static website that a reader opens from disk.

Builds it once with ``python -m autograder book`` (offline: no network is
needed or used), then checks that it holds the solved lessons and nothing of
the grader, and opens every page from ``file://`` in headless Chromium: the
page loads, math renders (with the MathJax copy inside the book), images
load, no JavaScript error, and every link between pages resolves.
"""

import re
from pathlib import Path
from urllib.parse import unquote, urlparse

import nbformat
import pytest
from bs4 import BeautifulSoup

from autograder.authoring.book_phrases import LAB_ONLY_PHRASES, reader_phrasing
from autograder.lessons import cells
from autograder.lessons.paths import COURSE, PROJECT_ROOT, SOLUTIONS
from book_build import shared_book
from browser_support import BOOK_SELECTORS, Browser, open_book_page, page_problems, require_chromium

LESSONS = sorted(p.stem for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb"))


@pytest.fixture(scope="module")
def book(tmp_path_factory, request):
    return shared_book(tmp_path_factory, getattr(request.config, "workerinput", None))


def _pages(book):
    return sorted(book.glob("*.html"))


def test_every_lesson_has_a_page_and_the_start_page_is_the_front_page(book):
    names = {p.stem for p in _pages(book)}
    assert {name for name in LESSONS if not name.startswith("00_")} <= names
    front = (book / "index.html").read_text(encoding="utf-8")
    assert "Start here" in front and "01_frames_and_rotations.html" in front


def test_the_book_holds_no_stubs_hidden_tests_or_grader(book):
    everything = "\n".join(
        p.read_text(encoding="utf-8", errors="replace")
        for p in book.rglob("*")
        if p.is_file() and p.suffix in (".html", ".js", ".txt", ".ipynb", ".py")
    )
    assert not list(book.rglob("*.ipynb")) and not list(book.rglob("*.py")), "notebook or Python sources leaked"
    for marker in (
        "raise NotImplementedError",
        "BEGIN SOLUTION",
        "END SOLUTION",
        "autograder/hidden",
        "@exercise(",
        "def test_",
        "from .helpers import",
        "public_check(",
    ):
        assert marker not in everything, f"the book contains {marker!r}"


# What only a student needs, named in issue 29; the rest comes from the cells the masters tag student-only.
STUDENT_PHRASES = (
    "How grading works",
    "Handing in",
    "raise NotImplementedError",
    "Save the notebook",
    "hand in this file",
    "hidden checks",
    "your log_so3",
    "Ready to hand in",
    "your notebook is graded",
    "not written yet",
)


def _plain_runs(markdown, shortest=25):
    """The longest run of plain words in each paragraph: text that reads the same in the HTML."""
    for paragraph in markdown.split("\n\n"):
        runs = re.findall(r"[A-Za-z][A-Za-z ,;'’-]+[A-Za-z]", paragraph)
        if runs and len(max(runs, key=len)) >= shortest:
            yield max(runs, key=len).replace("’", "'")


def _student_only_text():
    """(lesson, phrase) pairs from every cell a master tags student-only, but for phrases that a cell
    kept in the book also says (a lesson's title, a link)."""
    for path in sorted(SOLUTIONS.glob("[0-9][0-9]_*.ipynb")):
        nb = nbformat.read(str(path), as_version=4)
        kept = " ".join(" ".join(c.source.split()) for c in nb.cells if not cells.is_student_only(c))
        for cell in nb.cells:
            if cells.is_student_only(cell):
                phrases = list(_plain_runs(cell.source)) if cell.cell_type == "markdown" else [cell.source.strip()]
                yield from ((path.stem, phrase) for phrase in phrases if " ".join(phrase.split()) not in kept)


def _page_text(page):
    """What a reader can read on a page: its text and its images' alt text, whitespace collapsed."""
    soup = BeautifulSoup(page.read_text(encoding="utf-8"), "html.parser")
    article = soup.find("article") or soup
    words = article.get_text(" ") + " " + " ".join(img.get("alt", "") for img in article.find_all("img"))
    return " ".join(words.split()).replace("’", "'")  # Sphinx's smart quotes, as the masters type them


def test_the_book_is_the_readers_edition(book):
    """No student-only cell and no phrase of the lab reaches the book; the book's own cells do."""
    derived = list(_student_only_text())
    assert len({lesson for lesson, _ in derived}) == len(LESSONS), "a lesson tags nothing student-only"
    pages = {p.stem: _page_text(p) for p in _pages(book)}
    everything = " ".join(pages.values())
    found = [phrase for phrase in STUDENT_PHRASES if phrase.lower() in everything.lower()]
    found += [f"{lesson}: {phrase[:80]}" for lesson, phrase in derived if " ".join(phrase.split()) in everything]
    assert not found, found
    reader_only = [
        c
        for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb")
        for c in nbformat.read(str(p), as_version=4).cells
        if cells.is_reader_only(c)
    ]
    assert reader_only
    course = " ".join(p.read_text(encoding="utf-8") for p in COURSE.glob("[0-9][0-9]_*.ipynb"))
    course_code = "\n".join(
        c.source for p in COURSE.glob("[0-9][0-9]_*.ipynb") for c in nbformat.read(str(p), as_version=4).cells
    )
    for cell in reader_only:
        if cell.cell_type != "markdown":  # code: the book highlights it token by token, so compare with the course only
            assert cell.source.strip() not in course_code, cell.source[:80]
            continue
        for phrase in _plain_runs(cell.source):
            assert phrase in everything and phrase not in course, phrase
    assert "computed with the reference rot_x" in pages["01_frames_and_rotations"]  # a caption, as alt text


def test_the_book_says_the_reference_where_the_lab_says_your(book):
    """No page, figure alt text or printed output of the book speaks of the reader's own answer or of the
    lab's tools ("your numerical Jacobian", "before you run the check cell"), while the lab keeps them."""
    pages = {p.stem: _page_text(p) for p in _pages(book)}
    found = [
        f"{name}: ...{text[max(0, k - 60) : k + 40]}..."
        for name, text in pages.items()
        for phrase in LAB_ONLY_PHRASES
        for k in [text.lower().find(phrase.lower())]
        if k >= 0
    ]
    assert not found, found
    assert "The reference numerical Jacobian against two analytic ones" in pages["06_perturbations_and_jacobians"]
    assert "matches the reference numerical Jacobian = True" in pages["06_perturbations_and_jacobians"]
    assert "in your head" in pages["04_quaternions"]  # the reader as a person keeps "your"
    course = " ".join(p.read_text(encoding="utf-8") for p in COURSE.glob("[0-9][0-9]_*.ipynb"))
    assert "Your numerical Jacobian against two analytic ones" in course


@pytest.mark.parametrize(
    "lab, book",
    [
        (
            "With your `boxminus` and `boxplus_right`: a round trip",
            "With the reference `boxminus` and `boxplus_right`: a round trip",
        ),
        ("Your $\\mathbf J_r$ against the identities", "The reference $\\mathbf J_r$ against the identities"),
        (
            "Then a round trip through both of your functions",
            "Then a round trip through both of the reference functions",
        ),
        ("Here are your three rotations at work", "Here are the three reference rotations at work"),
        ("Your function must work for any length", "The function must work for any length"),
        ("Check your matrix, before you run the check cell.", "Check the reference matrix."),
        ("Do not call your `to_homogeneous`", "Do not call `to_homogeneous`"),
        (
            "design your own solver; point your fingers; in your head; Your turn",
            "design your own solver; point your fingers; in your head; Your turn",
        ),
    ],
)
def test_reader_phrasing(lab, book):
    assert reader_phrasing(lab) == book


def test_the_book_needs_no_network(book):
    """Scripts and styles are local files (MathJax included), so the book reads offline."""
    for page in _pages(book):
        html = page.read_text(encoding="utf-8")
        remote = re.findall(r'<(?:script|link)[^>]+(?:src|href)="(https?://[^"]+)"', html)
        assert not remote, f"{page.name} loads {remote[:3]}"


def test_every_page_in_a_browser(book):
    sync_api = require_chromium()
    browser = Browser(sync_api)
    problems, broken_links = {}, []
    try:
        for path in _pages(book):
            if path.stem in ("genindex", "search"):
                continue
            page = browser.page()
            formulas = open_book_page(page, path)
            found = page_problems(page, BOOK_SELECTORS, min_math=1 if formulas else 0)
            if formulas < 0:
                found.append("MathJax did not start")
            if path.stem in LESSONS[1:] and not formulas:
                found.append("a lesson page without math")
            if found:
                problems[path.name] = found
            for href in page.eval_on_selector_all("a[href]", "els => els.map(e => e.href)"):
                url = urlparse(href)
                if url.scheme == "file" and not Path(unquote(url.path)).exists():
                    broken_links.append(f"{path.name} -> {href}")
            page.close()
    finally:
        browser.close()
    assert not problems, problems
    assert not broken_links, broken_links[:10]


def test_the_browser_check_catches_a_broken_page(book, tmp_path):
    """The same check reports a formula MathJax cannot parse and an image that does not load."""
    sync_api = require_chromium()
    source = (book / "02_groups_and_so3.html").read_text(encoding="utf-8")
    article = source.index("<article")
    heading = source.index("</h1>", article) + len("</h1>")
    math = '<span class="math notranslate nohighlight">{}</span>'
    cases = {  # what a bad formula in a lesson becomes in the book, and what the check must say
        "unclosed brace": (math.format(r"\(\frac{1}{2\)"), "raw TeX"),
        "double exponent": (math.format(r"\(x^{1}^{2}\)"), "MathJax error"),
        "undefined macro": (math.format(r"\(\rotmat{R}\)"), "MathJax error: undefined macro"),
        "missing image": ('<img src="_images/missing.png" alt="a figure that is not there">', "broken or empty image"),
    }
    browser = Browser(sync_api)
    found = {}
    try:
        for case, (html, _) in cases.items():
            target = book / f"broken_{case.replace(' ', '_')}.html"
            target.write_text(
                source[:heading] + f"<p>Broken on purpose: {html}.</p>" + source[heading:], encoding="utf-8"
            )
            page = browser.page()
            open_book_page(page, target)
            found[case] = "\n".join(page_problems(page, BOOK_SELECTORS, min_math=1))
            page.close()
            target.unlink()
    finally:
        browser.close()
    for case, (_, expected) in cases.items():
        assert expected in found[case], (case, found[case])


EXPLORER_LESSONS = sorted(
    path.stem for path in SOLUTIONS.glob("[0-9][0-9]_*.ipynb") if "explore_" in path.read_text(encoding="utf-8")
)


def test_every_explorer_moves_in_the_book_and_the_gimbal_reaches_the_lock(book):
    """From file://, with no kernel: lesson 05's gimbal slider dragged to its last frame (pitch 90°) shows another frame.

    Every lesson with an explorer holds its frames under a slider, and says in a
    line that the book's explorer is precomputed. The screenshot is kept.
    """
    sync_api = require_chromium()
    artifacts = PROJECT_ROOT / "test-artifacts" / "book"
    artifacts.mkdir(parents=True, exist_ok=True)
    sizes = {name: (book / f"{name}.html").stat().st_size / 2**20 for name in EXPLORER_LESSONS}
    print("book: explorer pages " + ", ".join(f"{name[:2]} {mib:.1f} MiB" for name, mib in sizes.items()))
    browser = Browser(sync_api)
    try:
        for name in EXPLORER_LESSONS:
            page = browser.page()
            open_book_page(page, book / f"{name}.html")
            frames = page.locator(".coursekit-explorer-frames")
            assert frames.count() >= 1, f"{name}: no explorer frames in the book"
            assert "precomputed frames" in frames.first.inner_text(), name
            if name.startswith("05_"):
                explorer = frames.filter(has_text="pitch").first
                explorer.scroll_into_view_if_needed()
                picture = explorer.locator("img").first
                slider = explorer.locator("input[type=range]").first
                first = picture.get_attribute("src")
                last = int(slider.get_attribute("max"))
                slider.focus()
                page.keyboard.press("End")  # the keyboard's drag to the far end: pitch 90°
                page.wait_for_function(
                    "([img, before]) => img.getAttribute('src') !== before",
                    arg=[picture.element_handle(), first],
                    timeout=10_000,
                )
                shot = artifacts / "book_05_gimbal_locked.png"
                explorer.screenshot(path=str(shot))
                print(f"book: the gimbal at the lock, from file:// -> {shot}")
                assert last >= 20 and slider.input_value() == str(last), (last, slider.input_value())
                assert "pitch" in explorer.inner_text() and "from 0 to 90" in explorer.inner_text()
            assert not page.js_errors, (name, page.js_errors)
            page.close()
    finally:
        browser.close()


def test_the_readers_edition_drops_points_from_exercise_headings():
    """Every master's exercise headings lose their "(N points)" in the book, and nothing else does."""
    import re

    from autograder.authoring.book import _reader_copy
    from autograder.lessons.notebook_files import read_master
    from autograder.lessons.paths import SOLUTIONS

    headings = 0
    for path in sorted(SOLUTIONS.glob("[0-9][0-9]_*.ipynb")):
        for cell in _reader_copy(read_master(path)).cells:
            if cell.cell_type == "markdown":
                exercise_lines = re.findall(r"^#+ Exercise \d+: .*$", cell.source, re.MULTILINE)
                headings += len(exercise_lines)
                assert not [line for line in exercise_lines if re.search(r"\(\d+(\.\d+)? points?\)", line)]
    assert headings >= 50
