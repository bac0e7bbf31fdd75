#!/bin/sh
# Regenerates docs/engines-compare.md: the worst measured sigma of OGRE 1.12's
# and OSG 3.6's shadow matrices and of the library's defaults on the same
# scene (examples/ogre/compare_engines.cpp; needs libogre-1.12-dev and, for
# the OSG column, libopenscenegraph-dev at build time).  Under a second.
# Usage: sh docs/plots/compare_engines.sh [builddir]   (default: build)
set -eu
B=${1:-build}
EXE="$B/examples/ogre/compare-engines"
[ -x "$EXE" ] || { echo "compare_engines: $EXE not built (OGRE 1.12 missing?)" >&2; exit 1; }
COMMIT="$(git rev-parse --short HEAD), library sources (src/, include/) last changed at $(git log -1 --format=%h -- src include)"
[ -z "$(git status --porcelain -- src include)" ] || COMMIT="$COMMIT (with uncommitted changes in src/ or include/)"
T=$(mktemp)
"$EXE" --commit "$COMMIT" > "$T"
{
    sed -n '/^<!-- begin intro -->$/,/^<!-- end intro -->$/p' docs/engines-compare.md
    echo
    cat "$T"
} > "$T.md"
mv "$T.md" docs/engines-compare.md
rm -f "$T"
