"""The README's Python blocks run as written, and print what their comments
say: in a block with ``print(...)  # -> text`` lines, each print writes one
line and the marked ones write exactly their text."""

import contextlib
import io
import re
from pathlib import Path

README = Path(__file__).resolve().parents[2] / "README.md"


def python_blocks() -> list[str]:
    return re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)


def test_python_quick_start_runs():
    blocks = python_blocks()
    assert blocks, "README.md has no python block"
    for block in blocks:
        exec(compile(block, str(README), "exec"), {"__name__": "readme"})


def test_blocks_print_what_their_comments_say():
    checked = [b for b in python_blocks() if "# -> " in b]
    assert any("Chain.from_urdf" in b for b in checked), "the robot arm quick start has no claims"
    for block in checked:
        prints = [line for line in block.splitlines() if line.startswith("print(")]
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(block, str(README), "exec"), {"__name__": "readme"})
        lines = out.getvalue().splitlines()
        assert len(lines) == len(prints), (prints, lines)
        for statement, line in zip(prints, lines):
            if "# -> " in statement:
                assert line == statement.split("# -> ", 1)[1].rstrip(), (statement, line)
