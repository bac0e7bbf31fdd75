#!/bin/sh
# Consumer test: installs libshadowwarp into a temporary prefix, then builds
# and runs tests/consumers/consumer.c against it three ways:
#   1. pkg-config (shared, and --static),
#   2. CMake find_package(shadowwarp) (shared and static imported targets),
#   3. as a meson subproject (dependency('shadowwarp') with fallback).
# Usage: sh tests/consumers/run.sh      (from anywhere; needs meson, cmake, pkg-config, cc)
set -eu
src="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/swarp-consumer.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT INT TERM
prefix="$tmp/prefix"
cc="${CC:-cc}"

echo "-- consumer: install into $prefix"
meson setup "$tmp/lib" "$src" --prefix="$prefix" --buildtype=release \
    -Dtests=disabled -Dexamples=disabled >"$tmp/setup.log" 2>&1 || { cat "$tmp/setup.log"; exit 1; }
ninja -C "$tmp/lib" >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
meson install -C "$tmp/lib" >"$tmp/install.log" 2>&1 || { cat "$tmp/install.log"; exit 1; }
libdir="$(find "$prefix" -name shadowwarp.pc -path '*pkgconfig*' | head -n1 | xargs dirname | xargs dirname)"
test -n "$libdir" || { echo "shadowwarp.pc not installed"; exit 1; }
test -f "$prefix/include/shadowwarp.h"
test -f "$prefix/include/shadowwarp_cglm.h"
test -f "$libdir/libshadowwarp.a"
test -f "$libdir/cmake/shadowwarp/shadowwarpConfig.cmake"
test -f "$libdir/cmake/shadowwarp/shadowwarpConfigVersion.cmake"
soname="$(objdump -p "$libdir/libshadowwarp.so" | awk '/SONAME/{print $2}')"
major="$(awk '/#define SWARP_VERSION_MAJOR /{print $3}' "$src/include/shadowwarp.h")"
minor="$(awk '/#define SWARP_VERSION_MINOR /{print $3}' "$src/include/shadowwarp.h")"
# the major; while it is 0, major.minor (every 0.x minor may change layouts)
if [ "$major" = 0 ]; then sov="0.$minor"; else sov="$major"; fi
[ "$soname" = "libshadowwarp.so.$sov" ] || { echo "SONAME is '$soname', want libshadowwarp.so.$sov"; exit 1; }
test -e "$libdir/$soname"
echo "   installed; SONAME $soname"

echo "-- consumer: pkg-config"
export PKG_CONFIG_PATH="$libdir/pkgconfig"
# shellcheck disable=SC2046
"$cc" -std=c99 -Wall -Wextra -Werror -pedantic "$src/tests/consumers/consumer.c" -o "$tmp/pc_shared" \
    $(pkg-config --cflags --libs shadowwarp)
LD_LIBRARY_PATH="$libdir" "$tmp/pc_shared"
# shellcheck disable=SC2046
"$cc" -std=c99 -Wall -Wextra -Werror -pedantic "$src/tests/consumers/consumer.c" -o "$tmp/pc_static" \
    $(pkg-config --cflags shadowwarp) "$libdir/libshadowwarp.a" $(pkg-config --static --libs-only-l shadowwarp | sed 's/-lshadowwarp//')
"$tmp/pc_static"
unset PKG_CONFIG_PATH

echo "-- consumer: CMake find_package(shadowwarp)"
cmake -S "$src/tests/consumers/cmake" -B "$tmp/cmake" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >"$tmp/cmake.log" 2>&1 || { cat "$tmp/cmake.log"; exit 1; }
cmake --build "$tmp/cmake" >>"$tmp/cmake.log" 2>&1 || { cat "$tmp/cmake.log"; exit 1; }
"$tmp/cmake/consumer_shared"     # CMake sets an RPATH to the imported library
"$tmp/cmake/consumer_static"
if ldd "$tmp/cmake/consumer_static" | grep -q libshadowwarp; then
    echo "consumer_static links libshadowwarp dynamically"; exit 1
fi

echo "-- consumer: meson subproject"
mkdir -p "$tmp/sub/subprojects"
cp "$src/tests/consumers/consumer.c" "$tmp/sub/consumer.c"
sed 's#\.\./consumer\.c#consumer.c#' "$src/tests/consumers/meson/meson.build" >"$tmp/sub/meson.build"
# a copy of the source tree (no build directories), as a wrap or a git
# submodule would provide it
(cd "$src" && tar cf - --exclude='./build*' --exclude='./.git' --exclude='./out' .) |
    (mkdir -p "$tmp/sub/subprojects/shadowwarp" && cd "$tmp/sub/subprojects/shadowwarp" && tar xf -)
meson setup "$tmp/sub/build" "$tmp/sub" --force-fallback-for=shadowwarp >"$tmp/sub.log" 2>&1 ||
    { cat "$tmp/sub.log"; exit 1; }
ninja -C "$tmp/sub/build" >>"$tmp/sub.log" 2>&1 || { cat "$tmp/sub.log"; exit 1; }
"$tmp/sub/build/consumer"
echo "-- consumer: all three ways ok"
