#!/usr/bin/python3
"""Generates shadowwarp/_capi.py, the C API of include/shadowwarp.h as data.

    /usr/bin/python3 examples/python/gen_capi.py include/shadowwarp.h examples/python/shadowwarp/_capi.py

The package builds its ctypes structs and function prototypes from this
data, so the binding cannot drift from the header: tests/python/test_header.py
regenerates the file and fails if it differs from the committed one, and
fails if a stable function of the header has no wrapper in the package.

What is parsed (the header's own regular form, nothing more general):
numeric object-like ``#define SWARP_*`` constants, ``typedef enum``,
``typedef struct`` (fields ``type a, b[N];``, nested dimensions allowed),
the status X-macro lists ``X(NAME, code, "message")`` and every
``SWARP_API ret name(params);`` declaration, each marked experimental when it
lies inside the ``#ifdef SWARP_EXPERIMENTAL_API`` block.
"""
import pprint
import re
import sys


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def c_number(token, constants):
    """Value of a constant expression of the header: literals (1u, 0x1p47,
    3.0e-5), names of earlier constants, + - * << and parentheses."""
    expr = token.strip()
    expr = re.sub(r"\b(0[xX][0-9a-fA-F.]+[pP][-+]?\d+)\b", lambda m: repr(float.fromhex(m.group(1))), expr)
    expr = re.sub(r"\b(\d+)[uU][lL]*\b", r"\1", expr)
    expr = re.sub(r"\b(0[xX][0-9a-fA-F]+)[uU]\b", r"\1", expr)
    names = set(re.findall(r"(?<![\w.])[A-Za-z_]\w*", expr))
    if any(n not in constants for n in names) or not re.fullmatch(r"[\w.+\-*/<>() ]+", expr):
        return None
    return eval(expr, {"__builtins__": {}}, dict(constants))  # noqa: S307 (the header's own literals)


def parse_defines(text):
    constants = {}
    for m in re.finditer(r"^[ \t]*#define[ \t]+(SWARP_\w+)[ \t]+([^\n]+)$", text, re.M):
        name, body = m.group(1), m.group(2).strip()
        if body.endswith("\\"):
            continue
        value = c_number(body, constants)
        if value is not None:
            constants[name] = value
    return constants


def parse_statuses(raw):
    return [(n, int(c), msg) for n, c, msg in
            re.findall(r"X\((SWARP_\w+),\s*(\d+),\s*\"((?:[^\"\\]|\\.)*)\"\)", raw.replace("\\\n", " "))]


def parse_enums(text, constants):
    enums = {}
    for m in re.finditer(r"typedef\s+enum\s*\w*\s*\{(.*?)\}\s*(\w+)\s*;", text, re.S):
        values = {}
        nxt = 0
        for item in m.group(1).split(","):
            item = item.strip()
            if not re.fullmatch(r"SWARP_\w+(\s*=.*)?", item, re.S):
                continue
            if "=" in item:
                key, val = [s.strip() for s in item.split("=", 1)]
                nxt = c_number(val, {**constants, **values})
            else:
                key = item
            values[key] = nxt
            nxt += 1
        enums[m.group(2)] = values
    return enums


def parse_scalar_typedefs(text):
    """typedef int32_t swarp_status; and the like: name -> base type."""
    return {m.group(2): m.group(1) for m in
            re.finditer(r"typedef\s+((?:u?int\d+_t)|double|float|int)\s+(swarp_\w+)\s*;", text)}


def parse_structs(text, constants):
    structs, tags = [], {}
    for m in re.finditer(r"typedef\s+struct\s*(\w*)\s*\{(.*?)\}\s*(\w+)\s*;", text, re.S):
        tag, body, name = m.group(1), m.group(2), m.group(3)
        if tag:
            tags[tag] = name
        fields = []
        for decl in body.split(";"):
            decl = " ".join(decl.split())
            if not decl:
                continue
            dm = re.match(r"((?:const\s+)?(?:struct\s+)?\w+)\s+(.*)$", decl)
            ctype, names = dm.group(1), dm.group(2)
            for part in names.split(","):
                part = part.strip()
                fname = re.match(r"\w+", part).group(0)
                dims = [c_number(d, constants) for d in re.findall(r"\[([^\]]+)\]", part)]
                fields.append((fname, ctype, tuple(dims)))
        structs.append((name, fields))
    return structs, tags


def parse_param(decl, tags):
    decl = " ".join(decl.replace("*", " * ").split())
    if decl == "void":
        return None
    m = re.match(r"(const )?(?:struct )?(\w+)((?: \*)*) (\w+)((?:\[\w+\])*)$", decl)
    if not m:
        raise ValueError("cannot parse parameter: " + decl)
    base = tags.get(m.group(2), m.group(2))
    dims = tuple(int(d) for d in re.findall(r"\[(\d+)\]", m.group(5)))
    return (m.group(4), base, m.group(3).count("*"), bool(m.group(1)), dims)


def parse_functions(text, tags, experimental):
    funcs = []
    for m in re.finditer(r"SWARP_API\s+((?:const\s+)?\w+\s*\*?)\s*(swarp_\w+)\s*\((.*?)\)\s*;", text, re.S):
        ret = " ".join(m.group(1).replace("*", " *").split())
        params = [p for p in (parse_param(d, tags) for d in m.group(3).split(",")) if p]
        funcs.append((m.group(2), ret, params, experimental))
    return funcs


def parse_docs(raw):
    """The doc comment (/** ... */) right before each SWARP_API declaration,
    as plain text: the wrappers' docstrings."""
    docs = {}
    for m in re.finditer(r"/\*\*((?:(?!\*/).)*)\*/\s*SWARP_API\b[^;]*?\b(swarp_\w+)\s*\(", raw, re.S):
        lines = [re.sub(r"^\s*\* ?", "", line).rstrip() for line in m.group(1).strip().splitlines()]
        docs[m.group(2)] = "\n".join(lines).strip()
    return docs


def generate(header_path):
    with open(header_path, encoding="utf-8") as f:
        raw = f.read()
    text = strip_comments(raw)
    cut = text.index("#ifdef SWARP_EXPERIMENTAL_API")
    constants = parse_defines(text)
    enums = parse_enums(text, constants)
    structs, tags = parse_structs(text, constants)
    funcs = parse_functions(text[:cut], tags, False) + parse_functions(text[cut:], tags, True)
    data = {
        "CONSTANTS": constants,
        "ENUMS": enums,
        "SCALAR_TYPEDEFS": parse_scalar_typedefs(text),
        "STATUSES": parse_statuses(raw),
        "STRUCTS": structs,
        "STRUCT_TAGS": tags,
        "FUNCTIONS": funcs,
        "DOCS": parse_docs(raw),
    }
    out = ['"""The C API of include/shadowwarp.h as data (generated; do not edit).',
           "",
           "Regenerate with:",
           "    /usr/bin/python3 examples/python/gen_capi.py include/shadowwarp.h "
           "examples/python/shadowwarp/_capi.py",
           "",
           "FUNCTIONS entries: (name, return type, [(param, base type, pointer depth,",
           "const, array dims)], experimental).  STRUCTS: (typedef, [(field, type,",
           'dims)]) in header order."""', ""]
    for key, value in data.items():
        out.append("%s = %s" % (key, pprint.pformat(value, width=100, sort_dicts=False)))
        out.append("")
    return "\n".join(out)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: gen_capi.py HEADER OUT.py\n")
        return 2
    text = generate(argv[1])
    with open(argv[2], "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
