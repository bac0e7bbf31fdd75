#!/usr/bin/python3
"""Tests of the shadowwarp package (examples/python/shadowwarp).

Run by `meson test` (tests 'python' and 'python_nonumpy') with
SHADOWWARP_LIB set to the built shared library and SHADOWWARP_HEADER to
include/shadowwarp.h.  Every expected value is derived here from the
papers' formulas or by an independent evaluation (finite differences,
the definition of a matrix product), never copied from a run.
"""
import math
import os
import re
import subprocess
import sys
import unittest
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from support import HAVE_NUMPY, apply, header_text, mul, rows  # noqa: E402
import shadowwarp as sw  # noqa: E402

X = sw.experimental


def scene_camera(z_near=0.5, z_far=80.0):
    return sw.Camera(eye=(0, 5, 10), dir=(0, -0.3, -1), up=(0, 1, 0), fovy=1.0, aspect=16 / 9,
                     z_near=z_near, z_far=z_far)


SCENE_BOX = ((-30, 0, -60), (30, 10, 5))
SUN = sw.Light(sw.LIGHT_DIRECTIONAL, direction=(0.3, -1, 0.2))


class Conventions(unittest.TestCase):
    def test_version_matches_header(self):
        text = header_text()
        parts = [re.search(r"#define SWARP_VERSION_%s (\d+)" % k, text).group(1) for k in ("MAJOR", "MINOR", "PATCH")]
        s, n = sw.version()
        self.assertEqual(s, ".".join(parts))
        self.assertEqual(n, int(parts[0]) * 10000 + int(parts[1]) * 100 + int(parts[2]))
        self.assertEqual(sw.__version__, s)

    def test_every_status_of_the_header_is_the_librarys(self):
        # the X-macro lists parsed here, against the library's own table
        found = re.findall(r"X\((SWARP_\w+),\s*(\d+),", header_text())
        self.assertGreater(len(found), 50)
        for name, code in found:
            self.assertEqual(sw.status_name(int(code)), name)
            self.assertEqual(sw.STATUS[name], int(code))
            self.assertEqual(getattr(sw, name), int(code))
            self.assertEqual(getattr(sw, name), name)
        self.assertEqual(len(sw.STATUS), len(found))
        self.assertEqual(sw.status_name(999999), "SWARP_UNKNOWN_STATUS")

    def test_error_carries_status_name_and_message(self):
        with self.assertRaises(sw.SwarpError) as cm:
            sw.mat4_invert(sw.Mat4())  # the zero matrix
        e = cm.exception
        self.assertEqual(e.status, sw.STATUS["SWARP_ERR_SINGULAR"])
        self.assertEqual(e.name, "SWARP_ERR_SINGULAR")
        self.assertEqual(e.status.name, "SWARP_ERR_SINGULAR")
        self.assertEqual(e.message, sw.status_string(e.status))
        self.assertIn("singular", e.message)
        self.assertEqual(e.function, "swarp_mat4_invert")
        self.assertIn("SWARP_ERR_SINGULAR", str(e))

    def test_readable_reprs(self):
        cam = scene_camera()
        text = repr(cam)
        self.assertTrue(text.startswith("Camera(eye=(0.0, 5.0, 10.0), dir="), text)
        self.assertIn("z_near=0.5", text)
        self.assertNotIn("_reserved", text)
        self.assertEqual(repr(sw.SWARP_ERR_CAPACITY), "<SWARP_ERR_CAPACITY = 8>")
        self.assertIn("lambda_=0.5", repr(sw.SplitOptions(count=4, lambda_=0.5)))

    def test_deprecated_near_far_aliases(self):
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            cam = sw.Camera(eye=(0, 0, 0), dir=(0, 0, -1), up=(0, 1, 0), fovy=1, aspect=1, near=0.25, far=9)
        self.assertEqual((cam.z_near, cam.z_far), (0.25, 9.0))
        self.assertTrue(any(issubclass(x.category, DeprecationWarning) for x in w))

    def test_type_hints_and_docs(self):
        import inspect
        sig = inspect.signature(sw.setup)
        self.assertEqual(list(sig.parameters), ["cam", "light", "scene", "opts"])
        self.assertIsNone(sig.parameters["opts"].default)
        self.assertIn("swarp_setup", sw.setup.__doc__)
        self.assertIs(inspect.signature(sw.warp_nopt).parameters["d"].annotation, float)


class Layouts(unittest.TestCase):
    """ctypes structs against the C compiler's sizeof/offsetof (tests/python/layouts.c)."""

    def test_sizes_and_offsets_match_c(self):
        exe = os.environ.get("SHADOWWARP_LAYOUTS")
        if not exe:
            self.skipTest("SHADOWWARP_LAYOUTS not set")
        import ctypes
        out = subprocess.run([exe], check=True, capture_output=True, text=True).stdout
        c = dict(line.split() for line in out.splitlines() if line.strip())
        sizes = {k for k in c if "." not in k}
        header_structs = set(re.findall(r"\}\s*(swarp_\w+)\s*;", re.sub(r"/\*.*?\*/", "", header_text(), flags=re.S)))
        header_structs -= {k for k in header_structs if not isinstance(sw.STRUCT_CLASSES.get(k), type)}
        self.assertEqual(sizes, set(sw.STRUCT_CLASSES) - {"swarp_plan"}, "layouts.c must print every struct")
        self.assertTrue(sizes <= header_structs | {"swarp_plan_result"})
        for key, value in c.items():
            if "." in key:
                struct, field = key.split(".")
                self.assertEqual(sw.STRUCT_CLASSES[struct]._c_field(field).offset, int(value), key)
            else:
                self.assertEqual(ctypes.sizeof(sw.STRUCT_CLASSES[key]), int(value), key)


class Matrices(unittest.TestCase):
    A = [[2, 0, 1, 3], [0, 1, 0, -2], [1, 0, 3, 0.5], [0, 0, 0, 1]]

    def test_column_major_storage(self):
        a = sw.Mat4.from_rows(self.A)
        self.assertEqual(a.m[12], 3.0)  # translation x
        self.assertEqual(a[0, 3], 3.0)
        self.assertEqual(rows(sw.Mat4.from_column_major(list(a.m)).rows()), rows(self.A))

    def test_invert_then_multiply_is_identity(self):
        inv = sw.mat4_invert(self.A)
        self.assertEqual(inv.status, "SWARP_OK")
        prod = mul(self.A, inv)
        for r in range(4):
            for c in range(4):
                self.assertAlmostEqual(prod[r][c], 1.0 if r == c else 0.0, places=13)
        self.assertEqual(rows(sw.mat4_mul(self.A, self.A)), mul(self.A, self.A))  # exact small integers

    def test_transform_by_hand(self):
        v = sw.mat4_transform(self.A, (1, 2, 3))
        self.assertEqual(tuple(v), (2 + 3 + 3, 2 - 2, 1 + 9 + 0.5, 1))

    def test_matrix_type(self):
        m = sw.mat4_invert(sw.Mat4.identity())
        if HAVE_NUMPY:
            import numpy as np
            self.assertIsInstance(m, np.ndarray)
            self.assertEqual(m.shape, (4, 4))
        else:
            self.assertIsInstance(m, tuple)
            self.assertEqual([len(r) for r in m], [4, 4, 4, 4])
        self.assertEqual(rows(m), [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)])

    def test_to_float(self):
        f = sw.mat4_to_float(self.A)
        self.assertEqual(len(f), 16)
        self.assertEqual(f[12], 3.0)
        big = sw.Mat4.identity()
        big.m[0] = 1e39
        with self.assertRaises(sw.SwarpError) as cm:
            sw.mat4_to_float(big)
        self.assertEqual(cm.exception.status, "SWARP_ERR_NON_FINITE")


class Model(unittest.TestCase):
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

    def test_nopt_pseudo_reduces_to_nopt(self):
        self.assertAlmostEqual(sw.warp_nopt_pseudo(10.0, 1.0, 100.0, 0.0, 0.0) / sw.warp_nopt(10.0, 1.0, 100.0),
                               1.0, places=12)

    def test_nrepar_special_values(self):
        # [RHS] (3.4) at eta = -1, 0, 1
        alpha, W = 400.0, 7.0
        self.assertEqual(sw.warp_nrepar(-1.0, alpha, W), math.inf)
        self.assertAlmostEqual(sw.warp_nrepar(0.0, alpha, W), W / (math.sqrt(alpha) - 1), places=10)
        self.assertAlmostEqual(sw.warp_nrepar(1.0, alpha, W), W / (alpha - 1), places=10)

    def test_eta_range(self):
        theta = math.radians(30)
        self.assertEqual(sw.warp_eta(0.0, theta), -1.0)
        self.assertAlmostEqual(sw.warp_eta(theta, theta), -0.2, places=14)
        self.assertEqual(sw.warp_eta(math.pi / 2, theta), 0.0)

    def test_split_schemes(self):
        u = sw.split_uniform(1.0, 9.0, 4)
        self.assertEqual([round(v, 12) for v in u], [1.0, 3.0, 5.0, 7.0, 9.0])  # [RHS] (3.6)
        lg = sw.split_log(1.0, 16.0, 4)
        for i, v in enumerate(lg):
            self.assertAlmostEqual(v, 2.0 ** i, places=12)  # (3.7)
        p = sw.split_practical(1.0, 16.0, 0.5, 4)
        for i in range(5):
            self.assertAlmostEqual(p[i], 0.5 * 2.0 ** i + 0.5 * (1.0 + 15.0 * i / 4), places=12)  # (3.8)
        with self.assertRaises(sw.SwarpError) as cm:
            sw.split_uniform(1.0, 9.0, 0)
        self.assertEqual(cm.exception.status, "SWARP_ERR_SPLIT_COUNT")

    def test_split_schemes_at_the_largest_count(self):
        # m = SWARP_SPLIT_MAX_COUNT needs m + 1 slots; m + 1 splits is refused
        m = sw.SPLIT_MAX_COUNT
        for f, extra in ((sw.split_uniform, ()), (sw.split_log, ()), (sw.split_practical, (0.5,)),
                         (sw.split_pseudo, (2.0, 50.0, 0.5))):
            s = f(1.0, 100.0, *extra, m)
            self.assertEqual(len(s), m + 1, f.__name__)
            self.assertEqual((s[0], s[-1]), (1.0, 100.0))
            self.assertTrue(all(a < b for a, b in zip(s, s[1:])))
            with self.assertRaises(sw.SwarpError) as cm:
                f(1.0, 100.0, *extra, m + 1)
            self.assertEqual(cm.exception.status, "SWARP_ERR_SPLIT_COUNT")

    def test_error_max_is_at_an_end(self):
        cfg = sw.ErrorConfig(z_near=1.0, z_far=100.0, theta=math.radians(30), res_ix=1024, res_iy=768,
                             res_s=1024, res_t=1024)
        for n_prime in (1.0, 10.0, math.inf):
            mx, mz = sw.error_max(cfg, n_prime)
            self.assertEqual(mx, max(sw.error_mx(cfg, 1.0, n_prime), sw.error_mx(cfg, 100.0, n_prime)))
            self.assertEqual(mz, max(sw.error_mz(cfg, 1.0, n_prime), sw.error_mz(cfg, 100.0, n_prime)))

    def test_error_split_max_per_split_is_error_max_of_the_split(self):
        cfg = dict(z_near=1.0, z_far=100.0, theta=0.5, res_ix=1024, res_iy=768, res_s=1024, res_t=1024)
        splits = [1.0, 5.0, 20.0, 100.0]
        n_primes = [2.0, 7.0, math.inf]
        r = sw.error_split_max(cfg, splits, n_primes)
        self.assertEqual(r._fields, ("split_max_mx", "split_max_mz", "max_mx", "max_mz"))
        self.assertEqual(len(r.split_max_mx), 3)
        self.assertEqual(r.max_mx, max(r.split_max_mx))
        curve = sw.error_split_curve(cfg, splits, n_primes, [3.0, 50.0])
        self.assertEqual(len(curve.mx), 2)
        with self.assertRaises(ValueError):
            sw.error_split_curve(cfg, splits, n_primes[:2], [3.0])

    def test_gmnpr_equalises_near_and_far(self):
        n, f, phi = 1.0, 100.0, math.pi / 6
        for theta in (phi, 0.8, 1.2, math.pi / 2):
            lam = sw.gmnpr_lambda(theta, phi, n, f)
            self.assertEqual(lam.status, "SWARP_OK")
            Fn, Ff = sw.gmnpr_F(lam, theta, phi, n, f, n), sw.gmnpr_F(lam, theta, phi, n, f, f)
            self.assertAlmostEqual(Fn / Ff, 1.0, places=10)
        self.assertEqual(sw.gmnpr_lambda(0.1, phi, n, f).status, "SWARP_INFO_GMNPR_ADJUSTED")


class Setup(unittest.TestCase):
    def test_setup_maps_the_body_into_the_unit_cube(self):
        r = sw.setup(scene_camera(), SUN, SCENE_BOX)
        res, pts = r
        self.assertEqual(r._fields, ("result", "points"))
        self.assertIn(r.status.name, sw.STATUS)
        self.assertEqual(len(pts), res.point_count)
        self.assertTrue(pts)
        for p in pts:
            x, y, z, w = apply(res.matrix, p)
            self.assertGreater(w, 0)
            self.assertLessEqual(abs(x / w), 1 + 1e-9)
            self.assertLessEqual(abs(y / w), 1 + 1e-9)
        with self.assertRaises(sw.SwarpError) as cm:
            sw.setup(scene_camera(2.0, 1.0), SUN, SCENE_BOX)
        self.assertEqual(cm.exception.status, "SWARP_ERR_NEAR_FAR")

    def test_matrix_is_proj_times_view(self):
        for tech in (sw.TECHNIQUE_UNIFORM, sw.TECHNIQUE_LISPSM, sw.TECHNIQUE_PSM):
            res = sw.setup(scene_camera(), SUN, SCENE_BOX, {"technique": tech}).result
            want = mul(res.light_proj, res.light_view)
            got = rows(res.matrix)
            for r in range(4):
                for c in range(4):
                    self.assertAlmostEqual(got[r][c], want[r][c], delta=1e-12 * (1 + abs(want[r][c])))
            # returned matrices go back in as they are (numpy arrays or row tuples)
            again = sw.mat4_mul(res.light_proj, res.light_view)
            for r in range(4):
                for c in range(4):
                    self.assertAlmostEqual(rows(again)[r][c], want[r][c], delta=1e-12 * (1 + abs(want[r][c])))
            if HAVE_NUMPY:
                import numpy as np
                self.assertEqual(np.asarray(res.matrix).shape, (4, 4))
                v = sw.mat4_transform(np.asarray(res.matrix), np.array([1.0, 2.0, 3.0]))
                for got, ref in zip(v, apply(res.matrix, (1.0, 2.0, 3.0))):
                    self.assertAlmostEqual(got, ref, delta=1e-12 * (1 + abs(ref)))
                self.assertEqual(sw.cascade_select_depth(np.array([1.0, 2.0, 4.0]), np.float64(3.0)), 1)
                self.assertTrue(np.allclose(res.light_proj @ res.light_view, res.matrix, rtol=1e-12, atol=1e-12))

    def test_setup_range_stays_in_its_range(self):
        cam = scene_camera()
        res = sw.setup_range(cam, SUN, SCENE_BOX, 2.0, 20.0).result
        self.assertGreaterEqual(res.view_near, 2.0)
        self.assertLessEqual(res.view_far, 20.0 * (1 + 1e-9))

    def test_setup_follow_is_continuous_through_the_view_axis(self):
        # the light turns through the stateless rule's zero (5.57 degrees from
        # the view direction toward the camera's right, docs/geometry.md
        # section 7) in 0.01 degree steps, fed back through setup_follow
        cam = sw.Camera(eye=(0, 10, 0), dir=(0, 0, -1), up=(0, 1, 0), fovy=1.0, aspect=16 / 9,
                        z_near=1.0, z_far=100.0)
        box = ((-300, -5, -150), (300, 40, 50))
        opts = sw.SetupOptions(technique=sw.TECHNIQUE_UNIFORM)

        def light(deg):
            g = math.radians(deg)
            return sw.Light(direction=(math.sin(g), 0, -math.cos(g)), type=sw.LIGHT_DIRECTIONAL)

        def up(res):
            return rows(res.light_view)[1][:3]

        a = sw.setup(cam, light(5.5), box, opts)[0]
        b = sw.setup(cam, light(5.63), box, opts)[0]
        self.assertLess(sum(x * y for x, y in zip(up(a), up(b))), -0.9)  # the stateless flip
        prev = None
        for k in range(540, 571):
            r = X.setup_follow(cam, light(k * 0.01), box, opts, None, prev)  # errors raise
            self.assertIn(r.status.name, sw.STATUS)
            if prev is not None:
                self.assertGreater(sum(x * y for x, y in zip(up(prev), up(r.result))), math.cos(math.radians(0.1)))
            prev = r.result
        p0 = X.setup_follow(cam, light(30), box, opts)[0]
        p1 = sw.setup(cam, light(30), box, opts)[0]
        self.assertEqual(bytes(p0), bytes(p1))  # previous = None is swarp_setup's result
        with self.assertRaises(sw.SwarpError) as cm:
            X.setup_follow(cam, light(30), box, opts, None, sw.SetupResult())
        self.assertEqual(cm.exception.status, "SWARP_ERR_ZERO_VECTOR")


class Cascades(unittest.TestCase):
    def test_cascade_splits_and_selection(self):
        s = sw.cascade_splits(1.0, 100.0, {"count": 4, "scheme": sw.SCHEME_LOG})
        self.assertEqual(len(s), 5)
        for i, v in enumerate(s):
            self.assertAlmostEqual(v, 100.0 ** (i / 4), places=9)  # [RHS] (3.7)
        self.assertEqual(sw.cascade_select_depth(s, 5.0), 1)  # 100^(1/4) = 3.16 < 5 < 10
        n = sw.cascade_nopt(s, 0.0, 0.0)
        self.assertEqual(len(n), 4)
        for i in range(4):  # [RHS] (3.2) per split, d = z_1 - z_0
            self.assertAlmostEqual(n[i] / ((s[i + 1] - s[i]) / (math.sqrt(s[i + 1] / s[i]) - 1)), 1.0, places=9)
        self.assertEqual(sw.atlas_lsc(4), 0.5)

    def test_cascade_setup_four_practical_splits(self):
        cam = scene_camera()
        r = sw.cascade_setup(cam, SUN, SCENE_BOX, {"split": {"count": 4, "scheme": sw.SCHEME_PRACTICAL,
                                                             "lambda": 0.5}})
        res, splits = r
        self.assertEqual(res.split_count, 4)
        self.assertEqual(len(splits), 4)
        n, f = res.view_near, res.view_far
        for i in range(5):  # [RHS] (3.8) with the default lambda 0.5
            c = 0.5 * n * (f / n) ** (i / 4) + 0.5 * (n + (f - n) * i / 4)
            self.assertAlmostEqual(res.splits[i] / c, 1.0, places=9)
        for i, sp in enumerate(splits):
            self.assertEqual((sp.z_near, sp.z_far), (res.splits[i], res.splits[i + 1]))
            self.assertIn(sw.status_name(sp.status), sw.STATUS)
        self.assertEqual(res.max_mx, max(sp.max_mx for sp in splits))


class Measured(unittest.TestCase):
    """swarp_measure_points against finite differences of its definition
    (docs/accuracy.md): D = J_scr . J_tex^-1 in the receiver's tangent frame."""

    W, H, MAP = 1280, 720, 1024

    def numeric(self, cam, m, p, n):
        def norm(v):
            s = math.sqrt(sum(x * x for x in v))
            return [x / s for x in v]

        def cross(a, b):
            return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

        def dot(a, b):
            return sum(x * y for x, y in zip(a, b))
        d = norm(list(cam.dir))
        r = norm(cross(d, list(cam.up)))
        u = cross(r, d)
        n = norm(n)
        wx = norm([a - dot(r, n) * b for a, b in zip(r, n)])
        wz = cross(n, wx)
        t = math.tan(cam.fovy / 2)
        eye = list(cam.eye)

        def screen(q):
            v = [a - b for a, b in zip(q, eye)]
            z = dot(v, d)
            return [(dot(v, r) / (z * t * cam.aspect) + 1) * self.W / 2, (dot(v, u) / (z * t) + 1) * self.H / 2]

        def texel(q):
            x, y, _, w = apply(m, q)
            return [(x / w + 1) * self.MAP / 2, (y / w + 1) * self.MAP / 2]

        h = 1e-4 * math.sqrt(sum((a - b) ** 2 for a, b in zip(p, eye)))

        def jac(f):
            cols = []
            for w in (wx, wz):
                fp = f([a + h * b for a, b in zip(p, w)])
                fm = f([a - h * b for a, b in zip(p, w)])
                cols.append([(a - b) / (2 * h) for a, b in zip(fp, fm)])
            return [[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]]
        S, T = jac(screen), jac(texel)
        det = T[0][0] * T[1][1] - T[0][1] * T[1][0]
        Ti = [[T[1][1] / det, -T[0][1] / det], [-T[1][0] / det, T[0][0] / det]]
        D = [[sum(S[i][k] * Ti[k][j] for k in range(2)) for j in range(2)] for i in range(2)]
        m_s, m_t = math.hypot(D[0][0], D[1][0]), math.hypot(D[0][1], D[1][1])
        a, b, c = D[0][0] ** 2 + D[1][0] ** 2, D[0][0] * D[0][1] + D[1][0] * D[1][1], D[0][1] ** 2 + D[1][1] ** 2
        sigma = math.sqrt((a + c) / 2 + math.sqrt(((a - c) / 2) ** 2 + b * b))
        return m_s, m_t, sigma

    def test_measure_points_is_the_finite_difference_jacobian(self):
        cam = scene_camera()
        res = sw.setup(cam, SUN, SCENE_BOX, {"technique": sw.TECHNIQUE_LISPSM}).result
        mres = sw.MeasureRes(screen_width=self.W, screen_height=self.H, map_width=self.MAP, map_height=self.MAP)
        pts = [(1.0, 0.0, -5.0), (-4.0, 0.0, -20.0), (6.0, 0.0, -45.0)]
        normals = [(0, 1, 0), (0.2, 1, 0.1), (0, 1, 0)]
        out = sw.measure_points(cam, res.matrix, mres, pts, normals)
        self.assertEqual(len(out), 3)
        for p, n, e in zip(pts, normals, out):
            m_s, m_t, sigma = self.numeric(cam, res.matrix, p, n)
            # central differences with h = 1e-4 of the distance: truncation
            # O(h^2) relative, well inside 1e-6
            self.assertAlmostEqual(e.m_s / m_s, 1.0, delta=1e-6)
            self.assertAlmostEqual(e.m_t / m_t, 1.0, delta=1e-6)
            self.assertAlmostEqual(e.sigma / sigma, 1.0, delta=1e-6)
            self.assertGreaterEqual(e.sigma, max(e.m_s, e.m_t))  # the largest singular value
            self.assertTrue(e.flags & sw.TEXEL_INSIDE)
        with self.assertRaises(ValueError):  # one normal per point
            sw.measure_points(cam, res.matrix, mres, pts, normals[:2])

    def test_measure_max_is_attained_at_its_point(self):
        cam = scene_camera()
        res = sw.setup(cam, SUN, SCENE_BOX).result
        mres = sw.MeasureRes(screen_width=self.W, screen_height=self.H, map_width=self.MAP, map_height=self.MAP)
        mx = sw.measure_max(cam, cam.z_near, cam.z_far, SUN, SCENE_BOX, res.matrix, mres)
        self.assertGreater(mx.samples, 0)
        self.assertGreaterEqual(mx.max_sigma, max(mx.max_m_s, mx.max_m_t))
        # bisector receiver at `at`: N halfway between the directions to the eye and to the light
        at = list(mx.at)
        to_eye = [a - b for a, b in zip(cam.eye, at)]
        le = math.sqrt(sum(v * v for v in to_eye))
        ld = list(SUN.direction)
        ll = math.sqrt(sum(v * v for v in ld))
        n = [a / le - b / ll for a, b in zip(to_eye, ld)]
        e = sw.measure_points(cam, res.matrix, mres, [at], [n])[0]
        self.assertAlmostEqual(e.sigma / mx.max_sigma, 1.0, delta=1e-9)


HAS_MEASURED = "measured" in sw.SetupResult._field_types


@unittest.skipUnless(HAS_MEASURED, "the results carry no measured error in this header")
class MeasuredInResults(unittest.TestCase):
    """The measured fields of the results are swarp_measure_max of the
    returned matrices (their definition in the header)."""

    OPTS = {"technique": sw.TECHNIQUE_LISPSM, "map_width": 1024, "map_height": 1024,
            "screen_width": 1280, "screen_height": 720}
    RES = dict(screen_width=1280, screen_height=720, map_width=1024, map_height=1024)

    def test_default_measured_is_its_matrix_measure_max(self):
        # the default (measured warp) measures camera-relative: the same
        # maximum up to the rounding of coordinates of size |eye|
        cam = scene_camera()
        res = sw.setup(cam, SUN, SCENE_BOX, self.OPTS).result
        m = sw.measure_max(cam, res.view_near, res.view_far, SUN, SCENE_BOX, res.matrix, self.RES)
        self.assertGreater(res.measured.samples, 0)
        self.assertLessEqual(abs(res.measured.max_sigma - m.max_sigma), 1e-9 * m.max_sigma)

    def test_setup_result_measured_is_measure_max(self):
        cam = scene_camera()
        nopt = dict(self.OPTS, param=sw.WARP_PARAM_NOPT)  # a closed form: search-free
        res = sw.setup(cam, SUN, SCENE_BOX, nopt).result
        m = sw.measure_max(cam, res.view_near, res.view_far, SUN, SCENE_BOX, res.matrix, self.RES)
        self.assertGreater(res.measured.samples, 0)
        self.assertEqual(bytes(res.measured), bytes(m))
        off = sw.setup(cam, SUN, SCENE_BOX, dict(nopt, skip_measure=1)).result
        self.assertEqual(off.measured.samples, 0)
        self.assertEqual(rows(off.matrix), rows(res.matrix))  # the measurement changes no matrix

    def test_cascade_measured_is_the_worst_split(self):
        cam = scene_camera()
        res, splits = sw.cascade_setup(cam, SUN, SCENE_BOX, {"setup": self.OPTS, "split": {"count": 4}})
        for sp in splits:
            self.assertGreater(sp.measured.samples, 0)
            m = sw.measure_max(cam, sp.z_near, sp.z_far, SUN, SCENE_BOX, sp.matrix, self.RES)
            self.assertEqual(bytes(sp.measured), bytes(m))
        self.assertEqual(res.measured.max_sigma, max(sp.measured.max_sigma for sp in splits))
        self.assertEqual(res.measured.max_m_s, max(sp.measured.max_m_s for sp in splits))
        self.assertEqual(res.measured.samples, sum(sp.measured.samples for sp in splits))


class Experimental(unittest.TestCase):
    def test_lixel_plane_is_pixel_for_pixel(self):
        # viewer looking down at the floor y = 0 from (0, 2, 4), 640 x 480
        f = 1.0 / math.tan(0.5)
        n, fa = 0.1, 100.0
        P = [[f / (4 / 3), 0, 0, 0], [0, f, 0, 0], [0, 0, -(fa + n) / (fa - n), -2 * fa * n / (fa - n)], [0, 0, -1, 0]]
        d = (0.0, -0.5, -1.0)
        ln = math.sqrt(sum(v * v for v in d))
        fw = [v / ln for v in d]
        s = [-fw[2], 0.0, fw[0]]
        ls = math.sqrt(sum(v * v for v in s))
        s = [v / ls for v in s]
        u = [s[1] * fw[2] - s[2] * fw[1], s[2] * fw[0] - s[0] * fw[2], s[0] * fw[1] - s[1] * fw[0]]
        eye = (0.0, 2.0, 4.0)
        V = [s + [-sum(a * b for a, b in zip(s, eye))], u + [-sum(a * b for a, b in zip(u, eye))],
             [-v for v in fw] + [sum(a * b for a, b in zip(fw, eye))], [0, 0, 0, 1]]
        MV = mul(P, V)
        M_l, info = X.lixel_matrix(MV, 640, 480, sw.Light(sw.LIGHT_POINT, position=(1, 6, 0)), (0, 1, 0, 0))
        self.assertIsInstance(info, sw.LixelInfo)
        for p in ((0.3, 0.0, 1.0), (-1.0, 0.0, -2.0), (0.5, 0.0, -0.5)):
            cv = apply(MV, p)
            cl = apply(M_l, p)
            xp, yp = (cv[0] / cv[3] + 1) * 320 - 0.5, (cv[1] / cv[3] + 1) * 240 - 0.5
            self.assertAlmostEqual(cl[0] / cl[3], xp, places=6)
            self.assertAlmostEqual(cl[1] / cl[3], yp, places=6)
            self.assertGreater(cl[3], 0)

    def test_plan_meets_its_budget(self):
        p = X.plan(sw.SceneNeeds(), sw.Budget(max_error=2.0))
        self.assertTrue(1 <= p.split_count <= sw.PLAN_MAX_SPLITS)
        if p.meets_budget:
            self.assertLessEqual(p.max_error, 2.0)
        self.assertEqual(p.max_error, max(p.max_mx, p.max_mz))
        text = X.plan_explain(p)
        self.assertIn(X.plan_warp_name(p.warp), text)

    def test_poly_from_aabb_is_the_box(self):
        poly = X.poly_from_aabb(((0, 0, 0), (1, 2, 3)))
        self.assertEqual((poly.vertex_count, poly.face_count), (8, 6))
        corners = {tuple(poly.vertices[i]) for i in range(8)}
        self.assertEqual(corners, {(x, y, z) for x in (0.0, 1.0) for y in (0.0, 2.0) for z in (0.0, 3.0)})


if __name__ == "__main__":
    unittest.main(verbosity=2)
