#!/usr/bin/env bash
# Run fpm wherever `pip install fpm` put it (PATH, ~/.local/bin, the Python scripts directory).
if command -v fpm >/dev/null 2>&1; then exec fpm "$@"; fi
for dir in "$HOME/.local/bin" "$(python3 -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null)"; do
   if [ -n "$dir" ] && [ -x "$dir/fpm" ]; then exec "$dir/fpm" "$@"; fi
done
echo "hillstab: fpm not found (run scripts/setup.sh)" >&2
exit 1
