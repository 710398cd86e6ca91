#!/usr/bin/env bash
# Re-render the image-regression references. Only do this when a change of the pictures is
# intended (a fixed bug, a new feature); give the reason, it is recorded with the date.
#   tools/update_references.sh "why the images change"
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
reason="${1:-}"
[ -n "$reason" ] || { echo "usage: tools/update_references.sh \"reason for the new references\"" >&2; exit 2; }
lacrima="${LACRIMA:-${BUILD_DIR:-$here/build}/tools/lacrima}"
[ -x "$lacrima" ] || { echo "build first (tools/bootstrap.sh build), or set BUILD_DIR=your/build or LACRIMA=path/to/lacrima" >&2; exit 2; }
# The same renders as the regression tests: every shot of tests/data/regression, with PNG previews.
"$lacrima" test-suite "$here/tests/data/regression" --references "$here/tests/data/references" --update
echo "$(date -u +%Y-%m-%d) $(git -C "$here" rev-parse --short HEAD): $reason" >> "$here/tests/data/references/CHANGES.txt"
echo "references updated; review the PNGs in tests/data/references/ and commit them with the reason."
