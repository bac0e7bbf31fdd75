#!/usr/bin/python3
"""Tests of the ctypes binding examples/python/shadowwarp.py (numpy-free).

Run by `meson test` (test 'python') with SHADOWWARP_LIB set to the built
shared library and SHADOWWARP_HEADER to include/shadowwarp.h.  Functions the
library does not have yet are skipped (reported by unittest).
"""
import ctypes
import math
import os
import re
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "examples", "python"))
import shadowwarp as sw  # noqa: E402

HEADER = os.environ.get("SHADOWWARP_HEADER", os.path.join(HERE, "..", "..", "include", "shadowwarp.h"))


def need(name):
    return unittest.skipUnless(sw.has(name), name + " not in the library yet")


def header_text():
    with open(HEADER, encoding="utf-8") as f:
        return f.read()


class Conventions(unittest.TestCase):
    def test_version_matches_header(self):
        text = header_text()
        parts = [re.search(r"#define SWARP_VERSION_%s (\d+)" % k, text).group(1)
                 for k in ("MAJOR", "MINOR", "PATCH")]
        s, n = sw.version()
        self.assertEqual(s, ".".join(parts))
        self.assertEqual(n, int(parts[0]) * 10000 + int(parts[1]) * 100 + int(parts[2]))

    def test_every_status_of_the_header_is_known(self):
        # the X-macro lists, parsed from the header, against the library's table
        found = re.findall(r"X\((SWARP_\w+),\s*(\d+),", header_text())
        self.assertTrue(found)
        for name, code in found:
            self.assertEqual(sw.STATUS.get(name), int(code), name)
        self.assertEqual(len(sw.STATUS), len(found))

    def test_struct_sizes(self):
        for cls, size in sw.SIZES.items():
            self.assertEqual(ctypes.sizeof(cls), size, cls.__name__)
        self.assertEqual(sw.Camera.fovy.offset, 72)
        self.assertEqual(sw.Light.direction.offset, 8)

    def test_error_raises_with_status(self):
        with self.assertRaises(sw.SwarpError) as cm:
            sw.mat4_invert(sw.Mat4())  # zero matrix
        self.assertEqual(cm.exception.status, "SWARP_ERR_SINGULAR")
        self.assertEqual(cm.exception.code, sw.STATUS["SWARP_ERR_SINGULAR"])
        self.assertIn("singular", cm.exception.message)


class Layouts(unittest.TestCase):
    """ctypes structs against the C compiler's sizeof/offsetof (tests/python/layouts.c)."""

    def test_sizes_and_offsets_match_c(self):
        exe = os.environ.get("SHADOWWARP_LAYOUTS")
        if not exe:
            self.skipTest("SHADOWWARP_LAYOUTS not set")
        import subprocess
        lines = subprocess.run([exe], check=True, capture_output=True, text=True).stdout.split("\n")
        c = dict(line.split() for line in lines if line.strip())
        names = {"swarp_vec3": sw.Vec3, "swarp_vec4": sw.Vec4, "swarp_mat4": sw.Mat4, "swarp_aabb": sw.AABB,
                 "swarp_plane": sw.Plane, "swarp_camera": sw.Camera, "swarp_light": sw.Light,
                 "swarp_error_config": sw.ErrorConfig, "swarp_setup_options": sw.SetupOptions,
                 "swarp_setup_result": sw.SetupResult, "swarp_split_options": sw.SplitOptions,
                 "swarp_lixel_options": sw.LixelOptions, "swarp_lixel_info": sw.LixelInfo,
                 "swarp_scene_needs": sw.SceneNeeds, "swarp_budget": sw.Budget, "swarp_plan_result": sw.Plan}
        for key, value in c.items():
            if "." in key:
                struct, field = key.split(".")
                self.assertEqual(getattr(names[struct], field).offset, int(value), key)
            else:
                self.assertEqual(ctypes.sizeof(names[key]), int(value), key)


class Mat4(unittest.TestCase):
    def setUp(self):
        self.a = sw.Mat4.from_rows([[2, 0, 1, 3], [0, 1, 0, -2], [1, 0, 3, 0.5], [0, 0, 0, 1]])

    def test_column_major_storage(self):
        self.assertEqual(self.a.m[12], 3.0)  # translation x
        self.assertEqual(self.a.at(0, 3), 3.0)

    def test_invert_then_multiply_is_identity(self):
        inv = sw.mat4_invert(self.a)
        prod = sw.mat4_mul(self.a, inv)
        for r in range(4):
            for c in range(4):
                self.assertAlmostEqual(prod.at(r, c), 1.0 if r == c else 0.0, places=13)

    def test_transform_by_hand(self):
        v = sw.mat4_transform(self.a, (1, 2, 3))
        self.assertEqual(tuple(v), (2 + 3 + 3, 2 - 2, 1 + 9 + 0.5, 1))

    def test_to_float(self):
        f = sw.mat4_to_float(self.a)
        self.assertEqual(len(f), 16)
        self.assertEqual(f[12], 3.0)
        big = sw.Mat4.identity()
        big.m[0] = 1e39
        with self.assertRaises(sw.SwarpError) as cm:
            sw.mat4_to_float(big)
        self.assertEqual(cm.exception.status, "SWARP_ERR_NON_FINITE")


class Core(unittest.TestCase):
    @need("swarp_warp_nopt")
    def test_nopt(self):
        # [RHS] (3.2) evaluated here directly
        for d, z0, z1 in ((10.0, 1.0, 100.0), (3.5, 0.1, 1e4), (1.0, 2.0, 2.5)):
            self.assertAlmostEqual(sw.warp_nopt(d, z0, z1) / (d / (math.sqrt(z1 / z0) - 1)), 1.0, places=12)
        n = sw.warp_nopt(1.0, 2.0, 2.0)
        self.assertEqual(n, math.inf)
        self.assertEqual(n.status, "SWARP_INFO_WARP_UNIFORM")
        with self.assertRaises(sw.SwarpError) as cm:
            sw.warp_nopt(math.nan, 1.0, 2.0)
        self.assertEqual(cm.exception.status, "SWARP_ERR_NON_FINITE")
        with self.assertRaises(sw.SwarpError) as cm:
            sw.warp_nopt(1.0, 3.0, 2.0)
        self.assertEqual(cm.exception.status, "SWARP_ERR_OUT_OF_RANGE")

    @need("swarp_warp_nopt_pseudo")
    def test_nopt_pseudo_reduces_to_nopt(self):
        self.assertAlmostEqual(sw.warp_nopt_pseudo(10.0, 1.0, 100.0, 0.0, 0.0) / sw.warp_nopt(10.0, 1.0, 100.0),
                               1.0, places=12)

    @need("swarp_warp_nrepar")
    def test_nrepar_special_values(self):
        # the reading check of the papers README: eta = -1, 0, 1
        alpha, W = 400.0, 7.0
        self.assertEqual(sw.warp_nrepar(-1.0, alpha, W), math.inf)
        self.assertAlmostEqual(sw.warp_nrepar(0.0, alpha, W), W / (math.sqrt(alpha) - 1), places=10)
        self.assertAlmostEqual(sw.warp_nrepar(1.0, alpha, W), W / (alpha - 1), places=10)

    @need("swarp_warp_eta")
    def test_eta_range(self):
        theta = math.radians(30)
        self.assertEqual(sw.warp_eta(0.0, theta), -1.0)
        self.assertAlmostEqual(sw.warp_eta(theta, theta), -0.2, places=14)
        self.assertEqual(sw.warp_eta(math.pi / 2, theta), 0.0)

    @need("swarp_split_practical")
    def test_splits(self):
        u = sw.split_uniform(1.0, 9.0, 4)
        self.assertEqual(len(u), 5)
        for i, v in enumerate(u):
            self.assertAlmostEqual(v, 1.0 + 2.0 * i, places=12)
        lg = sw.split_log(1.0, 16.0, 4)
        for i, v in enumerate(lg):
            self.assertAlmostEqual(v, 2.0 ** i, places=12)
        p = sw.split_practical(1.0, 16.0, 0.5, 4)
        for i in range(5):
            self.assertAlmostEqual(p[i], 0.5 * lg[i] + 0.5 * (1.0 + 15.0 * i / 4), places=12)
        with self.assertRaises(sw.SwarpError) as cm:
            sw.split_uniform(1.0, 9.0, 0)
        self.assertEqual(cm.exception.status, "SWARP_ERR_SPLIT_COUNT")

    @need("swarp_error_max")
    def test_error_max_is_at_an_end(self):
        cfg = sw.ErrorConfig(near=1.0, far=100.0, theta=math.radians(30))
        for n_prime in (1.0, 10.0, math.inf):
            mx, mz = sw.error_max(cfg, n_prime)
            ends_x = max(sw.error_mx(cfg, 1.0, n_prime), sw.error_mx(cfg, 100.0, n_prime))
            ends_z = max(sw.error_mz(cfg, 1.0, n_prime), sw.error_mz(cfg, 100.0, n_prime))
            self.assertEqual(mx, ends_x)
            self.assertEqual(mz, ends_z)

    @need("swarp_gmnpr_lambda")
    def test_gmnpr_equalises_near_and_far(self):
        n, f, phi = 1.0, 100.0, math.pi / 6
        for theta in (phi, 0.8, 1.2, math.pi / 2):
            lam = sw.gmnpr_lambda(theta, phi, n, f)
            self.assertEqual(lam.status, "SWARP_OK")
            Fn, Ff = sw.gmnpr_F(lam, theta, phi, n, f, n), sw.gmnpr_F(lam, theta, phi, n, f, f)
            self.assertAlmostEqual(Fn / Ff, 1.0, places=10)
        self.assertEqual(sw.gmnpr_lambda(0.1, phi, n, f).status, "SWARP_INFO_GMNPR_ADJUSTED")


class LaterStages(unittest.TestCase):
    @need("swarp_setup")
    def test_setup_maps_the_body_into_the_unit_cube(self):
        cam = sw.Camera(eye=(0, 5, 10), dir=(0, -0.3, -1), up=(0, 1, 0), fovy=1.0, aspect=16 / 9,
                        near=0.5, far=80.0)
        light = sw.Light(direction=(0.3, -1, 0.2))
        r = sw.setup(cam, light, ((-30, 0, -60), (30, 10, 5)))
        res, pts = r
        self.assertIn(r.status, sw.STATUS)
        self.assertTrue(pts)
        for p in pts:
            x, y, z, w = sw.mat4_transform(res.matrix, p)
            self.assertGreater(w, 0)
            self.assertLessEqual(abs(x / w), 1 + 1e-9)
            self.assertLessEqual(abs(y / w), 1 + 1e-9)
        self.assertGreater(res.n_eye, 0)
        self.assertTrue(math.isfinite(res.max_mx) and math.isfinite(res.max_mz))
        with self.assertRaises(sw.SwarpError) as cm:
            sw.setup(sw.Camera(near=2.0, far=1.0), light, ((-1, -1, -1), (1, 1, 1)))
        self.assertEqual(cm.exception.status, "SWARP_ERR_NEAR_FAR")

    @need("swarp_setup_follow")
    def test_setup_follow_is_continuous_through_the_view_axis(self):
        # the light turns through the stateless rule's zero (5.57 degrees from
        # the view direction toward the camera's right, docs/geometry.md
        # section 7) in 0.01 degree steps, fed back through setup_follow
        cam = sw.Camera(eye=(0, 10, 0), dir=(0, 0, -1), up=(0, 1, 0), fovy=1.0, aspect=16 / 9,
                        near=1.0, far=100.0)
        box = ((-300, -5, -150), (300, 40, 50))
        opts = sw.SetupOptions(technique=sw.TECHNIQUE_UNIFORM)

        def light(deg):
            g = math.radians(deg)
            return sw.Light(direction=(math.sin(g), 0, -math.cos(g)))  # v = -z, r = +x

        def up(res):
            m = res.light_view
            return (m.m[1], m.m[5], m.m[9])

        a = sw.setup(cam, light(5.5), box, opts)[0]
        b = sw.setup(cam, light(5.63), box, opts)[0]
        self.assertLess(sum(x * y for x, y in zip(up(a), up(b))), -0.9)  # the stateless flip
        prev = None
        for k in range(540, 571):
            r = sw.setup_follow(cam, light(k * 0.01), box, prev, opts)  # errors raise
            res = r[0]
            self.assertIn(r.status, sw.STATUS)
            if prev is not None:
                self.assertGreater(sum(x * y for x, y in zip(up(prev), up(res))), math.cos(math.radians(0.1)))
            prev = res
        # previous = None is swarp_setup's result
        p0 = sw.setup_follow(cam, light(30), box, None, opts)[0]
        p1 = sw.setup(cam, light(30), box, opts)[0]
        self.assertEqual(bytes(p0), bytes(p1))
        bad = sw.SetupResult()
        with self.assertRaises(sw.SwarpError) as cm:
            sw.setup_follow(cam, light(30), box, bad, opts)
        self.assertEqual(cm.exception.status, "SWARP_ERR_ZERO_VECTOR")

    @need("swarp_cascade_splits")
    def test_cascade_splits_and_selection(self):
        s = sw.cascade_splits(1.0, 100.0, count=4, scheme=sw.SCHEME_LOG)
        self.assertEqual(len(s), 5)
        for i, v in enumerate(s):
            self.assertAlmostEqual(v, 100.0 ** (i / 4), places=9)  # [RHS] (3.7)
        self.assertEqual(sw.cascade_select_depth(s, 5.0)[0], 1)
        n = sw.cascade_nopt(s)
        self.assertEqual(len(n), 4)
        self.assertTrue(all(v > 0 for v in n))
        self.assertEqual(sw.atlas_lsc(4), 0.5)

    @need("swarp_lixel_matrix")
    def test_lixel_plane_is_pixel_for_pixel(self):
        # viewer looking down at the floor y = 0 from (0, 2, 4), 640 x 480
        f = 1.0 / math.tan(0.5)
        n, fa = 0.1, 100.0
        P = sw.Mat4.from_rows([[f / (4 / 3), 0, 0, 0], [0, f, 0, 0],
                               [0, 0, -(fa + n) / (fa - n), -2 * fa * n / (fa - n)], [0, 0, -1, 0]])
        d = (0.0, -0.5, -1.0)
        ln = math.sqrt(sum(v * v for v in d))
        fw = [v / ln for v in d]
        s = [-fw[2], 0.0, fw[0]]
        ls = math.sqrt(sum(v * v for v in s))
        s = [v / ls for v in s]
        u = [s[1] * fw[2] - s[2] * fw[1], s[2] * fw[0] - s[0] * fw[2], s[0] * fw[1] - s[1] * fw[0]]
        eye = (0.0, 2.0, 4.0)
        V = sw.Mat4.from_rows([s + [-sum(a * b for a, b in zip(s, eye))],
                               u + [-sum(a * b for a, b in zip(u, eye))],
                               [-v for v in fw] + [sum(a * b for a, b in zip(fw, eye))], [0, 0, 0, 1]])
        MV = sw.mat4_mul(P, V)
        M_l, info = sw.lixel_matrix(MV, 640, 480, sw.Light(sw.LIGHT_POINT, position=(1, 6, 0)), (0, 1, 0, 0))
        for p in ((0.3, 0.0, 1.0), (-1.0, 0.0, -2.0), (0.5, 0.0, -0.5)):
            cv = sw.mat4_transform(MV, p)
            cl = sw.mat4_transform(M_l, p)
            xp, yp = (cv.x / cv.w + 1) * 320 - 0.5, (cv.y / cv.w + 1) * 240 - 0.5
            self.assertAlmostEqual(cl.x / cl.w, xp, places=6)
            self.assertAlmostEqual(cl.y / cl.w, yp, places=6)
            self.assertGreater(cl.w, 0)

    @need("swarp_plan")
    def test_plan_meets_its_budget(self):
        p = sw.plan(sw.SceneNeeds(), sw.Budget(max_error=2.0))
        self.assertTrue(1 <= p.split_count <= sw.PLAN_MAX_SPLITS)
        if p.meets_budget:
            self.assertLessEqual(p.max_error, 2.0)
        self.assertEqual(p.max_error, max(p.max_mx, p.max_mz))
        text = sw.plan_explain(p)
        self.assertIn(sw.plan_warp_name(p.warp), text)


if __name__ == "__main__":
    unittest.main(verbosity=2)
