#!/bin/sh
# The table "Continuity over the whole sphere" of docs/geometry.md: stateless
# swarp_setup vs swarp_setup_follow on the light paths of
# tests/geometry/test_continuity.c, in 0.01° steps (about a minute).
# Usage: sh docs/plots/continuity_table.sh [builddir]   (default: build)
set -e
B=${1:-build}
SWARP_CONT_TABLE=1 CK_FORK=no "$B/tests/geometry/test_continuity" | grep '^|'
