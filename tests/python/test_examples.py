"""The Python examples in examples/python run against the installed package,
from outside the source tree, pass their own checks and print what they found."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "python"

# A line each example prints, to know it ran to its end.
EXPECTED = {
    "arm_kinematics.py": "10000 configurations: the tool stays between 0.100 and 0.700 m",
    "average_and_spline.py": "the spline passes through the means: worst",
    "poses_and_frames.py": "as a twist xi = (v, w):",
    "pose_graph.py": "chi2 of the true poses:",
    "imu_propagation.py": "the invariant EKF's prediction matches Monte Carlo",
    "robot_arm.py": "peak torque within the effort limits of every joint: True",
    "twist_from_trajectory.py": "worst error over the trajectory:",
    "urdf_arm.py": "1000 configurations: forward kinematics within",
    "wrench_transformation.py": "line of action through",
}


def test_every_example_is_listed():
    assert sorted(p.name for p in EXAMPLES.glob("*.py")) == sorted(EXPECTED)


def test_every_example_is_in_the_examples_readme():
    """examples/README.md's table names every Python and C++ example."""
    readme = (EXAMPLES.parent / "README.md").read_text(encoding="utf-8")
    programs = [p.relative_to(EXAMPLES.parent) for p in (*EXAMPLES.glob("*.py"), *EXAMPLES.parent.glob("cpp/*.cpp"))]
    missing = [str(p) for p in programs if f"`{p.as_posix()}`" not in readme]
    assert not missing, f"examples/README.md does not list {missing}"


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_example_runs(name, tmp_path):
    r = subprocess.run(
        [sys.executable, str(EXAMPLES / name)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        cwd=tmp_path,
    )
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stderr == ""
    assert EXPECTED[name] in r.stdout
    assert list(tmp_path.iterdir()) == []  # writes nothing


def test_robot_arm_writes_its_picture_where_asked(tmp_path):
    """robot_arm.py --png PATH: a PNG of the arm (docs/images/robot_arm.png is made so)."""
    pytest.importorskip("matplotlib")
    target = tmp_path / "arm.png"
    r = subprocess.run(
        [sys.executable, str(EXAMPLES / "robot_arm.py"), "--png", str(target)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        cwd=tmp_path,
    )
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"written to {target}" in r.stdout
    head = target.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
    assert int.from_bytes(head[16:20], "big") >= 400 and int.from_bytes(head[20:24], "big") >= 400
    assert list(tmp_path.iterdir()) == [target]
