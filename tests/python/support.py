"""Shared set-up of the Python package's tests.

The package comes from examples/python unless SHADOWWARP_TEST_INSTALLED is
set (then the installed one, e.g. python3-shadowwarp).  With
SHADOWWARP_TEST_NO_NUMPY set, numpy is made unimportable before the package
is imported, so the same tests run against the tuple fallback.
"""
import importlib.abc
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
HEADER = os.environ.get("SHADOWWARP_HEADER", os.path.join(ROOT, "include", "shadowwarp.h"))
SOURCE_PACKAGE = os.path.join(ROOT, "examples", "python")


class _NoNumpy(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):  # noqa: D401 - finder protocol
        if name == "numpy" or name.startswith("numpy."):
            raise ImportError("numpy hidden by SHADOWWARP_TEST_NO_NUMPY")
        return None


if os.environ.get("SHADOWWARP_TEST_NO_NUMPY"):
    sys.meta_path.insert(0, _NoNumpy())
if not os.environ.get("SHADOWWARP_TEST_INSTALLED"):
    sys.path.insert(0, SOURCE_PACKAGE)

import shadowwarp  # noqa: E402,F401

try:
    import numpy  # noqa: F401
    HAVE_NUMPY = True
except ImportError:
    HAVE_NUMPY = False


def header_text():
    with open(HEADER, encoding="utf-8") as f:
        return f.read()


def rows(m):
    """A returned matrix (numpy array or tuple of rows) as lists of floats."""
    return [[float(v) for v in row] for row in m]


def mul(a, b):
    """4x4 product by the definition (independent of numpy and the library)."""
    a, b = rows(a), rows(b)
    return [[sum(a[r][k] * b[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


def apply(m, p):
    """m (rows) applied to the point p (w = 1): (x, y, z, w)."""
    m = rows(m)
    v = list(p) + [1.0]
    return [sum(m[r][k] * v[k] for k in range(4)) for r in range(4)]
