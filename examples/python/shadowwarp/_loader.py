"""Finding libshadowwarp: by its SONAME through the system loader.

Order: the path given to shadowwarp.load(path); else $SHADOWWARP_LIB (a path,
used by the build tree's tests); else the SONAME (libshadowwarp.so.0.2 on
Linux for version 0.2.x, what the Debian package libshadowwarp0.2 installs); else
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

# The ABI version of the SONAME (meson.build's soversion): the major version,
# or "0.minor" before 1.0, when every minor release may break the ABI.
_MAJOR, _MINOR = _capi.CONSTANTS["SWARP_VERSION_MAJOR"], _capi.CONSTANTS["SWARP_VERSION_MINOR"]
SOVERSION = "0.%d" % _MINOR if _MAJOR == 0 else "%d" % _MAJOR

if sys.platform == "darwin":
    SONAMES = ["libshadowwarp.%s.dylib" % SOVERSION]
elif sys.platform == "win32":
    SONAMES = ["shadowwarp-%s.dll" % SOVERSION, "shadowwarp.dll", "libshadowwarp.dll"]
else:
    SONAMES = ["libshadowwarp.so.%s" % SOVERSION]

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
    raise OSError("libshadowwarp not found (%s); install libshadowwarp%s, or pass its path to "
                  "shadowwarp.load(path) or in $SHADOWWARP_LIB" % ("; ".join(errors), SOVERSION))


def lib() -> ctypes.CDLL:
    current = _state["lib"]
    return current if current is not None else load()


def loaded_path() -> Optional[str]:
    """The name or path the library was loaded from (None before the first call)."""
    return _state["path"]
