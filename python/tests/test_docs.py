"""docs/python.md and the README's Python example: every Python block runs, in order, in one
namespace (their asserts check the numbers they show); examples/python/fig2.py runs."""

import pathlib
import re
import subprocess
import sys

from conftest import ROOT


def _blocks(path):
    return re.findall(r"```python\n(.*?)```", pathlib.Path(path).read_text(), re.S)


def test_python_md_snippets_run():
    blocks = _blocks(ROOT / "docs" / "python.md")
    assert len(blocks) >= 9
    namespace = {}
    for code in blocks:
        exec(compile(code, "docs/python.md", "exec"), namespace)


def test_readme_python_example_runs():
    blocks = _blocks(ROOT / "README.md")
    assert len(blocks) == 1 and len(blocks[0].strip().splitlines()) <= 6
    exec(compile(blocks[0], "README.md", "exec"), {})


def test_fig2_example_prints_the_table_without_matplotlib():
    out = subprocess.run([sys.executable, "-c", (
        "import sys; sys.modules['matplotlib'] = None; sys.argv = ['fig2'];"
        f"exec(open({str(ROOT / 'examples/python/fig2.py')!r}).read())")],
        capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[0] == "M_R,A1/B1,e,e_error" and len(out) == 1 + 8 * 200
    rows = [line.split(",") for line in out[1:]]
    e = [float(r[2]) for r in rows]
    assert all(0 <= x < 1 for x in e)
    # At A1/B1 = 1 the static contact is circular (e = 0) and motion elongates it across.
    assert float(rows[199][2]) < 1e-6 < float(rows[-1][2])
