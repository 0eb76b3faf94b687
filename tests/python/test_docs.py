"""The Python code of docs/*.md runs as written: on each page, the fenced
```python blocks run in order in one namespace (a later block may use what an
earlier one defined), as a reader would run them. (README.md's block is run by
test_readme.py; the C++ blocks are built by the install_and_consume ctest.)"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

DOCS = Path(__file__).resolve().parents[2] / "docs"
PAGES = sorted(DOCS.glob("*.md"))


def python_blocks(page: Path) -> list[str]:
    return re.findall(r"```python\n(.*?)```", page.read_text(encoding="utf-8"), flags=re.S)


def test_the_pages_are_there():
    assert {p.name for p in PAGES} >= {"conventions.md", "numerics.md", "realtime.md", "coming_from.md"}


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_python_blocks_run(page):
    namespace = {"__name__": f"docs.{page.stem}"}
    for i, block in enumerate(python_blocks(page), start=1):
        exec(compile(block, f"{page} (python block {i})", "exec"), namespace)


def test_scipy_rigid_transform_takes_modern_robotics_exp_coords():
    """docs/conventions.md: RigidTransform's exponential coordinates are (w, v)."""
    transform = pytest.importorskip("scipy.spatial.transform")
    if not hasattr(transform, "RigidTransform"):
        pytest.skip("scipy < 1.16 has no RigidTransform")
    from chasles import SE3, Twist

    xi = Twist(v=[1.0, -2.0, 0.5], w=[0.3, 0.2, -0.9])
    g = transform.RigidTransform.from_exp_coords(xi.to_modern_robotics())
    assert np.allclose(g.as_matrix(), SE3.exp(xi).as_matrix(), atol=1e-14)
    assert np.allclose(g.as_exp_coords(), xi.to_modern_robotics(), atol=1e-14)


def test_every_picture_is_there_and_used():
    """The pictures that README.md and docs/*.md show are PNG files of docs/images
    (made by the commands written beside them: ``python -m chasles --png ...``,
    ``python examples/python/robot_arm.py --png ...``), and each is shown."""
    root = DOCS.parent
    shown = set()
    for page in [root / "README.md", *PAGES]:
        for target in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", page.read_text(encoding="utf-8")):
            path = (page.parent / target).resolve()
            assert path.is_file(), f"{page.name} shows {target}, which is not there"
            head = path.read_bytes()[:24]
            assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", target
            width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
            assert width >= 400 and height >= 300, (target, width, height)
            shown.add(path)
    assert {p.resolve() for p in (DOCS / "images").iterdir()} == shown
    readme = (root / "README.md").read_text(encoding="utf-8")
    assert "python examples/python/robot_arm.py --png docs/images/robot_arm.png" in readme
