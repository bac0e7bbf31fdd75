#!/usr/bin/python3
"""docs/python.md shows what examples/python/example.py prints now.

    /usr/bin/python3 tests/python/test_docs.py            # check
    /usr/bin/python3 tests/python/test_docs.py --update   # rewrite the block
(with SHADOWWARP_LIB and PYTHONPATH as for the other tests)
"""
import os
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from support import ROOT  # noqa: E402

DOC = os.path.join(ROOT, "docs", "python.md")
EXAMPLE = os.path.join(ROOT, "examples", "python", "example.py")
START, END = "<!-- example output -->\n```\n", "```\n<!-- end example output -->"


def example_output():
    return subprocess.run([sys.executable, EXAMPLE], capture_output=True, text=True, check=True).stdout


def split_doc():
    with open(DOC, encoding="utf-8") as f:
        text = f.read()
    a = text.index(START) + len(START)
    return text[:a], text[a:text.index(END, a)], text[text.index(END, a):]


class Docs(unittest.TestCase):
    def test_output_block_is_current(self):
        _, block, _ = split_doc()
        self.assertEqual(block, example_output(),
                         "docs/python.md is stale: run tests/python/test_docs.py --update")

    def test_example_code_is_the_program(self):
        with open(EXAMPLE, encoding="utf-8") as f:
            code = f.read()
        with open(DOC, encoding="utf-8") as f:
            self.assertIn(code[code.index("import math"):], f.read())


if __name__ == "__main__":
    if "--update" in sys.argv:
        head, _, tail = split_doc()
        with open(DOC, "w", encoding="utf-8") as f:
            f.write(head + example_output() + tail)
        sys.exit(0)
    unittest.main(verbosity=2)
