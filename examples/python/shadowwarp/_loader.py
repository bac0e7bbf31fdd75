"""Finding libshadowwarp: by its SONAME through the system loader.

Order: the path given to shadowwarp.load(path); else $SHADOWWARP_LIB (a path,
used by the build tree's tests); else the SONAME (libshadowwarp.so.0 on
Linux, which is what the Debian package libshadowwarp0 installs); else
whatever ctypes.util.find_library('shadowwarp') finds.  Loading happens on
the first call into the library, so `import shadowwarp` never fails for a
missing library and load(path) can still choose one.
"""
import ctypes
import ctypes.util
import os
import sys
import threading
from typing import List, Optional

from . import _capi

SONAME_MAJOR = _capi.CONSTANTS["SWARP_VERSION_MAJOR"]

if sys.platform == "darwin":
    SONAMES = ["libshadowwarp.%d.dylib" % SONAME_MAJOR]
elif sys.platform == "win32":
    SONAMES = ["shadowwarp-%d.dll" % SONAME_MAJOR, "shadowwarp.dll", "libshadowwarp.dll"]
else:
    SONAMES = ["libshadowwarp.so.%d" % SONAME_MAJOR]

_state = {"lib": None, "path": None}
_lock = threading.Lock()


def _candidates(path: Optional[str]) -> List[str]:
    if path:
        return [path]
    env = os.environ.get("SHADOWWARP_LIB")
    if env:
        return [env]
    found = ctypes.util.find_library("shadowwarp")
    return SONAMES + ([found] if found and found not in SONAMES else [])


def load(path: Optional[str] = None) -> ctypes.CDLL:
    """Loads libshadowwarp (see the module docstring for the order) and makes
    it the library every wrapper calls.  Returns the ctypes.CDLL."""
    errors = []
    for name in _candidates(path):
        try:
            lib = ctypes.CDLL(name)
        except OSError as e:
            errors.append("%s: %s" % (name, e))
            continue
        with _lock:
            _state["lib"], _state["path"] = lib, name
        return lib
    raise OSError("libshadowwarp not found (%s); install libshadowwarp%d, or pass its path to "
                  "shadowwarp.load(path) or in $SHADOWWARP_LIB" % ("; ".join(errors), SONAME_MAJOR))


def lib() -> ctypes.CDLL:
    current = _state["lib"]
    return current if current is not None else load()


def loaded_path() -> Optional[str]:
    """The name or path the library was loaded from (None before the first call)."""
    return _state["path"]
