#!/usr/bin/python3
"""README.md's API tour compiles and runs as written.

    check_tour.py README.md LIBSHADOWWARP_A    the source-tree command
    check_tour.py --installed README.md        the pkg-config command

Takes the section "## API tour" of README.md: its C block is saved as
tour.c, one command of its sh block is run as given with sh, and what the
program prints must equal the section's text block line for line.  The
source-tree command (the one without pkg-config) runs in a scratch directory
that holds tour.c, include/ -> the source tree's include/ and
build/src/libshadowwarp.a -> the library meson built; the pkg-config one
(--installed, tests/packages/run.sh) in a scratch directory with tour.c
alone, against the installed libshadowwarp-dev.  The compiler must
be silent: the command has -Wall -Wextra -pedantic, a warning is a failure.

The printed numbers are also checked against their definitions, evaluated
here independently of the library: n_opt = z_n + sqrt(z_n z_f)  [RHS] (3.2),
and the practical split bounds
C_i = (1 - lambda) (n + (f - n) i/m) + lambda n (f/n)^(i/m)  [RHS] (3.8).
Exit 77 (skipped) only when the command's compiler is not installed.
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile


def fail(msg):
    print("readme_tour: FAIL: " + msg)
    sys.exit(1)


def tour_section(readme):
    """The text from '## API tour' up to the next '## ' heading."""
    m = re.search(r"^## API tour\n(.*?)(?=^## )", readme, re.S | re.M)
    if not m:
        fail("README.md has no '## API tour' section")
    return m.group(1)


def fenced_blocks(section):
    """[(language, text)] of the section's fenced blocks, in order."""
    return [(lang, body) for lang, body in
            re.findall(r"^```(\w*)\n(.*?)^```\s*$", section, re.S | re.M)]


def one_block(blocks, lang):
    found = [body for l, body in blocks if l == lang]
    if len(found) != 1:
        fail("the API tour needs exactly one ```%s block, has %d" % (lang, len(found)))
    return found[0]


def the_command(block, installed):
    """The sh block's command line with pkg-config (installed) or without."""
    lines = [l.strip() for l in block.splitlines() if l.strip() and not l.strip().startswith("#")]
    found = [l for l in lines if ("pkg-config" in l) == installed]
    if len(found) != 1:
        fail("the API tour's sh block needs one command %s pkg-config, has %d"
             % ("with" if installed else "without", len(found)))
    return found[0]


def run_command(command, source, lib):
    """Runs README's command as written in a scratch copy of the layout it
    expects: the top of a source tree with a meson build in build/ (lib), or
    any directory (lib None: the installed package)."""
    scratch = tempfile.mkdtemp(prefix="swarp-readme.")
    try:
        with open(os.path.join(scratch, "tour.c"), "w") as f:
            f.write(source)
        if lib is not None:
            os.symlink(os.path.join(SRC_ROOT, "include"), os.path.join(scratch, "include"))
            os.makedirs(os.path.join(scratch, "build", "src"))
            os.symlink(lib, os.path.join(scratch, "build", "src", "libshadowwarp.a"))
        p = subprocess.run(["sh", "-c", command], cwd=scratch, capture_output=True, text=True)
    finally:
        shutil.rmtree(scratch)
    return p


def check_definitions(lines):
    """The printed numbers against [RHS] (3.2) and (3.8), to their printed precision."""
    m = re.search(r"^n_opt = (\S+)$", lines, re.M)
    if not m:
        fail("no 'n_opt = ' line")
    n_opt = 1.0 + math.sqrt(1.0 * 100.0)
    if float(m.group(1)) != float("%.4g" % n_opt):
        fail("n_opt printed %s, z_n + sqrt(z_n z_f) = %.4g" % (m.group(1), n_opt))
    m = re.search(r"^splits: (\d+) bounds:((?: \S+)+)$", lines, re.M)
    if not m:
        fail("no 'splits:' line")
    bounds = [float(v) for v in m.group(2).split()]
    n, f, lam, parts = 1.0, 100.0, 0.5, 4
    want = [(1 - lam) * (n + (f - n) * i / parts) + lam * n * (f / n) ** (i / parts)
            for i in range(parts + 1)]
    if int(m.group(1)) != parts + 1 or len(bounds) != parts + 1:
        fail("splits: want %d bounds, printed %s" % (parts + 1, m.group(1)))
    for i, (got, w) in enumerate(zip(bounds, want)):
        if got != float("%.2f" % w):
            fail("split bound C_%d printed %.2f, [RHS] (3.8) gives %.2f" % (i, got, w))


def main():
    global SRC_ROOT
    installed = sys.argv[1:2] == ["--installed"]
    if installed and len(sys.argv) == 3:
        readme, lib = sys.argv[2], None
    elif not installed and len(sys.argv) == 3:
        readme, lib = sys.argv[1], os.path.abspath(sys.argv[2])
    else:
        fail("usage: check_tour.py README.md LIBSHADOWWARP_A | --installed README.md")
    SRC_ROOT = os.path.dirname(os.path.abspath(readme))
    with open(readme) as f:
        blocks = fenced_blocks(tour_section(f.read()))
    source, expected = one_block(blocks, "c"), one_block(blocks, "text")
    command = the_command(one_block(blocks, "sh"), installed)
    compiler = command.split()[0]
    if shutil.which(compiler) is None:
        print("readme_tour: %s not installed, skipped" % compiler)
        sys.exit(77)
    p = run_command(command, source, lib)
    if p.returncode != 0:
        fail("'%s' exited %d\nstdout:\n%s\nstderr:\n%s" % (command, p.returncode, p.stdout, p.stderr))
    if p.stderr:
        fail("'%s' is not silent:\n%s" % (command, p.stderr))
    if p.stdout != expected:
        fail("the tour prints\n%s\nREADME.md states\n%s" % (p.stdout, expected))
    check_definitions(p.stdout)
    print("readme_tour: README's C block built with '%s', printed the %d lines README states"
          % (command, len(expected.splitlines())))


SRC_ROOT = ""
if __name__ == "__main__":
    main()
