#!/usr/bin/env bash
# Build the API reference with FORD into build/doc (make doc), installing FORD through
# pip when it is missing. Fails when FORD prints a warning; scripts/doc_check.py (make
# doc-check) separately fails on undocumented public entities and arguments.
set -euo pipefail
cd "$(dirname "$0")/.."
find_ford() {
   command -v ford 2>/dev/null && return
   for dir in "$HOME/.local/bin" "$(python3 -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null)"; do
      if [ -n "$dir" ] && [ -x "$dir/ford" ]; then echo "$dir/ford"; return; fi
   done
}
ford=$(find_ford || true)
if [ -z "$ford" ]; then
   echo "doc: installing FORD" >&2
   # a Debian system Python refuses plain pip installs (PEP 668): fall back to --user/--break-system-packages
   python3 -m pip install --quiet ford 2>/dev/null \
      || python3 -m pip install --quiet --user --break-system-packages ford
   hash -r
   ford=$(find_ford || true)
   [ -n "$ford" ] || { echo "doc: ford not found after pip install" >&2; exit 1; }
fi
mkdir -p build
log=build/ford.log
(cd docs && "$ford" ford.md) > "$log" 2>&1 || { cat "$log" >&2; echo "doc: FORD failed" >&2; exit 1; }
if grep -qi "warning" "$log"; then
   grep -i -A2 "warning" "$log" >&2
   echo "doc: FORD warnings (above); fix the doc comments" >&2
   exit 1
fi
echo "doc: API reference in build/doc/index.html (no FORD warnings)"
