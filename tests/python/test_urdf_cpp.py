"""The C++ URDF loader (chasles::chain_from_urdf, include/chasles/urdf.hpp,
over urdfdom) against the Python one (Chain.from_urdf, its own XML reading)
on the real arms of example-robot-data, a Python package that the C++ tests
(ctest runs before the Python environment exists) cannot reach, and on the
hostile descriptions of hostile_urdf.py: both load them alike, or both
refuse them with the same text after their prefixes (the loaders' shared
contract), or, where the contract leaves it to each parser, both refuse.

The C++ side is the program tests/cpp/urdf_dump.cpp, which prints the loaded
chain as JSON; tests/run.sh builds it and passes its path in the environment
variable CHASLES_URDF_DUMP. These tests are skipped only when the variable is
unset in a pytest run outside the full pipeline; set, the program must exist
and work, and example-robot-data must be installed. With
CHASLES_REQUIRE_URDF_DUMP=1 (tests/run.sh sets it), what would skip the
cross-check fails it instead: an unset CHASLES_URDF_DUMP, example-robot-data
or one of its arms missing."""

import json
import os
import re
import subprocess

import hostile_urdf
import numpy as np
import pytest
from test_urdf import ARMS, ROBOTS

from chasles import Chain

DUMP = os.environ.get("CHASLES_URDF_DUMP")
REQUIRED = bool(DUMP) or os.environ.get("CHASLES_REQUIRE_URDF_DUMP") == "1"


@pytest.fixture(autouse=True)
def dump_program():
    """Skips the test outside the full pipeline; fails it inside when the
    program is not there."""
    if not DUMP:
        if REQUIRED:
            pytest.fail(
                "CHASLES_REQUIRE_URDF_DUMP=1 but CHASLES_URDF_DUMP is unset: the C++ URDF cross-check "
                "needs the program of tests/cpp/urdf_dump.cpp"
            )
        pytest.skip("CHASLES_URDF_DUMP is unset (tests/run.sh sets it to the program of tests/cpp/urdf_dump.cpp)")
    assert os.access(DUMP, os.X_OK), f"CHASLES_URDF_DUMP={DUMP!r} is not an executable program"


def robots():
    """The robots directory of example-robot-data: a skip without it, a
    failure when the cross-check is required (tests/run.sh installs it)."""
    if ROBOTS is None:
        if REQUIRED:
            pytest.fail("example-robot-data is not installed (pip install .[test] installs it)")
        pytest.skip("example-robot-data is not installed")
    return ROBOTS


COMPARED = ["ur5", "panda", "xarm7", "kinova", "z1", "ur3", "ur10", "talos_left_arm"]


def dump(*args, timeout=60):
    r = subprocess.run([DUMP, *map(str, args)], capture_output=True, text=True, timeout=timeout, check=False)
    if r.returncode != 0:
        return r.returncode, None, r.stderr
    # the program prints matrices with %.17g: a chain with non-finite numbers
    # (which neither loader should give) has 'inf' and 'nan' there
    out = re.sub(r"(?<![\w.])(-?)inf\b", r"\1Infinity", r.stdout)
    return 0, json.loads(re.sub(r"(?<![\w.])-?nan\b", "NaN", out)), r.stderr


def assert_same_chain(cpp, py, rtol=0.0):
    """The chain the C++ program printed equals the Python one (to 1e-14,
    and relatively to rtol for huge numbers)."""
    assert tuple(cpp["names"]) == py.joint_names
    assert tuple(cpp["joint_types"]) == py.joint_types
    close = {"rtol": rtol, "atol": 1e-14}
    np.testing.assert_allclose(cpp["screws"], py.space_screws, **close)
    np.testing.assert_allclose(cpp["home"], np.asarray(py.home), **close)
    for name in ("lower", "upper", "velocity_limits", "effort_limits"):
        np.testing.assert_allclose(cpp[name], getattr(py, name), **close, err_msg=name)  # inf == inf
    np.testing.assert_allclose(cpp["link_inertias"], py.link_inertias, **close)


@pytest.mark.parametrize("key", COMPARED)
def test_cpp_loader_equals_python_loader(key):
    rel, tip, base = ARMS[key]
    path = robots() / rel
    if not path.exists():
        if REQUIRED:
            pytest.fail(f"{rel} is not in this version of example-robot-data: the cross-check cannot run")
        pytest.skip(f"{rel} is not in this version of example-robot-data")
    code, cpp, err = dump(path, tip, *([base] if base else []))
    assert code == 0, err
    py = Chain.from_urdf(path, tip, base)
    assert_same_chain(cpp, py)
    assert np.asarray(cpp["link_inertias"])[:, 0].sum() > 0  # the arm has masses: the comparison is not of zeros


def test_cpp_loader_refuses_with_the_element_named():
    path = robots() / ARMS["ur5"][0]
    code, _, err = dump(path, "no_such_link")
    assert code == 1
    assert err.strip() == "chain_from_urdf(tip_link): no link named 'no_such_link' in the description"
    code, _, err = dump(path, "base_link", "tool0")
    assert code == 1
    assert "tip_link 'base_link' is not below base_link 'tool0'" in err


# ---- the hostile descriptions ---------------------------------------------------


def after_prefix(message, prefix):
    """A refusal's text after the loader's prefix; an argument's refusal
    ("Chain.from_urdf(tip_link): ...") keeps its parenthesis."""
    name = prefix[:-2]  # "Chain.from_urdf" or "chain_from_urdf"
    assert message.startswith(name), message
    return message[len(prefix) :] if message.startswith(prefix) else message[len(name) :]


def python_outcome(source, case):
    try:
        return Chain.from_urdf(source, case.tip, case.base), None
    except ValueError as e:
        return None, after_prefix(str(e), "Chain.from_urdf: ")


def cpp_outcome(source, case):
    code, chain, err = dump(source, case.tip, *([case.base] if case.base else []))
    assert code in (0, 1), f"the C++ loader ended with status {code}: {err[-2000:]}"
    return chain, (None if code == 0 else after_prefix(err.strip(), "chain_from_urdf: "))


def assert_agree(case, cpp, cpp_error, py, py_error):
    outcome = f"C++: {cpp_error or 'loads'}; Python: {py_error or 'loads'}"
    if case.agree == "either":
        return  # the contract leaves it open: each ended cleanly
    if case.agree in ("refuse", "prefix") or case.error is not None:
        assert cpp_error is not None and py_error is not None, outcome
        if case.agree == "prefix":
            assert cpp_error.startswith(case.error) and py_error.startswith(case.error), outcome
        elif case.agree == "exact":
            assert cpp_error == py_error == case.error, outcome
        return
    assert cpp_error is None and py_error is None, outcome
    assert_same_chain(cpp, py, rtol=1e-14)


HOSTILE = {case.name: case for case in hostile_urdf.cases()}


@pytest.mark.parametrize("name", list(HOSTILE))
def test_hostile_descriptions_from_files(name, tmp_path):
    case = HOSTILE[name]
    path = tmp_path / "robot.urdf"
    path.write_bytes(case.text.encode("utf-8"))
    cpp, cpp_error = cpp_outcome(path, case)
    py, py_error = python_outcome(path, case)
    assert_agree(case, cpp, cpp_error, py, py_error)


@pytest.mark.parametrize("name", [name for name, case in HOSTILE.items() if case.argv_ok])
def test_hostile_descriptions_as_text(name):
    case = HOSTILE[name]
    cpp, cpp_error = cpp_outcome(case.text, case)
    py, py_error = python_outcome(case.text, case)
    assert_agree(case, cpp, cpp_error, py, py_error)


@pytest.mark.parametrize("kind", ["missing file", "directory", "larger than 64 MiB", "empty path", "/dev/zero", "FIFO"])
def test_sources_that_are_not_urdf_files(kind, tmp_path):
    cases = {name: (path, error) for name, path, error in hostile_urdf.path_cases(tmp_path)}
    if kind not in cases:
        pytest.skip(f"no {kind} on this system")
    path, error = cases[kind]
    case = hostile_urdf.Case(kind, "", "c", error)
    try:
        code, _, err = dump(path, "c", timeout=20)  # a FIFO must not be waited on
    except subprocess.TimeoutExpired:
        pytest.fail(f"the C++ loader still waits on {kind} {path!r} after 20 s")
    assert code == 1, f"status {code}: {err}"
    _, py_error = python_outcome(path, case)
    assert after_prefix(err.strip(), "chain_from_urdf: ") == py_error == error
