"""The demo, ``python -m chasles``: it runs, prints the worked example and the
screw of a random motion, its checks pass for any seed, and it draws both
into a PNG whose drawn axis, helix and frames are where the maths puts them
(checked on the plotted data, headless), or says how to get the picture when
matplotlib is missing."""

from __future__ import annotations

import os
import re
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from chasles import SE3, Twist
from chasles.__main__ import main, random_motion

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run(*args: str, cwd: Path, block_matplotlib: bool = False) -> subprocess.CompletedProcess:
    """python -m chasles ARGS in cwd, headless (MPLBACKEND=Agg)."""
    env = {**os.environ, "MPLBACKEND": "Agg"}
    command = [sys.executable, "-m", "chasles", *args]
    if block_matplotlib:
        # `import matplotlib` raises ImportError, as when it is not installed.
        code = (
            "import runpy, sys; sys.modules['matplotlib'] = None; "
            "sys.argv = ['chasles', *sys.argv[1:]]; runpy.run_module('chasles', run_name='__main__')"
        )
        command = [sys.executable, "-c", code, *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=120, check=False, cwd=cwd, env=env)


def png_size(path: Path) -> tuple[int, int]:
    """(width, height) from a PNG's header, after checking its signature."""
    head = path.read_bytes()[:24]
    assert head[:8] == PNG_SIGNATURE, f"{path} is not a PNG"
    assert head[12:16] == b"IHDR"
    return struct.unpack(">II", head[16:24])


def have_matplotlib() -> bool:
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return False
    return True


def test_python_m_chasles_runs_and_passes(tmp_path):
    r = run(cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stderr == ""
    out = r.stdout
    assert "All checks passed." in out
    assert "FAILED" not in out
    for text in (
        "twist xi = (v, w), linear part first",
        "[ 2.000000  0.000000  0.000000  0.000000  0.000000  1.000000]",  # (l1, 0, 0, 0, 0, 1), l1 = 2
        "[[ 0.000000 -1.000000  0.000000  2.000000]",  # the first row of [xi]
        "g(theta) equals the closed form",
        "axis point",
        "axis direction",
        "pitch h",
        "magnitude theta",
        "SE3.from_screw reproduces g",
    ):
        assert text in out, text
    # g(pi/3) for l1 = 2: the translation column (l1 sin, l1 (1 - cos), 0).
    assert "1.732051" in out and re.search(r"0\.866025\s+0\.500000\s+0\.000000\s+1\.000000", out)
    # The picture goes to chasles_demo.png in the working directory by default.
    if have_matplotlib():
        assert "3. Picture of both written to chasles_demo.png" in out
        width, height = png_size(tmp_path / "chasles_demo.png")
        assert width >= 600 and height >= 300
    else:
        assert "pip install chasles[plot]" in out


def test_png_option_writes_a_valid_png_where_asked(tmp_path):
    pytest.importorskip("matplotlib")
    target = tmp_path / "sub" / "pic.png"
    target.parent.mkdir()
    r = run("--png", str(target), "--seed", "3", cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stderr == ""
    assert f"written to {target}" in r.stdout
    assert 20_000 < target.stat().st_size < 400_000
    png_size(target)
    assert not (tmp_path / "chasles_demo.png").exists()


def test_without_matplotlib_the_demo_prints_its_numbers_and_how_to_get_the_picture(tmp_path):
    r = run("--png", "pic.png", cwd=tmp_path, block_matplotlib=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "All checks passed." in r.stdout
    assert "pip install chasles[plot]" in r.stdout
    assert not (tmp_path / "pic.png").exists()


def test_no_png_draws_nothing(tmp_path):
    r = run("--no-png", cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Picture" not in r.stdout
    assert list(tmp_path.iterdir()) == []


def test_png_and_no_png_are_exclusive(tmp_path):
    r = run("--png", "a.png", "--no-png", cwd=tmp_path)
    assert r.returncode == 2
    assert "not allowed with" in r.stderr


def points(line) -> np.ndarray:
    return np.stack(line.get_data_3d(), axis=1)


@pytest.mark.parametrize("l1, seed", [(2.0, 0), (0.5, 7), (-3.0, 11)])
def test_the_picture_draws_the_worked_example_where_the_maths_puts_it(l1, seed):
    pytest.importorskip("matplotlib")
    from chasles.__main__ import picture

    pic = picture(l1, seed)
    # The screw axis is the z line through (0, l1, 0): x = 0, y = l1 at every drawn point.
    axis = points(pic.worked_screw.axis)
    assert np.allclose(axis[:, :2], [0.0, l1], atol=1e-15, rtol=0)
    assert np.ptp(axis[:, 2]) > 1.0
    assert pic.worked_screw.pitch.get_text() == "pitch h = 0"
    # The origin circles the axis at distance |l1| in the plane z = 0, a whole turn.
    helix = points(pic.worked_screw.helix)
    assert np.allclose(np.hypot(helix[:, 0], helix[:, 1] - l1), abs(l1), atol=1e-13, rtol=0)
    assert np.allclose(helix[:, 2], 0.0, atol=1e-15) and np.allclose(helix[0], helix[-1], atol=1e-13)
    # The body frames at theta = k pi / 4 sit at the closed form's
    # (l1 sin, l1 (1 - cos), 0), x axis along (cos, sin, 0).
    assert len(pic.worked_frames.frames) == 7
    for k, f in enumerate(pic.worked_frames.frames):
        c, s = np.cos(k * np.pi / 4), np.sin(k * np.pi / 4)
        x = points(f.x)
        assert np.allclose(x[0], [l1 * s, l1 * (1 - c), 0.0], atol=1e-13, rtol=0)
        direction = x[1] - x[0]
        assert np.allclose(direction / np.linalg.norm(direction), [c, s, 0.0], atol=1e-13)
    # The random motion: its axis and the helix of the origin end where g puts it.
    g = random_motion(seed)
    s = Twist.from_vector(g.log()).screw()
    assert pic.random_screw.screw.is_approx(s, 1e-12)
    axis = points(pic.random_screw.axis) - s.point
    assert np.allclose(axis - np.outer(axis @ s.direction, s.direction), 0.0, atol=1e-12)
    helix = points(pic.random_screw.helix)
    assert np.allclose(helix[0], 0.0, atol=1e-15)
    assert np.allclose(helix[-1], g.translation, atol=1e-12)
    last = pic.random_frames.frames[-1]
    moved = SE3.exp(g.log())
    assert np.allclose(points(last.z)[1] - points(last.z)[0], 0.6 * moved.rotation.as_matrix()[:, 2])
    assert last.label.get_text().strip() == "g"


def test_seed_changes_the_random_motion_and_is_reproducible(tmp_path):
    a, b, c = (run("--no-png", "--seed", s, cwd=tmp_path) for s in ("1", "1", "2"))
    assert a.returncode == b.returncode == c.returncode == 0
    assert a.stdout == b.stdout
    assert a.stdout != c.stdout
    assert "seed 1" in a.stdout


def test_bad_arguments_are_reported_by_argparse(tmp_path):
    r = run("--seed", "abc", cwd=tmp_path)
    assert r.returncode == 2
    assert "invalid int value" in r.stderr


@pytest.mark.parametrize("seed", range(20))
def test_checks_pass_for_many_seeds(seed, capsys):
    args = ["--seed", str(seed), "--l1", str(0.5 + seed), "--theta", str(0.3 * seed), "--no-png"]
    assert main(args) == 0
    assert "All checks passed." in capsys.readouterr().out


def test_random_motion_is_a_rigid_motion():
    g = random_motion(0)
    R = g.rotation.as_matrix()
    assert np.allclose(R.T @ R, np.eye(3), atol=1e-15, rtol=0)
    assert np.all(np.abs(g.translation) <= 2.0)
