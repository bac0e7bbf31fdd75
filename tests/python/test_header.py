#!/usr/bin/python3
"""The package against include/shadowwarp.h: nothing missing, nothing stale.

* _capi.py is what gen_capi.py makes of the header now (a header change
  without regenerating fails here, with the command to run);
* every SWARP_API function declared outside the SWARP_EXPERIMENTAL_API
  block is a callable of the package, and every experimental one of
  shadowwarp.experimental; the declarations are found here by a line scan
  independent of the generator's parser.
"""
import os
import re
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from support import HEADER, SOURCE_PACKAGE, header_text  # noqa: E402
import shadowwarp as sw  # noqa: E402


def elf_soname(path):
    """DT_SONAME of a shared library, as readelf reports it."""
    import subprocess
    out = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True).stdout
    return re.search(r"\(SONAME\)\s+Library soname: \[([^\]]+)\]", out).group(1)


def declared_functions():
    """(stable, experimental) function names: each `SWARP_API ... swarp_x(`
    of the header, split at its `#ifdef SWARP_EXPERIMENTAL_API` line."""
    stable, experimental, inside = set(), set(), False
    for line in header_text().splitlines():
        if line.startswith("#ifdef SWARP_EXPERIMENTAL_API"):
            inside = True
        elif line.startswith("#endif /* SWARP_EXPERIMENTAL_API"):
            inside = False
        m = re.match(r"\s*SWARP_API\b.*?\b(swarp_\w+)\s*\(", line)
        if m:
            (experimental if inside else stable).add(m.group(1))
    return stable, experimental


class Header(unittest.TestCase):
    def test_every_stable_function_is_wrapped(self):
        stable, _ = declared_functions()
        self.assertGreater(len(stable), 80)
        missing = sorted(n for n in stable if not callable(getattr(sw, n[len("swarp_"):], None)))
        self.assertEqual(missing, [], "stable functions of the header without a wrapper")
        self.assertEqual(set(sw.STABLE), stable)

    def test_every_experimental_function_is_wrapped(self):
        _, experimental = declared_functions()
        self.assertGreater(len(experimental), 10)
        missing = sorted(n for n in experimental if not callable(getattr(sw.experimental, n[len("swarp_"):], None)))
        self.assertEqual(missing, [])
        for n in experimental:  # the stable namespace stays stable
            self.assertFalse(hasattr(sw, n[len("swarp_"):]), n)

    def test_every_array_convention_is_reviewed(self):
        from shadowwarp._wrap import WRAPPERS
        self.assertEqual(sorted(n for n, w in WRAPPERS.items() if not w.reviewed), [])

    def test_every_wrapped_function_is_in_the_library(self):
        stable, experimental = declared_functions()
        lib = sw.load(os.environ.get("SHADOWWARP_LIB"))
        self.assertEqual(sorted(n for n in stable | experimental if not hasattr(lib, n)), [])

    def test_generated_api_is_current(self):
        if os.environ.get("SHADOWWARP_TEST_INSTALLED"):
            self.skipTest("installed package: checked in the source tree")
        sys.path.insert(0, SOURCE_PACKAGE)
        import gen_capi
        with open(os.path.join(SOURCE_PACKAGE, "shadowwarp", "_capi.py"), encoding="utf-8") as f:
            committed = f.read()
        self.assertEqual(gen_capi.generate(HEADER), committed,
                         "examples/python/shadowwarp/_capi.py is stale: run /usr/bin/python3 "
                         "examples/python/gen_capi.py include/shadowwarp.h examples/python/shadowwarp/_capi.py")

    def test_type_stubs_are_current(self):
        if os.environ.get("SHADOWWARP_TEST_INSTALLED"):
            self.skipTest("installed package: checked in the source tree")
        import ast
        sys.path.insert(0, SOURCE_PACKAGE)
        import gen_stubs
        for name, text in (("__init__.pyi", gen_stubs.module_stub()), ("experimental.pyi", gen_stubs.experimental_stub())):
            with open(os.path.join(SOURCE_PACKAGE, "shadowwarp", name), encoding="utf-8") as f:
                committed = f.read()
            self.assertEqual(text, committed, "%s is stale: run PYTHONPATH=examples/python /usr/bin/python3 "
                             "examples/python/gen_stubs.py" % name)
            tree = ast.parse(committed)
            defined = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
            wanted = sw.STABLE if name == "__init__.pyi" else sw.experimental.EXPERIMENTAL
            self.assertEqual(sorted(n[len("swarp_"):] for n in wanted if n[len("swarp_"):] not in defined), [])

    def test_packaging_lists_every_module_and_the_version(self):
        if os.environ.get("SHADOWWARP_TEST_INSTALLED"):
            self.skipTest("installed package: checked in the source tree")
        pkg = os.path.join(SOURCE_PACKAGE, "shadowwarp")
        files = sorted(f for f in os.listdir(pkg) if f.endswith((".py", ".pyi")) or f == "py.typed")
        with open(os.path.join(SOURCE_PACKAGE, "meson.build"), encoding="utf-8") as f:
            listed = sorted(os.path.basename(x) for x in re.findall(r"'shadowwarp/([^']+)'", f.read()))
        self.assertEqual(listed, files, "examples/python/meson.build must install every module")
        with open(os.path.join(SOURCE_PACKAGE, "pyproject.toml"), encoding="utf-8") as f:
            version = re.search(r'^version = "([^"]+)"', f.read(), re.M).group(1)
        self.assertEqual(version, sw.__version__, "pyproject.toml version is the header's")

    def test_loads_by_soname_or_the_given_path(self):
        lib = os.environ.get("SHADOWWARP_LIB")
        if not lib or not sys.platform.startswith("linux"):
            self.skipTest("needs the built library on Linux")
        import subprocess
        code = "import shadowwarp as sw; sw.version(); print(sw.loaded_path())"
        env = {k: v for k, v in os.environ.items() if k != "SHADOWWARP_LIB"}
        env["LD_LIBRARY_PATH"] = os.path.dirname(os.path.abspath(lib))
        out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
        self.assertEqual(out.stdout.strip(), elf_soname(lib))  # the SONAME, through the system loader
        env.pop("LD_LIBRARY_PATH")
        code = "import shadowwarp as sw; sw.load(%r); print(sw.loaded_path(), sw.version()[0])" % lib
        out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
        self.assertEqual(out.stdout.split(), [lib, sw.__version__])
        code = "import shadowwarp as sw\ntry:\n sw.load('/nonexistent/libshadowwarp.so')\nexcept OSError as e:\n print(e)"
        out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
        self.assertIn("SHADOWWARP_LIB", out.stdout)

    def test_detects_a_new_function(self):
        # the check above is not vacuous: a header with one more stable
        # declaration generates a different API with a function the package lacks
        sys.path.insert(0, SOURCE_PACKAGE)
        import gen_capi
        import tempfile
        text = header_text().replace(
            "#ifdef SWARP_EXPERIMENTAL_API",
            "SWARP_API swarp_status swarp_new_function(double x, double* out_y);\n#ifdef SWARP_EXPERIMENTAL_API", 1)
        with tempfile.NamedTemporaryFile("w", suffix=".h", delete=False) as f:
            f.write(text)
        try:
            ns = {}
            exec(gen_capi.generate(f.name), ns)  # noqa: S102 - the generator's own output
        finally:
            os.unlink(f.name)
        names = {fn[0] for fn in ns["FUNCTIONS"] if not fn[3]}
        self.assertIn("swarp_new_function", names)
        self.assertNotIn("swarp_new_function", sw.STABLE)


if __name__ == "__main__":
    unittest.main(verbosity=2)
