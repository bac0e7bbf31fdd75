"""Statuses, exceptions and the ctypes mirrors of the header's structs.

Every struct class is built from the header's field list (_capi.STRUCTS), so
its layout is the C layout by construction (ctypes applies the C alignment
rules; tests/python/layouts.c checks sizeof and offsetof against the C
compiler).  Integer fields are range-checked on assignment: ctypes would
silently keep the low bits of 2**40, which would turn a hostile value into a
valid-looking one.
"""
import ctypes
import keyword
import numbers
import operator
import warnings
import typing as t
from typing import Any, Dict, Iterator, Optional, Sequence

from . import _capi

try:  # numpy is optional: 4x4 numpy arrays when present, tuples of rows otherwise
    import numpy as _np
except ImportError:  # pragma: no cover - exercised by the numpy-free test run
    _np = None

# ---- statuses ----------------------------------------------------------------
_STATUS_INFO = {code: (name, message) for name, code, message in _capi.STATUSES}
STATUS: Dict[str, int] = {name: code for name, code, _ in _capi.STATUSES}


class Status(int):
    """A swarp_status: an int (the ABI number) with .name and .message.

    Compares equal to its number and to its name: ``st == 'SWARP_OK'``."""

    name: str
    message: str

    def __new__(cls, code: int) -> "Status":
        self = super().__new__(cls, code)
        self.name, self.message = _STATUS_INFO.get(int(code), ("SWARP_UNKNOWN_STATUS", "unknown status"))
        return self

    @property
    def is_error(self) -> bool:
        """Errors are 1..999; 0 is SWARP_OK, 1000.. are informational."""
        return 0 < int(self) < 1000

    def __eq__(self, other: Any) -> bool:
        if isinstance(other, str):
            return self.name == other
        return int.__eq__(self, other)

    def __ne__(self, other: Any) -> bool:
        return not self.__eq__(other)

    __hash__ = int.__hash__

    def __repr__(self) -> str:
        return "<%s = %d>" % (self.name, int(self))

    def __str__(self) -> str:
        return self.name


class SwarpError(Exception):
    """An error status (1..999) returned by a libshadowwarp function; the
    function wrote none of its outputs.  .status (a Status: number, .name,
    .message), .name, .message, .function (the C name)."""

    def __init__(self, status: int, function: str) -> None:
        self.status = Status(status)
        self.name = self.status.name
        self.message = self.status.message
        self.function = function
        super().__init__("%s: %s (%s)" % (function, self.name, self.message))

    @property
    def code(self) -> int:
        return int(self.status)


# ---- results carrying the call's status -------------------------------------------
class Float(float):
    """A float result with the call's .status."""
    status: Status = Status(0)


class Int(int):
    """An integer result with the call's .status."""
    status: Status = Status(0)


class List(list):
    """A list result with the call's .status."""
    status: Status = Status(0)


class Tuple(tuple):
    """A tuple result (a vector, a fixed array) with the call's .status."""
    status: Status = Status(0)


class Result(tuple):
    """Several outputs of one call: a tuple, also readable by name
    (r.result, r.points, ...), with the call's .status."""
    status: Status = Status(0)
    _fields: t.Tuple[str, ...] = ()

    def __getattr__(self, name: str) -> Any:
        try:
            return self[self._fields.index(name)]
        except ValueError:
            raise AttributeError(name) from None

    def __repr__(self) -> str:
        body = ", ".join("%s=%r" % (f, v) for f, v in zip(self._fields, self))
        return "Result(%s; status=%s)" % (body, self.status.name)


if _np is not None:
    class Matrix(_np.ndarray):
        """A 4x4 numpy array (M[row, column]) with the call's .status."""
        status = Status(0)

        def __array_finalize__(self, obj: Any) -> None:
            self.status = getattr(obj, "status", Status(0))
else:
    class Matrix(tuple):  # type: ignore[no-redef]
        """Four row tuples (M[row][column]) with the call's .status."""
        status = Status(0)


def matrix(rows: Sequence[Sequence[float]], status: int = 0) -> Any:
    """rows as a Matrix: a 4x4 numpy array when numpy is present."""
    if _np is not None:
        out = _np.array(rows, dtype=_np.float64).reshape(4, 4).view(Matrix)
    else:
        out = Matrix(tuple(float(v) for v in row) for row in rows)
    out.status = Status(status)
    return out


# ---- scalar conversion ------------------------------------------------------------
_INT_RANGES = {
    "uint8_t": (0, 2 ** 8 - 1), "uint32_t": (0, 2 ** 32 - 1), "int32_t": (-2 ** 31, 2 ** 31 - 1),
    "uint64_t": (0, 2 ** 64 - 1), "int": (-2 ** 31, 2 ** 31 - 1),
    "size_t": (0, 2 ** (8 * ctypes.sizeof(ctypes.c_size_t)) - 1),
}
_CTYPES = {"double": ctypes.c_double, "float": ctypes.c_float, "uint8_t": ctypes.c_uint8,
           "uint32_t": ctypes.c_uint32, "int32_t": ctypes.c_int32, "uint64_t": ctypes.c_uint64,
           "int": ctypes.c_int, "size_t": ctypes.c_size_t, "char": ctypes.c_char}
for _enum in _capi.ENUMS:  # C enums are int; every enum of the header forces 32 bits
    _INT_RANGES[_enum] = _INT_RANGES["int32_t"]
    _CTYPES[_enum] = ctypes.c_int32
for _name, _base in _capi.SCALAR_TYPEDEFS.items():  # swarp_status is an int32_t
    _INT_RANGES[_name] = _INT_RANGES[_base]
    _CTYPES[_name] = _CTYPES[_base]


def is_integer_type(ctype: str) -> bool:
    return ctype in _INT_RANGES


def to_int(value: Any, ctype: str, what: str) -> int:
    """value as an integer of C type ctype, or TypeError/OverflowError: no
    truncation, no rounding of a float."""
    if isinstance(value, bool):
        value = int(value)
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError("%s must be an integer (%s), not %s" % (what, ctype, type(value).__name__)) from None
    lo, hi = _INT_RANGES[ctype]
    if not lo <= v <= hi:
        raise OverflowError("%s = %d is outside %s [%d, %d]" % (what, v, ctype, lo, hi))
    return v


def to_float(value: Any, what: str) -> float:
    """value as a double; NaN and infinities pass (the library reports them)."""
    if isinstance(value, (str, bytes)) or not isinstance(value, numbers.Real) and not hasattr(value, "__float__"):
        raise TypeError("%s must be a real number, not %s" % (what, type(value).__name__))
    return float(value)


def to_scalar(value: Any, ctype: str, what: str) -> Any:
    if ctype in ("double", "float"):
        return to_float(value, what)
    return to_int(value, ctype, what)


def sequence(value: Any, what: str) -> t.List[Any]:
    if isinstance(value, (str, bytes, dict)) or value is None:
        raise TypeError("%s must be a sequence, not %s" % (what, type(value).__name__))
    if _np is not None and isinstance(value, _np.ndarray):
        return list(value)
    try:
        return list(value)
    except TypeError:
        raise TypeError("%s must be a sequence, not %s" % (what, type(value).__name__)) from None


# ---- structs ------------------------------------------------------------------------
DEPRECATED_ALIASES = {"near": "z_near", "far": "z_far"}


def python_name(c_name: str) -> str:
    """C names that are Python keywords (lambda, raise, in) take a trailing underscore."""
    return c_name + "_" if keyword.iskeyword(c_name) else c_name


def c_name_of(py_name: str) -> Optional[str]:
    """The C name behind a keyword-escaped Python name, else None."""
    return py_name[:-1] if py_name.endswith("_") and keyword.iskeyword(py_name[:-1]) else None


class Struct(ctypes.Structure):
    """Base of the header's structs: zero-initialised (zero means default in
    every options struct), fields by position or keyword, range-checked."""

    _c_name = ""
    _field_types: Dict[str, t.Tuple[str, t.Tuple[int, ...]]] = {}

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__()
        public = self.public_fields()
        if len(args) > len(public):
            raise TypeError("%s takes at most %d positional fields" % (type(self).__name__, len(public)))
        for name, value in zip(public, args):
            setattr(self, name, value)
        for key, value in kwargs.items():
            if key in DEPRECATED_ALIASES and DEPRECATED_ALIASES[key] in self._field_types:
                warnings.warn("%s=: use %s=" % (key, DEPRECATED_ALIASES[key]), DeprecationWarning, stacklevel=2)
                key = DEPRECATED_ALIASES[key]
            key = c_name_of(key) or key
            if key not in self._field_types or key.startswith("_"):
                raise TypeError("%s has no field %r" % (type(self).__name__, key))
            setattr(self, key, value)

    @classmethod
    def public_fields(cls) -> t.List[str]:
        return [f for f in cls._field_types if not f.startswith("_")]

    def __setattr__(self, name: str, value: Any) -> None:
        spec = self._field_types.get(name)
        if spec is None:
            alias = c_name_of(name)
            if alias is not None:
                return setattr(self, alias, value)
            return object.__setattr__(self, name, value)
        ctype, dims = spec
        what = "%s.%s" % (type(self).__name__, name)
        if ctype == "swarp_mat4" and not dims and type(self)._c_name != "swarp_mat4":
            return object.__setattr__(self, name, value)  # the matrix property
        if dims:
            arr = getattr(self, name)
            _fill_array(arr, value, ctype, dims, what)
            return None
        super().__setattr__(name, _convert(value, ctype, what))
        return None

    def __getattr__(self, name: str) -> Any:
        alias = c_name_of(name)
        if alias is not None:
            return getattr(self, alias)
        raise AttributeError("%s has no field %r" % (type(self).__name__, name))

    @classmethod
    def coerce(cls, value: Any, what: str = "") -> "Struct":
        """value as this struct: an instance, a dict of fields, or (vectors,
        planes, boxes, matrices) a plain sequence."""
        if isinstance(value, cls):
            return value
        if isinstance(value, dict):
            return cls(**value)
        if isinstance(value, Struct):
            raise TypeError("%s must be %s, not %s" % (what or "value", cls.__name__, type(value).__name__))
        return cls._from_sequence(value, what or cls.__name__)

    @classmethod
    def _from_sequence(cls, value: Any, what: str) -> "Struct":
        raise TypeError("%s must be %s or a dict of its fields, not %s"
                        % (what, cls.__name__, type(value).__name__))

    def to_dict(self) -> Dict[str, Any]:
        return {python_name(f): _plain(getattr(self, f)) for f in self.public_fields()}

    def __eq__(self, other: Any) -> bool:
        if isinstance(other, Struct):
            return type(self) is type(other) and bytes(self) == bytes(other)
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]  # mutable

    def __repr__(self) -> str:
        return "%s(%s)" % (type(self).__name__,
                           ", ".join("%s=%r" % (python_name(f), _plain(getattr(self, f))) for f in self.public_fields()))


def _plain(value: Any) -> Any:
    if isinstance(value, Mat4):
        return value.rows()
    if isinstance(value, Matrix):
        return [list(map(float, row)) for row in value]
    if isinstance(value, (Vec3, Vec4, Plane)):
        return tuple(value)
    if isinstance(value, Struct):
        return value
    if isinstance(value, ctypes.Array):
        return [_plain(v) for v in value]
    if isinstance(value, bytes):
        return value
    return value


def _convert(value: Any, ctype: str, what: str) -> Any:
    if ctype in STRUCT_CLASSES:
        return STRUCT_CLASSES[ctype].coerce(value, what)
    return to_scalar(value, ctype, what)


def _fill_array(arr: Any, value: Any, ctype: str, dims: t.Tuple[int, ...], what: str) -> None:
    items = sequence(value, what)
    if len(items) != dims[0]:
        raise ValueError("%s needs %d values, got %d" % (what, dims[0], len(items)))
    converted = [None] * dims[0]
    for i, item in enumerate(items):  # convert all before writing any: outputs untouched on error
        if len(dims) > 1:
            sub = sequence(item, "%s[%d]" % (what, i))
            if len(sub) != dims[1]:
                raise ValueError("%s[%d] needs %d values, got %d" % (what, i, dims[1], len(sub)))
            converted[i] = [_convert(v, ctype, "%s[%d]" % (what, i)) for v in sub]
        else:
            converted[i] = _convert(item, ctype, "%s[%d]" % (what, i))
    for i, item in enumerate(converted):
        if len(dims) > 1:
            for j, v in enumerate(item):
                arr[i][j] = v
        else:
            arr[i] = item


def ctype_of(ctype: str, dims: t.Tuple[int, ...] = ()) -> Any:
    t = STRUCT_CLASSES[ctype] if ctype in STRUCT_CLASSES else _CTYPES[ctype]
    for d in reversed(dims):
        t = t * d
    return t


class _VectorMixin:
    """Vectors and planes read as tuples: iteration, len, indexing, numpy."""
    _n = 0

    def __iter__(self) -> Iterator[float]:
        return iter([getattr(self, f) for f in self.public_fields()])  # type: ignore[attr-defined]

    def __len__(self) -> int:
        return self._n

    def __getitem__(self, i: int) -> float:
        return tuple(self)[i]

    def __array__(self, dtype: Any = None, copy: Any = None) -> Any:
        return _np.array(tuple(self), dtype=dtype)

    @classmethod
    def _from_sequence(cls, value: Any, what: str) -> Any:
        items = sequence(value, what)
        if len(items) != cls._n:
            raise ValueError("%s needs %d numbers, got %d" % (what, cls._n, len(items)))
        return cls(*[to_float(v, "%s[%d]" % (what, i)) for i, v in enumerate(items)])


def _struct_class(c_name: str, fields: t.List[t.Tuple[str, str, t.Tuple[int, ...]]]) -> type:
    bases: t.Tuple[type, ...] = (Struct,)
    cls_name = "".join(p.capitalize() for p in c_name[len("swarp_"):].split("_"))
    cls_name = {"Aabb": "AABB", "PlanResult": "PlanResult"}.get(cls_name, cls_name)
    if c_name in ("swarp_vec3", "swarp_vec4", "swarp_plane"):
        bases = (_VectorMixin, Struct)
    elif c_name == "swarp_mat4":
        bases = (_Mat4Mixin, Struct)
    elif c_name == "swarp_aabb":
        bases = (_AABBMixin, Struct)
    cls = type(cls_name, bases, {
        "_fields_": [(f, ctype_of(t, d)) for f, t, d in fields],
        "_c_name": c_name,
        "_field_types": {f: (t, d) for f, t, d in fields},
        "_n": len(fields),
        "__doc__": "%s of include/shadowwarp.h (fields: %s)."
                   % (c_name, ", ".join(python_name(f) for f, _, _ in fields if not f.startswith("_"))),
        "__module__": "shadowwarp",
    })
    return cls


class _Mat4Mixin:
    """Column-major 4x4 (element row r, column c is m[c*4 + r]), read as its
    rows: M[r, c], rows(), numpy.asarray(M) is the 4x4 array."""

    @classmethod
    def from_rows(cls, rows: Any) -> Any:
        out = cls()
        items = sequence(rows, "matrix rows")
        if len(items) != 4:
            raise ValueError("a matrix needs 4 rows, got %d" % len(items))
        vals = []
        for r, row in enumerate(items):
            cols = sequence(row, "matrix row %d" % r)
            if len(cols) != 4:
                raise ValueError("matrix row %d needs 4 values, got %d" % (r, len(cols)))
            vals.append([to_float(v, "matrix[%d][%d]" % (r, c)) for c, v in enumerate(cols)])
        for r in range(4):
            for c in range(4):
                out.m[c * 4 + r] = vals[r][c]
        return out

    @classmethod
    def from_column_major(cls, values: Sequence[float]) -> Any:
        items = sequence(values, "column-major matrix")
        if len(items) != 16:
            raise ValueError("a column-major matrix needs 16 values, got %d" % len(items))
        return cls(m=items)

    @classmethod
    def identity(cls) -> Any:
        return cls.from_rows([[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)])

    @classmethod
    def _from_sequence(cls, value: Any, what: str) -> Any:
        return cls.from_rows(value)

    def rows(self) -> t.List[t.List[float]]:
        return [[self.m[c * 4 + r] for c in range(4)] for r in range(4)]  # type: ignore[attr-defined]

    def at(self, r: int, c: int) -> float:
        return self.m[c * 4 + r]  # type: ignore[attr-defined]

    def __getitem__(self, rc: t.Tuple[int, int]) -> float:
        r, c = rc
        return self.at(r, c)

    def __array__(self, dtype: Any = None, copy: Any = None) -> Any:
        return _np.array(self.rows(), dtype=dtype)

    def __repr__(self) -> str:
        return "Mat4.from_rows(%r)" % (self.rows(),)

    def __str__(self) -> str:
        return "\n".join("  ".join("%12.6g" % v for v in row) for row in self.rows())


class _AABBMixin:
    @classmethod
    def _from_sequence(cls, value: Any, what: str) -> Any:
        items = sequence(value, what)
        if len(items) != 2:
            raise ValueError("%s needs (min, max), got %d items" % (what, len(items)))
        return cls(Vec3.coerce(items[0], what + ".min"), Vec3.coerce(items[1], what + ".max"))

    def __iter__(self) -> Iterator[Any]:
        return iter((tuple(self.min), tuple(self.max)))  # type: ignore[attr-defined]


def _matrix_property(cls: Any, name: str) -> None:
    """Field `name` (a swarp_mat4) read as a Matrix, so numpy.asarray(res.matrix)
    is the 4x4 array (a ctypes struct would hand numpy its raw buffer, one
    structured scalar); the raw Mat4 stays reachable as cls._c_field(name)."""
    raw = cls.__dict__[name]
    setattr(cls, "_c_" + name, raw)

    def get(self: Any) -> Any:
        return matrix(raw.__get__(self, cls).rows())

    def put(self: Any, value: Any) -> None:
        raw.__set__(self, Mat4.coerce(value, "%s.%s" % (cls.__name__, name)))
    setattr(cls, name, property(get, put, doc="%s (4x4, world or clip convention of the C field)" % name))


def _c_field(cls: Any, name: str) -> Any:
    """The ctypes field descriptor (offset, size) of C field `name`."""
    return cls.__dict__.get("_c_" + name, cls.__dict__.get(name))


STRUCT_CLASSES: Dict[str, Any] = {}
for _c_name, _fields in _capi.STRUCTS:
    STRUCT_CLASSES[_c_name] = _struct_class(_c_name, _fields)
    STRUCT_CLASSES[_c_name]._c_field = classmethod(_c_field)
    if _c_name != "swarp_mat4":
        for _f, _t, _d in _fields:
            if _t == "swarp_mat4" and not _d:
                _matrix_property(STRUCT_CLASSES[_c_name], _f)
for _tag, _name in _capi.STRUCT_TAGS.items():
    STRUCT_CLASSES.setdefault(_tag, STRUCT_CLASSES[_name])

Vec3 = STRUCT_CLASSES["swarp_vec3"]
Vec4 = STRUCT_CLASSES["swarp_vec4"]
Mat4 = STRUCT_CLASSES["swarp_mat4"]
Plane = STRUCT_CLASSES["swarp_plane"]
AABB = STRUCT_CLASSES["swarp_aabb"]


def to_output(value: Any, status: int) -> Any:
    """A C output as the Python value returned: matrices as Matrix, vectors
    and planes as tuples, structs as themselves, each with .status."""
    st = Status(status)
    if isinstance(value, Mat4):
        return matrix(value.rows(), status)
    if isinstance(value, (Vec3, Vec4, Plane)):
        out: Any = Tuple(value)
    elif isinstance(value, Struct):
        out = value
    elif isinstance(value, float):
        out = Float(value)
    elif isinstance(value, int):
        out = Int(value)
    elif isinstance(value, list):
        out = List(value)
    elif isinstance(value, tuple):
        out = Tuple(value)
    else:
        out = value
    try:
        out.status = st
    except AttributeError:
        pass
    return out


__all__ = ["Status", "SwarpError", "STATUS", "Float", "Int", "List", "Tuple", "Result", "Matrix",
           "matrix", "Struct", "STRUCT_CLASSES", "Vec3", "Vec4", "Mat4", "Plane", "AABB"]
