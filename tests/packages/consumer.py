#!/usr/bin/python3
"""A Python program against the installed python3-shadowwarp (tests/packages/run.sh).

Run from outside the source tree with SHADOWWARP_LIB unset: the module must
come from the system's dist-packages, the library it maps must be the
packaged /usr/lib/<multiarch>/libshadowwarp.so.0.x.y (found by its SONAME,
read from /proc/self/maps, not from the module's own report), and n_opt for the
depth range [1, 100] must be z_n + sqrt(z_n z_f) = 11  [RHS] (3.2).
"""
import math
import os
import sys

if "SHADOWWARP_LIB" in os.environ:
    sys.exit("consumer.py: SHADOWWARP_LIB is set; the test is loading by SONAME")
import shadowwarp as sw

if not sw.__file__.startswith("/usr/lib/python3/dist-packages/shadowwarp/"):
    sys.exit("consumer.py: shadowwarp imported from %s, not from the package" % sw.__file__)
n_opt = float(sw.warp_nopt(100.0 - 1.0, 1.0, 100.0))
want = 1.0 + math.sqrt(1.0 * 100.0)
if abs(n_opt - want) > 1e-12 * want:
    sys.exit("consumer.py: warp_nopt gave %r, z_n + sqrt(z_n z_f) = %r" % (n_opt, want))
with open("/proc/self/maps") as f:
    mapped = sorted({line.split()[-1] for line in f if "libshadowwarp" in line})
# realpath: the loader may name it through the merged /lib -> /usr/lib
real = sorted({os.path.realpath(m) for m in mapped})
if len(real) != 1 or not (real[0].startswith("/usr/lib/") and
                          os.path.basename(real[0]).startswith("libshadowwarp.so.")):
    sys.exit("consumer.py: mapped %s, want the packaged /usr/lib/.../libshadowwarp.so.N" % mapped)
print("consumer.py: shadowwarp %s from %s, library %s, n_opt = %g"
      % (sw.__version__, os.path.dirname(sw.__file__), real[0], n_opt))
