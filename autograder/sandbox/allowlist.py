"""What a sandbox sees of this machine: an allow-list, never a system folder wholesale.

A sandbox's world is bubblewrap's empty root plus, read-only, exactly:

- the interpreter (the venv's ``bin/python`` links and ``pyvenv.cfg``, the real binary) and its standard
  library (with any ``site-packages`` inside it masked by an empty folder);
- the distributions the sandboxed programs import (:data:`ROOT_DISTRIBUTIONS` and everything they require,
  by ``importlib.metadata``): each one's own top-level entries of its ``site-packages`` and its metadata
  folder, never the ``site-packages`` folder as a whole;
- the shared libraries all of that links to (the ELF ``DT_NEEDED`` closure of the interpreter and of every
  extension module bound, resolved as the dynamic loader would: ``RUNPATH``/``RPATH``, the loader's
  configured folders, the default ones), and the loader itself;
- a handful of ``/etc`` files (the loader's cache, ``passwd``, ``localtime``...) and the top-level links of
  merged-``/usr`` systems (``/lib -> usr/lib``).

``coursekit`` and the sandbox's own programs are copied to ``/sandbox`` by the launcher, and ``/tmp`` is
the sandbox's scratch. Nothing else exists inside: not ``/usr/share``, not the grader's checkout, not other
distributions. The list is computed once per grader process (:func:`sandbox_view`, cached; about 0.1 s) and
works wherever Python lives (``/usr``, ``/usr/local``, ``~/.pyenv``, a venv, ``/tmp``). What it lets through
is checked from inside, before any student is graded, by the canary's view probe
(:func:`autograder.grading.canary.check_sandbox_view`).

Examples
--------
>>> view = sandbox_view()
>>> any(dest == "/usr" for _, dest in view.binds)
False
>>> view.bwrap_args()[:2]                                     # doctest: +SKIP
['--symlink', 'usr/bin']
"""

from __future__ import annotations

import functools
import glob
import importlib.metadata as metadata
import os
import re
import struct
import sys
from dataclasses import dataclass

# What the sandboxed programs import (child/: the worker, feeder and zygote: numpy, scipy, coursekit; the
# notebook stage's runner and kernels: pytest, nbval, ipykernel, jupyter_client; the course's notebooks and
# coursekit: matplotlib, IPython, ipywidgets). Their requirements come along by importlib.metadata.
ROOT_DISTRIBUTIONS = (
    "numpy",
    "scipy",
    "matplotlib",
    "ipython",
    "ipykernel",
    "ipywidgets",
    "jupyter_client",
    "nbformat",
    "nbval",
    "pytest",
)

ETC_FILES = (
    "/etc/ld.so.cache",
    "/etc/ld.so.conf",
    "/etc/ld.so.conf.d",
    "/etc/localtime",
    "/etc/nsswitch.conf",
    "/etc/passwd",
    "/etc/group",
)
TOP_LEVEL_LINKS = ("/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")
DEFAULT_LIBRARY_DIRS = ("/lib64", "/usr/lib64", "/lib", "/usr/lib")
SITE_NAMES = ("site-packages", "dist-packages")


@dataclass(frozen=True)
class View:
    """A sandbox's view of the host: what bubblewrap binds (``(source, destination)``, read-only), the links
    it makes (``(target, path)``) and the folders it masks with an empty read-only tmpfs."""

    binds: tuple[tuple[str, str], ...]
    links: tuple[tuple[str, str], ...]
    masks: tuple[str, ...]

    def bwrap_args(self) -> list[str]:
        """bubblewrap arguments that build this view (parents before children; missing parents 0755).

        >>> View(binds=(("/opt/py/lib/libz.so.1", "/opt/py/lib/libz.so.1"),), links=(), masks=()).bwrap_args()
        ['--perms', '0755', '--dir', '/opt', '--perms', '0755', '--dir', '/opt/py', '--perms', '0755', \
'--dir', '/opt/py/lib', '--ro-bind', '/opt/py/lib/libz.so.1', '/opt/py/lib/libz.so.1']
        """
        operations = [(dest, 0, ("--symlink", target, dest)) for target, dest in self.links]
        operations += [(dest, 1, ("--ro-bind", source, dest)) for source, dest in self.binds]
        operations += [(dest, 2, ("--tmpfs", dest)) for dest in self.masks]
        # a mount point's parents first: a bind inside a masked folder comes after its mask
        operations.sort(key=lambda op: (op[0].count("/"), op[1], op[0]))
        mounted = {dest for dest, kind, _ in operations if kind}
        made: set[str] = set()
        args: list[str] = []
        for dest, _, op in operations:
            for parent in _parents(dest):
                if parent in made or parent == "/tmp" or _under_any(parent, mounted, strict=False):
                    continue
                made.add(parent)
                args += ["--perms", "0755", "--dir", parent]
            args += list(op)
        # read-only once the binds inside them are made
        return args + [arg for dest in self.masks for arg in ("--remount-ro", dest)]

    def paths(self) -> list[str]:
        """Every path this view makes exist inside (bind destinations, links and masks), sorted."""
        return sorted({d for _, d in self.binds} | {p for _, p in self.links} | set(self.masks))


def _parents(path: str) -> list[str]:
    parts = path.strip("/").split("/")[:-1]
    return ["/" + "/".join(parts[: i + 1]) for i in range(len(parts))]


def _under_any(path: str, folders, strict: bool = True) -> bool:
    """Is ``path`` inside one of ``folders`` (or one of them, unless ``strict``)?"""
    return any(path.startswith(f.rstrip("/") + "/") or (not strict and path == f) for f in folders)


# --- distributions ------------------------------------------------------------------------------------------------

_NAME = re.compile(r"\s*([A-Za-z0-9][A-Za-z0-9._-]*)")


def _required(dist: metadata.Distribution) -> list[str]:
    """The distributions ``dist`` requires (no extras; markers evaluated when ``packaging`` is there)."""
    text = dist.read_text("METADATA") or dist.read_text("PKG-INFO") or ""
    names = []
    for line in text.split("\n\n", 1)[0].splitlines():  # the headers only, not the long description
        if not line.startswith("Requires-Dist:"):
            continue
        name, _, marker = line[len("Requires-Dist:") :].partition(";")
        if "extra" in marker:
            continue
        if marker.strip() and not _marker_holds(marker.strip()):
            continue
        match = _NAME.match(name)
        if match:
            names.append(match.group(1))
    return names


def _marker_holds(marker: str) -> bool:
    try:
        from packaging.markers import Marker

        return Marker(marker).evaluate()
    except Exception:  # no packaging, or a marker it cannot read: keep it (one folder too many at worst)
        return True


def _normal(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def distribution_closure(roots: tuple[str, ...] = ROOT_DISTRIBUTIONS) -> list[metadata.Distribution]:
    """The installed distributions ``roots`` names and everything they require, transitively.

    >>> "numpy" in {_normal(d.metadata["Name"]) for d in distribution_closure(("scipy",))}
    True
    """
    seen: dict[str, metadata.Distribution] = {}
    todo = list(roots)
    while todo:
        name = _normal(todo.pop())
        if name in seen:
            continue
        try:
            dist = metadata.distribution(name)
        except metadata.PackageNotFoundError:
            continue
        seen[name] = dist
        todo += _required(dist)
    return list(seen.values())


def _distribution_entries(dist: metadata.Distribution) -> tuple[set[str], list[str]]:
    """Top-level paths of ``dist`` inside its ``site-packages`` (packages, modules, ``.libs``, its metadata
    folder), absolute, and its ELF files (by name: ``*.so*``); never a ``.pth`` file, nothing outside that
    folder (scripts, ``share/``)."""
    metadata_dir = getattr(dist, "_path", None)
    if metadata_dir is None:
        return set(), []
    site_dir = os.path.dirname(os.path.abspath(str(metadata_dir)))
    entries = {os.path.abspath(str(metadata_dir))}
    elves = []
    record = dist.read_text("RECORD")  # read as text: dist.files builds a Path per line, ten times slower
    if record:
        for line in record.splitlines():
            path = line.rsplit(",", 2)[0].strip('"')
            top = path.split("/", 1)[0]
            if not top or top == ".." or path.startswith("/") or top.endswith(".pth") or top == "__pycache__":
                continue
            entries.add(os.path.join(site_dir, top))
            if ".so" in path.rsplit("/", 1)[-1]:
                elves.append(os.path.join(site_dir, path))
    else:  # no RECORD (a distribution installed by the system's package manager): its top-level names
        names = (dist.read_text("top_level.txt") or "").split() or [dist.metadata["Name"].replace("-", "_")]
        for name in names:
            for candidate in (name, name + ".py", *glob.glob(os.path.join(site_dir, glob.escape(name) + ".*.so"))):
                entries.add(os.path.join(site_dir, candidate))
        elves += _extension_modules({os.path.join(site_dir, name) for name in names})
    return {e for e in entries if os.path.lexists(e)}, elves


# --- the interpreter ----------------------------------------------------------------------------------------------


def _link_chain(path: str) -> tuple[list[tuple[str, str]], str]:
    """The symbolic links from ``path`` to the file it names (``(target, link)``), and that file's real path."""
    links = []
    path = os.path.abspath(path)
    for _ in range(40):
        if not os.path.islink(path):
            break
        target = os.readlink(path)
        links.append((target, path))
        path = os.path.normpath(os.path.join(os.path.dirname(path), target))
    return links, os.path.realpath(path)


def _python_parts() -> tuple[set[str], list[tuple[str, str]], set[str]]:
    """(paths to bind, links to make, folders to mask) for the interpreter and its standard library."""
    binds: set[str] = set()
    links, real = _link_chain(sys.executable)
    binds.add(real)
    for prefix in {sys.prefix, os.path.abspath(sys.prefix)}:
        cfg = os.path.join(prefix, "pyvenv.cfg")
        if os.path.isfile(cfg):
            binds.add(cfg)
    stdlib = os.path.dirname(os.path.abspath(os.__file__))
    binds.add(stdlib)
    masks: set[str] = set()
    for entry in sys.path:
        if entry and os.path.basename(entry) == "lib-dynload" and os.path.isdir(entry):
            binds.add(entry)  # the standard library's extension modules (inside it or apart)
    for name in SITE_NAMES:  # a site-packages inside the standard library (pyenv, /usr/local) is masked
        inside = os.path.join(stdlib, name)
        if os.path.isdir(inside):
            masks.add(inside)
    return binds, links, masks


# --- shared libraries ---------------------------------------------------------------------------------------------

DT_NEEDED, DT_STRTAB, DT_RPATH, DT_RUNPATH = 1, 5, 15, 29
PT_LOAD, PT_DYNAMIC, PT_INTERP = 1, 2, 3


def elf_dependencies(path: str) -> tuple[list[str], list[str], str]:
    """``(needed, search path, interpreter)`` of an ELF file: its ``DT_NEEDED`` names, its ``RUNPATH`` (else
    ``RPATH``) folders with ``$ORIGIN`` expanded, and its ``PT_INTERP``; empty when it is not a 64- or 32-bit
    ELF file this reader understands.

    >>> needed, _, interpreter = elf_dependencies(os.path.realpath(sys.executable))
    >>> any(name.startswith("libc.so") for name in needed) and interpreter.startswith("/")   # doctest: +SKIP
    True
    """
    try:
        with open(path, "rb") as file:
            head = file.read(64)
            if len(head) < 52 or head[:4] != b"\x7fELF":
                return [], [], ""
            wide, order = head[4] == 2, "<" if head[5] == 1 else ">"
            if wide:
                phoff, phentsize, phnum = (
                    struct.unpack_from(order + "Q", head, 32)[0],
                    *struct.unpack_from(order + "HH", head, 54),
                )
            else:
                phoff, phentsize, phnum = (
                    struct.unpack_from(order + "I", head, 28)[0],
                    *struct.unpack_from(order + "HH", head, 42),
                )
            file.seek(phoff)
            table = file.read(phentsize * phnum)
            loads, dynamic, interpreter = [], None, ""
            for i in range(phnum):
                if wide:
                    kind, _, offset, vaddr, _, filesz = struct.unpack_from(order + "IIQQQQ", table, i * phentsize)
                else:
                    kind, offset, vaddr, _, filesz = struct.unpack_from(order + "IIIII", table, i * phentsize)
                if kind == PT_LOAD:
                    loads.append((vaddr, offset, filesz))
                elif kind == PT_DYNAMIC:
                    dynamic = (offset, filesz)
                elif kind == PT_INTERP:
                    file.seek(offset)
                    interpreter = file.read(filesz).split(b"\0")[0].decode("utf-8", "replace")
            if dynamic is None:
                return [], [], interpreter
            file.seek(dynamic[0])
            raw = file.read(dynamic[1])
            size = 16 if wide else 8
            entries = [struct.unpack_from(order + ("qQ" if wide else "iI"), raw, i) for i in range(0, len(raw), size)]
            strtab = next((value for tag, value in entries if tag == DT_STRTAB), None)
            if strtab is None:
                return [], [], interpreter
            base = next((off + strtab - va for va, off, sz in loads if va <= strtab < va + sz), None)
            if base is None:
                return [], [], interpreter

            def string(at):
                file.seek(base + at)
                return file.read(4096).split(b"\0")[0].decode("utf-8", "replace")

            needed, runpath, rpath = [], [], []
            for tag, value in entries:
                if tag == 0:
                    break
                if tag == DT_NEEDED:
                    needed.append(string(value))
                elif tag == DT_RUNPATH:
                    runpath += string(value).split(":")
                elif tag == DT_RPATH:
                    rpath += string(value).split(":")
    except (OSError, struct.error):
        return [], [], ""
    origin = os.path.dirname(path)
    search = [p.replace("$ORIGIN", origin).replace("${ORIGIN}", origin) for p in (runpath or rpath) if p]
    return needed, search, interpreter


def _loader_dirs() -> list[str]:
    """The folders the dynamic loader searches after RUNPATH: /etc/ld.so.conf (with its includes), the
    folders this process's own libraries came from, and the default ones."""
    folders: list[str] = []

    def read(conf, depth=0):
        try:
            lines = open(conf, encoding="utf-8", errors="replace").read().splitlines()
        except OSError:
            return
        for line in lines:
            line = line.split("#")[0].strip()
            if line.startswith("include ") and depth < 4:
                for included in sorted(glob.glob(os.path.join(os.path.dirname(conf), line.split(None, 1)[1]))):
                    read(included, depth + 1)
            elif line.startswith("/"):
                folders.append(line)

    read("/etc/ld.so.conf")
    try:
        with open("/proc/self/maps", encoding="utf-8", errors="replace") as maps:
            for line in maps:
                path = line.split(None, 5)[-1].strip()
                if path.startswith("/") and ".so" in os.path.basename(path):
                    folders.append(os.path.dirname(path))
    except OSError:
        pass
    multiarch = getattr(sys.implementation, "_multiarch", "")
    if multiarch:
        folders += [f"/lib/{multiarch}", f"/usr/lib/{multiarch}"]
    folders += list(DEFAULT_LIBRARY_DIRS)
    return list(dict.fromkeys(folders))


def shared_libraries(files: list[str]) -> set[str]:
    """Every shared library ``files`` (ELF executables and extension modules) need, transitively, and their
    loader: paths as the loader finds them (not resolved through links).

    >>> any("libc.so" in lib for lib in shared_libraries([os.path.realpath(sys.executable)]))  # doctest: +SKIP
    True
    """
    loader_dirs = _loader_dirs()
    found: set[str] = set()
    done: set[str] = set()
    todo = list(files)
    while todo:
        path = todo.pop()
        real = os.path.realpath(path)
        if real in done:
            continue
        done.add(real)
        needed, search, interpreter = elf_dependencies(real)
        if interpreter and os.path.exists(interpreter):
            found.add(interpreter)
            todo.append(interpreter)
        for name in needed:
            candidates = [name] if "/" in name else [os.path.join(d, name) for d in search + loader_dirs]
            hit = next((c for c in candidates if os.path.isfile(c)), None)
            if hit is not None:
                found.add(os.path.abspath(hit))
                todo.append(hit)
    return found


def _extension_modules(paths: set[str]) -> list[str]:
    """The ELF files (``*.so``, ``*.so.N``) under ``paths`` (files or folders)."""
    modules = []
    for path in paths:
        if os.path.isfile(path):
            if ".so" in os.path.basename(path):
                modules.append(path)
            continue
        for folder, dirs, names in os.walk(path):
            dirs[:] = [d for d in dirs if d != "__pycache__"]
            modules += [os.path.join(folder, n) for n in names if ".so" in n]
    return modules


# --- the view -----------------------------------------------------------------------------------------------------


def _in_sandbox(path: str) -> str:
    """Where a host path is bound inside: its folder resolved through links, its own name kept (so
    ``/lib/x86_64-linux-gnu/libz.so.1`` lands in ``/usr/lib/...`` where ``/lib`` links to ``usr/lib``)."""
    return os.path.join(os.path.realpath(os.path.dirname(os.path.abspath(path))), os.path.basename(path))


def build_view(roots: tuple[str, ...] = ROOT_DISTRIBUTIONS) -> View:
    """Compute the allow-list for this interpreter and the distributions ``roots`` (see the module's doc).

    >>> view = build_view(("numpy",))
    >>> any(dest.endswith("/site-packages/numpy") for _, dest in view.binds)     # doctest: +SKIP
    True
    """
    python, links, masks = _python_parts()
    packages: set[str] = set()
    elves = [p for p in python if os.path.isfile(p)]
    for dist in distribution_closure(roots):
        entries, files = _distribution_entries(dist)
        packages |= entries
        elves += files
    # an allowed entry that is itself a site folder, or holds one, would bring everything: never
    packages = {p for p in packages if os.path.basename(p) not in SITE_NAMES}
    # the standard library's extension modules but tkinter's: no display in a sandbox, and Tk's X11 libraries
    # would be a fifth of the binds (each one costs bubblewrap about a millisecond at every start)
    elves += [
        path
        for path in _extension_modules({p for p in python if os.path.basename(p) == "lib-dynload"})
        if not os.path.basename(path).startswith("_tkinter")
    ]
    libraries = shared_libraries(elves)
    binds: dict[str, str] = {}
    for path in sorted(python | packages | libraries):
        dest = _in_sandbox(path)
        # already seen through a folder bound above it, unless a mask between hides it
        holders = [d for d in [*binds.values(), *masks] if _under_any(dest, [d])]
        if not holders or max(holders, key=len) in masks:
            binds[path] = dest
    # the interpreter's links (the venv's bin/python -> python3 -> /root/.pyenv/.../python3.11): made as links
    links_made = [(target, _in_sandbox(link)) for target, link in links]
    for name in TOP_LEVEL_LINKS:
        if os.path.islink(name):
            links_made.append((os.readlink(name), name))
    for name in ETC_FILES:
        if os.path.exists(name):
            binds[name] = name
    for name in ("/usr/lib/locale/C.utf8", "/usr/lib/locale/C.UTF-8"):
        if os.path.isdir(name):
            binds[name] = name
    # a mask only where something bound would otherwise show it
    masks = {m for m in masks if _under_any(m, binds.values())}
    return View(
        binds=tuple(sorted((s, d) for s, d in binds.items())),
        links=tuple(sorted(set(links_made))),
        masks=tuple(sorted(masks)),
    )


@functools.lru_cache(maxsize=1)
def sandbox_view() -> View:
    """:func:`build_view` for this grader process (computed once, then cached)."""
    return build_view()
