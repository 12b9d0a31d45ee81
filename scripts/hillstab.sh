#!/usr/bin/env bash
# Run the hillstab program of `make run`'s build: fpm's release profile with the release
# flags (scripts/release_flags.sh), so nothing is rebuilt after `make run`. Builds first
# when the sources changed (quietly; compiler errors still show), then runs the program
# in the current directory with the arguments, so scene and output paths are relative to
# where you are and stdout is the program's own:
#   bash scripts/hillstab.sh data/scenes/default_paper.nml
#   bash scripts/hillstab.sh --template chart > my.nml
#   bash scripts/hillstab.sh --example paper_fig4 [ARGS]    an example of fpm.toml, same build
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
flags=$(bash "$root/scripts/release_flags.sh")
link=$(bash "$root/scripts/release_link_flags.sh")
target=(hillstab)
if [ "${1:-}" = "--example" ]; then
   [ $# -ge 2 ] || { echo "usage: hillstab.sh --example NAME [ARGS]" >&2; exit 2; }
   target=(--example "$2")
   shift 2
fi
cd "$root"
if ! log=$(bash scripts/fpm.sh build --profile release --flag "$flags" --link-flag "$link" 2>&1); then
   printf '%s\n' "$log" >&2
   exit 1
fi
exe=$(bash scripts/fpm.sh run --profile release --flag "$flags" --link-flag "$link" --runner echo "${target[@]}" 2>/dev/null | tail -1)
cd - >/dev/null
case "$exe" in /*) ;; *) exe="$root/$exe" ;; esac
exec "$exe" "$@"
