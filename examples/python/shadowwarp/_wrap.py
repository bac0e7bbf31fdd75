"""Python wrappers made from the header's prototypes (_capi.FUNCTIONS).

The C conventions of include/shadowwarp.h decide what each parameter is:

* a scalar by value is a Python argument (integers range-checked for their
  C type, never truncated);
* ``const T* x`` is one struct (an instance, a dict of fields or, for
  vectors, planes, boxes and matrices, a plain sequence; None is NULL),
  and ``const T* x, size_t n`` an array whose n the wrapper takes from
  len(x);
* ``T* out_x`` is an output the wrapper allocates and returns, and
  ``T* out, size_t capacity, size_t* out_count`` an output array it
  allocates with the capacity the function can need and returns cut to
  out_count;
* fixed arrays (``double out[16]``, ``const double moments[2]``) have their
  declared length.

SPECS states, per function, what the prototype alone does not say: array
lengths tied to other arguments (``splits`` holds m + 1 values), counts taken
from them, and the capacity each output array needs.  Every length is
checked before the call, so the library never reads or writes past a
Python-provided buffer.
"""
import ctypes
import inspect
import warnings
from typing import Any, Callable, Dict, List, Optional, Tuple

from . import _capi
from . import _loader
from ._types import (STRUCT_CLASSES, DEPRECATED_ALIASES, Mat4, Result, Status, Struct, SwarpError,
                     ctype_of, python_name, sequence, to_output, to_scalar)

C = _capi.CONSTANTS
# the largest output a Python caller is given for a size-dependent array:
# beyond it the library's own SWARP_ERR_CAPACITY applies (an error curve of
# SWARP_CASCADE_MAX_SPLITS splits at 65536 samples each fits).
CURVE_CAPACITY_MAX = C["SWARP_CASCADE_MAX_SPLITS"] * 65536

# Per function: "len" = length of array parameters (an expression in the C
# parameter names, evaluated once the counts are known), "derive" = counts
# computed from Python arguments, "cap" = capacity passed for an output
# array, "count" = which size_t* gives the number of valid output elements
# (with "group" doubles per element), "check" = further conditions.
SPECS: Dict[str, Dict[str, Any]] = {
    "swarp_setup": {"cap": {"capacity": "SWARP_BODY_MAX_POINTS"}},
    "swarp_setup_range": {"cap": {"capacity": "SWARP_BODY_MAX_POINTS"}},
    "swarp_setup_follow": {"cap": {"capacity": "SWARP_BODY_MAX_POINTS"}},
    "swarp_body_points": {"cap": {"capacity": "SWARP_BODY_MAX_POINTS"}},
    "swarp_measure_points": {"len": {"points": "count", "normals": "count", "out": "count"},
                             "derive": {"count": "len(points)"}},
    "swarp_error_split_curve": {"len": {"splits": "m + 1", "n_primes": "m", "z": "count",
                                        "out_mx": "count", "out_mz": "count"},
                                "derive": {"m": "len(n_primes)", "count": "len(z)"}},
    "swarp_error_split_max": {"len": {"splits": "m + 1", "n_primes": "m", "out_split_max_mx": "m",
                                      "out_split_max_mz": "m"},
                              "derive": {"m": "len(n_primes)"}},
    "swarp_split_uniform": {"cap": {"capacity": "max(1, min(m, SWARP_SPLIT_MAX_COUNT) + 1)"}},
    "swarp_split_log": {"cap": {"capacity": "max(1, min(m, SWARP_SPLIT_MAX_COUNT) + 1)"}},
    "swarp_split_practical": {"cap": {"capacity": "max(1, min(m, SWARP_SPLIT_MAX_COUNT) + 1)"}},
    "swarp_split_pseudo": {"cap": {"capacity": "max(1, min(m, SWARP_SPLIT_MAX_COUNT) + 1)"}},
    "swarp_atlas_layout": {"cap": {"capacity": "max(1, min(m, SWARP_ATLAS_MAX_SPLITS))"}},
    "swarp_cascade_select_depth": {"len": {"splits": "m + 1"}, "derive": {"m": "len(splits) - 1"}},
    "swarp_cascade_blend": {"len": {"splits": "m + 1"}, "derive": {"m": "len(splits) - 1"}},
    "swarp_cascade_splits": {"cap": {"capacity": "SWARP_SPLIT_MAX_COUNT + 1"}},
    "swarp_cascade_nopt": {"len": {"splits": "m + 1", "out_n_primes": "m"},
                           "derive": {"m": "len(splits) - 1"}},
    "swarp_cascade_error_curve": {
        "len": {"splits": "m + 1", "n_primes": "m", "out_z": "capacity", "out_mx": "capacity",
                "out_mz": "capacity"},
        "derive": {"m": "len(n_primes)"},
        "cap": {"capacity": "max(1, min(m * samples_per_split, CURVE_CAPACITY_MAX))"}},
    "swarp_cascade_setup": {"cap": {"capacity": "SWARP_CASCADE_MAX_SPLITS"}},
    "swarp_plan_cost_fit": {"len": {"texels": "count", "pass_ns": "count"}, "derive": {"count": "len(texels)"}},
    "swarp_lvsm_layer_interval": {"len": {"splits": "n_layers + 1"}, "derive": {"n_layers": "len(splits) - 1"}},
    "swarp_lvsm_layer_find": {"len": {"splits": "n_layers + 1"}, "derive": {"n_layers": "len(splits) - 1"}},
    "swarp_lvsm_transition": {"len": {"splits": "n_layers + 1"}, "derive": {"n_layers": "len(splits) - 1"}},
    "swarp_lvsm_visibility": {"len": {"splits": "n_layers + 1", "layer_moments": "2 * n_layers"},
                              "derive": {"n_layers": "len(splits) - 1"}},
    "swarp_lvsm_lloyd": {"len": {"mu": "count", "sigma2": "count", "splits_in": "n_layers + 1",
                                 "splits_out": "n_layers + 1"},
                         "derive": {"count": "len(mu)", "n_layers": "len(splits_in) - 1"}},
    "swarp_pcf_poisson_disk": {"len": {"out_xy": "2 * capacity"},
                               "cap": {"capacity": "max(1, min(count, SWARP_PCF_MAX_SAMPLES))"},
                               "count": {"out_xy": ("out_count", 2)}},
    "swarp_plan_explain": {"cap": {"capacity": "SWARP_PLAN_EXPLAIN_MAX"}},
    "swarp_lixel_split": {"cap": {"floor_capacity": "n + 1", "wall_capacity": "n + 1"}},
    "swarp_cube_faces": {"cap": {"capacity": "SWARP_CUBE_MAX_FACES"}},
    "swarp_mindepth_pyramid": {
        "len": {"depth": "len(depth)", "scratch": "scratch_capacity"},
        "cap": {"scratch_capacity": "max(1, ((width + 1) // 2) * ((height + 1) // 2))"},
        "check": [("width == 0 or height == 0 or len(depth) >= (height - 1) * row_stride + width",
                   "depth holds fewer than (height - 1) * row_stride + width values")],
        "hidden_out": ["scratch", "out_scratch_needed"]},
    "swarp_mindepth_direct": {
        "len": {"depth": "len(depth)"},
        "check": [("width == 0 or height == 0 or len(depth) >= (height - 1) * row_stride + width",
                   "depth holds fewer than (height - 1) * row_stride + width values")]},
}

# Functions whose pointer-and-count pairs follow the plain rule (an array of
# exactly count elements), each checked against its comment in the header.
# A new array function must be added here or to SPECS: until then calling it
# raises NotImplementedError and tests/python/test_header.py fails.
REVIEWED_PLAIN_ARRAYS = {
    "swarp_setup_points", "swarp_focus_fit", "swarp_warp_lispsm", "swarp_stabilize_directional",
    "swarp_cascade_select_best", "swarp_lixel_restrict", "swarp_lixel_select",
}

_SCALARS = ("double", "float", "uint8_t", "uint32_t", "int32_t", "uint64_t", "int", "size_t") + tuple(_capi.ENUMS) + tuple(_capi.SCALAR_TYPEDEFS)


class Param:
    """One C parameter and the role the conventions give it."""

    def __init__(self, name: str, base: str, ptr: int, const: bool, dims: Tuple[int, ...]) -> None:
        self.name, self.base, self.ptr, self.const, self.dims = name, base, ptr, const, dims
        self.role = ""          # in_scalar, in_fixed, out_fixed, in_one, in_array, out_one, out_array,
        self.length = None      # count, capacity, out_count, out_string
        self.count_of = None    # for out arrays: (out_count param, group)

    @property
    def py_name(self) -> str:
        return python_name(self.name)

    def __repr__(self) -> str:
        return "Param(%s %s)" % (self.name, self.role)


def classify(name: str, params: List[Tuple[str, str, int, bool, Tuple[int, ...]]]
             ) -> Tuple[List[Param], Dict[str, str]]:
    """Roles of the parameters of function `name` (module docstring)."""
    spec = SPECS.get(name, {})
    ps = [Param(*p) for p in params]
    lens, derive, caps = spec.get("len", {}), spec.get("derive", {}), spec.get("cap", {})
    for i, p in enumerate(ps):
        nxt = ps[i + 1] if i + 1 < len(ps) else None
        if p.ptr == 0 and p.dims:
            p.role = "in_fixed" if p.const else "out_fixed"
        elif p.ptr == 0:
            p.role = "count" if p.name in derive else "capacity" if p.name in caps else "in_scalar"
        elif p.const:
            p.role = "in_array" if p.name in lens else "in_one"
            if p.role == "in_one" and nxt is not None and nxt.base == "size_t" and nxt.ptr == 0 \
                    and nxt.name not in caps and nxt.name not in derive:
                p.role, p.length = "in_array", nxt.name
                derive = dict(derive, **{nxt.name: "len(%s)" % p.name})
            elif p.role == "in_array":
                p.length = lens[p.name]
        elif p.base == "char":
            p.role, p.length = "out_string", nxt.name
        elif p.name in lens:
            p.role, p.length = "out_array", lens[p.name]
        elif nxt is not None and nxt.name.endswith("capacity") and p.base != "char":
            p.role, p.length = "out_array", nxt.name
        elif p.base == "size_t" and (p.name.endswith("_count") or p.name in spec.get("hidden_out", [])):
            p.role = "out_count"
        else:
            p.role = "out_one"
    for p in ps:
        if p.role == "count" and p.name not in derive:
            raise AssertionError("%s: no way to compute %s" % (name, p.name))
        if p.role in ("out_array", "out_string") and p.length in [q.name for q in ps if q.name.endswith("capacity")]:
            cap = next(q for q in ps if q.name == p.length)
            cap.role = "capacity"
            if cap.name not in caps:
                raise AssertionError("%s: no capacity given for %s" % (name, cap.name))
            prefix = cap.name[:-len("capacity")]
            counter = [q.name for q in ps if q.role == "out_count" and q.name == "out_%scount" % prefix]
            p.count_of = (counter[0], 1) if counter else None
        if p.name in spec.get("count", {}):
            p.count_of = spec["count"][p.name]
    return ps, derive


def _eval(expr: str, env: Dict[str, Any]) -> int:
    return int(eval(expr, {"__builtins__": {"len": len, "max": max, "min": min}},  # noqa: S307
                    dict(C, CURVE_CAPACITY_MAX=CURVE_CAPACITY_MAX, **env)))


def _c_type(p: Param) -> Any:
    """The ctypes argtype of parameter p."""
    base = ctypes.c_char if p.base == "char" else ctype_of(p.base)
    if p.ptr or p.dims:
        return ctypes.POINTER(base)
    return base


def _restype(ret: str) -> Any:
    if ret == "const char *":
        return ctypes.c_char_p
    return ctypes.c_int


class Wrapper:
    """A callable that converts, checks, calls one C function and returns its
    outputs; .c_name, .params, .experimental."""

    def __init__(self, name: str, ret: str, params: List[Tuple[str, str, int, bool, Tuple[int, ...]]],
                 experimental: bool) -> None:
        self.c_name, self.ret, self.experimental = name, ret, experimental
        self.params, self.derive = classify(name, params)
        self.spec = SPECS.get(name, {})
        self.inputs = [p for p in self.params if p.role in ("in_scalar", "in_fixed", "in_one", "in_array")]
        hidden = self.spec.get("hidden_out", [])
        self.outputs = [p for p in self.params if p.role in ("out_one", "out_fixed", "out_array", "out_string")
                        and p.name not in hidden]
        self._fn = None
        self.reviewed = name in SPECS or name in REVIEWED_PLAIN_ARRAYS or not any(
            p.role in ("in_array", "out_array", "count", "capacity", "out_count", "out_string") for p in self.params)
        self.__name__ = name[len("swarp_"):]
        self.__qualname__ = self.__name__
        self.__doc__ = self._doc()
        self.__signature__ = self._signature()

    def _doc(self) -> str:
        ins = ", ".join(p.py_name for p in self.inputs)
        outs = ", ".join(self._out_name(p) for p in self.outputs) or "status"
        return ("%s(%s) -> %s\n\nWraps %s of include/shadowwarp.h; an error status raises "
                "SwarpError, the returned value carries the status in .status.  Array counts and "
                "capacities are the wrapper's.  The header's comment:\n\n%s"
                % (self.__name__, ins, outs, self.c_name, _capi.DOCS.get(self.c_name, "")))

    def _signature(self) -> inspect.Signature:
        params = []
        trailing = len(self.inputs)  # options (and previous frames) default to NULL when trailing
        while trailing > 0 and self.inputs[trailing - 1].role == "in_one" and \
                ("opt" in self.inputs[trailing - 1].name or self.inputs[trailing - 1].name.startswith("previous")):
            trailing -= 1
        for i, p in enumerate(self.inputs):
            optional = i >= trailing
            params.append(inspect.Parameter(p.py_name, inspect.Parameter.POSITIONAL_OR_KEYWORD,
                                            default=None if optional else inspect.Parameter.empty,
                                            annotation=self._annotation(p)))
        return inspect.Signature(params)

    @staticmethod
    def _annotation(p: Param) -> Any:
        if p.role == "in_scalar":
            return float if p.base in ("double", "float") else int
        if p.role in ("in_fixed", "in_array"):
            return "Sequence[%s]" % ("float" if p.base in ("double", "float") else STRUCT_CLASSES[p.base].__name__)
        return "Optional[%s]" % STRUCT_CLASSES[p.base].__name__

    @staticmethod
    def _out_name(p: Param) -> str:
        if p.name in ("out", "r"):
            return "result"
        return p.name[len("out_"):] if p.name.startswith("out_") else p.name

    def as_function(self) -> Callable[..., Any]:
        """A plain Python function calling this wrapper, so help() and
        inspect show its name, signature and documentation."""
        def call(*args: Any, **kwargs: Any) -> Any:
            return self(*args, **kwargs)
        call.__name__ = call.__qualname__ = self.__name__
        call.__doc__ = self.__doc__
        call.__signature__ = self.__signature__  # type: ignore[attr-defined]
        call.__module__ = "shadowwarp.experimental" if self.experimental else "shadowwarp"
        call.wrapper = self  # type: ignore[attr-defined]
        return call

    def function(self) -> Any:
        if self._fn is None:
            try:
                f = getattr(_loader.lib(), self.c_name)
            except AttributeError:
                raise NotImplementedError(self.c_name + " is not in the loaded libshadowwarp") from None
            f.argtypes = [_c_type(p) for p in self.params]
            f.restype = _restype(self.ret)
            self._fn = f
        return self._fn

    def bind(self, args: Tuple[Any, ...], kwargs: Dict[str, Any]) -> Dict[str, Any]:
        """Python arguments by C parameter name (keyword aliases resolved)."""
        names = [p.py_name for p in self.inputs]
        for old, new in DEPRECATED_ALIASES.items():
            if old in kwargs and new in names:
                warnings.warn("%s=: use %s=" % (old, new), DeprecationWarning, stacklevel=3)
                kwargs[new] = kwargs.pop(old)
        bound = self.__signature__.bind(*args, **kwargs)
        bound.apply_defaults()
        return {p.name: bound.arguments[p.py_name] for p in self.inputs}

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        if not self.reviewed:
            raise NotImplementedError("%s: array lengths not reviewed (shadowwarp/_wrap.py SPECS)" % self.c_name)
        values = self.bind(args, kwargs)
        env: Dict[str, Any] = {}
        converted: Dict[str, Any] = {}
        seqs: Dict[str, List[Any]] = {}
        for p in self.inputs:
            v = values[p.name]
            if p.role == "in_scalar":
                converted[p.name] = env[p.name] = to_scalar(v, p.base, p.py_name)
            elif p.role == "in_array" and v is None:  # NULL with a count of 0: nothing is read
                seqs[p.name] = None
                env[p.name] = []
            elif p.role in ("in_fixed", "in_array"):
                seqs[p.name] = env[p.name] = sequence(v, p.py_name)
            else:
                converted[p.name] = None if v is None else STRUCT_CLASSES[p.base].coerce(v, p.py_name)
        for name, expr in self.derive.items():
            ctype = next(p.base for p in self.params if p.name == name)
            n = _eval(expr, env)
            if n < 0:
                raise ValueError("%s: %s gives %s = %d (too few values)" % (self.__name__, expr, name, n))
            converted[name] = env[name] = to_scalar(n, ctype, name)
        for p in self.params:
            if p.role == "capacity":
                converted[p.name] = env[p.name] = _eval(self.spec["cap"][p.name], env)
        for expr, message in self.spec.get("check", []):
            if not _eval(expr, env):
                raise ValueError("%s: %s" % (self.__name__, message))
        call = []
        outs: Dict[str, Any] = {}
        for p in self.params:
            if p.role in ("in_fixed", "in_array"):
                n = p.dims[0] if p.role == "in_fixed" else _eval(p.length, env)
                items = seqs[p.name]
                if items is None:
                    call.append(None)
                    continue
                if len(items) != n:
                    raise ValueError("%s: %s needs %d values, got %d" % (self.__name__, p.py_name, n, len(items)))
                call.append(_in_array(p, items))
            elif p.role == "in_one":
                v = converted[p.name]
                call.append(None if v is None else ctypes.byref(v))
            elif p.role in ("in_scalar", "count", "capacity"):
                call.append(converted[p.name])
            elif p.role in ("out_fixed", "out_array", "out_string"):
                n = p.dims[0] if p.role == "out_fixed" else _eval(p.length, env)
                base = ctypes.c_char if p.base == "char" else ctype_of(p.base)
                outs[p.name] = (base * max(1, n))()
                call.append(outs[p.name])
            else:  # out_one, out_count
                outs[p.name] = ctype_of(p.base)()
                call.append(ctypes.byref(outs[p.name]))
        code = self.function()(*call)
        if self.ret == "const char *":
            return code.decode() if code is not None else None
        if self.ret != "swarp_status":
            return code
        if 0 < code < 1000:
            raise SwarpError(code, self.c_name)
        return self._results(outs, code)

    def _results(self, outs: Dict[str, Any], code: int) -> Any:
        results = []
        for p in self.outputs:
            buf = outs[p.name]
            if p.role == "out_string":
                value: Any = buf.value.decode()
            elif p.role == "out_one":
                value = buf if isinstance(buf, Struct) else buf.value
                if isinstance(value, Mat4):
                    value = to_output(value, code)
                elif isinstance(value, Struct):
                    value = type(value).from_buffer_copy(value)
            elif p.role == "out_fixed":
                value = list(buf)
            else:
                n = len(buf)
                group = 1
                if p.count_of is not None:
                    counter, group = p.count_of
                    n = min(n, outs[counter].value * group)
                value = [to_output(v, code) if isinstance(v, Struct) else v for v in buf[:n]]
                if isinstance(value and value[0], Struct):
                    value = [type(v).from_buffer_copy(v) for v in value]
                if group > 1:
                    value = [tuple(value[i:i + group]) for i in range(0, n, group)]
                elif p.base in ("swarp_vec3", "swarp_vec4", "swarp_plane"):
                    value = [tuple(v) for v in value]
            results.append(to_output(value, code))
        if not results:
            return Status(code)
        if len(results) == 1:
            return results[0]
        r = Result(results)
        r._fields = tuple(self._out_name(p) for p in self.outputs)
        r.status = Status(code)
        return r


def _in_array(p: Param, items: List[Any]) -> Any:
    what = p.py_name
    if p.base in STRUCT_CLASSES:
        cls = STRUCT_CLASSES[p.base]
        vals = [cls.coerce(v, "%s[%d]" % (what, i)) for i, v in enumerate(items)]
        return (cls * max(1, len(vals)))(*vals)
    vals = [to_scalar(v, p.base, "%s[%d]" % (what, i)) for i, v in enumerate(items)]
    return (ctype_of(p.base) * max(1, len(vals)))(*vals)


WRAPPERS: Dict[str, Wrapper] = {f[0]: Wrapper(*f) for f in _capi.FUNCTIONS}


def has(name: str) -> bool:
    """True if the loaded library exports the C function `name`."""
    return hasattr(_loader.lib(), name)


__all__ = ["WRAPPERS", "Wrapper", "has", "SPECS", "Optional", "Callable"]
