#!/bin/sh
# The whole test suite: installs what is missing, builds with
# -Wall -Wextra -Werror, runs every Check suite, then the same suite again
# under AddressSanitizer + UndefinedBehaviorSanitizer.
#   sh tests/run.sh            everything
#   SWARP_QUICK=1 sh tests/run.sh   only the plain build
set -eu
cd "$(dirname "$0")/.."
sh tests/install-deps.sh

echo "== build (-Werror) and test"
[ -d build-ci ] || meson setup build-ci -Dwerror=true --buildtype=debugoptimized >/dev/null
ninja -C build-ci
meson test -C build-ci --print-errorlogs

if [ "${SWARP_QUICK:-0}" = "1" ]; then exit 0; fi

echo "== ASan + UBSan"
[ -d build-asan ] || meson setup build-asan -Dwerror=true -Db_sanitize=address,undefined \
    -Db_lundef=false --buildtype=debug >/dev/null
ninja -C build-asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    meson test -C build-asan --print-errorlogs --timeout-multiplier 10
# stage: robustness (valgrind, coverage, fuzz, consumers)
