"""A folder student code wrote into is removed whatever it holds (autograder/sandbox/cleanup.py).

Oracles: after ``remove_tree`` the folder is gone, and what a link inside pointed to is untouched.
Edge cases: a tree 3,000 levels deep (a recursive walk stops near 1,000; its paths pass PATH_MAX),
folders made unreadable (chmod 0), links to folders outside, a file at the top instead of a folder,
a folder that does not exist. Run as root and, by tests/test_as_ordinary_user.py, as an ordinary user.
"""

import os

from autograder.sandbox.cleanup import remove_tree


def _deep(base, levels):
    here = os.getcwd()
    os.chdir(base)
    try:
        for _ in range(levels):
            os.mkdir("d" * 200)
            os.chdir("d" * 200)
        with open("bottom.txt", "w") as handle:
            handle.write("x")
    finally:
        os.chdir(here)


def test_a_deep_locked_tree_with_links_outside_is_removed(tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "keep.txt").write_text("the grader's file")
    top = tmp_path / "scratch"
    top.mkdir()
    _deep(top, 3000)
    (top / "link_out").symlink_to(outside)
    (top / "locked" / "inner").mkdir(parents=True)
    (top / "locked" / "inner" / "f").write_text("x")
    os.chmod(top / "locked" / "inner", 0)
    os.chmod(top / "locked", 0)
    assert remove_tree(top)
    assert not top.exists()
    assert (outside / "keep.txt").read_text() == "the grader's file"


def test_a_file_a_link_and_nothing(tmp_path):
    (tmp_path / "f").write_text("x")
    (tmp_path / "link").symlink_to(tmp_path / "f")
    assert remove_tree(tmp_path / "link") and (tmp_path / "f").exists()
    assert remove_tree(tmp_path / "f") and not (tmp_path / "f").exists()
    assert remove_tree(tmp_path / "never-made")


def test_a_killed_graders_folders_are_swept_and_a_live_ones_kept(tmp_path, monkeypatch):
    import subprocess
    import tempfile

    from autograder.sandbox import cleanup

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    gone = subprocess.Popen(["true"])
    gone.wait()  # a pid that no process has now
    stale = tmp_path / f"autograder-slot0-p{gone.pid}-x1"
    (stale / "scratch" / "deep").mkdir(parents=True)
    mine = cleanup.private_folder("sandbox")
    other = tmp_path / "autograder-notes"  # not one of ours
    other.mkdir()
    assert cleanup.sweep_stale() == 1
    assert not stale.exists() and os.path.isdir(mine) and other.exists()
