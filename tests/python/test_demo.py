"""The demo, ``python -m chasles``: it runs, prints the worked example and the
screw of a random motion, and its checks pass for any seed."""

from __future__ import annotations

import re
import subprocess
import sys

import numpy as np
import pytest
from chasles.__main__ import main, random_motion


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "chasles", *args],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def test_python_m_chasles_runs_and_passes():
    r = run()
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


def test_seed_changes_the_random_motion_and_is_reproducible():
    a, b, c = run("--seed", "1"), run("--seed", "1"), run("--seed", "2")
    assert a.returncode == b.returncode == c.returncode == 0
    assert a.stdout == b.stdout
    assert a.stdout != c.stdout
    assert "seed 1" in a.stdout


def test_bad_arguments_are_reported_by_argparse():
    r = run("--seed", "abc")
    assert r.returncode == 2
    assert "invalid int value" in r.stderr


@pytest.mark.parametrize("seed", range(20))
def test_checks_pass_for_many_seeds(seed, capsys):
    assert main(["--seed", str(seed), "--l1", str(0.5 + seed), "--theta", str(0.3 * seed)]) == 0
    assert "All checks passed." in capsys.readouterr().out


def test_random_motion_is_a_rigid_motion():
    g = random_motion(0)
    R = g.rotation().as_matrix()
    assert np.allclose(R.T @ R, np.eye(3), atol=1e-15, rtol=0)
    assert np.all(np.abs(g.translation()) <= 2.0)
