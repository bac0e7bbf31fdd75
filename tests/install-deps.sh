#!/bin/sh
# Installs the Debian 12 packages the build, the tests and the examples need,
# only when something is missing.  Root, or sudo, is needed only then.
set -eu
PKGS="meson ninja-build pkg-config gcc libc6-dev libcglm-dev check gnuplot-nox libosmesa6-dev libpng-dev libstb-dev clang libclang-rt-14-dev valgrind gcovr cmake g++ abigail-tools"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "install-deps: installing$missing"
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
