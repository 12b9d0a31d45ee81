#!/usr/bin/env python3
"""Check that every public entity of the library is documented for FORD.

FORD's own `warn` option flags every local variable too, so it cannot tell a missing
doc comment on the API from an undocumented loop index. This checker reads the
sources under src/ and reports, with file and line:
  - a module without a `!>` header;
  - a public procedure, derived type, parameter, variable or interface without a
    `!>` comment before it (or `!!` after it);
  - an argument of a public procedure (module procedure, interface body, external
    procedure) without a `!>` line before its declaration or `!!` on it;
  - a component or type-bound procedure of a public derived type without one.
A public generic interface makes its specific procedures public. Without file arguments
it also checks the documentation around the code:
  - README.md has at most 150 lines and its Quick start exactly the two commands
    `make run` and `make test`;
  - every page of docs/guide/ is listed in the `ordered_subpage` lines of its index.md,
    and every listed page exists;
  - no page of docs/guide/ and not the README refers to a file outside the repository
    (an absolute path under /work, /home or /tmp, a brief or a paper file);
  - every declaration of include/hillstab.h (macros, enums, prototypes) appears on the
    guide page library.md;
  - docs/guide/api.md and the export list of src/hillstab.f90 are what scripts/api_page.py
    writes;
  - every relative link of the Markdown (README.md, CHANGELOG.md, docs/guide) resolves in
    the repository, as the pages are read there (scripts/doc_links.py --markdown).
Exit status 1 when anything is missing. Usage: scripts/doc_check.py [FILE.f90...]
(default: every .f90 file under src/, and the checks above).
"""
import os
import subprocess
import glob
import re
import sys

IDENT = r"[a-z_][a-z0-9_]*"
PROC_START = re.compile(
    r"^(?:(?:pure|elemental|impure|recursive|module|non_recursive)\s+)*"
    r"(?:(?:integer|real|logical|complex|character|double\s+precision|type|class)\s*(?:\([^)]*\))?\s*(?:\([^)]*\))?\s+)?"
    r"(?:(?:pure|elemental|impure|recursive)\s+)*"
    r"(subroutine|function)\s+(" + IDENT + r")\s*(\(([^)]*)\))?",
    re.I)
END_PROC = re.compile(r"^end\s*(subroutine|function)\b", re.I)
END_ANY_PROC = re.compile(r"^end\s*(subroutine|function)?\s*(" + IDENT + r")?\s*$", re.I)


class Statement:
    """A logical line: continuation lines joined, comments split off."""

    def __init__(self, first, code, trailing_doc, docs_before):
        self.line = first            # 1-based line number of the first physical line
        self.code = code             # code without comments, lower case
        self.trailing_doc = trailing_doc  # a `!!` comment on one of its lines
        self.docs_before = docs_before    # `!>` lines immediately before it


def split_comment(line):
    """Code and comment of one physical line (quotes respected)."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:i], line[i:]
    return line, ""


def statements(lines):
    result = []
    pending_docs = False
    i = 0
    while i < len(lines):
        code, comment = split_comment(lines[i])
        stripped = code.strip()
        if not stripped:
            if comment.strip().startswith("!>"):
                pending_docs = True
            elif comment.strip().startswith("!!") and result:
                result[-1].trailing_doc = True  # `!!` on the line after a statement
            elif comment.strip() and not comment.strip().startswith("!$"):
                pass  # a plain comment between a `!>` block and its entity keeps the doc
            elif not comment.strip():
                pending_docs = False if not lines[i].strip() else pending_docs
            i += 1
            continue
        first = i + 1
        parts = [stripped]
        trailing = comment.strip().startswith("!!")
        while parts[-1].endswith("&") and i + 1 < len(lines):
            parts[-1] = parts[-1][:-1]
            i += 1
            code, comment = split_comment(lines[i])
            parts.append(code.strip().lstrip("&"))
            trailing = trailing or comment.strip().startswith("!!")
        for piece in " ".join(parts).split(";"):
            if piece.strip():
                result.append(Statement(first, piece.strip().lower(), trailing, pending_docs))
        pending_docs = False
        i += 1
    return result


def declared_names(code):
    """Names declared by a type declaration statement `... :: a, b = 1, c(2)`."""
    if "::" not in code:
        return []
    rest = code.split("::", 1)[1]
    depth, current, names = 0, "", []
    for ch in rest:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            names.append(current)
            current = ""
        else:
            current += ch
    names.append(current)
    out = []
    for n in names:
        m = re.match(r"\s*(" + IDENT + ")", n)
        if m:
            out.append(m.group(1))
    return out


def documented(st):
    return st.docs_before or st.trailing_doc


class Checker:
    def __init__(self):
        self.problems = []

    def report(self, path, line, what):
        self.problems.append(f"{path}:{line}: {what}")

    def check_file(self, path):
        with open(path, encoding="utf-8") as f:
            sts = statements(f.read().splitlines())
        module = None
        for k, st in enumerate(sts):
            m = re.match(r"^module\s+(" + IDENT + r")\s*$", st.code)
            if m:
                module = m.group(1)
                if not documented(st):
                    self.report(path, st.line, f"module {module} has no !> header")
                self.check_module(path, sts[k:], module)
                return
        # no module: external procedures, all public
        self.check_procedures(path, sts, None, top_level=True)

    def check_module(self, path, sts, module):
        public, default_public = set(), False
        for st in sts:
            if re.match(r"^public\s*$", st.code):
                default_public = True
            m = re.match(r"^public\s*(::)?\s*(.*)$", st.code)
            if m and m.group(2):
                public.update(n.strip() for n in m.group(2).split(",") if n.strip())
        if default_public:
            return  # an umbrella module re-exporting other modules
        # attribute form: `integer, public :: x`
        in_contains = False
        depth_type = None
        in_interface = None
        generic_specifics = set()
        for idx, st in enumerate(sts):
            c = st.code
            if c == "contains":
                in_contains = True
                break
            if re.match(r"^(abstract\s+)?interface\b", c):
                m = re.match(r"^interface\s+(" + IDENT + r")", c)
                in_interface = m.group(1) if m else "(abstract)"
                if m and in_interface in public and not documented(st):
                    self.report(path, st.line, f"public interface {in_interface} has no doc comment")
                continue
            if re.match(r"^end\s*interface", c):
                in_interface = None
                continue
            if in_interface:
                m = re.match(r"^module\s+procedure\s+(.*)$", c)
                if m and in_interface in public:
                    generic_specifics.update(n.strip() for n in m.group(1).split(","))
                continue
            m = re.match(r"^type\s*(,[^:]*)?(::)?\s*(" + IDENT + r")\s*$", c)
            if m and not c.startswith("type("):
                depth_type = m.group(3)
                if depth_type in public and not documented(st):
                    self.report(path, st.line, f"public type {depth_type} has no doc comment")
                continue
            if re.match(r"^end\s*type", c):
                depth_type = None
                continue
            if depth_type:
                if depth_type in public and ("::" in c or c.startswith("procedure")) \
                        and not c.startswith(("private", "contains", "sequence")) and not documented(st):
                    names = declared_names(c) if "::" in c else [c]
                    self.report(path, st.line, f"component {', '.join(names)} of public type {depth_type} "
                                               "has no doc comment")
                continue
            if "::" in c and not c.startswith(("public", "private", "use ", "use,", "namelist", "procedure")):
                attrs = c.split("::", 1)[0]
                names = declared_names(c)
                exposed = [n for n in names if n in public or ", public" in attrs or ",public" in attrs]
                if exposed and not documented(st):
                    self.report(path, st.line, f"public entity {', '.join(exposed)} has no doc comment")
        self.check_interface_bodies(path, sts, public)
        self.check_procedures(path, sts, public | generic_specifics, top_level=False)

    def check_interface_bodies(self, path, sts, public):
        """Procedures declared in interface blocks: the legacy interfaces and abstract ones."""
        in_interface = False
        interface_name = None
        for idx, st in enumerate(sts):
            c = st.code
            if c == "contains":
                return
            if re.match(r"^(abstract\s+)?interface\b", c):
                in_interface = True
                m = re.match(r"^interface\s+(" + IDENT + r")", c)
                interface_name = m.group(1) if m else None
                continue
            if re.match(r"^end\s*interface", c):
                in_interface = False
                continue
            if in_interface:
                m = PROC_START.match(c)
                if m and (m.group(2) in public or interface_name in public):
                    self.check_one_procedure(path, sts, idx, m)

    def check_procedures(self, path, sts, public, top_level):
        in_contains = top_level
        depth = 0
        for idx, st in enumerate(sts):
            c = st.code
            if c == "contains":
                in_contains = True
                continue
            if not in_contains:
                continue
            m = PROC_START.match(c)
            if m and not c.startswith("end"):
                depth += 1
                if depth == 1 and (public is None or m.group(2) in public):
                    self.check_one_procedure(path, sts, idx, m)
                continue
            if END_PROC.match(c):
                depth -= 1

    def check_one_procedure(self, path, sts, idx, match):
        kind, name = match.group(1).lower(), match.group(2)
        st = sts[idx]
        if not documented(st):
            self.report(path, st.line, f"public {kind} {name} has no !> doc comment")
        args = [a.strip() for a in (match.group(4) or "").split(",") if a.strip() and a.strip() != "*"]
        if not args:
            return
        pending = set(args)
        depth = 0
        for st2 in sts[idx + 1:]:
            c = st2.code
            if PROC_START.match(c) and not c.startswith("end"):
                depth += 1
                continue
            if END_PROC.match(c) or re.match(r"^end\s*$", c):
                if depth == 0:
                    break
                depth -= 1
                continue
            if depth or "::" not in c:
                continue
            for n in declared_names(c):
                if n in pending:
                    pending.discard(n)
                    if not documented(st2):
                        self.report(path, st2.line, f"argument {n} of public {kind} {name} has no doc comment")
        for n in sorted(pending):
            self.report(path, st.line, f"argument {n} of public {kind} {name}: declaration not found")


README_LIMIT = 150
OUTSIDE = re.compile(r"(?<![\w.])(/work/|/home/|/tmp/[\w.-]+\.md|BRIEF|elastic-pendulum-stability-paper)")


def c_declarations(header):
    """The macros, enum bodies and prototypes of a C header, whitespace-normalised."""
    text = re.sub(r"/\*.*?\*/", " ", open(header, encoding="utf-8").read(), flags=re.S)
    out = [" ".join(m.split()) for m in re.findall(r"^#define[ \t]+HILLSTAB_\w+[ \t]+\S.*$", text, re.M)]
    body = re.sub(r"^#.*$", " ", text, flags=re.M).replace('extern "C" {', " ")
    for statement in body.split(";"):
        statement = " ".join(statement.split()).strip("{} ")
        if statement and ("(" in statement or statement.startswith("enum")):
            out.append(statement)
    return [d for d in out if d]


def check_guide(root):
    """The documentation checks around the code (see the module docstring)."""
    problems = []
    readme = os.path.join(root, "README.md")
    lines = open(readme, encoding="utf-8").read().splitlines()
    if len(lines) > README_LIMIT:
        problems.append(f"README.md: {len(lines)} lines, more than {README_LIMIT} (move the detail to docs/guide/)")
    text = "\n".join(lines)
    quick = re.search(r"^## Quick start\s*\n+```sh\n(.*?)```", text, re.M | re.S)
    if not quick or quick.group(1).strip().split("\n") != ["make run", "make test"]:
        problems.append("README.md: the Quick start must be exactly the two commands `make run` and `make test`")
    guide = os.path.join(root, "docs", "guide")
    pages = sorted(n for n in os.listdir(guide) if n.endswith(".md"))
    index = open(os.path.join(guide, "index.md"), encoding="utf-8").read()
    listed = re.findall(r"^ordered_subpage:\s*(\S+)\s*$", index, re.M)
    for name in pages:
        if name != "index.md" and name not in listed:
            problems.append(f"docs/guide/index.md: page {name} is not listed (ordered_subpage)")
    for name in listed:
        if name not in pages:
            problems.append(f"docs/guide/index.md: listed page {name} does not exist")
    for path in [readme] + [os.path.join(guide, n) for n in pages]:
        for number, line in enumerate(open(path, encoding="utf-8"), 1):
            if OUTSIDE.search(line):
                problems.append(f"{os.path.relpath(path, root)}:{number}: refers to a file outside the repository")
    library = " ".join(open(os.path.join(guide, "library.md"), encoding="utf-8").read().split())
    for declaration in c_declarations(os.path.join(root, "include", "hillstab.h")):
        if declaration not in library:
            problems.append(f"docs/guide/library.md: lacks the declaration of include/hillstab.h: {declaration[:90]}")
    api = subprocess.run([sys.executable, os.path.join(root, "scripts", "api_page.py"), "--check"],
                         capture_output=True, text=True)
    if api.returncode != 0:
        problems.append(api.stderr.strip())
    links = subprocess.run([sys.executable, os.path.join(root, "scripts", "doc_links.py"), "--markdown"],
                           capture_output=True, text=True)
    if links.returncode != 0:
        problems.append(links.stderr.strip())
    return problems


def main(argv):
    files = argv[1:] or sorted(glob.glob("src/**/*.f90", recursive=True))
    checker = Checker()
    for path in files:
        checker.check_file(path)
    for p in checker.problems:
        print(p)
    guide = [] if argv[1:] else check_guide(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    for p in guide:
        print(p)
    if checker.problems:
        print(f"doc-check: {len(checker.problems)} undocumented public entities or arguments", file=sys.stderr)
    if guide:
        print(f"doc-check: {len(guide)} problems of the README and the guide", file=sys.stderr)
    if checker.problems or guide:
        return 1
    print(f"doc-check: every public entity and argument of {len(files)} files is documented; "
          "the README and the guide pass their checks")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
