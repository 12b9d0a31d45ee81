#!/usr/bin/env python3
"""Write docs/guide/api.md: everything `use hillstab` gives, grouped by the module it
comes from, each name linked to its page of the API reference with the first line of its
doc comment; and the same names, linked, into the doc comment of src/hillstab.f90 (the
block "What it exports"), so that the umbrella's own page lists them.

The umbrella module src/hillstab.f90 re-exports with `only:` lists; FORD documents the
entities on the pages of the modules that define them and shows the umbrella itself
without contents, so this page is the umbrella's table of contents. `make doc-check`
(scripts/doc_check.py) fails when the page is not what this script writes: run it after
changing an `only:` list or a doc comment of an exported entity.
Usage: scripts/api_page.py [--check]   (--check: exit 1 when either is not current)
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UMBRELLA = os.path.join(ROOT, "src", "hillstab.f90")
PAGE = os.path.join(ROOT, "docs", "guide", "api.md")
FOLDERS = ("core", "ffi", "hill", "integrate", "curves", "pendulum", "batch", "interop")


def joined(lines):
    """Logical lines (continuations joined), with their doc comments kept apart."""
    out, current = [], ""
    for line in lines:
        code = line.split("!", 1)[0] if not line.lstrip().startswith("!") else ""
        if current:
            current += " " + code.strip().lstrip("&")
        else:
            current = code.strip()
        if current.endswith("&"):
            current = current[:-1]
            continue
        if current:
            out.append(current)
        current = ""
    return out


def module_path(module):
    rest = module[len("hillstab_"):]
    for folder in FOLDERS:
        if rest.startswith(folder + "_"):
            return os.path.join(ROOT, "src", "hillstab", folder, rest[len(folder) + 1:] + ".f90")
    raise SystemExit(f"api_page: no file for module {module}")


def first_sentence(text):
    text = " ".join(text.split())
    m = re.match(r"(.+?[.:;])(\s|$)", text)
    return (m.group(1) if m else text).rstrip(":;").rstrip()


def doc_before(lines, k):
    """The `!>` block right above line k (blank-free), joined."""
    block = []
    j = k - 1
    while j >= 0 and lines[j].lstrip().startswith("!>"):
        block.insert(0, lines[j].lstrip()[2:].strip())
        j -= 1
    # stop at the first empty doc line: the summary paragraph
    summary = []
    for line in block:
        if not line:
            if summary:
                break
            continue
        summary.append(line)
    return " ".join(summary)


def declared(code):
    """The names a declaration `... :: a, b = 1, c(2)` declares (lower case)."""
    if "::" not in code:
        return []
    depth, current, names = 0, "", []
    for ch in code.split("::", 1)[1]:
        depth += ch in "([" and 1 or 0
        depth -= ch in ")]" and 1 or 0
        if ch == "," and depth == 0:
            names.append(current)
            current = ""
        else:
            current += ch
    names.append(current)
    return [m.group(1).lower() for m in (re.match(r"\s*([a-z_]\w*)", n, re.I) for n in names) if m]


def entity_doc(lines, name):
    ident = re.escape(name)
    patterns = [
        re.compile(r"^\s*(?:(?:pure|elemental|impure|recursive|module)\s+)*(?:[a-z]+(?:\([^)]*\))?\s+)?"
                   r"(?:(?:pure|elemental|impure|recursive)\s+)*(?:function|subroutine)\s+" + ident + r"\b", re.I),
        re.compile(r"^\s*type\s*(?:,[^:]*)?(?:::)?\s*" + ident + r"\b(?!\s*\()", re.I),
        re.compile(r"^\s*(?:abstract\s+)?interface\s+" + ident + r"\b", re.I),
        re.compile(r"^\s*[a-z]+.*::.*\b" + ident + r"\b", re.I),
    ]
    for pattern in patterns:
        for k, line in enumerate(lines):
            if line.lstrip().startswith("!"):
                continue
            code = line.split("!", 1)[0]
            if pattern is patterns[-1] and name.lower() not in declared(code):
                continue
            if pattern.match(code):
                doc = doc_before(lines, k)
                if not doc and "!!" in line:
                    doc = line.split("!!", 1)[1].strip()
                if not doc and pattern is patterns[-1]:
                    # a declaration continued over lines: its `!!` may be on a later line
                    j = k
                    while lines[j].split("!", 1)[0].rstrip().endswith("&") and j + 1 < len(lines):
                        j += 1
                        if "!!" in lines[j]:
                            doc = lines[j].split("!!", 1)[1].strip()
                            break
                if doc:
                    return first_sentence(doc)
    return ""


INTRINSIC = {"wp": "The working precision: `real64` of `iso_fortran_env` (every real is `real(wp)`, every literal `1.0_wp`).",
             "int64": "The 64-bit integer kind of `iso_fortran_env` (counters, sizes)."}


def defined_in(module, name, seen=()):
    """The module that defines `name` (following re-exports by `use ..., only:`) and its lines."""
    with open(module_path(module), encoding="utf-8") as f:
        lines = f.read().splitlines()
    if entity_doc(lines, name) or module in seen:
        return module, lines
    for statement in joined(lines):
        m = re.match(r"use\s+(hillstab_\w+)\s*,\s*only\s*:\s*(.*)$", statement, re.I)
        if m and name in [n.strip().lower() for n in m.group(2).split(",")]:
            return defined_in(m.group(1).lower(), name, seen + (module,))
    return module, lines


BEGIN = "!> **What it exports.**"
END = "!> (end of the exports)"


def split_name(item):
    """(the name `use hillstab` gives, the name in its module) of an `only:` item `local => name`."""
    local, _, name = item.partition("=>")
    return (local.strip(), name.strip()) if name else (local.strip(), local.strip())


def linked(module, item):
    """An exported name linked to its entry: `[[module:name]]`, or `hillstab_x` = [[module:x]]."""
    local, name = split_name(item)
    if name in INTRINSIC:
        return f"`{local}`"
    link = f"[[{defined_in(module, name)[0]}:{name}]]"
    return link if local == name else f"`{local}` = {link}"


def umbrella_block(groups):
    """The umbrella's doc lines listing its exports, each linked, by defining module."""
    out = [BEGIN, "!>", "!> Each name links to its entry; the guide page [The public API](../page/api.html)",
           "!> gives the first doc line of each. Written by `scripts/api_page.py`.", "!>"]
    for module, names in groups:
        links = [linked(module, n) for n in names]
        line = f"!> - [[{module}]]:"
        for link in links:
            piece = " " + link + ("," if link is not links[-1] else "")
            if len(line) + len(piece) > 110:
                out.append(line)
                line = "!>  "
            line += piece
        out.append(line)
    out += ["!>", END]
    return out


def umbrella_text(umbrella, groups):
    """src/hillstab.f90 with its block of exports rewritten."""
    if BEGIN in umbrella and END in umbrella:
        start, stop = umbrella.index(BEGIN), umbrella.index(END) + 1
        umbrella = umbrella[:start] + umbrella_block(groups) + umbrella[stop:]
    else:
        at = next(k for k, line in enumerate(umbrella) if line.startswith("!>```fortran"))
        umbrella = umbrella[:at] + umbrella_block(groups) + ["!>"] + umbrella[at:]
    return "\n".join(umbrella) + "\n"


def exports():
    with open(UMBRELLA, encoding="utf-8") as f:
        umbrella = f.read().splitlines()
    groups = []
    for statement in joined(umbrella):
        m = re.match(r"use\s+(hillstab_\w+)\s*,\s*only\s*:\s*(.*)$", statement, re.I)
        if m:
            names = [n.strip() for n in m.group(2).split(",") if n.strip()]
            groups.append((m.group(1).lower(), names))
    return umbrella, groups


def is_constant(lines, name):
    """Whether `name` is declared as a named constant (`parameter`) in these lines."""
    for statement in joined(lines):
        if re.search(r"\bparameter\b", statement.split("::", 1)[0], re.I) and name.lower() in declared(statement):
            return True
    return False


def unprefixed_constants(groups):
    """Exported kinds and named constants without the prefix `hillstab_`: the names a
    program's own `pi` or `wp` would clash with."""
    bad = []
    for module, names in groups:
        for item in names:
            local, name = split_name(item)
            if local.lower().startswith("hillstab_"):
                continue
            if name in INTRINSIC or is_constant(defined_in(module, name)[1], name):
                bad.append(f"{local} (from {module})")
    return bad


def page_text(groups):
    out = ["---", "title: The public API (use hillstab)", "---", "",
           "`use hillstab` gives the library's numerical API: the names below, re-exported by the",
           "umbrella module [[hillstab]] from the modules that define them. Each name links to its",
           "entry in the API reference, with the first line of its documentation. The batch",
           "program's modules (`src/hillstab/batch/`: scenes, tasks, output files) are internal",
           "and not part of it. This page is written by `scripts/api_page.py` from",
           "`src/hillstab.f90` and the doc comments; `make doc-check` fails when it is not current.",
           "",
           "Every constant it gives (the kinds, π, the codes of methods, models, statuses and errors)",
           "and the few procedures and types with everyday names (`hillstab_error_t`,",
           "`hillstab_determinant`, `hillstab_model_name`, ...) carry the prefix `hillstab_`, so they",
           "cannot clash with a program's own `pi`, `wp` or `determinant`; the other names are types",
           "(`..._t`) and procedures named for what they compute. Where a name appears as",
           "`hillstab_x` = `x`, its module defines it as `x`, and `use` of that module gives it",
           "under that name. `use hillstab, only: wp => hillstab_wp, ...` takes just what a program",
           "needs, under names of its choosing ([Using the library](library.md)).",
           ""]
    for module, names in groups:
        with open(module_path(module), encoding="utf-8") as f:
            lines = f.read().splitlines()
        header = ""
        for k, line in enumerate(lines):
            if re.match(r"^\s*module\s+" + module + r"\s*$", line, re.I):
                header = first_sentence(doc_before(lines, k))
                break
        out += [f"## {module}", "", f"[[{module}]]: {header}" if header else f"[[{module}]]", "",
                "| name | what it is |", "|---|---|"]
        for item in names:
            local, name = split_name(item)
            if name in INTRINSIC:
                out.append(f"| `{local}` | {INTRINSIC[name]} |")
                continue
            home, home_lines = defined_in(module, name)
            doc = entity_doc(home_lines, name).replace("|", "\\|")
            out.append(f"| {linked(module, item)} | {doc} |")
        out.append("")
    return "\n".join(out)


def main():
    umbrella, groups = exports()
    bad = unprefixed_constants(groups)
    if bad:
        print("api_page: src/hillstab.f90 exports constants without the prefix hillstab_ (rename them "
              "there, `hillstab_x => x`): " + ", ".join(bad), file=sys.stderr)
        return 1
    outputs = {PAGE: page_text(groups), UMBRELLA: umbrella_text(umbrella, groups)}
    stale = []
    for path, text in outputs.items():
        current = open(path, encoding="utf-8").read() if os.path.exists(path) else ""
        if current == text:
            continue
        stale.append(os.path.relpath(path, ROOT))
        if "--check" not in sys.argv[1:]:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            print(f"api_page: {os.path.relpath(path, ROOT)} written")
    if stale and "--check" in sys.argv[1:]:
        print(f"api_page: {', '.join(stale)} not current: run python3 scripts/api_page.py", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
