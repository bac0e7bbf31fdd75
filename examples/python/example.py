#!/usr/bin/python3
"""The worked example of docs/python.md: one LiSPSM matrix, one 4-split
cascade and the measured error of both.

    SHADOWWARP_LIB=build/src/libshadowwarp.so PYTHONPATH=examples/python \
        /usr/bin/python3 examples/python/example.py

(tests/python/test_docs.py --update copies its output into docs/python.md)
"""
import math

import shadowwarp as sw

print("libshadowwarp %s (%d)" % sw.version())

# a camera over a 100 x 20 x 140 scene, the sun 50 degrees from the view
cam = sw.Camera(eye=(0, 8, 30), dir=(0, -0.25, -1), up=(0, 1, 0), fovy=math.radians(60),
                aspect=16 / 9, z_near=0.5, z_far=200.0)
sun = sw.Light(sw.LIGHT_DIRECTIONAL, direction=(0.6, -0.7, -0.4))
scene = ((-50, 0, -100), (50, 20, 40))
res_px = sw.MeasureRes(screen_width=1920, screen_height=1080, map_width=2048, map_height=2048)

# 1. one LiSPSM map, n' = n_opt ([RHS] 3.2.1)
opts = sw.SetupOptions(technique=sw.TECHNIQUE_LISPSM, param=sw.WARP_PARAM_NOPT,
                       map_width=2048, map_height=2048, screen_width=1920, screen_height=1080)
r = sw.setup(cam, sun, scene, opts)
res = r.result
print("\nsetup: %s, n' = %.6g, view depth [%.4g, %.4g], B has %d points"
      % (r.status.name, res.n_eye, res.view_near, res.view_far, len(r.points)))
print("world -> light clip matrix (rows):")
for row in res.matrix:
    print("  " + "  ".join("%10.5f" % v for v in row))
print("model (overhead light on the view axis): max m_x = %.4g, max m_z = %.4g" % (res.max_mx, res.max_mz))
m = res.measured  # swarp_measure_max of the matrix over H = V n S, bisector receivers
print("measured over V n S: max m_s = %.4g, max m_t = %.4g, max sigma = %.4g at (%.3g, %.3g, %.3g), %d samples"
      % (m.max_m_s, m.max_m_t, m.max_sigma, m.at.x, m.at.y, m.at.z, m.samples))

# 2. four practical splits ([RHS] (3.8), lambda 0.5), LiSPSM in each
cr = sw.cascade_setup(cam, sun, scene, {"setup": opts, "split": {"count": 4}})
print("\ncascade_setup: %s, splits %s" % (cr.status.name,
                                          ", ".join("%.4g" % z for z in cr.result.splits[:cr.result.split_count + 1])))
for i, sp in enumerate(cr.splits):
    print("  split %d [%7.4g, %7.4g]: n' = %8.4g  model max m_x %6.3g m_z %6.3g  measured max sigma %6.3g"
          % (i, sp.z_near, sp.z_far, sp.n_eye, sp.max_mx, sp.max_mz, sp.measured.max_sigma))
print("  whole cascade: measured max sigma %.4g (%d samples)"
      % (cr.result.measured.max_sigma, cr.result.measured.samples))

# 3. the same measurement at another resolution, and at points of your own
# (e.g. a depth/normal read-back)
m = sw.measure_max(cam, res.view_near, res.view_far, sun, scene, res.matrix,
                   sw.MeasureRes(screen_width=1920, screen_height=1080, map_width=1024, map_height=1024))
print("\nwith a 1024^2 map: max sigma = %.4g" % m.max_sigma)
pts = [(0.0, 0.0, 0.0), (10.0, 0.0, -60.0)]
for p, e in zip(pts, sw.measure_points(cam, res.matrix, res_px, pts, [(0, 1, 0)] * len(pts))):
    print("\nat %s, normal +y: m_s = %.4g, m_t = %.4g, sigma = %.4g, inside = %s"
          % (p, e.m_s, e.m_t, e.sigma, bool(e.flags & sw.TEXEL_INSIDE)), end="")
print()

# 4. errors raise SwarpError with the status name and message
try:
    sw.setup(sw.Camera(eye=(0, 8, 30), dir=(0, 0, -1), up=(0, 1, 0), fovy=1.0, aspect=1.0,
                       z_near=2.0, z_far=1.0), sun, scene)
except sw.SwarpError as err:
    print("\nbad camera: %s (%s)" % (err.name, err.message))
