#!/usr/bin/python3
"""Every wrapper of the package fed hostile values (run under ASan too).

For each function of the header (stable and experimental) the test builds
arguments of the right shape, then replaces one argument at a time by
hostile values: integers >= 2^32 and negative ones for unsigned types, a
float or a string for an integer, NaN and infinities, None, arrays one
element short or long, empty, of the wrong element shape, structs with an
out-of-range integer field.  Each call must either return or raise
SwarpError, TypeError, ValueError or OverflowError; nothing else, no crash.
Where the package must refuse before calling (a length, a range), the test
replaces the C function by a recorder and asserts it was never reached.

Under ASan (meson test in a b_sanitize build: tests/meson.build preloads
the sanitizer runtime and sets PYTHONMALLOC=malloc, so every ctypes buffer
above 16 bytes is its own allocation; smaller ones live inside the Python
object, where ASan cannot see them, hence BASE_LENGTH = 3) a read or write
past a buffer aborts the run; a control checks that it does.
"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support  # noqa: E402,F401
import shadowwarp as sw  # noqa: E402
from shadowwarp import _wrap  # noqa: E402

ALLOWED = (sw.SwarpError, TypeError, ValueError, OverflowError)
INT_HOSTILE = [2 ** 32, 2 ** 40, 2 ** 64, -1, -2 ** 63, 1.5, "1", None, math.nan]
FLOAT_HOSTILE = [math.nan, math.inf, -math.inf, 1e308, -0.0, 5e-324, 2 ** 1100, "x", None, 1j]
BASE_LENGTH = 3  # elements of an array whose length is free


def plain_scalar(p):
    return 1.0 if p.base in ("double", "float") else 1


def plain_struct(c_name):
    """A valid value of the common input structs (so hostile values reach
    past the first argument checks), zero for the others."""
    valid = {
        "swarp_camera": lambda: sw.Camera(eye=(0, 2, 0), dir=(0, -0.3, -1), up=(0, 1, 0), fovy=1.0,
                                          aspect=16 / 9, z_near=1.0, z_far=100.0),
        "swarp_light": lambda: sw.Light(sw.LIGHT_DIRECTIONAL, direction=(0.3, -1, 0.2)),
        "swarp_aabb": lambda: sw.AABB((-50, -1, -200), (50, 10, 50)),
        "swarp_mat4": lambda: sw.Mat4.from_rows([[1, 0, 0, 0.1], [0, 1, 0, 0.2], [0, 0, 1, 0.3], [0, 0, -0.1, 1]]),
        "swarp_vec3": lambda: sw.Vec3(0.3, -1.0, 0.2),
        "swarp_vec4": lambda: sw.Vec4(0.3, -1.0, 0.2, 1.0),
        "swarp_plane": lambda: sw.Plane(0, 1, 0, 0),
        "swarp_error_config": lambda: sw.ErrorConfig(z_near=1, z_far=100, theta=0.5, res_ix=1024, res_iy=768,
                                                     res_s=1024, res_t=1024),
        "swarp_measure_res": lambda: sw.MeasureRes(screen_width=64, screen_height=64, map_width=64, map_height=64),
        "swarp_bias_map": lambda: sw.BiasMap(world_to_clip=sw.Mat4.identity(), res_s=64, res_t=64),
    }
    return valid[c_name]() if c_name in valid else sw.STRUCT_CLASSES[c_name]()


def plain_element(p):
    return plain_struct(p.base) if p.base in sw.STRUCT_CLASSES else plain_scalar(p)


def plain_array(p, n):
    """n elements; numbers strictly increasing (split lists must be)."""
    if p.base in sw.STRUCT_CLASSES:
        return [plain_struct(p.base) for _ in range(n)]
    return [plain_scalar(p) * (1 + i) for i in range(n)]


def plain_arguments(w):
    """Arguments of the right shape for wrapper w: free arrays get
    BASE_LENGTH elements, linked ones the length their relation gives."""
    env, args = {}, {}
    free = {name for expr in w.derive.values() for name in _names(expr)}
    for p in w.inputs:
        if p.role == "in_scalar":
            args[p.name] = env[p.name] = plain_scalar(p)
        elif p.role == "in_one":
            args[p.name] = plain_struct(p.base)
        elif p.role == "in_fixed":
            args[p.name] = plain_array(p, p.dims[0])
        elif p.name in free or "len(" in (p.length or ""):
            args[p.name] = env[p.name] = plain_array(p, BASE_LENGTH)
    for name, expr in w.derive.items():
        env[name] = _wrap._eval(expr, env)
    for p in w.inputs:
        if p.role == "in_array" and p.name not in args:
            args[p.name] = plain_array(p, max(0, _wrap._eval(p.length, env)))
    return {p.py_name: args[p.name] for p in w.inputs}


def _names(expr):
    import re
    return set(re.findall(r"len\((\w+)\)", expr))


def hostile_values(w, p, plain):
    if p.role == "in_scalar":
        return FLOAT_HOSTILE if p.base in ("double", "float") else INT_HOSTILE
    if p.role == "in_one":
        cls = sw.STRUCT_CLASSES[p.base]
        out = [None, 42, "s", (1, 2), [], {"no_such_field": 1}, sw.Vec3() if cls is not sw.Vec3 else sw.Mat4()]
        for f, (ctype, dims) in cls._field_types.items():
            if not f.startswith("_") and not dims and ctype not in ("double", "float") \
                    and ctype not in sw.STRUCT_CLASSES:
                out += [{f: 2 ** 32}, {f: -1 if ctype.startswith("u") else -2 ** 31 - 1}, {f: 0.5}]
        return out
    values = [None, [], "abc", 7, [None] * max(1, len(plain)), plain[:-1], plain + plain[:1]]
    if plain:
        values.append([(1, 2)] * len(plain))
        values.append([2 ** 64] * len(plain))
        values.append([math.nan] * len(plain))
    return values


OVERREAD = """
import ctypes, sys
lib = ctypes.CDLL(sys.argv[1])
cfg = (ctypes.c_double * 9)(1, 100, 0.5, 1024, 768, 1024, 1024, 0, 0)
splits = (ctypes.c_double * 3)(1, 10, 20)       # m + 1 = 4 are read
n_primes = (ctypes.c_double * 3)(2, 3, 4)
out = (ctypes.c_double * 3)()
d = ctypes.c_double()
lib.swarp_error_split_max(cfg, splits, n_primes, ctypes.c_size_t(3), out, out, ctypes.byref(d), ctypes.byref(d))
"""


class Recorder:
    def __init__(self):
        self.calls = 0

    def __call__(self, *args):
        self.calls += 1
        return 3  # SWARP_ERR_INVALID_ARGUMENT, never a crash


class Hostile(unittest.TestCase):
    outcomes = {"returned": 0, "SwarpError": 0, "refused": 0}

    def run_one(self, w, kwargs):
        try:
            w(**kwargs)
            self.outcomes["returned"] += 1
        except sw.SwarpError:
            self.outcomes["SwarpError"] += 1
        except ALLOWED[1:]:
            self.outcomes["refused"] += 1

    def test_every_wrapper_survives_hostile_arguments(self):
        calls = 0
        for name, w in sorted(_wrap.WRAPPERS.items()):
            with self.subTest(function=name):
                base = plain_arguments(w)
                self.run_one(w, base)
                for p in w.inputs:
                    for bad in hostile_values(w, p, base[p.py_name] if isinstance(base[p.py_name], list) else []):
                        args = dict(base)
                        args[p.py_name] = bad
                        self.run_one(w, args)
                        calls += 1
        self.assertGreater(calls, 1000)
        # not vacuous: many calls reach the library and many get through it
        self.assertGreater(self.outcomes["returned"], 150, self.outcomes)
        self.assertGreater(self.outcomes["SwarpError"], 300, self.outcomes)
        print("\nhostile calls: %d, %r" % (calls, self.outcomes), file=sys.stderr)

    def test_refused_before_the_call(self):
        # a wrong length or an integer out of its C range never reaches C
        reached = []
        for name, w in sorted(_wrap.WRAPPERS.items()):
            base = plain_arguments(w)
            rec = Recorder()
            saved = w._fn
            w._fn = rec
            try:
                for p in w.inputs:
                    bad = []
                    if p.role == "in_scalar" and p.base not in ("double", "float"):
                        bad = [2 ** 64, -2 ** 63 - 1, 1.5, "1"]
                    elif p.role in ("in_fixed", "in_array") and base[p.py_name]:
                        linked = p.role == "in_fixed" or "len(" not in (p.length or "") and \
                            not any(("len(%s)" % p.name) in e for e in w.derive.values())
                        if linked:
                            bad = [base[p.py_name][:-1], base[p.py_name] + base[p.py_name][:1]]
                    for v in bad:
                        args = dict(base)
                        args[p.py_name] = v
                        before = rec.calls
                        try:
                            w(**args)
                        except (TypeError, ValueError, OverflowError):
                            pass
                        if rec.calls != before:
                            reached.append((name, p.py_name, repr(v)[:40]))
            finally:
                w._fn = saved
        self.assertEqual(reached, [])

    @unittest.skipUnless(os.environ.get("SHADOWWARP_ASAN"), "not a sanitizer build")
    def test_asan_sees_an_overread_control(self):
        # the binding's former bug, called through raw ctypes: ASan must abort,
        # else the hostile sweep above proves nothing about memory safety
        import subprocess
        r = subprocess.run([sys.executable, "-c", OVERREAD, os.environ["SHADOWWARP_LIB"]],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("heap-buffer-overflow", r.stderr)

    def test_lengths_of_the_issue_inputs(self):
        cfg = sw.ErrorConfig(z_near=1, z_far=100, theta=0.5, res_ix=1024, res_iy=768, res_s=1024, res_t=1024)
        for f in (lambda: sw.error_split_max(cfg, [1.0, 10.0], [2.0, 3.0]),
                  lambda: sw.error_split_max(cfg, [1.0, 10.0, 50.0, 100.0], [2.0, 3.0]),
                  lambda: sw.error_split_curve(cfg, [1.0, 10.0], [2.0, 3.0], [5.0])):
            with self.assertRaises(ValueError):
                f()
        with self.assertRaises(OverflowError):
            sw.status_name(2 ** 40)
        with self.assertRaises(OverflowError):
            sw.Light(type=2 ** 40)
        light = sw.Light()
        with self.assertRaises(OverflowError):
            light.type = 2 ** 32 + 1  # the field keeps its value
        self.assertEqual(light.type, 0)
        with self.assertRaises(OverflowError):
            sw.SetupOptions(map_width=2 ** 32)
        with self.assertRaises(TypeError):
            sw.atlas_lsc(4.0)  # no silent rounding of a float to an integer

    def test_a_failed_conversion_leaves_a_struct_unchanged(self):
        cam = sw.Camera(eye=(1, 2, 3))
        with self.assertRaises(ValueError):
            cam.eye = (4, 5)
        with self.assertRaises(TypeError):
            cam.eye = (4, 5, "x")
        self.assertEqual(tuple(cam.eye), (1.0, 2.0, 3.0))


if __name__ == "__main__":
    unittest.main(verbosity=2)
