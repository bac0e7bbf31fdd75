"""shadowwarp -- Python binding of libshadowwarp (shadow-map matrices).

    import shadowwarp as sw
    cam = sw.Camera(eye=(0, 8, 30), dir=(0, -0.25, -1), up=(0, 1, 0),
                    fovy=1.0, aspect=16 / 9, z_near=0.5, z_far=200.0)
    light = sw.Light(sw.LIGHT_DIRECTIONAL, direction=(0.6, -0.7, -0.4))
    res, points = sw.setup(cam, light, ((-50, 0, -100), (50, 20, 40)))
    res.matrix          # world -> light clip; numpy.asarray(res.matrix) is 4x4

Every function of include/shadowwarp.h's stable API is here under its C name
without the ``swarp_`` prefix (swarp_setup -> setup); the experimental API is
in shadowwarp.experimental.  Conventions (docs/python.md):

* the library is loaded by its SONAME (libshadowwarp.so.0.2 for 0.2.x) on the first
  call; load(path) or $SHADOWWARP_LIB choose another file;
* inputs: structs (Camera, Light, AABB, ...) or plain values (a vector is 3
  numbers, a box (min, max), a matrix 4 rows of 4); array lengths,
  capacities and integer ranges are checked before the call (ValueError,
  TypeError, OverflowError), so the library never sees a short buffer or a
  truncated integer;
* outputs are returned (several as a Result tuple, readable by name); a
  matrix is a 4x4 numpy array when numpy is installed, a tuple of 4 rows
  otherwise; every returned value has .status (a Status: SWARP_OK or an
  informational status);
* an error status raises SwarpError (.status, .name, .message); nothing was
  written then.
"""
from typing import Tuple as _Tuple

from . import _capi
from ._loader import load, loaded_path, SONAMES
from ._types import (AABB, STATUS, STRUCT_CLASSES, Float, Int, List, Mat4, Matrix, Plane, Result,
                     Status, Struct, SwarpError, Tuple, Vec3, Vec4, matrix)
from ._wrap import WRAPPERS, has

__version__ = "%d.%d.%d" % tuple(_capi.CONSTANTS["SWARP_VERSION_" + k] for k in ("MAJOR", "MINOR", "PATCH"))

# structs: swarp_setup_result -> SetupResult, ...
for _c, _cls in STRUCT_CLASSES.items():
    globals()[_cls.__name__] = _cls
Plan = STRUCT_CLASSES["swarp_plan_result"]

# enums and constants without the SWARP_ prefix: LIGHT_DIRECTIONAL, BODY_MAX_POINTS, ...
for _values in _capi.ENUMS.values():
    for _k, _v in _values.items():
        if not _k.endswith("_FORCE_I32") and not _k.endswith("_FORCE_U32"):
            globals()[_k[len("SWARP_"):]] = _v
for _k, _v in _capi.CONSTANTS.items():
    globals().setdefault(_k[len("SWARP_"):], _v)
# statuses keep their full names: SWARP_OK, SWARP_ERR_CAPACITY, ...
for _name, _code, _msg in _capi.STATUSES:
    globals()[_name] = Status(_code)

# the stable API
STABLE = sorted(n for n, w in WRAPPERS.items() if not w.experimental)
for _n in STABLE:
    globals()[_n[len("swarp_"):]] = WRAPPERS[_n].as_function()


def version() -> _Tuple[str, int]:
    """(version string, version number) of the loaded library."""
    return WRAPPERS["swarp_version_string"](), WRAPPERS["swarp_version_number"]()


from . import experimental  # noqa: E402,F401  (after the stable names it builds on)
