#!/bin/sh
# The Debian packages, built and used as a Debian user would:
#   1. dpkg-buildpackage -us -uc -b on a copy of the source tree (the suite
#      is not run again inside the build: DEB_BUILD_OPTIONS=nocheck),
#   2. lintian on the result (errors fail the step; docs/packaging.md lists
#      the remaining warnings),
#   3. the four .debs installed with apt-get (their dependencies resolved
#      like any package's),
#   4. consumers against the installed files only: tests/consumers/consumer.c
#      through pkg-config (shared and static) and CMake find_package,
#      README.md's API tour with its pkg-config command, swtool and its man
#      page, and a Python program
#      (import shadowwarp) with SHADOWWARP_LIB unset,
#   5. the packages purged again, also when a step fails.
# Usage: sh tests/packages/run.sh [SOURCE_DIR]   (root or sudo; refuses to
# run when one of the packages is installed already, so that it never
# removes what it did not install)
set -eu
here="$(cd "$(dirname "$0")" && pwd)"
src="$(cd "${1:-$here/../..}" && pwd)"
pkgs="libshadowwarp0.2 libshadowwarp-dev shadowwarp-tools python3-shadowwarp"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
for p in $pkgs; do
    if dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed"; then
        echo "packages: $p is installed already; remove it first ($SUDO apt-get purge $pkgs)"
        exit 1
    fi
done

tmp="$(mktemp -d "${TMPDIR:-/tmp}/swarp-packages.XXXXXX")"
installed=0
cleanup() {
    if [ "$installed" = 1 ]; then
        echo "-- packages: purge"
        # shellcheck disable=SC2086
        $SUDO env DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq $pkgs >"$tmp/purge.log" 2>&1 ||
            { cat "$tmp/purge.log"; }
    fi
    rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# debian/changelog names the version meson builds (the header's)
deb_version="$(cd "$src" && dpkg-parsechangelog -S Version)"
header_version="$(awk '/#define SWARP_VERSION_(MAJOR|MINOR|PATCH) /{v = v sep $3; sep = "."} END{print v}' "$src/include/shadowwarp.h")"
[ "${deb_version%-*}" = "$header_version" ] ||
    { echo "packages: debian/changelog is $deb_version, include/shadowwarp.h $header_version"; exit 1; }

echo "-- packages: dpkg-buildpackage -us -uc -b ($deb_version)"
mkdir "$tmp/src"
(cd "$src" && tar cf - --exclude='./build*' --exclude='./.git' --exclude='./out' \
    --exclude='./obj-*' --exclude='./debian/.debhelper' --exclude='./debian/tmp' .) | (cd "$tmp/src" && tar xf -)
jobs="$(nproc 2>/dev/null || echo 1)"
(cd "$tmp/src" && DEB_BUILD_OPTIONS="nocheck parallel=$jobs" DEB_BUILD_PROFILES=nocheck \
    dpkg-buildpackage -us -uc -b) \
    >"$tmp/build.log" 2>&1 || { tail -n 60 "$tmp/build.log"; exit 1; }
for p in $pkgs; do
    ls "$tmp/${p}_"*.deb >/dev/null 2>&1 || { echo "packages: $p was not built"; exit 1; }
done
for deb in "$tmp"/*.deb; do echo "   ${deb##*/}"; done

echo "-- packages: lintian"
changes="$(ls "$tmp"/*.changes)"
lintian --fail-on error "$changes" >"$tmp/lintian.log" 2>&1 ||
    { cat "$tmp/lintian.log"; echo "packages: lintian reports errors"; exit 1; }
sed 's/^/   /' "$tmp/lintian.log"

echo "-- packages: apt-get install"
installed=1
# shellcheck disable=SC2046
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    $(for p in $pkgs; do ls "$tmp/${p}_"*.deb; done) >"$tmp/install.log" 2>&1 ||
    { cat "$tmp/install.log"; exit 1; }

echo "-- packages: C consumers through pkg-config"
cc="${CC:-cc}"
mkdir "$tmp/use" && cd "$tmp/use"
# shellcheck disable=SC2046
"$cc" -std=c99 -Wall -Wextra -Werror -pedantic "$src/tests/consumers/consumer.c" -o pc_shared \
    $(pkg-config --cflags --libs shadowwarp)
./pc_shared
# the file the loader resolves belongs to libshadowwarp0.2 (dpkg -S; the
# realpath, since the loader may name it through the merged /lib)
loaded="$(ldd ./pc_shared | awk '/libshadowwarp/{print $3}')"
owner="$(dpkg -S "$(readlink -f "$loaded")" 2>/dev/null | cut -d: -f1)"
[ "$owner" = libshadowwarp0.2 ] ||
    { ldd ./pc_shared; echo "packages: pc_shared loads '$loaded', not libshadowwarp0.2's library"; exit 1; }
# shellcheck disable=SC2046
"$cc" -std=c99 -Wall -Wextra -Werror -pedantic "$src/tests/consumers/consumer.c" -o pc_static \
    $(pkg-config --cflags shadowwarp) -Wl,-Bstatic -lshadowwarp -Wl,-Bdynamic \
    $(pkg-config --static --libs-only-l shadowwarp | sed 's/-lshadowwarp//')
./pc_static
if ldd ./pc_static | grep -q libshadowwarp; then
    echo "packages: pc_static links libshadowwarp dynamically"; exit 1
fi
/usr/bin/python3 "$src/tests/readme/check_tour.py" --installed "$src/README.md"

echo "-- packages: CMake find_package(shadowwarp) from the multiarch libdir"
cmake -S "$src/tests/consumers/cmake" -B "$tmp/cmake" -DCMAKE_BUILD_TYPE=Release >"$tmp/cmake.log" 2>&1 ||
    { cat "$tmp/cmake.log"; exit 1; }
cmake --build "$tmp/cmake" >>"$tmp/cmake.log" 2>&1 || { cat "$tmp/cmake.log"; exit 1; }
"$tmp/cmake/consumer_shared"
"$tmp/cmake/consumer_static"

echo "-- packages: swtool"
swtool report >/dev/null
dpkg -L shadowwarp-tools | grep -q '^/usr/share/man/man1/swtool\.1\.gz$' ||
    { echo "packages: shadowwarp-tools has no swtool.1"; exit 1; }

echo "-- packages: Python consumer (import shadowwarp)"
env -u SHADOWWARP_LIB -u PYTHONPATH PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 "$here/consumer.py"
echo "-- packages: built, lintian-clean of errors, installed and used"
