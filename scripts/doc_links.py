#!/usr/bin/env python3
"""Check that every relative link of a generated HTML site resolves, or of Markdown sources.

Reads every .html file under DIR (default build/doc), collects the href and src
attributes, and for each relative one (no scheme, not protocol-relative) checks that the
target file exists inside the site and, for a `#fragment` on a guide page (page/) or
into one, that the page has an element with that id (or an anchor with that name); the
API pages' fragments are FORD's own (it links the private specific procedures of a public
generic interface to entries it does not display). External links are not
followed (no network). Prints each broken link with the page it is on; exit status 1
when there is one. Standard library only.

With --markdown, the Markdown sources instead, as they are read in the repository (its web
page, an editor): in each file (a directory: its *.md files) every relative link —
`[text](target)`, `![alt](target)`, `[name]: target` and HTML `href`/`src`, outside code
spans and fenced blocks — must name a file or directory that exists inside the repository,
and a `#fragment` into a Markdown file (or `#fragment` alone) a heading of it (GitHub's
anchors: lower case, punctuation dropped, blanks as '-'). A guide page (docs/guide) is also
read on the site, so its links must be to what the site holds (other guide pages, figures,
the library's sources outside src/hillstab/batch/), with no #fragment (the site's headings
have no ids). Default: README.md, CHANGELOG.md and docs/guide.
Usage: scripts/doc_links.py [DIR]
       scripts/doc_links.py --markdown [FILE|DIR...]
"""
import re
import html.parser
import os
import sys
import urllib.parse


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links = []
        self.ids = set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value is None:
                continue
            if name in ("href", "src"):
                self.links.append((tag, value))
            elif name == "id" or (tag == "a" and name == "name"):
                self.ids.add(value)


def parse(path, cache):
    if path not in cache:
        page = Page()
        with open(path, encoding="utf-8", errors="replace") as f:
            page.feed(f.read())
        cache[path] = page
    return cache[path]


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FENCE = re.compile(r"^ {0,3}(```|~~~).*?^ {0,3}\1[^\n]*$", re.M | re.S)
CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1", re.S)
INLINE = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^ {0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)", re.M)
HTML_LINK = re.compile(r"\b(?:href|src)\s*=\s*[\"']([^\"']+)[\"']", re.I)
HEADING = re.compile(r"^ {0,3}#{1,6}\s+(.*?)\s*#*\s*$", re.M)


def anchors(path):
    """The anchors GitHub gives the headings of a Markdown file (and explicit ids)."""
    with open(path, encoding="utf-8") as f:
        text = FENCE.sub("", f.read())
    seen, found = {}, set()
    for heading in HEADING.findall(text):
        plain = re.sub(r"[`*_]|\[([^\]]*)\]\([^)]*\)", lambda m: m.group(1) or "", heading)
        slug = re.sub(r"[^\w\- ]", "", plain.lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        found.add(slug if count == 0 else f"{slug}-{count}")
    found.update(re.findall(r"\bid=[\"']([^\"']+)[\"']", text))
    return found


def markdown_links(path):
    """The link targets of a Markdown file, code removed."""
    with open(path, encoding="utf-8") as f:
        text = CODE_SPAN.sub("", FENCE.sub("", f.read()))
    return INLINE.findall(text) + REFERENCE.findall(text) + HTML_LINK.findall(text)


GUIDE = os.path.join(ROOT, "docs", "guide")


def on_site(target):
    """Whether a guide page's link target is on the site (scripts/doc_site.py): another guide
    page, a figure, or a source of the library (the umbrella, or a module outside batch/)."""
    relative = os.path.relpath(target, ROOT).replace(os.sep, "/")
    if relative.startswith("docs/guide/") and relative.endswith(".md"):
        return True
    if relative.startswith("docs/figures/"):
        return True
    if relative == "src/hillstab.f90":
        return True
    return (relative.startswith("src/hillstab/") and relative.endswith(".f90")
            and not relative.startswith("src/hillstab/batch/"))


def check_markdown(paths):
    files = []
    for path in paths or ["README.md", "CHANGELOG.md", "docs/guide"]:
        path = os.path.join(ROOT, path) if not os.path.isabs(path) else path
        if os.path.isdir(path):
            files += sorted(os.path.join(path, n) for n in os.listdir(path) if n.endswith(".md"))
        elif os.path.exists(path):
            files.append(path)
        else:
            print(f"doc_links: no such file {path}", file=sys.stderr)
            return 1
    broken, checked, cache = [], 0, {}
    for path in files:
        where = os.path.relpath(path, ROOT)
        for link in markdown_links(path):
            parts = urllib.parse.urlsplit(link)
            if parts.scheme or link.startswith("//"):
                continue
            checked += 1
            target = path if not parts.path else os.path.normpath(
                os.path.join(os.path.dirname(path), urllib.parse.unquote(parts.path)))
            if not (target == ROOT or target.startswith(ROOT + os.sep)):
                broken.append(f"{where}: {link} (outside the repository)")
            elif not os.path.exists(target):
                broken.append(f"{where}: {link} (no such file)")
            elif os.path.dirname(path) == GUIDE and not on_site(target):
                broken.append(f"{where}: {link} (not on the site: a guide page links pages, figures and "
                              "the library's sources; name other files as paths)")
            elif os.path.dirname(path) == GUIDE and parts.fragment:
                broken.append(f"{where}: {link} (the site's headings have no ids: link the page)")
            elif parts.fragment and target.endswith(".md"):
                if target not in cache:
                    cache[target] = anchors(target)
                if urllib.parse.unquote(parts.fragment) not in cache[target]:
                    broken.append(f"{where}: {link} (no heading '{parts.fragment}' there)")
    for line in broken:
        print("doc_links: broken link in " + line, file=sys.stderr)
    print(f"doc_links: {len(files)} Markdown files, {checked} relative links, {len(broken)} broken")
    return 1 if broken else 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--markdown":
        return check_markdown(sys.argv[2:])
    site = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/doc")
    if not os.path.isdir(site):
        print(f"doc_links: no site at {site}", file=sys.stderr)
        return 1
    cache = {}
    broken = []
    checked = 0
    files = sorted(os.path.join(d, n) for d, _, names in os.walk(site) for n in names if n.endswith(".html"))
    for path in files:
        for tag, link in parse(path, cache).links:
            parts = urllib.parse.urlsplit(link)
            if parts.scheme or link.startswith("//"):
                continue
            checked += 1
            target = path if not parts.path else os.path.normpath(
                os.path.join(os.path.dirname(path), urllib.parse.unquote(parts.path)))
            where = os.path.relpath(path, site)
            if not (target == site or target.startswith(site + os.sep)):
                broken.append(f"{where}: {link} (outside the site)")
            elif os.path.isdir(target):
                if not os.path.exists(os.path.join(target, "index.html")):
                    broken.append(f"{where}: {link} (a directory without index.html)")
            elif not os.path.exists(target):
                broken.append(f"{where}: {link} (no such file)")
            elif parts.fragment and target.endswith(".html") and (
                    where.startswith("page" + os.sep) or os.path.relpath(target, site).startswith("page" + os.sep)):
                if urllib.parse.unquote(parts.fragment) not in parse(target, cache).ids:
                    broken.append(f"{where}: {link} (no id '{parts.fragment}' there)")
    for line in broken:
        print("doc_links: broken link in " + line, file=sys.stderr)
    print(f"doc_links: {len(files)} pages, {checked} relative links, {len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
