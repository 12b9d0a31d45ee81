#!/usr/bin/env bash
# Build the documentation site with FORD into build/doc (make doc): the guide pages of
# docs/guide and the API reference from the `!>`/`!!` comments of src/. FORD runs without
# its preprocessor (every source is free-form .f90; docs/ford.md: preprocess: false).
# The guide's Markdown links are written for the repository (its web page, an editor):
# `page.md`, `../figures/x.png`, `../../src/...f90`; first every relative link of the
# Markdown sources (README, CHANGELOG, docs/guide) must resolve there (scripts/doc_links.py
# --markdown). Then the figures are copied beside the pages, the guide's links turned into
# the site's (`page.html`, the module pages), Bootstrap is taken from Debian's
# libjs-bootstrap5 when it is installed (else the pages load it from its CDN)
# (scripts/doc_site.py), and every relative link of the site must resolve
# (scripts/doc_links.py). Fails on a FORD warning or a broken link; scripts/doc_check.py
# (make doc-check) separately fails on undocumented public entities and arguments.
#   bash scripts/doc.sh               build and check (FORD must be installed: scripts/setup.sh doc)
#   bash scripts/doc.sh --find-ford   print where FORD is (exit 1 when it is not installed)
set -euo pipefail
cd "$(dirname "$0")/.."
find_ford() {
   command -v ford 2>/dev/null && return
   for dir in "$HOME/.local/bin" "$(python3 -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null)"; do
      if [ -n "$dir" ] && [ -x "$dir/ford" ]; then echo "$dir/ford"; return; fi
   done
   return 1
}
if [ "${1:-}" = "--find-ford" ]; then find_ford; exit; fi
ford=$(find_ford || true)
[ -n "$ford" ] || { echo "doc: ford not found (bash scripts/setup.sh doc, or python3 -m pip install --user ford)" >&2; exit 1; }
python3 scripts/doc_links.py --markdown
mkdir -p build
log=build/ford.log
rm -rf build/doc
(cd docs && "$ford" ford.md) > "$log" 2>&1 || { cat "$log" >&2; echo "doc: FORD failed" >&2; exit 1; }
if grep -qi "warning" "$log"; then
   grep -i -A2 "warning" "$log" >&2
   echo "doc: FORD warnings (above); fix the doc comments" >&2
   exit 1
fi
python3 scripts/doc_site.py build/doc
python3 scripts/doc_links.py build/doc
echo "doc: site in build/doc/index.html, guide in build/doc/page/index.html (no FORD warnings, every link resolves, in the site and in the Markdown)"
