#!/bin/sh
# Installs the Debian 12 packages a task needs, only those missing.  Root, or
# sudo, is needed only then.
#   sh tests/install-deps.sh               everything (tests/run.sh, CI)
#   sh tests/install-deps.sh build demo    what examples/run.sh needs
# Sets:
#   build    the library and swtool
#   demo     the OSMesa demo (OpenGL offscreen, PNG output, cglm, stb)
#   test     the Check suites, sanitizers, valgrind, coverage, the consumers
#            (CMake, C++), the ABI check, the fuzzer, the plots (gnuplot), the
#            HLSL path (glslang, spirv-cross), the OGRE adapter, numpy
#   package  dpkg-buildpackage, lintian and the Build-Depends of debian/control
#            (tests/packages/run.sh)
set -eu
pkgs_build="meson ninja-build pkg-config gcc libc6-dev"
pkgs_demo="libcglm-dev libosmesa6-dev libpng-dev libstb-dev"
pkgs_test="libcglm-dev check python3 python3-numpy gnuplot-nox clang libclang-rt-14-dev valgrind gcovr cmake g++ abigail-tools glslang-tools spirv-cross libogre-1.12-dev libopenscenegraph-dev"
pkgs_package="build-essential dpkg-dev debhelper dh-python python3 lintian libcglm-dev check"
[ "$#" -gt 0 ] || set -- build demo test package
PKGS=""
for set_name in "$@"; do
    case "$set_name" in
        build) PKGS="$PKGS $pkgs_build" ;;
        demo) PKGS="$PKGS $pkgs_demo" ;;
        test) PKGS="$PKGS $pkgs_test" ;;
        package) PKGS="$PKGS $pkgs_package" ;;
        *) echo "install-deps: unknown set '$set_name' (build, demo, test, package)" >&2; exit 2 ;;
    esac
done
missing=""
for p in $PKGS; do
    case " $missing " in *" $p "*) continue ;; esac
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "install-deps: installing$missing"
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    # shellcheck disable=SC2086
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
