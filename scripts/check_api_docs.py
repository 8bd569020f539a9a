#!/usr/bin/env python3
"""Check that every field of the public Options / Result / ... structs and every enum value is documented.

Issue 12: every public Options/Result field documented. Scanned files: include/conforma/**/*.hpp and the C interface
capi/conforma_c.h. A simple heuristic, not a C++ parser:

  * Structs and classes whose name ends in Options, Result, Summary, Report, Solution, Input, Problem, Record, Row,
    Case or Setup (in conforma_c.h: every typedef struct). Every data member declared directly in such a block,
    `type name = value;`, `type name{value};` or `type name;` (also `static constexpr` ones, not functions, types,
    `using` or `friend` lines), must be documented:
      - a comment on one of its own lines (`//` or `/* */`), or
      - a `//` comment line directly above it, at the member's own indentation, or above a run of consecutive
        members that the comment covers (the run may include trailing-comment continuation lines).
  * Every enum (`enum` / `enum class`): each value needs a comment on its own line when it is alone on its line, or
    a comment mentioning its name (as a word) on its line or in the comment lines directly above that line (so a
    one-line enum is documented by a comment block above it that names every value).

Usage: check_api_docs.py [--root DIR] [--list]
  --root   the repository to check (default: the repository this script is in, the parent of scripts/).
  --list   print every checked member and enum value with its location and verdict (instead of the problems only).
Exit status 0 when everything is documented; 1 and one line "file:line: struct::member undocumented" per problem
otherwise. Standard library only.
"""
import argparse
import os
import re
import sys

KINDS = ("Options", "Result", "Summary", "Report", "Solution", "Input", "Problem", "Record", "Row", "Case", "Setup")
C_HEADER = os.path.join("capi", "conforma_c.h")
NON_MEMBER_START = re.compile(r"^(using|typedef|friend|static_assert|template|enum|struct|class|union|operator)\b")
TYPE_HEAD = re.compile(r"\b(struct|class|union)\s+(\w+)\b[^=();]*$")
ENUM_HEAD = re.compile(r"\benum\b(?:\s+(?:class|struct))?\s*(\w*)[^=();]*$")
ACCESS = re.compile(r"^\s*(public|private|protected)\s*$")
IDENT = re.compile(r"[A-Za-z_]\w*")


def strip_comments(text):
    """Returns (code, comment_lines): the text with comments blanked (newlines kept, so offsets and line numbers
    stay) and, per line number (1-based), whether a comment is on that line."""
    out = []
    has_comment = {}
    i, n, line = 0, len(text), 1
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            has_comment[line] = True
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            for ch in text[i:j]:
                has_comment[line] = True
                if ch == "\n":
                    line += 1
                    out.append("\n")
                else:
                    out.append(" ")
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            line += text[i:j + 1].count("\n")
            i = j + 1
        else:
            if c == "\n":
                line += 1
            out.append(c)
            i += 1
    return "".join(out), has_comment


def remove_templates(s):
    prev = None
    while prev != s:
        prev = s
        s = re.sub(r"<[^<>]*>", "", s)
    return s


def is_data_member(stmt):
    s = " ".join(stmt.split())
    if not s or NON_MEMBER_START.match(s) or ACCESS.match(s):
        return False
    s = re.sub(r"^(static|constexpr|inline|mutable|const|volatile)\s+", "", s)
    s = remove_templates(s)
    head = re.split(r"[={]", s, maxsplit=1)[0]
    if "(" in head or "operator" in head or "~" in head:
        return False  # a function (declaration, definition or operator)
    return len(IDENT.findall(head)) >= 2


def declarator_names(stmt):
    """The names declared by a member statement (`double a = 0.0, b = 0.0` -> a, b)."""
    s = remove_templates(" ".join(stmt.split()))
    depth, parts, cur = 0, [], ""
    for ch in s:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    names = []
    for k, part in enumerate(parts):
        head = re.split(r"[={\[]", part, maxsplit=1)[0]
        ids = IDENT.findall(head)
        if ids:
            names.append(ids[-1])
    return names


class Frame:
    def __init__(self, kind, name="", checked=False):
        self.kind = kind      # "struct", "enum", "init" (brace initialiser of a member), "other"
        self.name = name
        self.checked = checked
        self.stmt = ""
        self.stmt_start = None  # offset of the first non-space character of the statement


def scan(code, is_c_header):
    """Yields ("member", struct, names, start_offset, end_offset) and ("enum", enum, value, start, end)."""
    stack = [Frame("other")]
    i, n = 0, len(code)

    def add(frame, ch, pos):
        if frame.stmt_start is None and not ch.isspace():
            frame.stmt_start = pos
        frame.stmt += ch

    def reset(frame):
        frame.stmt, frame.stmt_start = "", None

    while i < n:
        c = code[i]
        top = stack[-1]
        if c == "#" and not code[code.rfind("\n", 0, i) + 1:i].strip():
            j = code.find("\n", i)
            while j > 0 and code[j - 1] == "\\":
                j = code.find("\n", j + 1)
            i = n if j < 0 else j
            continue
        if top.kind == "init":
            if c == "{":
                stack.append(Frame("init"))
            elif c == "}":
                stack.pop()
            add(_owner(stack), c, i)
            i += 1
            continue
        if c == "{":
            stmt = " ".join(top.stmt.split())
            m_type = TYPE_HEAD.search(stmt)
            m_enum = ENUM_HEAD.search(stmt)
            if m_enum and "enum" in stmt:
                stack.append(Frame("enum", m_enum.group(1) or "(anonymous)", True))
            elif m_type and not re.search(r"\)\s*$", stmt):
                name = m_type.group(2)
                checked = (top.kind in ("other", "struct")) and (
                    (is_c_header and stmt.startswith("typedef")) or name.endswith(KINDS))
                stack.append(Frame("struct", name, checked))
            elif top.kind == "struct" and top.stmt_start is not None and is_data_member(top.stmt):
                stack.append(Frame("init"))
                add(top, c, i)
            else:
                stack.append(Frame("other"))
            i += 1
            continue
        if c == "}":
            frame = stack.pop() if len(stack) > 1 else top
            if frame.kind == "enum" and frame.stmt.strip():
                yield from _enum_value(frame, code)
            parent = stack[-1]
            if frame.kind == "other" and parent.kind == "struct":
                reset(parent)  # end of an inline function body
            elif frame.kind in ("struct", "enum"):
                reset(parent)  # `} name;` of a typedef or `};`: not a member
                parent.stmt = "__type_end__"
                parent.stmt_start = None
            i += 1
            continue
        if top.kind == "enum":
            if c == ",":
                yield from _enum_value(top, code)
                reset(top)
            else:
                add(top, c, i)
            i += 1
            continue
        if c == ";":
            if top.kind == "struct" and top.checked and top.stmt_start is not None \
                    and top.stmt != "__type_end__" and is_data_member(top.stmt):
                yield ("member", top.name, declarator_names(top.stmt), top.stmt_start, i)
            reset(top)
            i += 1
            continue
        if c == ":" and top.kind == "struct" and ACCESS.match(top.stmt):
            reset(top)
            i += 1
            continue
        if top.stmt == "__type_end__":
            reset(top)
        add(top, c, i)
        i += 1


def _owner(stack):
    for frame in reversed(stack):
        if frame.kind != "init":
            return frame
    return stack[0]


def _enum_value(frame, code):
    text = frame.stmt
    ids = IDENT.findall(text.split("=")[0])
    if ids and frame.stmt_start is not None:
        end = frame.stmt_start + len(text.strip()) - 1
        yield ("enum", frame.name, [ids[0]], frame.stmt_start, end)


def line_of(offsets, pos):
    lo, hi = 0, len(offsets)
    while lo < hi:
        mid = (lo + hi) // 2
        if offsets[mid] <= pos:
            lo = mid + 1
        else:
            hi = mid
    return lo  # 1-based line number


def check_file(path, rel, is_c_header, listing):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    lines = text.split("\n")
    code, has_comment = strip_comments(text)
    offsets = [0]
    for k, ch in enumerate(text):
        if ch == "\n":
            offsets.append(k + 1)
    items = list(scan(code, is_c_header))

    def indent(k):
        return len(lines[k - 1]) - len(lines[k - 1].lstrip())

    code_lines = code.split("\n")

    def comment_only(k):
        return 1 <= k <= len(lines) and has_comment.get(k, False) and not code_lines[k - 1].strip()

    def comment_text(k):
        return "".join(t if c == " " else " " for t, c in zip(lines[k - 1], code_lines[k - 1]))

    member_lines = set()
    enum_line_values = {}
    for kind, owner, names, start, end in items:
        a, b = line_of(offsets, start), line_of(offsets, end)
        if kind == "member":
            member_lines.update(range(a, b + 1))
        else:
            enum_line_values.setdefault(a, []).append(names[0])

    def comment_block_above(k):
        """Text of the comment-only lines directly above line k."""
        block, j = [], k - 1
        while comment_only(j):
            block.append(lines[j - 1])
            j -= 1
        return "\n".join(block)

    problems, count = [], 0
    for kind, owner, names, start, end in items:
        a, b = line_of(offsets, start), line_of(offsets, end)
        count += len(names)
        if kind == "member":
            ok = any(has_comment.get(k) for k in range(a, b + 1))
            if not ok:
                j = a - 1
                while j in member_lines or (comment_only(j) and indent(j) > indent(a)):
                    j -= 1
                ok = comment_only(j) and indent(j) == indent(a)
        else:
            name = names[0]
            word = re.compile(r"\b" + re.escape(name) + r"\b")
            own_comment = comment_text(a)
            alone = len(enum_line_values.get(a, [])) == 1
            ok = bool(word.search(own_comment)) or bool(word.search(comment_block_above(a)))
            if not ok and alone:
                j = a - 1
                ok = has_comment.get(a, False) or (comment_only(j) and indent(j) == indent(a))
        what = owner + "::" + ",".join(names)
        if listing:
            print(f"{rel}:{a}: {what} {'ok' if ok else 'UNDOCUMENTED'}")
        if not ok:
            problems.append(f"{rel}:{a}: {what} undocumented")
    return problems, count


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--root", default=os.path.dirname(here))
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    files = []
    include = os.path.join(root, "include", "conforma")
    for dirpath, dirnames, filenames in os.walk(include):
        dirnames.sort()
        for name in sorted(filenames):
            if name.endswith(".hpp"):
                files.append((os.path.join(dirpath, name), False))
    if os.path.isfile(os.path.join(root, C_HEADER)):
        files.append((os.path.join(root, C_HEADER), True))
    if not files:
        print(f"no public headers under {include}", file=sys.stderr)
        return 1
    problems, count = [], 0
    for path, is_c in files:
        p, c = check_file(path, os.path.relpath(path, root), is_c, args.list)
        problems += p
        count += c
    if not args.list:  # --list already printed every item with its verdict
        for p in problems:
            print(p)
    print(f"check_api_docs: {count} members and enum values in {len(files)} headers, {len(problems)} undocumented",
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
