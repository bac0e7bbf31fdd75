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


if __name__ == "__main__":
    unittest.main(verbosity=2)
