#!/usr/bin/python3
"""Prints a few libshadowwarp results through the ctypes binding.

    SHADOWWARP_LIB=build/src/libshadowwarp.so /usr/bin/python3 examples/python/example.py
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shadowwarp as sw  # noqa: E402

print("libshadowwarp %s (%d)" % sw.version())

# LiSPSM for a view from 0.5 to 200 with a 60 degree field of view, light at
# 50 degrees to the view direction
near, far, fovy, gamma = 0.5, 200.0, math.radians(60), math.radians(50)
theta = fovy / 2
if sw.has("swarp_warp_nopt"):
    n_opt = sw.warp_nopt(far - near, near, far)
    print("n_opt [RHS] (3.2) for d = f - n, z_0 = n, z_1 = f: %.6g (%s)" % (n_opt, n_opt.status))
    eta = sw.warp_eta(gamma, theta)
    W_lz = sw.warp_wlz(gamma, theta, near, far, 2 * near * math.tan(theta))
    n_repar = sw.warp_nrepar(eta, far / near, W_lz)
    print("eta [RHS] (3.3) = %.6g, W_lz (3.5) = %.6g, n_repar (3.4) = %.6g" % (eta, W_lz, n_repar))
    cfg = sw.ErrorConfig(near=near, far=far, theta=theta, res_ix=1920, res_iy=1080,
                         res_s=2048, res_t=2048)
    for label, n_prime in (("PSM", near), ("LiSPSM n_repar", n_repar), ("uniform", math.inf)):
        mx, mz = sw.error_max(cfg, n_prime)
        print("  max error %-15s m_x = %9.4g  m_z = %9.4g" % (label, mx, mz))
else:
    print("(the closed forms are not in this library build yet)")

if sw.has("swarp_setup"):
    # the one call: a LiSPSM shadow matrix (n_opt, [RHS] §3.2.1) for a camera
    # over a 100 x 20 x 100 scene and the sun 50 degrees from the view direction
    cam = sw.Camera(eye=(0, 8, 30), dir=(0, -0.25, -1), up=(0, 1, 0), fovy=fovy, aspect=16 / 9,
                    near=near, far=far)
    light = sw.Light(sw.LIGHT_DIRECTIONAL, direction=(0.6, -0.7, -0.4))
    opts = sw.SetupOptions(technique=sw.TECHNIQUE_LISPSM, param=sw.WARP_PARAM_NOPT)
    r = sw.setup(cam, light, ((-50, 0, -100), (50, 20, 40)), opts)
    res, pts = r
    print("swarp_setup (%s): n' = %.6g eye units, view depth [%.4g, %.4g], B has %d points"
          % (r.status, res.n_eye, res.view_near, res.view_far, len(pts)))
    print("predicted max error m_x = %.4g, m_z = %.4g pixels per texel" % (res.max_mx, res.max_mz))
    print("LiSPSM light matrix (world -> light clip, printed by rows):")
    print(res.matrix)
else:
    # until the geometry stage is in the library: the matrix helpers on a
    # perspective warp
    n = 1.0
    P = sw.Mat4.from_rows([[n, 0, 0, 0], [0, n, 0, 0], [0, 0, -(far + n) / (far - n), -2 * far * n / (far - n)],
                           [0, 0, -1, 0]])
    print("a warp matrix P (column-major in memory, printed by rows):")
    print(P)
    print("its inverse:")
    print(sw.mat4_invert(P))
