#!/usr/bin/env python3
"""Check that every relative link of a generated HTML site resolves.

Reads every .html file under DIR (default build/doc), collects the href and src
attributes, and for each relative one (no scheme, not protocol-relative) checks that the
target file exists inside the site and, for a `#fragment` on a guide page (page/) or
into one, that the page has an element with that id (or an anchor with that name); the
API pages' fragments are FORD's own (it links the private specific procedures of a public
generic interface to entries it does not display). External links are not
followed (no network). Prints each broken link with the page it is on; exit status 1
when there is one. Standard library only.
Usage: scripts/doc_links.py [DIR]
"""
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


def main():
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
