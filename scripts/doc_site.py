#!/usr/bin/env python3
"""Finish the FORD site in DIR (default build/doc) so that it reads without a network.

- copies docs/figures to DIR/figures (the guide pages show them as ../figures/NAME.png,
  the same path that works when docs/guide/*.md is read in the repository);
- when Debian's libjs-bootstrap5 is installed, copies its bootstrap.min.css and
  bootstrap.bundle.min.js into DIR/css and DIR/js and points every page at them instead
  of the CDN (else the pages keep loading Bootstrap from the CDN, and read unstyled
  offline);
- removes the MathJax script that FORD loads from its CDN: no page uses TeX (the guide
  writes its equations in plain text);
- keeps images within the text column (the figures are wider than it);
- fills the "Contents" column of the umbrella module's page, which FORD leaves at "None"
  (the umbrella defines nothing, it re-exports): the modules its names come from, each
  linked, and the guide page that lists every name;
- turns the guide's links, written for the Markdown as it is read in the repository, into
  the site's: `other-page.md#x` into `other-page.html#x`, a link to a source file
  `../../src/hillstab/<folder>/<name>.f90` (or `../../src/hillstab.f90`) into the page of
  its module, `../module/hillstab_<folder>_<name>.html` (scripts/doc_links.py then checks
  every link of the site, and `--markdown` the sources).
Usage: scripts/doc_site.py [DIR]
"""
import os
import re
import shutil
import sys

BOOTSTRAP = "/usr/share/javascript/bootstrap5"
CSS_CDN = re.compile(r'<link href="https://cdn\.jsdelivr\.net/npm/bootstrap@[^"]*/bootstrap\.min\.css"[^>]*>', re.S)
JS_CDN = re.compile(r'<script src="https://cdn\.jsdelivr\.net/npm/bootstrap@[^"]*/bootstrap\.bundle\.min\.js"[^>]*>\s*</script>', re.S)
MATHJAX = re.compile(r'<!-- MathJax -->.*?<script src="https://cdn\.jsdelivr\.net/npm/mathjax@[^"]*"[^>]*>\s*</script>', re.S)
LOCAL_CSS = re.compile(r'<link href="([^"]*)css/local\.css"')
NO_CONTENTS = re.compile(r'(<h3>Contents</h3>\s*)<em>None</em>')
GUIDE_LINK = re.compile(r'(\b(?:href|src)=")([^"#:]+)\.md((?:#[^"]*)?")')
SOURCE_LINK = re.compile(r'(\bhref=")\.\./\.\./src/([^"#:]+)\.f90((?:#[^"]*)?")')


def site_links(text):
    """A guide page's links to other pages (.md) and to sources (../../src/...f90) as the site's."""
    text = GUIDE_LINK.sub(lambda m: m.group(1) + m.group(2) + ".html" + m.group(3), text)
    return SOURCE_LINK.sub(lambda m: m.group(1) + "../module/" + m.group(2).replace("/", "_") + ".html" + m.group(3),
                           text)


def umbrella_contents():
    """The sidebar of module/hillstab.html: the modules it re-exports from."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import api_page
    _, groups = api_page.exports()
    items = "".join(f'<li><a href="{m}.html">{m}</a> ({len(names)})</li>' for m, names in groups)
    count = sum(len(names) for _, names in groups)
    return (f'<p>No entities of its own: {count} names re-exported from</p>'
            f'<ul class="list-unstyled small">{items}</ul>'
            f'<p>Each with its first doc line: <a href="../page/api.html">The public API</a></p>')


def main():
    site = sys.argv[1] if len(sys.argv) > 1 else "build/doc"
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    figures = os.path.join(root, "docs", "figures")
    shutil.copytree(figures, os.path.join(site, "figures"), dirs_exist_ok=True)
    local = all(os.path.exists(os.path.join(BOOTSTRAP, p))
                for p in ("css/bootstrap.min.css", "js/bootstrap.bundle.min.js"))
    if local:
        shutil.copy(os.path.join(BOOTSTRAP, "css/bootstrap.min.css"), os.path.join(site, "css"))
        shutil.copy(os.path.join(BOOTSTRAP, "js/bootstrap.bundle.min.js"), os.path.join(site, "js"))
    with open(os.path.join(site, "css", "local.css"), "a", encoding="utf-8") as f:
        f.write("\n/* scripts/doc_site.py: figures fit the text column */\n#text img { max-width: 100%; height: auto; }\n")
    pages = 0
    for folder, _, files in os.walk(site):
        for name in files:
            if not name.endswith(".html"):
                continue
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            new = MATHJAX.sub("", text)
            if os.path.relpath(path, site).startswith("page" + os.sep):
                new = site_links(new)
            if os.path.relpath(path, site) == os.path.join("module", "hillstab.html"):
                new = NO_CONTENTS.sub(lambda m: m.group(1) + umbrella_contents(), new)
            found = LOCAL_CSS.search(new)
            if local and found:
                prefix = found.group(1)
                new = CSS_CDN.sub(f'<link href="{prefix}css/bootstrap.min.css" rel="stylesheet">', new)
                new = JS_CDN.sub(f'<script src="{prefix}js/bootstrap.bundle.min.js"></script>', new)
            if new != text:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(new)
                pages += 1
    where = "Debian's libjs-bootstrap5, copied in" if local else "its CDN (install libjs-bootstrap5 to read offline)"
    print(f"doc_site: {pages} pages finished; Bootstrap from {where}")


if __name__ == "__main__":
    main()
