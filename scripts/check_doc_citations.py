#!/usr/bin/env python3
"""Check that the documentation citations in the repository resolve inside the repository.

Checks (exit status 1 and one line per problem when any fails, 0 otherwise):
  1. Every section number cited from docs/physics-reference.md ("docs/physics-reference.md §3.2", or a bare
     "§3.2" in a file that cites the physics reference) is a heading of docs/physics-reference.md.
  2. Every section number cited from docs/profiles-and-formats.md is a heading of that file.
  3. The two references are cited by their repository path: a bare "physics-reference §3.2",
     "profiles-and-formats.md §1.1" or "physics-reference.md" (without "docs/") is a problem, and so is the
     old "architecture guide" (cite docs/architecture.md).
  4. Every cited docs/architecture.md, docs/physics-reference.md, docs/profiles-and-formats.md,
     docs/bibliography.md and docs/data.md exists.
  5. Every "paper NNN" cited has an entry "paper NNN" in docs/bibliography.md.
  6. No source, header, script, scenario, CMake or documentation file names a path outside the repository
     (parent-directory references to the shared folder, absolute paths under /work or /home, the shared docs
     or papers folders). The one exception is the run-time default of the shared data folder: the parent
     folder's shared/data exactly (not a path below it), in CMakeLists.txt (the CONFORMA_SHARED_DATA default)
     and README.md.

A "§" is attributed to the nearest source named before it on the same line: "physics-reference",
"profiles-and-formats", "paper NNN" (the paper's own sections: not checked), or an author/year just before the
"§" (e.g. "Johnson 1985 §4.2": an outside book, not checked). A bare "§" belongs to the file's reference
document: profiles-and-formats in files that cite only that document, the physics reference otherwise.

Usage: check_doc_citations.py [--root DIR] [--list]
  --root   the repository to check (default: the repository this script is in, the parent of scripts/).
  --list   also print every cited physics-reference / profiles-and-formats section with its locations.
Runs as a test: exit 0 when clean; 1 and one line per problem otherwise. Standard library only.
"""
import argparse
import os
import re
import sys

SOURCE_EXT = {".c", ".cc", ".cpp", ".h", ".hpp", ".py", ".sh", ".yaml", ".yml", ".md", ".cmake", ".csv"}
SOURCE_NAMES = {"CMakeLists.txt"}
SCRIPT_DIRS = {"scripts", ".ci"}  # every text file there is a script, whatever its extension
SKIP_DIRS = {".git", "__pycache__", "node_modules"}

# Paths outside the repository. Built from pieces so that this file does not match itself.
OUTSIDE_PATTERNS = [
    re.compile(re.escape(".." + "/shared")),
    re.compile(re.escape("/" + "work/")),
    re.compile(re.escape("/" + "home/")),
    re.compile(r"(?<![\w.])" + re.escape("shared" + "/docs/")),
    re.compile(r"(?<![\w.])" + re.escape("shared" + "/papers/")),
]
# The run-time default of the shared data folder (docs/data.md), tolerated in these files only, as the exact
# folder (a path below it, e.g. a data file, is still a problem).
DATA_DEFAULT = re.compile(re.escape(".." + "/shared/data") + r"(?![\w/.-])")
DATA_DEFAULT_FILES = {"CMakeLists.txt", "README.md"}

# The two references are cited by their repository path, exactly "docs/physics-reference.md" and
# "docs/profiles-and-formats.md". Other forms ("physics-reference §3.2", "physics reference §3.2",
# "profiles-and-formats.md §1.1", "shared/physics-reference.md") name the old outside documents.
REFERENCE_NAME = re.compile(r"(?<![\w.-])((?:[\w.-]*/)*)(physics-reference|profiles-and-formats)(\.md)?(?![\w-])"
                            r"|physics reference(?=\s*§)", re.I)
OUTSIDE_DOCUMENTS = [(re.compile(r"architecture guide", re.I), "docs/architecture.md")]
# Repository documents whose citations ("docs/NAME") must exist.
CITED_DOCS = ("architecture.md", "physics-reference.md", "profiles-and-formats.md", "bibliography.md", "data.md")
DOC_CITE = re.compile(r"(?<![\w/.-])docs/(" + "|".join(re.escape(d) for d in CITED_DOCS) + r")(?![\w-])")

PR, PF, PAPER, EXTERNAL = "physics-reference", "profiles-and-formats", "paper", "external"
QUALIFIERS = [
    (PR, re.compile(r"physics[- ]reference", re.I)),
    (PF, re.compile(r"profiles-and-formats", re.I)),
    (PAPER, re.compile(r"\bpaper\s+\d{3}\b", re.I)),
]
# An author / year (or a named outside document) immediately before the "§".
EXTERNAL_BEFORE = re.compile(r"(\b(1[6-9]|20)\d\d[a-z]?\)?,?|user[- ]guide|\.f90|\.tex|EN\s?\d{4,5}(-\d+)?)\s*$", re.I)

NUM = r"\d+(?:\.\d+)?"
DASH = r"\s*[-\u2013]\s*"
SECTION_TOKEN = re.compile(r"(§§?)\s*(" + NUM + r")(?:" + DASH + r"(" + NUM + r"))?")
LIST_TAIL = re.compile(r"\s*(?:,|and)\s*(" + NUM + r")(?:" + DASH + r"(" + NUM + r"))?")
HEADING = re.compile(r"^#{1,6}\s+(\d+(?:\.\d+)*)\.?(?:\s|$)")
PAPER_CITE = re.compile(r"\bpaper\s+(\d{3})\b", re.I)
BIB_KEY = re.compile(r"^#{1,6}\s+.*?\bpaper\s+(\d{3})\b", re.I)


def expand(first, last):
    """Section numbers of "first" or of the range "first-last" (expanded within one chapter)."""
    if last is None:
        return [first]
    a, b = first.split("."), last.split(".")
    if len(a) == 1 and len(b) == 1 and int(a[0]) <= int(b[0]):
        return [str(k) for k in range(int(a[0]), int(b[0]) + 1)]
    if len(a) == 2 and len(b) == 2 and a[0] == b[0] and int(a[1]) <= int(b[1]):
        return ["%s.%d" % (a[0], k) for k in range(int(a[1]), int(b[1]) + 1)]
    if len(a) == 2 and len(b) == 1 and int(a[1]) <= int(b[0]):  # "§1.2-4" = 1.2 ... 1.4
        return ["%s.%d" % (a[0], k) for k in range(int(a[1]), int(b[0]) + 1)]
    return [first, last]


def normalise(number):
    return ".".join(str(int(part)) for part in number.split("."))


def headings(path):
    found = set()
    if os.path.isfile(path):
        with open(path, encoding="utf-8") as f:
            for line in f:
                m = HEADING.match(line)
                if m:
                    found.add(normalise(m.group(1)))
    return found


def bibliography_keys(path):
    keys = set()
    if os.path.isfile(path):
        with open(path, encoding="utf-8") as f:
            for line in f:
                m = BIB_KEY.match(line)
                if m:
                    keys.add(m.group(1))
    return keys


def repository_files(root, self_path):
    for dirpath, dirnames, filenames in os.walk(root):
        rel_dir = os.path.relpath(dirpath, root)
        top = rel_dir.split(os.sep)[0]
        dirnames[:] = sorted(d for d in dirnames
                             if d not in SKIP_DIRS and not (rel_dir == "." and d.startswith("build")))
        for name in sorted(filenames):
            path = os.path.join(dirpath, name)
            if os.path.abspath(path) == self_path:
                continue
            ext = os.path.splitext(name)[1].lower()
            if ext in SOURCE_EXT or name in SOURCE_NAMES or (top in SCRIPT_DIRS and not ext):
                yield path


def read_lines(path):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read().splitlines()
    except (UnicodeDecodeError, OSError):
        return None


def file_default(rel, text):
    if rel == os.path.join("docs", "profiles-and-formats.md"):
        return PF
    if rel == os.path.join("docs", "physics-reference.md"):
        return PR
    cites_pr = re.search(r"physics[- ]reference", text, re.I) is not None
    cites_pf = re.search(r"profiles-and-formats", text, re.I) is not None
    return PF if cites_pf and not cites_pr else PR


def attribute(line, start, default):
    before = line[:start]
    if EXTERNAL_BEFORE.search(before):
        return EXTERNAL
    best, best_end = None, -1
    for kind, rx in QUALIFIERS:
        for m in rx.finditer(before):
            if m.end() > best_end:
                best, best_end = kind, m.end()
    return best if best is not None else default


def section_citations(line, default):
    """(kind, [section numbers]) for every § token of a line."""
    out = []
    for m in SECTION_TOKEN.finditer(line):
        kind = attribute(line, m.start(), default)
        numbers = expand(m.group(2), m.group(3))
        if m.group(1) == "§§":  # "§§3, 4, 5, 9"
            pos = m.end()
            while True:
                t = LIST_TAIL.match(line, pos)
                if not t:
                    break
                numbers += expand(t.group(1), t.group(2))
                pos = t.end()
        out.append((kind, [normalise(n) for n in numbers]))
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", default=os.path.dirname(here), help="repository root (default: parent of scripts/)")
    parser.add_argument("--list", action="store_true", help="print every cited section with its locations")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    self_path = os.path.abspath(__file__)

    docs = os.path.join(root, "docs")
    known = {PR: headings(os.path.join(docs, "physics-reference.md")),
             PF: headings(os.path.join(docs, "profiles-and-formats.md"))}
    bib = bibliography_keys(os.path.join(docs, "bibliography.md"))

    problems = []
    cited = {PR: {}, PF: {}}
    for path in repository_files(root, self_path):
        rel = os.path.relpath(path, root)
        lines = read_lines(path)
        if lines is None:
            continue
        default = file_default(rel, "\n".join(lines))
        for number, line in enumerate(lines, 1):
            where = "%s:%d" % (rel, number)
            checked = line
            if rel in DATA_DEFAULT_FILES:
                checked = DATA_DEFAULT.sub("", checked)
            for rx in OUTSIDE_PATTERNS:
                m = rx.search(checked)
                if m:
                    problems.append("%s: path outside the repository '%s': %s" % (where, m.group(0), line.strip()[:120]))
                    break
            for m in REFERENCE_NAME.finditer(line):
                if m.group(2) is None or m.group(1) != "docs/" or m.group(3) != ".md":
                    problems.append("%s: cite '%s' as docs/%s.md: %s" % (
                        where, m.group(0), (m.group(2) or "physics-reference").lower(), line.strip()[:120]))
            for rx, doc in OUTSIDE_DOCUMENTS:
                m = rx.search(line)
                if m:
                    problems.append("%s: '%s' is not in the repository, cite %s: %s" % (
                        where, m.group(0), doc, line.strip()[:120]))
            for m in DOC_CITE.finditer(line):
                if not os.path.isfile(os.path.join(docs, m.group(1))):
                    problems.append("%s: docs/%s is cited but does not exist" % (where, m.group(1)))
            if "§" in line:
                for kind, numbers in section_citations(line, default):
                    if kind not in cited:
                        continue
                    for n in numbers:
                        cited[kind].setdefault(n, []).append(where)
            for m in PAPER_CITE.finditer(line):
                if m.group(1) not in bib:
                    problems.append("%s: 'paper %s' has no entry in docs/bibliography.md" % (where, m.group(1)))

    def key(n):
        return [int(p) for p in n.split(".")]

    for kind, doc in ((PR, "docs/physics-reference.md"), (PF, "docs/profiles-and-formats.md")):
        for n in sorted(cited[kind], key=key):
            if n not in known[kind]:
                locations = cited[kind][n]
                problems.append("%s §%s has no heading (cited at %s%s)" % (
                    doc, n, ", ".join(locations[:5]), " and %d more" % (len(locations) - 5) if len(locations) > 5 else ""))

    if args.list:
        for kind, doc in ((PR, "docs/physics-reference.md"), (PF, "docs/profiles-and-formats.md")):
            print("%s: sections cited" % doc)
            for n in sorted(cited[kind], key=key):
                locations = cited[kind][n]
                in_code = [w for w in locations if not w.startswith("docs" + os.sep)]
                print("  §%-6s %-8s code %3d, docs %3d   e.g. %s" % (
                    n, "ok" if n in known[kind] else "MISSING", len(in_code), len(locations) - len(in_code),
                    (in_code or locations)[0]))

    for p in problems:
        print(p)
    if problems:
        print("check_doc_citations: %d problem(s)" % len(problems), file=sys.stderr)
        return 1
    print("check_doc_citations: all citations resolve inside the repository")
    return 0


if __name__ == "__main__":
    sys.exit(main())
