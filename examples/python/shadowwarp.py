"""shadowwarp -- ctypes binding of libshadowwarp (standard library only).

Usage:
    import shadowwarp as sw
    n = sw.warp_nopt(d=10.0, z_0=1.0, z_1=100.0)      # a float
    n.status                                          # 'SWARP_OK' or an informational name
    cam = sw.Camera(eye=(0, 2, 5), dir=(0, 0, -1), up=(0, 1, 0),
                    fovy=1.0, aspect=16/9, near=0.1, far=100.0)

Conventions (those of include/shadowwarp.h):
  * matrices are swarp_mat4, 16 doubles in COLUMN-MAJOR order; Mat4.rows()
    gives them row by row, Mat4.from_rows() builds one;
  * angles in radians;
  * an error status raises SwarpError (.status is the symbolic name, .code the
    number, .message the library's text); the outputs are untouched then;
  * a success returns the outputs; each carries .status ('SWARP_OK' or an
    informational name such as 'SWARP_INFO_WARP_UNIFORM').  Results of
    several values are tuples (Result) with .status.

The library is found through $SHADOWWARP_LIB (a path to libshadowwarp.so),
then next to this file (build trees: ../../build*/src), then the system
(ctypes.util.find_library).  Functions that are not in the loaded library
(an older version) raise NotImplementedError when called; has(name) tells.
"""
import ctypes
import ctypes.util
import glob
import math
import os

__all__ = ["SwarpError", "Vec3", "Vec4", "Mat4", "AABB", "Plane", "Camera", "Light",
           "ErrorConfig", "has", "version", "status_name", "status_string"]

_c_double_p = ctypes.POINTER(ctypes.c_double)
_c_size_p = ctypes.POINTER(ctypes.c_size_t)


def _find_library():
    env = os.environ.get("SHADOWWARP_LIB")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    for pattern in ("../../build*/src/libshadowwarp.so", "../../build*/src/libshadowwarp.so.*"):
        hits = sorted(glob.glob(os.path.join(here, pattern)))
        if hits:
            return hits[0]
    found = ctypes.util.find_library("shadowwarp")
    if found:
        return found
    raise OSError("libshadowwarp not found: set SHADOWWARP_LIB to the path of libshadowwarp.so")


_lib = ctypes.CDLL(_find_library())


def has(name):
    """True if the loaded library exports the C function `name`."""
    try:
        getattr(_lib, name)
        return True
    except AttributeError:
        return False


def _fn(name, argtypes, restype=ctypes.c_int):
    """Binds a C function lazily, so a missing symbol only fails when called."""
    cache = {}

    def call(*args):
        f = cache.get("f")
        if f is None:
            if not has(name):
                raise NotImplementedError(name + " is not in the loaded libshadowwarp")
            f = getattr(_lib, name)
            f.argtypes = argtypes
            f.restype = restype
            cache["f"] = f
        return f(*args)
    call.__name__ = name
    return call


# ---- status ---------------------------------------------------------------
_status_name = _fn("swarp_status_name", [ctypes.c_int], ctypes.c_char_p)
_status_string = _fn("swarp_status_string", [ctypes.c_int], ctypes.c_char_p)
_status_is_error = _fn("swarp_status_is_error", [ctypes.c_int], ctypes.c_int)


def status_name(code):
    return _status_name(int(code)).decode()


def status_string(code):
    return _status_string(int(code)).decode()


# Every status the library knows, by name: STATUS['SWARP_ERR_CAPACITY'] == 8.
STATUS = {}
for _code in range(0, 2000):
    _n = status_name(_code)
    if _n != "SWARP_UNKNOWN_STATUS":
        STATUS[_n] = _code
        globals()[_n] = _code


class SwarpError(Exception):
    """An error status (1..999) from libshadowwarp."""

    def __init__(self, code, function):
        self.code = int(code)
        self.status = status_name(code)
        self.message = status_string(code)
        self.function = function
        super().__init__("%s: %s (%s)" % (function, self.status, self.message))


class Float(float):
    """A float result with the call's .status."""
    status = "SWARP_OK"


class Result(tuple):
    """A tuple of results with the call's .status."""
    status = "SWARP_OK"


def _check(code, function):
    if _status_is_error(code):
        raise SwarpError(code, function)
    return status_name(code)


def _float(value, status):
    r = Float(value)
    r.status = status
    return r


def _result(values, status):
    r = Result(values)
    r.status = status
    return r


def version():
    """(runtime version string, version number)."""
    return (_fn("swarp_version_string", [], ctypes.c_char_p)().decode(),
            _fn("swarp_version_number", [], ctypes.c_int)())


# ---- boundary types (layouts checked by _Static_assert in src/) ---------------
class Vec3(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("z", ctypes.c_double)]

    def __iter__(self):
        return iter((self.x, self.y, self.z))

    def __repr__(self):
        return "Vec3(%r, %r, %r)" % (self.x, self.y, self.z)


class Vec4(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("z", ctypes.c_double),
                ("w", ctypes.c_double)]

    def __iter__(self):
        return iter((self.x, self.y, self.z, self.w))

    def __repr__(self):
        return "Vec4(%r, %r, %r, %r)" % tuple(self)


class Mat4(ctypes.Structure):
    """Column-major 4x4: element (row r, column c) is m[c*4 + r]."""
    _fields_ = [("m", ctypes.c_double * 16)]

    @classmethod
    def from_rows(cls, rows):
        out = cls()
        for r in range(4):
            for c in range(4):
                out.m[c * 4 + r] = float(rows[r][c])
        return out

    @classmethod
    def identity(cls):
        return cls.from_rows([[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)])

    def at(self, r, c):
        return self.m[c * 4 + r]

    def rows(self):
        return [[self.m[c * 4 + r] for c in range(4)] for r in range(4)]

    def __repr__(self):
        return "Mat4.from_rows(%r)" % (self.rows(),)

    def __str__(self):
        return "\n".join("  ".join("%12.6g" % v for v in row) for row in self.rows())


class AABB(ctypes.Structure):
    _fields_ = [("min", Vec3), ("max", Vec3)]


class Plane(ctypes.Structure):
    _fields_ = [("a", ctypes.c_double), ("b", ctypes.c_double), ("c", ctypes.c_double),
                ("d", ctypes.c_double)]


def _vec3(v):
    if isinstance(v, Vec3):
        return v
    x, y, z = v
    return Vec3(float(x), float(y), float(z))


class Camera(ctypes.Structure):
    _fields_ = [("eye", Vec3), ("dir", Vec3), ("up", Vec3), ("fovy", ctypes.c_double),
                ("aspect", ctypes.c_double), ("z_near", ctypes.c_double), ("z_far", ctypes.c_double),
                ("_reserved", ctypes.c_uint32 * 4)]

    def __init__(self, eye=(0, 0, 0), dir=(0, 0, -1), up=(0, 1, 0), fovy=math.pi / 3,
                 aspect=1.0, near=0.1, far=100.0):
        super().__init__(_vec3(eye), _vec3(dir), _vec3(up), fovy, aspect, near, far)


DEPTH_DEFAULT, DEPTH_NEG_ONE_TO_ONE, DEPTH_ZERO_TO_ONE = 0, 1, 2
LIGHT_DEFAULT, LIGHT_DIRECTIONAL, LIGHT_POINT = 0, 1, 2


class Light(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int32), ("_reserved0", ctypes.c_uint32), ("direction", Vec3),
                ("position", Vec3), ("cone_angle", ctypes.c_double),
                ("_reserved", ctypes.c_uint32 * 4)]

    def __init__(self, type=LIGHT_DIRECTIONAL, direction=(0, -1, 0), position=(0, 0, 0),
                 cone_angle=0.0):
        super().__init__(type, 0, _vec3(direction), _vec3(position), cone_angle)


class ErrorConfig(ctypes.Structure):
    """Inputs of Lloyd's error metric [RHS] (2.3)-(2.8)."""
    _fields_ = [("z_near", ctypes.c_double), ("z_far", ctypes.c_double), ("theta", ctypes.c_double),
                ("res_ix", ctypes.c_double), ("res_iy", ctypes.c_double),
                ("res_s", ctypes.c_double), ("res_t", ctypes.c_double),
                ("_reserved", ctypes.c_uint32 * 4)]

    def __init__(self, near=1.0, far=100.0, theta=math.pi / 6, res_ix=1024, res_iy=768,
                 res_s=1024, res_t=1024):
        super().__init__(near, far, theta, res_ix, res_iy, res_s, res_t)


SIZES = {Vec3: 24, Vec4: 32, Mat4: 128, AABB: 48, Plane: 32, Camera: 120, Light: 80,
         ErrorConfig: 72}

# ---- mat4 -----------------------------------------------------------------------
_P = ctypes.POINTER
_mat4_to_float = _fn("swarp_mat4_to_float", [_P(Mat4), _P(ctypes.c_float)])
_mat4_mul = _fn("swarp_mat4_mul", [_P(Mat4), _P(Mat4), _P(Mat4)])
_mat4_invert = _fn("swarp_mat4_invert", [_P(Mat4), _P(Mat4)])
_mat4_transform = _fn("swarp_mat4_transform", [_P(Mat4), _P(Vec3), _P(Vec4)])


def mat4_to_float(m):
    out = (ctypes.c_float * 16)()
    st = _check(_mat4_to_float(ctypes.byref(m), out), "swarp_mat4_to_float")
    return _result(list(out), st)


def mat4_mul(a, b):
    r = Mat4()
    _check(_mat4_mul(ctypes.byref(a), ctypes.byref(b), ctypes.byref(r)), "swarp_mat4_mul")
    return r


def mat4_invert(a):
    r = Mat4()
    _check(_mat4_invert(ctypes.byref(a), ctypes.byref(r)), "swarp_mat4_invert")
    return r


def mat4_transform(m, p):
    out = Vec4()
    _check(_mat4_transform(ctypes.byref(m), ctypes.byref(_vec3(p)), ctypes.byref(out)),
           "swarp_mat4_transform")
    return out


# ---- core: scalar functions with one or two double outputs --------------------------
def _scalar(cname, nargs, nout=1):
    f = _fn(cname, [ctypes.c_double] * nargs + [_c_double_p] * nout)

    def call(*args):
        if len(args) != nargs:
            raise TypeError("%s takes %d arguments" % (cname, nargs))
        outs = [ctypes.c_double() for _ in range(nout)]
        st = _check(f(*[float(a) for a in args], *[ctypes.byref(o) for o in outs]), cname)
        if nout == 1:
            return _float(outs[0].value, st)
        return _result([o.value for o in outs], st)
    call.__name__ = cname[len("swarp_"):]
    return call


#: [RHS] (3.2) n_opt(d, z_0, z_1)
warp_nopt = _scalar("swarp_warp_nopt", 3)
#: [RHS] (4.2) n_opt(d, z_0, z_1, n_p, f_p) with pseudo near/far
warp_nopt_pseudo = _scalar("swarp_warp_nopt_pseudo", 5)
#: [RHS] (3.3) eta(gamma, theta)
warp_eta = _scalar("swarp_warp_eta", 2)
#: [RHS] (3.5) W_lz(gamma, theta, n_e, f_e, W_e)
warp_wlz = _scalar("swarp_warp_wlz", 5)
#: [RHS] (3.4) n_repar(eta, alpha, W_lz)
warp_nrepar = _scalar("swarp_warp_nrepar", 3)
#: [GMNPR] (2) psi(lambda, theta, phi, n, f)
gmnpr_psi = _scalar("swarp_gmnpr_psi", 5)
#: [GMNPR] (2) offset phi(lambda, theta) (lambda, theta, phi, n, f)
gmnpr_offset = _scalar("swarp_gmnpr_offset", 5)
#: [GMNPR] (2) F(lambda, theta, phi, n, f, z)
gmnpr_F = _scalar("swarp_gmnpr_F", 6)
#: [GMNPR] (4) (lambda_1, lambda_2)(theta, phi, n, f)
gmnpr_lambda12 = _scalar("swarp_gmnpr_lambda12", 4, nout=2)
#: [GMNPR] (8) lambda_GMNPR(theta, phi, n, f)
gmnpr_lambda = _scalar("swarp_gmnpr_lambda", 4)
#: [GMNPR] (9) lambda_LiSPSM(theta, phi, n, f)
gmnpr_lambda_lispsm = _scalar("swarp_gmnpr_lambda_lispsm", 4)
#: GLPR lambda(theta, phi, n, f)
gmnpr_lambda_glpr = _scalar("swarp_gmnpr_lambda_glpr", 4)

# ---- core: Lloyd's error metric ----------------------------------------------------
_error_mx = _fn("swarp_error_mx", [_P(ErrorConfig), ctypes.c_double, ctypes.c_double, _c_double_p])
_error_mz = _fn("swarp_error_mz", [_P(ErrorConfig), ctypes.c_double, ctypes.c_double, _c_double_p])
_error_max = _fn("swarp_error_max", [_P(ErrorConfig), ctypes.c_double, _c_double_p, _c_double_p])
_error_split_curve = _fn("swarp_error_split_curve",
                         [_P(ErrorConfig), _c_double_p, _c_double_p, ctypes.c_size_t, _c_double_p,
                          ctypes.c_size_t, _c_double_p, _c_double_p])
_error_split_max = _fn("swarp_error_split_max",
                       [_P(ErrorConfig), _c_double_p, _c_double_p, ctypes.c_size_t, _c_double_p,
                        _c_double_p, _c_double_p, _c_double_p])


def error_mx(cfg, z, n_prime):
    """[RHS] (2.3); n_prime = cfg.z_near gives PSM (2.5), math.inf uniform (2.7)."""
    out = ctypes.c_double()
    st = _check(_error_mx(ctypes.byref(cfg), z, n_prime, ctypes.byref(out)), "swarp_error_mx")
    return _float(out.value, st)


def error_mz(cfg, z, n_prime):
    """[RHS] (2.4); (2.6) and (2.8) as for error_mx."""
    out = ctypes.c_double()
    st = _check(_error_mz(ctypes.byref(cfg), z, n_prime, ctypes.byref(out)), "swarp_error_mz")
    return _float(out.value, st)


def error_max(cfg, n_prime):
    """(max m_x, max m_z) over [near, far]."""
    mx, mz = ctypes.c_double(), ctypes.c_double()
    st = _check(_error_max(ctypes.byref(cfg), n_prime, ctypes.byref(mx), ctypes.byref(mz)),
                "swarp_error_max")
    return _result([mx.value, mz.value], st)


def _darr(values):
    values = [float(v) for v in values]
    return (ctypes.c_double * max(1, len(values)))(*values), len(values)


def error_split_curve(cfg, splits, n_primes, z):
    """([m_x(z_k)], [m_z(z_k)]) of the piecewise curve of a partitioned frustum."""
    sp, _ = _darr(splits)
    npr, m = _darr(n_primes)
    zz, count = _darr(z)
    mx = (ctypes.c_double * max(1, count))()
    mz = (ctypes.c_double * max(1, count))()
    st = _check(_error_split_curve(ctypes.byref(cfg), sp, npr, m, zz, count, mx, mz),
                "swarp_error_split_curve")
    return _result([list(mx[:count]), list(mz[:count])], st)


def error_split_max(cfg, splits, n_primes):
    """([max m_x per split], [max m_z per split], max m_x, max m_z)."""
    sp, _ = _darr(splits)
    npr, m = _darr(n_primes)
    sx = (ctypes.c_double * max(1, m))()
    sz = (ctypes.c_double * max(1, m))()
    mx, mz = ctypes.c_double(), ctypes.c_double()
    st = _check(_error_split_max(ctypes.byref(cfg), sp, npr, m, sx, sz, ctypes.byref(mx),
                                 ctypes.byref(mz)), "swarp_error_split_max")
    return _result([list(sx[:m]), list(sz[:m]), mx.value, mz.value], st)


# ---- core: split schemes ------------------------------------------------------------
SPLIT_MAX_COUNT = 64


def _scheme(cname, nargs):
    f = _fn(cname, [ctypes.c_double] * nargs + [ctypes.c_uint32, _c_double_p, ctypes.c_size_t,
                                                 _c_size_p])

    def call(*args):
        *dargs, m = args
        if len(dargs) != nargs:
            raise TypeError("%s takes %d arguments and m" % (cname, nargs))
        out = (ctypes.c_double * SPLIT_MAX_COUNT)()
        count = ctypes.c_size_t()
        st = _check(f(*[float(a) for a in dargs], int(m), out, SPLIT_MAX_COUNT,
                      ctypes.byref(count)), cname)
        return _result(list(out[:count.value]), st)
    call.__name__ = cname[len("swarp_"):]
    return call


#: [RHS] (3.6) split_uniform(n, f, m) -> [C_0 .. C_m]
split_uniform = _scheme("swarp_split_uniform", 2)
#: [RHS] (3.7) split_log(n, f, m)
split_log = _scheme("swarp_split_log", 2)
#: [RHS] (3.8) split_practical(n, f, lambda, m)
split_practical = _scheme("swarp_split_practical", 3)
#: [RHS] (4.1) split_pseudo(n, f, n_p, f_p, lambda, m)
split_pseudo = _scheme("swarp_split_pseudo", 5)

# >>> stages that landed later add their wrappers below this line

# ---- geometry: the one call ---------------------------------------------------------
TECHNIQUE_DEFAULT, TECHNIQUE_UNIFORM, TECHNIQUE_LISPSM, TECHNIQUE_PSM = 0, 1, 2, 3
WARP_PARAM_DEFAULT, WARP_PARAM_NOPT, WARP_PARAM_NREPAR, WARP_PARAM_GMNPR, WARP_PARAM_PSEUDO, \
    WARP_PARAM_USER = 0, 1, 2, 3, 4, 5
WARP_CENTER_DEFAULT, WARP_CENTER_VIEW_VECTOR, WARP_CENTER_NEAREST_VERTEX = 0, 1, 2
BODY_MAX_POINTS = 128


class SetupOptions(ctypes.Structure):
    """swarp_setup_options; zero means default."""
    _fields_ = [("technique", ctypes.c_int32), ("param", ctypes.c_int32), ("center", ctypes.c_int32),
                ("depth_range", ctypes.c_int32), ("map_width", ctypes.c_uint32),
                ("map_height", ctypes.c_uint32), ("screen_width", ctypes.c_uint32),
                ("screen_height", ctypes.c_uint32), ("pancake", ctypes.c_uint32),
                ("psm_slideback", ctypes.c_uint32), ("_pad0", ctypes.c_uint32),
                ("_pad1", ctypes.c_uint32), ("n_user", ctypes.c_double),
                ("pseudo_near", ctypes.c_double), ("pseudo_far", ctypes.c_double),
                ("slideback", ctypes.c_double), ("min_depth", ctypes.c_double),
                ("skip_measure", ctypes.c_uint32), ("_reserved", ctypes.c_uint32 * 1)]


class MeasuredError(ctypes.Structure):
    """swarp_measured_error: the measured error of a matrix over H."""
    _fields_ = [("max_m_s", ctypes.c_double), ("max_m_t", ctypes.c_double),
                ("max_sigma", ctypes.c_double), ("at", Vec3), ("samples", ctypes.c_uint32),
                ("outside", ctypes.c_uint32)]


class SetupResult(ctypes.Structure):
    """swarp_setup_result: matrix = light_proj . light_view (world -> light clip)."""
    _fields_ = [("light_view", Mat4), ("light_proj", Mat4), ("matrix", Mat4),
                ("n_eye", ctypes.c_double), ("n_light", ctypes.c_double),
                ("view_near", ctypes.c_double), ("view_far", ctypes.c_double),
                ("gamma", ctypes.c_double), ("max_mx", ctypes.c_double), ("max_mz", ctypes.c_double),
                ("light_near", ctypes.c_double), ("light_far", ctypes.c_double),
                ("point_count", ctypes.c_uint32), ("_pad", ctypes.c_uint32),
                ("measured", MeasuredError), ("_reserved", ctypes.c_uint32 * 4)]


def _aabb(box):
    if isinstance(box, AABB):
        return box
    lo, hi = box
    return AABB(_vec3(lo), _vec3(hi))


_setup = _fn("swarp_setup", [_P(Camera), _P(Light), _P(AABB), _P(SetupOptions), _P(SetupResult),
                            _P(Vec3), ctypes.c_size_t, _c_size_p])
_setup_range = _fn("swarp_setup_range", [_P(Camera), _P(Light), _P(AABB), ctypes.c_double,
                                        ctypes.c_double, _P(SetupOptions), _P(SetupResult),
                                        _P(Vec3), ctypes.c_size_t, _c_size_p])


def setup(camera, light, scene, options=None, near_far=None):
    """The one call ([RHS] §3.1-§3.3, (2.3)-(2.8)): returns (SetupResult,
    [points of B]) with .status.  scene: AABB or ((x0, y0, z0), (x1, y1, z1)).
    near_far=(n, f): swarp_setup_range for a split frustum."""
    res = SetupResult()
    pts = (Vec3 * BODY_MAX_POINTS)()
    count = ctypes.c_size_t()
    opt = ctypes.byref(options) if options is not None else None
    box = _aabb(scene)
    if near_far is None:
        code = _setup(ctypes.byref(camera), ctypes.byref(light), ctypes.byref(box), opt,
                      ctypes.byref(res), pts, BODY_MAX_POINTS, ctypes.byref(count))
        st = _check(code, "swarp_setup")
    else:
        code = _setup_range(ctypes.byref(camera), ctypes.byref(light), ctypes.byref(box),
                            float(near_far[0]), float(near_far[1]), opt, ctypes.byref(res), pts,
                            BODY_MAX_POINTS, ctypes.byref(count))
        st = _check(code, "swarp_setup_range")
    return _result([res, [tuple(p) for p in pts[:count.value]]], st)


_setup_follow = _fn("swarp_setup_follow", [_P(Camera), _P(Light), _P(AABB), _P(SetupOptions), _P(Camera),
                                          _P(SetupResult), _P(SetupResult), _P(Vec3), ctypes.c_size_t,
                                          _c_size_p])


def setup_follow(camera, light, scene, previous, options=None, previous_camera=None):
    """swarp_setup whose light frame follows the previous frame's continuously
    (docs/geometry.md, "Continuity over the whole sphere"; [RHS] §3.2.1).
    previous: the SetupResult of the previous frame (same technique), or
    None for exactly swarp_setup's result; previous_camera: the previous
    frame's Camera (None: the same as camera).  Returns (SetupResult,
    [points of B]) with .status, like setup()."""
    res = SetupResult()
    pts = (Vec3 * BODY_MAX_POINTS)()
    count = ctypes.c_size_t()
    opt = ctypes.byref(options) if options is not None else None
    prev = ctypes.byref(previous) if previous is not None else None
    pcam = ctypes.byref(previous_camera) if previous_camera is not None else None
    box = _aabb(scene)
    code = _setup_follow(ctypes.byref(camera), ctypes.byref(light), ctypes.byref(box), opt, pcam, prev,
                         ctypes.byref(res), pts, BODY_MAX_POINTS, ctypes.byref(count))
    st = _check(code, "swarp_setup_follow")
    return _result([res, [tuple(p) for p in pts[:count.value]]], st)


# ---- splits stage: cascades, atlas ---------------------------------------------------
SCHEME_DEFAULT, SCHEME_UNIFORM, SCHEME_LOG, SCHEME_PRACTICAL, SCHEME_PSEUDO = 0, 1, 2, 3, 4


class SplitOptions(ctypes.Structure):
    """swarp_split_options; zero means default (4 PSSM splits, lambda 0.5)."""
    _fields_ = [("count", ctypes.c_uint32), ("scheme", ctypes.c_int32), ("lambda_", ctypes.c_double),
                ("pseudo_near", ctypes.c_double), ("pseudo_far", ctypes.c_double),
                ("_reserved", ctypes.c_uint32 * 4)]


_cascade_splits = _fn("swarp_cascade_splits", [ctypes.c_double, ctypes.c_double, _P(SplitOptions),
                                              _c_double_p, ctypes.c_size_t, _c_size_p])
_cascade_nopt = _fn("swarp_cascade_nopt", [_c_double_p, ctypes.c_size_t, ctypes.c_double,
                                          ctypes.c_double, _c_double_p])
_cascade_select_depth = _fn("swarp_cascade_select_depth", [_c_double_p, ctypes.c_size_t,
                                                          ctypes.c_double, _P(ctypes.c_uint32)])
_atlas_lsc = _fn("swarp_atlas_lsc", [ctypes.c_uint32, _c_double_p])


def cascade_splits(n, f, count=0, scheme=SCHEME_DEFAULT, lambda_=0.0, pseudo_near=0.0,
                   pseudo_far=0.0):
    """Split distances C_0 = n .. C_m = f ([RHS] (3.6)-(3.8), (4.1))."""
    opt = SplitOptions(count, scheme, lambda_, pseudo_near, pseudo_far)
    out = (ctypes.c_double * (SPLIT_MAX_COUNT + 1))()
    cnt = ctypes.c_size_t()
    st = _check(_cascade_splits(float(n), float(f), ctypes.byref(opt), out, SPLIT_MAX_COUNT + 1,
                                ctypes.byref(cnt)), "swarp_cascade_splits")
    return _result(list(out[:cnt.value]), st)


def cascade_nopt(splits, pseudo_near=0.0, pseudo_far=0.0):
    """n' per split ([RHS] (3.2), (4.2)); +inf = uniform."""
    sp, _ = _darr(splits)
    m = len(splits) - 1
    out = (ctypes.c_double * max(1, m))()
    st = _check(_cascade_nopt(sp, m, pseudo_near, pseudo_far, out), "swarp_cascade_nopt")
    return _result(list(out[:m]), st)


def cascade_select_depth(splits, view_depth):
    """The split holding an eye depth ([RHS] §3.3.3)."""
    sp, _ = _darr(splits)
    idx = ctypes.c_uint32()
    st = _check(_cascade_select_depth(sp, len(splits) - 1, float(view_depth), ctypes.byref(idx)),
                "swarp_cascade_select_depth")
    r = _result([idx.value], st)
    return r


def atlas_lsc(m):
    """l_sc of [RHS] (3.9)."""
    out = ctypes.c_double()
    st = _check(_atlas_lsc(int(m), ctypes.byref(out)), "swarp_atlas_lsc")
    return _float(out.value, st)


# ---- lixel ([LIXEL] Chong & Gortler) ----------------------------------------------
class LixelOptions(ctypes.Structure):
    _fields_ = [("raise_", ctypes.c_double), ("_reserved", ctypes.c_uint32 * 4)]


class LixelInfo(ctypes.Structure):
    _fields_ = [("corners", Vec4 * 4), ("raised", Vec4), ("raised_index", ctypes.c_uint32),
                ("corners_in_front", ctypes.c_uint32), ("conditioning", ctypes.c_double),
                ("_reserved", ctypes.c_uint32 * 4)]


_lixel_matrix = _fn("swarp_lixel_matrix", [_P(Mat4), ctypes.c_uint32, ctypes.c_uint32, _P(Light),
                                          _P(Plane), _P(LixelOptions), _P(Mat4), _P(LixelInfo)])


def lixel_matrix(view_proj, width, height, light, plane, raise_=0.0):
    """Plane-stabilised light matrix M_l ([LIXEL] (1), (7)-(10)): (M_l, LixelInfo)."""
    if not isinstance(plane, Plane):
        plane = Plane(*[float(v) for v in plane])
    opt = LixelOptions(raise_)
    out = Mat4()
    info = LixelInfo()
    st = _check(_lixel_matrix(ctypes.byref(view_proj), int(width), int(height), ctypes.byref(light),
                              ctypes.byref(plane), ctypes.byref(opt), ctypes.byref(out),
                              ctypes.byref(info)), "swarp_lixel_matrix")
    return _result([out, info], st)


# ---- plan --------------------------------------------------------------------------
PLAN_MAX_SPLITS = 16
PLAN_MAX_PLANES = 4
PLAN_EXPLAIN_MAX = 4096


class SceneNeeds(ctypes.Structure):
    """swarp_scene_needs; a zeroed struct is the default scene."""
    _fields_ = [("camera", Camera), ("light", Light), ("scene_box", AABB),
                ("screen_width", ctypes.c_uint32), ("screen_height", ctypes.c_uint32),
                ("camera_moves", ctypes.c_uint32), ("soft_shadows", ctypes.c_uint32),
                ("soft_width", ctypes.c_double), ("bleed_risk", ctypes.c_int32),
                ("allow_depth_clamp", ctypes.c_uint32), ("plane_count", ctypes.c_uint32),
                ("_pad0", ctypes.c_uint32), ("planes", Plane * PLAN_MAX_PLANES),
                ("_reserved", ctypes.c_uint32 * 4)]

    def __init__(self, **kw):
        super().__init__()
        for k, v in kw.items():
            setattr(self, k, v)


class Budget(ctypes.Structure):
    """swarp_budget; zero means default (1 pixel per texel, 2048 maps, 16 passes)."""
    _fields_ = [("max_error", ctypes.c_double), ("map_resolution", ctypes.c_uint32),
                ("atlas_limit", ctypes.c_uint32), ("max_passes", ctypes.c_uint32),
                ("_pad0", ctypes.c_uint32), ("time_budget_ns", ctypes.c_double),
                ("pass_cost_ns", ctypes.c_double), ("blur_pass_cost_ns", ctypes.c_double),
                ("_reserved", ctypes.c_uint32 * 4)]

    def __init__(self, **kw):
        super().__init__()
        for k, v in kw.items():
            setattr(self, k, v)


class Plan(ctypes.Structure):
    """struct swarp_plan (swarp_plan_result)."""
    _fields_ = [("warp", ctypes.c_int32), ("scheme", ctypes.c_int32), ("split_count", ctypes.c_uint32),
                ("map_resolution", ctypes.c_uint32), ("atlas_tiles", ctypes.c_uint32),
                ("stabilize", ctypes.c_int32), ("inverse_projection", ctypes.c_uint32),
                ("depth_clamp", ctypes.c_uint32), ("gamma", ctypes.c_double),
                ("z_near", ctypes.c_double), ("z_far", ctypes.c_double),
                ("splits", ctypes.c_double * (PLAN_MAX_SPLITS + 1)),
                ("n_prime", ctypes.c_double * PLAN_MAX_SPLITS),
                ("split_max_mx", ctypes.c_double * PLAN_MAX_SPLITS),
                ("split_max_mz", ctypes.c_double * PLAN_MAX_SPLITS),
                ("max_mx", ctypes.c_double), ("max_mz", ctypes.c_double),
                ("max_error", ctypes.c_double), ("error_area", ctypes.c_double),
                ("lixel_count", ctypes.c_uint32), ("lixel_planes", ctypes.c_uint32 * PLAN_MAX_PLANES),
                ("plane_reason", ctypes.c_uint32 * PLAN_MAX_PLANES), ("lixel_error", ctypes.c_double),
                ("filter", ctypes.c_int32), ("filter_layers", ctypes.c_uint32),
                ("filter_width", ctypes.c_double), ("filter_exponent_pos", ctypes.c_double),
                ("filter_exponent_neg", ctypes.c_double), ("shadow_passes", ctypes.c_uint32),
                ("blur_passes", ctypes.c_uint32), ("texels", ctypes.c_double),
                ("cost_ns", ctypes.c_double), ("meets_budget", ctypes.c_uint32),
                ("reasons", ctypes.c_uint32), ("candidates", ctypes.c_uint32),
                ("plane_count", ctypes.c_uint32), ("_reserved", ctypes.c_uint32 * 4)]


_plan = _fn("swarp_plan", [_P(SceneNeeds), _P(Budget), _P(Plan)])
_plan_explain = _fn("swarp_plan_explain", [_P(Plan), ctypes.c_char_p, ctypes.c_size_t, _c_size_p])
_plan_warp_name = _fn("swarp_plan_warp_name", [ctypes.c_int32], ctypes.c_char_p)


def plan(needs=None, budget=None):
    """The cheapest chain that meets the budget (docs/planning.md): a Plan with .status."""
    out = Plan()
    st = _check(_plan(ctypes.byref(needs) if needs is not None else None,
                      ctypes.byref(budget) if budget is not None else None, ctypes.byref(out)),
                "swarp_plan")
    out.status = st
    return out


def plan_explain(p):
    """Readable text of a plan."""
    buf = ctypes.create_string_buffer(PLAN_EXPLAIN_MAX)
    n = ctypes.c_size_t()
    _check(_plan_explain(ctypes.byref(p), buf, PLAN_EXPLAIN_MAX, ctypes.byref(n)),
           "swarp_plan_explain")
    return buf.value.decode()


def plan_warp_name(w):
    return _plan_warp_name(int(w)).decode()

