#!/usr/bin/python3
"""swtool setup/cascade with an engine's camera: --far inf and --view/--proj.

Usage: swtool_engine_camera.py SWTOOL

Independent evaluations: the far plane used for --far inf is the largest
view depth of the scene box's 8 corners ([RHS] 3.3.1, as
swarp_camera_from_matrices bounds an infinite engine far plane), computed
here by hand; the engine matrices are built here by hand (lookAt and the
OpenGL / reversed-Z [0, 1] perspectives, right- and left-handed, column- and
row-major) for the camera the options describe, and must give that camera's
light matrix.  Mistakes exit 2 naming the option; a non-perspective
projection exits 1 with the library's status.
"""
import json
import math
import subprocess
import sys

SWTOOL = sys.argv[1]
failures = []

EYE, DIR, UP = (0.0, 10.0, 0.0), (0.0, -0.2, -1.0), (0.0, 1.0, 0.0)
FOVY, ASPECT, NEAR, FAR = 60.0, 16.0 / 9.0, 1.0, 100.0
BOX = (-50.0, 0.0, -150.0, 50.0, 5.0, 50.0)
SCENE = ['--box', ','.join(map(repr, BOX)), '--light-dir', '0.3,-1,0.2', '--technique', 'uniform']
OPTS = ['--eye', '0,10,0', '--dir', '0,-0.2,-1']


def run(args):
    p = subprocess.run([SWTOOL] + args, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def check(cond, what):
    if not cond:
        failures.append(what)
        print('FAIL', what)


def js(args, what, rc_want=0):
    rc, out, err = run(args + ['--json'])
    check(rc == rc_want, '%s: exit %d (want %d): %s' % (what, rc, rc_want, err.strip()))
    try:
        return json.loads(out)
    except ValueError:
        check(False, '%s: not one JSON object: %r' % (what, out))
        return {}


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def box_far():
    """largest view depth of the box's corners"""
    f = unit(DIR)
    corners = [(BOX[0 + 3 * (i & 1)], BOX[1 + 3 * ((i >> 1) & 1)], BOX[2 + 3 * ((i >> 2) & 1)]) for i in range(8)]
    return max(dot(sub(c, EYE), f) for c in corners)


def view_rh():
    """lookAt, column-major: rows s, u, -f and -R eye"""
    f = unit(DIR)
    s = unit(cross(f, UP))
    u = cross(s, f)
    rows = [s, u, [-x for x in f]]
    m = [0.0] * 16
    for r in range(3):
        for c in range(3):
            m[c * 4 + r] = rows[r][c]
        m[12 + r] = -dot(rows[r], EYE)
    m[15] = 1.0
    return m


def proj(kind, far=FAR):
    """column-major perspective: 'gl' [-1, 1], 'rev_inf' reversed-Z [0, 1] infinite"""
    sy = 1.0 / math.tan(math.radians(FOVY) / 2)
    m = [0.0] * 16
    m[0], m[5], m[11] = sy / ASPECT, sy, -1.0
    if kind == 'gl':
        m[10], m[14] = -(far + NEAR) / (far - NEAR), -2 * far * NEAR / (far - NEAR)
    elif kind == 'rev_inf':  # z_ndc = n / d
        m[10], m[14] = 0.0, NEAR
    return m


def to_lh(view, pr):
    """the same eye, dir and up as an LH engine builds them (cglm's glm_lookat_lh
    and glm_perspective_lh_no): view rows (up x f, u, f), a proper rotation
    in its own handedness (rows 0 and 2 of the RH view negated), and the
    projection looking down +z (column 2 negated)"""
    v, p = list(view), list(pr)
    for c in range(4):
        v[c * 4 + 0] = -v[c * 4 + 0]
        v[c * 4 + 2] = -v[c * 4 + 2]
    for r in range(4):
        p[8 + r] = -p[8 + r]
    return v, p


def transpose(m):
    return [m[(i % 4) * 4 + i // 4] for i in range(16)]


def arg(m):
    return ','.join(repr(x) for x in m)


def close(a, b, tol):
    return all(abs(x - y) <= tol * (1 + abs(y)) for x, y in zip(a, b))


# --far inf: bounded by the box, and the same result as that far given
want = box_far()
for cmd in ('setup', 'cascade'):
    extra = ['--splits', '3'] if cmd == 'cascade' else ['--reps', '1']
    d = js([cmd] + OPTS + SCENE + extra + ['--far', 'inf'], cmd + ' --far inf')
    check(d.get('camera_far_from') == 'scene_box', '%s --far inf: camera_far_from %r' % (cmd, d.get('camera_far_from')))
    far = d.get('camera_far', 0)
    check(abs(far - want) <= 1e-12 * want, '%s --far inf: camera_far %r, box bound %r' % (cmd, far, want))
    e = js([cmd] + OPTS + SCENE + extra + ['--far', repr(far)], cmd + ' --far <bound>')
    check(e.get('camera_far_from') == 'far', '%s --far F: camera_far_from %r' % (cmd, e.get('camera_far_from')))
    key = 'matrix' if cmd == 'setup' else 'splits'
    check(d.get(key) == e.get(key), '%s: --far inf and --far %r differ in %s' % (cmd, far, key))

# engine matrices for the camera of the options
ref = js(['setup'] + OPTS + SCENE + ['--reps', '1', '--far', repr(FAR)], 'setup reference')
V, P = view_rh(), proj('gl')
Vl, Pl = to_lh(V, P)
cases = [('rh', V, P), ('lh', Vl, Pl), ('rh-t', transpose(V), transpose(P)), ('lh-t', transpose(Vl), transpose(Pl))]
for conv, v, p in cases:
    d = js(['setup'] + SCENE + ['--reps', '1', '--view', arg(v), '--proj', arg(p), '--proj-convention', conv],
           'setup --view/--proj ' + conv)
    check(d.get('camera_from') == 'matrices', conv + ': camera_from')
    # the camera is recovered to rounding (float-free: double matrices), so
    # the light matrix agrees to the conditioning of the setup (~1e-9)
    check(close(d.get('camera_eye', []), EYE, 1e-12), conv + ': eye %r' % d.get('camera_eye'))
    check(abs(d.get('camera_far', 0) - FAR) <= 1e-9 * FAR, conv + ': far %r' % d.get('camera_far'))
    check(abs(d.get('camera_fovy_deg', 0) - FOVY) <= 1e-9, conv + ': fovy %r' % d.get('camera_fovy_deg'))
    check(close(d.get('matrix', []), ref['matrix'], 1e-9), conv + ': light matrix differs from the options camera')

# reversed-Z infinite [0, 1] (D3D12/Vulkan engines): far from the box
d = js(['setup'] + SCENE + ['--reps', '1', '--view', arg(V), '--proj', arg(proj('rev_inf')), '--proj-depth', 'zo'],
       'setup reversed infinite')
check(d.get('camera_reversed_z') == 1, 'reversed infinite: reversed_z %r' % d.get('camera_reversed_z'))
check(d.get('camera_far_from') == 'scene_box', 'reversed infinite: far from %r' % d.get('camera_far_from'))
check(abs(d.get('camera_far', 0) - want) <= 1e-9 * want, 'reversed infinite: far %r, want %r' % (d.get('camera_far'), want))
check(abs(d.get('camera_near', 0) - NEAR) <= 1e-12, 'reversed infinite: near %r' % d.get('camera_near'))
c = js(['cascade'] + SCENE + ['--splits', '3', '--view', arg(V), '--proj', arg(proj('rev_inf')), '--proj-depth', 'zo',
                              '--depth', 'rev'], 'cascade reversed infinite, reversed light depth')
splits = c.get('split', [])
check(len(splits) == 3 and all(s['depth_per_world'] < 0 for s in splits),
      'cascade --depth rev: depth_per_world negative in every split')
check(abs(c.get('camera_far', 0) - want) <= 1e-9 * want, 'cascade reversed infinite: far %r' % c.get('camera_far'))

# the text output says the same
rc, out, err = run(['setup'] + SCENE + ['--reps', '1', '--view', arg(V), '--proj', arg(proj('rev_inf')),
                                        '--proj-depth', 'zo'])
check(rc == 0 and 'from --view/--proj' in out and 'reversed-Z' in out, 'text: the camera line: %r' % out[:300])
far_line = [l for l in out.splitlines() if l.startswith('camera far')]
check(len(far_line) == 1 and 'bounded by the scene box' in far_line[0] and
      abs(float(far_line[0].split()[2]) - want) <= 1e-8 * want, 'text: camera far line %r' % far_line)
rc, out, err = run(['cascade'] + OPTS + SCENE + ['--splits', '2', '--far', '80'])
check(rc == 0 and 'camera far  80 (given)' in out, 'text: cascade camera far line')

# mistakes (exit 2, the option named) and a library error (exit 1)
mistakes = [
    (['--view', arg(V)], '--proj'),
    (['--view', arg(V), '--proj', arg(P), '--eye', '0,0,0'], '--eye'),
    (['--view', arg(V), '--proj', arg(P), '--proj-convention', 'xy'], '--proj-convention'),
    (['--view', arg(V), '--proj', arg(P), '--proj-depth', 'rev'], '--proj-depth'),
    (['--view', '1,2,3', '--proj', arg(P)], '--view'),
    (OPTS + ['--proj-depth', 'zo'], '--proj-depth'),
]
for extra, opt in mistakes:
    d = js(['setup'] + SCENE + ['--reps', '1'] + extra, 'mistake ' + opt, rc_want=2)
    check(d.get('status') == 'SWTOOL_ERR_USAGE' and d.get('option') == opt, 'mistake %s: %r' % (opt, d))
ortho = [0.02, 0, 0, 0, 0, 0.03, 0, 0, 0, 0, -0.01, 0, 0, 0, -1.0, 1.0]
d = js(['setup'] + SCENE + ['--reps', '1', '--view', arg(V), '--proj', arg(ortho)], 'orthographic', rc_want=1)
check(d.get('status') == 'SWARP_ERR_CAMERA_NOT_PERSPECTIVE', 'orthographic: %r' % d.get('status'))

print('%d failures' % len(failures))
sys.exit(1 if failures else 0)
