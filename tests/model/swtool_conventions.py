#!/usr/bin/python3
"""swtool follows the command-line conventions of docs/swtool.md.

Usage: swtool_conventions.py SWTOOL

Each check runs swtool and asserts a convention: the exit status (0 success,
1 library error, 2 command-line mistake), that a mistake's message names the
option or argument that caused it, that under --json stdout is exactly one
JSON object with "status" whatever happens (command-line errors included),
that --opt=value means --opt value, that one option has one format in every
command, that printed matrices are what their label says (compared with the
column-major JSON arrays), and the measured error's defining bound
(sigma >= |D e| for every unit e, so max_sigma >= max_m_s, max_m_t).
"""
import json
import math
import os
import re
import struct
import subprocess
import sys
import tempfile

SWTOOL = sys.argv[1]
failures = []

SCENE = ['--eye', '0,10,0', '--dir', '0,-0.2,-1', '--box', '-50,0,-150,50,5,50', '--light-dir', '0.3,-1,0.2']
COMMANDS = ['params', 'curve', 'report', 'setup', 'measure', 'lixel', 'cascade', 'stabwalk', 'plan',
            'bench-report', 'cube', 'mindepth']


def run(args, stdin=None):
    p = subprocess.run([SWTOOL] + args, capture_output=True, text=True, timeout=300, input=stdin)
    return p.returncode, p.stdout, p.stderr


def check(cond, what):
    if not cond:
        failures.append(what)
        print('FAIL:', what)


def one_object(out, what):
    """stdout is exactly one JSON object with a string "status"; returns it."""
    try:
        obj = json.loads(out)
    except ValueError as e:
        check(False, '%s: stdout is not one JSON value (%s): %r' % (what, e, out[:200]))
        return {}
    check(isinstance(obj, dict) and isinstance(obj.get('status'), str), '%s: no "status" in %r' % (what, out[:200]))
    return obj if isinstance(obj, dict) else {}


def mistake(args, names, what):
    """A command-line mistake: exit 2, stderr names each of `names`, and under
    --json one object with status SWTOOL_ERR_USAGE whose message names them."""
    rc, out, err = run(args)
    check(rc == 2, '%s: exit %d, expected 2 (stderr %r)' % (what, rc, err))
    check(out == '', '%s: a mistake prints nothing on stdout without --json: %r' % (what, out[:200]))
    for n in names:
        check(n in err, '%s: stderr does not name %r: %r' % (what, n, err))
    rc, out, err = run(args + ['--json'])
    check(rc == 2, '%s --json: exit %d, expected 2' % (what, rc))
    obj = one_object(out, what + ' --json')
    check(obj.get('status') == 'SWTOOL_ERR_USAGE', '%s --json: status %r' % (what, obj.get('status')))
    text = obj.get('message', '') + ' ' + obj.get('option', '')
    for n in names:
        check(n in text, '%s --json: message does not name %r: %r' % (what, n, obj))


# ---- --version, help, CMD --help -------------------------------------------
rc, out, err = run(['--version'])
check(rc == 0 and out.startswith('swtool (libshadowwarp) ') and out.count('.') >= 2, '--version: %d %r' % (rc, out))
for top in (['help'], ['--help'], ['-h']):
    rc, out, err = run(top)
    check(rc == 0 and all(c in out for c in COMMANDS), '%s: exit %d or a command missing' % (top, rc))
rc, out, err = run([])
check(rc == 2 and 'usage' in err, 'no command: exit %d' % rc)
mistake(['frobnicate'], ['frobnicate'], 'unknown command')
mistake(['help', 'frobnicate'], ['frobnicate'], 'help of an unknown command')
for c in COMMANDS:
    rc, out, err = run([c, '--help'])
    check(rc == 0 and out.startswith('usage: swtool %s ' % c) and '--json' in out, '%s --help: exit %d' % (c, rc))
    rc2, out2, _ = run(['help', c])
    check(rc2 == 0 and out2 == out, 'help %s differs from %s --help' % (c, c))
    rc, out, err = run([c, '--help', '--json'])
    obj = one_object(out, c + ' --help --json')
    check(rc == 0 and obj.get('usage', '').startswith('usage: swtool %s ' % c), '%s --help --json' % c)
# a command's help lists exactly the options it takes: setup takes --box, not --gamma
rc, out, _ = run(['setup', '--help'])
check('--box X0,Y0,Z0,X1,Y1,Z1' in out and '--gamma' not in out, 'setup --help lists its own options')

# ---- parsing: --opt=value, repeated, missing value, stray, unknown ---------
base = run(['setup'] + SCENE + ['--fovy', '45', '--reps', '3', '--json'])
eq = run(['setup'] + [a if not a.startswith('--') else a for a in SCENE] + ['--fovy=45', '--reps=3', '--json'])
b, e = one_object(base[1], 'setup'), one_object(eq[1], 'setup --opt=value')
b.pop('setup_ns', None), e.pop('setup_ns', None)
check(base[0] == 0 and b == e, '--fovy=45 and --fovy 45 give different results')
# a negative number is a value, not an option
rc, out, _ = run(['params', '--near', '-1', '--far', '100', '--fovy', '60', '--gamma', '45', '--json'])
o = one_object(out, 'params --near -1')
check(rc == 1 and o.get('status') == 'SWARP_ERR_NEAR_FAR' and '--near -1' in o.get('inputs', []),
      '--near -1 not read as the value -1: %r' % o)

mistake(['setup'] + SCENE + ['--fovy', '60', '--fovy', '30'], ['--fovy', '60', '30'], 'repeated option')
mistake(['setup'] + SCENE + ['--fovy'], ['--fovy'], 'trailing option without its value')
mistake(['setup'] + SCENE + ['extra'], ["'extra'"], 'stray argument')
mistake(['setup'] + SCENE + ['--', 'extra'], ["'extra'"], 'stray argument after --')
mistake(['setup'] + SCENE + ['--bogus', '1'], ['--bogus'], 'unknown option')
mistake(['setup'] + SCENE + ['--fov', '30'], ['--fov', '--fovy'], 'abbreviated option')
mistake(['setup'] + SCENE + ['--json=1'], ['--json'], 'flag with a value')
mistake(['setup'] + SCENE + ['--gamma', '30'], ['--gamma'], 'option of another command')
mistake(['setup'] + SCENE + ['--fovy', 'sixty'], ['--fovy', 'sixty'], 'not a number')
mistake(['setup'] + SCENE + ['--map', '2048x'], ['--map', '2048x'], 'bad --map')
mistake(['setup'] + SCENE + ['--screen', '1920'], ['--screen', '1920'], 'bad --screen')
mistake(['setup'] + SCENE + ['--box', '1,2,3'], ['--box', '1,2,3'], 'short --box')
mistake(['setup'] + SCENE + ['--box', '-50,0,-150,,5,50'], ['--box'], 'empty field in --box')
mistake(['setup'] + SCENE[:6] + ['--light-dir', '0,-1,0', '--light-pos', '0,5,0'], ['--light-dir', '--light-pos'],
        'two lights')
mistake(['setup', '--eye', '0,10,0', '--dir', '0,1,0', '--box', '-50,0,-150,50,5,50', '--light-dir', '0.3,-1,0.2'],
        ['--dir', '0,1,0', '--up'], 'view direction parallel to up')
mistake(['setup'] + SCENE + ['--technique', 'fancy'], ['--technique', 'fancy'], 'unknown technique')
mistake(['setup'] + SCENE + ['--depth', 'dx'], ['--depth', 'dx'], 'unknown depth range')
mistake(['setup'] + SCENE + ['--reps', '0'], ['--reps'], 'zero repetitions')
mistake(['params', '--near', '1', '--far', '100', '--fovy', '60'], ['--gamma'], 'missing required option')
mistake(['plan', '--splits', '4'], ['--splits', '--force'], 'plan --splits without --force')
mistake(['plan', '--gamma', '30', '--light-dir', '0,-1,0'], ['--gamma'], 'plan --gamma with a light')
mistake(['plan', '--map', '2048x1024'], ['--map', 'square'], 'plan with a non-square map')
mistake(['cube'], ['--light'], 'cube without --light')
mistake(['bench-report', '--reps', '3'], ['--reps'], 'bench-report with too few repetitions')
mistake(['stabwalk', '--res', '1024'], ['--res'], 'stabwalk --res is --map now')
mistake(['cascade', '--image', '1024x1024'], ['--image'], 'cascade --image is --screen now')
mistake(['plan', '--box-min', '0,0,0'], ['--box-min'], 'plan --box-min is --box now')
# every command refuses a stray argument and a repeated option
for c, ok_args in [('params', ['--near', '1', '--far', '100', '--fovy', '60', '--gamma', '45']),
                   ('report', []), ('curve', ['--near', '1', '--far', '100', '--fovy', '60', '--technique', 'psm']),
                   ('cascade', []), ('stabwalk', ['--steps', '2']), ('plan', []), ('cube', ['--light', '0,0,3,1']),
                   ('mindepth', ['--near', '0.1', '--far', '100', '--min', '6']),
                   ('lixel', ['--light-pos', '3,6,-2'])]:
    rc, out, err = run([c] + ok_args + ['--json'])
    check(rc == 0, '%s %s: exit %d (%s)' % (c, ok_args, rc, err))
    one_object(out, c)
    mistake([c] + ok_args + ['stray'], ["'stray'"], c + ' stray argument')
    mistake([c] + ok_args + ['--near', '1', '--near', '2'], ['--near'], c + ' repeated --near')

# ---- one option, one format, in every command ------------------------------
def same(args1, args2, what, drop=()):
    r1, r2 = run(args1 + ['--json']), run(args2 + ['--json'])
    o1, o2 = one_object(r1[1], what), one_object(r2[1], what)
    for k in drop:
        o1.pop(k, None), o2.pop(k, None)
    check(r1[0] == 0 and o1 == o2, '%s: %s and %s differ' % (what, args1[-1], args2[-1]))


same(['setup'] + SCENE + ['--reps', '1', '--map', '1024'], ['setup'] + SCENE + ['--reps', '1', '--map', '1024x1024'],
     'setup --map N = NxN', drop=('setup_ns',))
same(['curve', '--near', '1', '--far', '100', '--fovy', '60', '--technique', 'lispsm', '--map', '512'],
     ['curve', '--near', '1', '--far', '100', '--fovy', '60', '--technique', 'lispsm', '--map', '512x512'],
     'curve --map N = NxN')
same(['report', '--map', '512'], ['report', '--map', '512x512'], 'report --map N = NxN')
same(['plan', '--map', '1024'], ['plan', '--map', '1024x1024'], 'plan --map N = NxN')
same(['cascade', '--map', '512', '--screen', '800x600'], ['cascade', '--map', '512x512', '--screen', '800x600'],
     'cascade --map N = NxN')
same(['curve', '--near', '1', '--far', '100', '--fovy', '60', '--technique', 'lispsm', '--splits', '3',
      '--scheme', 'practical'],
     ['curve', '--near', '1', '--far', '100', '--fovy', '60', '--technique', 'lispsm', '--splits', '3',
      '--scheme', 'practical:0.5'], 'curve --scheme practical = practical:0.5 as in cascade')
# --box is one format in setup, cascade and plan: plan's box changes its result
rc, out, _ = run(['plan', '--box', '-5,0,-20,5,3,0', '--json'])
rc0, out0, _ = run(['plan', '--json'])
check(rc == 0 and one_object(out, 'plan --box') != one_object(out0, 'plan'), 'plan --box has no effect')
rc, out, _ = run(['cascade'] + SCENE + ['--splits', '2', '--json'])
check(rc == 0 and one_object(out, 'cascade --box').get('status') == 'SWARP_OK', 'cascade --box')

# ---- printed matrices are what their label says ----------------------------
def text_rows(text, label):
    lines = text.splitlines()
    i = next((k for k, l in enumerate(lines) if l.strip().startswith(label)), None)
    check(i is not None, 'no matrix labelled %r in %r' % (label, text[:300]))
    if i is None:
        return [[math.nan] * 4 for _ in range(4)]
    return [[float(v) for v in lines[i + 1 + r].split()] for r in range(4)]


rc, txt, _ = run(['setup'] + SCENE + ['--reps', '1'])
rc, js, _ = run(['setup'] + SCENE + ['--reps', '1', '--json'])
m = one_object(js, 'setup')['matrix']
check('matrix (rows of the matrix' in txt, 'setup text: matrix label')
rows = text_rows(txt, 'matrix (rows')
for r in range(4):
    for c in range(4):
        # the JSON array is column-major: element (row r, column c) is m[4 c + r]
        check(math.isclose(rows[r][c], m[4 * c + r], rel_tol=1e-7, abs_tol=1e-12 * max(map(abs, m))),
              'setup text row %d col %d = %g, JSON m[%d] = %g' % (r, c, rows[r][c], 4 * c + r, m[4 * c + r]))
rc, txt, _ = run(['cube', '--light', '0,0,3,1'])
rc, js, _ = run(['cube', '--light', '0,0,3,1', '--json'])
vp = one_object(js, 'cube')['faces'][0]['view_proj']
rows = text_rows(txt, 'view_proj (rows')
check(all(math.isclose(rows[r][c], vp[4 * c + r], rel_tol=1e-7, abs_tol=1e-9) for r in range(4) for c in range(4)),
      'cube text rows are not the rows of view_proj')

# ---- measured error in setup and in every split -----------------------------
KEYS = {'max_m_s', 'max_m_t', 'max_sigma', 'at', 'samples'}


def measured_ok(meas, what):
    check(isinstance(meas, dict) and KEYS <= set(meas), '%s: "measured" lacks %s' % (what, KEYS - set(meas or {})))
    if not isinstance(meas, dict) or not KEYS <= set(meas):
        return
    check(meas['samples'] > 0 and len(meas['at']) == 3, '%s: measured nothing' % what)
    s = meas['max_sigma']
    # sigma is the largest singular value of D: >= |D e_s| = m_s and |D e_t| = m_t
    check(s is None or (s >= meas['max_m_s'] * (1 - 1e-12) and s >= meas['max_m_t'] * (1 - 1e-12)),
          '%s: max_sigma %r below max_m_s %r or max_m_t %r' % (what, s, meas['max_m_s'], meas['max_m_t']))


rc, js, _ = run(['setup'] + SCENE + ['--json'])
o = one_object(js, 'setup')
measured_ok(o.get('measured'), 'setup')
check(o.get('setup_reps', 0) >= 51, 'setup times too few calls by default: %r' % o.get('setup_reps'))
rc, txt, _ = run(['setup'] + SCENE)
check(re.search(r'\(median of \d+ calls\)', txt) is not None, 'setup text does not say how many calls the median is over')
rc, js, _ = run(['setup'] + SCENE + ['--reps', '7', '--json'])
check(one_object(js, 'setup --reps 7').get('setup_reps') == 7, 'setup --reps 7 not 7 calls')
rc, js, _ = run(['setup'] + SCENE + ['--splits', '4', '--json'])
o = one_object(js, 'setup --splits 4')
measured_ok(o.get('measured'), 'setup --splits 4')
splits = o.get('split', [])
check(len(splits) == 4, 'setup --splits 4: %d split entries' % len(splits))
for i, sp in enumerate(splits):
    measured_ok(sp.get('measured'), 'split %d' % i)
if len(splits) == 4 and all('measured' in sp for sp in splits) and 'measured' in o:
    # the whole cascade's measured error is the worst split's, samples summed
    worst = max(sp['measured']['max_sigma'] for sp in splits)
    check(o['measured']['max_sigma'] == worst, 'cascade max_sigma is not the worst split\'s')
    check(o['measured']['samples'] == sum(sp['measured']['samples'] for sp in splits), 'cascade samples not summed')

# ---- library errors: exit 1, one object, the inputs named --------------------
rc, out, err = run(['setup'] + SCENE + ['--near', '5', '--far', '1'])
check(rc == 1 and '--near 5' in err and '--far 1' in err, 'near > far: exit %d, %r' % (rc, err))
rc, out, err = run(['setup'] + SCENE + ['--near', '5', '--far', '1', '--json'])
o = one_object(out, 'setup near > far --json')
check(rc == 1 and o.get('status') == 'SWARP_ERR_NEAR_FAR' and '--near 5' in o.get('inputs', []), 'near>far json')
for bad in (['--near', '5', '--far', '1'], ['--map', '1'], ['--near', 'nan']):
    rc, out, err = run(['stabwalk', '--steps', '3'] + bad + ['--json'])
    o = one_object(out, 'stabwalk %s --json' % bad)
    check(rc == 1 and o.get('status', '').startswith('SWARP_ERR_'), 'stabwalk %s: exit %d, %r' % (bad, rc, o))
    check(any(bad[0] in i for i in o.get('inputs', [])), 'stabwalk %s: inputs %r' % (bad, o.get('inputs')))
rc, out, _ = run(['stabwalk', '--steps', '3', '--json'])
o = one_object(out, 'stabwalk --json')
check(rc == 0 and o.get('status') == 'SWARP_OK' and len(o.get('frames', [])) == 3, 'stabwalk --json')
rc, out, _ = run(['bench-report', '--reps', '10', '--json'])
check(rc == 0 and one_object(out, 'bench-report').get('status') == 'SWARP_OK', 'bench-report --json status')

# ---- measure: the same conventions ---------------------------------------------
MEASURE = ['measure', '--eye', '0,10,0', '--dir', '0,0,-1', '--matrix', '1,0,0,0,0,0,-1,0,0,1,0,0,0,0,0,1']
rc, out, _ = run(MEASURE + ['--points', '-', '--json'], stdin='0 0 -10 0 1 0\n# comment\n1 0 -20 0 1 0\n')
o = one_object(out, 'measure')
check(rc == 0 and len(o.get('points', [])) == 2 and {'m_s', 'm_t', 'sigma', 'inside'} <= set(o['points'][0]),
      'measure --points -: %r' % o)
mistake(MEASURE, ['--points'], 'measure without --points')
mistake(MEASURE[:5] + ['--points', '-'], ['--matrix'], 'measure without --matrix')
mistake(MEASURE + ['--points', '/nonexistent/p.txt'], ['--points', '/nonexistent/p.txt'], 'measure unreadable file')
rc, out, err = run(MEASURE + ['--points', '-', '--json'], stdin='0 0 -10 0 1 0\n1 2 3\n')
o = one_object(out, 'measure bad line')
check(rc == 2 and o.get('status') == 'SWTOOL_ERR_USAGE' and ':2' in o.get('option', ''), 'measure bad line: %r' % o)

# ---- mindepth: sizes checked before anything is read ---------------------------
MD = ['mindepth', '--near', '0.1', '--far', '100']
with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, 'depth.f32')
    vals = [7.5, 3.25, 9.0, 4.0, 12.0, 6.0]
    with open(path, 'wb') as f:
        f.write(struct.pack('<6f', *vals))
    rc, out, _ = run(MD + ['--file', path, '--size', '3x2', '--json'])
    o = one_object(out, 'mindepth --file')
    check(rc == 0 and o.get('min_depth') == min(vals) and o.get('min_depth_direct') == min(vals),
          'mindepth min of the file: %r, expected %g' % (o, min(vals)))
    mistake(MD + ['--file', path, '--size', '4x2'], ['--file', '24 bytes', '32'], 'mindepth file smaller than --size')
    mistake(MD + ['--file', path, '--size', '1x2'], ['--file', '24 bytes', '8'], 'mindepth file larger than --size')
    mistake(MD + ['--file', path, '--size', '4294967295x4294967295'], ['--size'], 'mindepth --size overflow')
    mistake(MD + ['--file', '/dev/zero', '--size', '65536x65536'], ['--file', 'regular'], 'mindepth /dev/zero')
    mistake(MD + ['--file', path], ['--size'], 'mindepth --file without --size')
    mistake(MD + ['--min', '6', '--size', '3x2'], ['--size'], 'mindepth --size without --file')

if failures:
    print('%d convention(s) broken' % len(failures))
    sys.exit(1)
print('all swtool conventions hold')
