"""The experimental API of include/shadowwarp.h (SWARP_EXPERIMENTAL_API):
polyhedra and the body B, the continuous light frame, lixel maps, the
planner's evaluate, cube maps, min depth.  Same conventions as the stable
API; these functions may change between minor versions."""
from ._wrap import WRAPPERS

EXPERIMENTAL = sorted(n for n, w in WRAPPERS.items() if w.experimental)
for _n in EXPERIMENTAL:
    globals()[_n[len("swarp_"):]] = WRAPPERS[_n].as_function()
