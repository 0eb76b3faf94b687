"""The C++ URDF loader (chasles::chain_from_urdf, include/chasles/urdf.hpp,
over urdfdom) against the Python one (Chain.from_urdf, its own XML reading)
on the real arms of example-robot-data, a Python package that the C++ tests
(ctest runs before the Python environment exists) cannot reach.

The C++ side is the program tests/cpp/urdf_dump.cpp, which prints the loaded
chain as JSON; tests/run.sh builds it and passes its path in the environment
variable CHASLES_URDF_DUMP. These tests are skipped only when the variable is
unset (a pytest run outside run.sh); set, the program must exist and work."""

import json
import os
import subprocess

import numpy as np
import pytest
from test_urdf import ARMS, ROBOTS

from chasles import Chain

DUMP = os.environ.get("CHASLES_URDF_DUMP")
pytestmark = pytest.mark.skipif(
    not DUMP, reason="CHASLES_URDF_DUMP is unset (tests/run.sh sets it to the program of tests/cpp/urdf_dump.cpp)"
)
needs_data = pytest.mark.skipif(ROBOTS is None, reason="example-robot-data is not installed")

COMPARED = ["ur5", "panda", "xarm7", "kinova", "z1", "ur3", "ur10", "talos_left_arm"]


def dump(*args):
    r = subprocess.run([DUMP, *map(str, args)], capture_output=True, text=True, timeout=60, check=False)
    return r.returncode, (json.loads(r.stdout) if r.returncode == 0 else None), r.stderr


@needs_data
@pytest.mark.parametrize("key", COMPARED)
def test_cpp_loader_equals_python_loader(key):
    rel, tip, base = ARMS[key]
    path = ROBOTS / rel
    if not path.exists():
        pytest.skip(f"{rel} is not in this version of example-robot-data")
    code, cpp, err = dump(path, tip, *([base] if base else []))
    assert code == 0, err
    py = Chain.from_urdf(path, tip, base)
    assert tuple(cpp["names"]) == py.names
    assert tuple(cpp["joint_types"]) == py.joint_types
    close = {"rtol": 0, "atol": 1e-14}
    np.testing.assert_allclose(cpp["screws"], py.screws, **close)
    np.testing.assert_allclose(cpp["home"], np.asarray(py.home), **close)
    for name in ("lower", "upper", "velocity_limits", "effort_limits"):
        np.testing.assert_allclose(cpp[name], getattr(py, name), **close, err_msg=name)  # inf == inf
    np.testing.assert_allclose(cpp["link_inertias"], py.link_inertias, **close)
    assert np.asarray(cpp["link_inertias"])[:, 0].sum() > 0  # the arm has masses: the comparison is not of zeros


@needs_data
def test_cpp_loader_refuses_with_the_element_named():
    path = ROBOTS / ARMS["ur5"][0]
    code, _, err = dump(path, "no_such_link")
    assert code == 1
    assert err.strip() == "chain_from_urdf(tip_link): no link named 'no_such_link' in the description"
    code, _, err = dump(path, "base_link", "tool0")
    assert code == 1
    assert "tip_link 'base_link' is not below base_link 'tool0'" in err
