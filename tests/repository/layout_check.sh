#!/usr/bin/env bash
# The layout docs/design.md describes, held: no tracked source file of the
# library, the adapters, the plugins, the tools or the Python package is
# over 700 lines (a file of one job reads in one sitting), and codec/src
# keeps at most 15 files at its top, the rest in its stage folders.
# Usage: layout_check.sh PROJECT_DIR   (exit 77 outside a git work tree)
set -euo pipefail
project=${1:?usage: layout_check.sh PROJECT_DIR}
cd "$project"
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "not a git work tree: skipped"; exit 77; }
max_lines=700
max_top=15
status=0
while IFS= read -r file; do
    [ -f "$file" ] || continue
    lines=$(wc -l <"$file")
    if [ "$lines" -gt "$max_lines" ]; then
        echo "$file: $lines lines (at most $max_lines)"
        status=1
    fi
done < <(git ls-files --cached --others --exclude-standard -- codec vcg_adapters plugin tools python |
         grep -E '\.(h|hpp|c|cc|cpp|py|pyi)$')
top=$(find codec/src -maxdepth 1 -type f | wc -l)
if [ "$top" -gt "$max_top" ]; then
    echo "codec/src holds $top files at its top (at most $max_top): $(find codec/src -maxdepth 1 -type f -printf '%f ')"
    status=1
fi
[ "$status" = 0 ] && echo "layout holds: every source file at most $max_lines lines, $top files at codec/src's top"
exit "$status"
