#!/bin/sh
# ABI check: compares the built libshadowwarp.so against the committed
# baseline tests/abi/shadowwarp.abi (made by abidw) with abidiff.
#   sh tests/abi/check.sh [BUILD_DIR]          check (default BUILD_DIR: build-ci)
#   sh tests/abi/check.sh --update [BUILD_DIR] rewrite the baseline from BUILD_DIR
# abidiff exit status is a bit field: 1 tool error, 2 usage error, 4 ABI
# change (e.g. a function was added: fine), 8 INCOMPATIBLE change (a
# function removed, a type or signature changed).  Bit 8 fails the check
# unless the SONAME differs from the baseline's (the major version was bumped;
# then refresh the baseline in the same commit).  The library must be built
# with debug info (-g: debugoptimized or debug buildtype).
set -eu
cd "$(dirname "$0")/../.."
update=0
if [ "${1:-}" = "--update" ]; then update=1; shift; fi
build="${1:-build-ci}"
lib="$build/src/libshadowwarp.so"
baseline=tests/abi/shadowwarp.abi
[ -e "$lib" ] || { echo "abi: $lib not found (build first)"; exit 1; }
dump() {
    abidw --no-show-locs --no-corpus-path --no-comp-dir-path --drop-undefined-syms \
        --drop-private-types --headers-dir include --out-file "$2" "$1"
}
if [ "$update" = 1 ]; then
    dump "$lib" "$baseline"
    echo "abi: baseline $baseline rewritten from $lib"
    grep -c '<elf-symbol name=' "$baseline" | sed 's/^/abi: exported symbols: /'
    exit 0
fi
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT INT TERM
dump "$lib" "$tmp/current.abi"
set +e
abidiff --no-show-locs --headers-dir2 include "$baseline" "$tmp/current.abi" >"$tmp/diff.txt" 2>&1
rc=$?
set -e
base_so="$(sed -n "s/.*soname='\([^']*\)'.*/\1/p" "$baseline" | head -n1)"
cur_so="$(sed -n "s/.*soname='\([^']*\)'.*/\1/p" "$tmp/current.abi" | head -n1)"
nsym="$(grep -c '<elf-symbol name=' "$tmp/current.abi" || true)"
if [ $((rc & 3)) -ne 0 ]; then
    cat "$tmp/diff.txt"; echo "abi: abidiff failed to run (exit $rc)"; exit 1
fi
if [ $((rc & 8)) -ne 0 ]; then
    cat "$tmp/diff.txt"
    if [ "$base_so" != "$cur_so" ]; then
        echo "abi: incompatible change, but SONAME bumped ($base_so -> $cur_so): ok; refresh the baseline (sh tests/abi/check.sh --update)"
        exit 0
    fi
    echo "abi: INCOMPATIBLE change against $baseline without a SONAME bump ($cur_so)"
    exit 1
fi
if [ $((rc & 4)) -ne 0 ]; then
    sed -n '1,40p' "$tmp/diff.txt"
    echo "abi: compatible additions against the baseline ($nsym symbols now); ok"
else
    echo "abi: identical to the baseline ($nsym symbols, $cur_so)"
fi
