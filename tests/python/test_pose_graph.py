"""Pose graphs: the g2o reader and writer, chi2, the solve, the generated graphs.

Oracles: chi2 written out edge by edge with the object API
(Z^-1 X_i^-1 X_j, its log and the information); the solution's optimality
by central differences of chi2 (its gradient vanishes: no perturbation of a
free pose lowers it); the statistics of the optimum (chi2 about the number
of residuals minus unknowns, and below the truth's); the g2o text written
and read back bit for bit. (GTSAM, where installed, reaches the same final
chi2 on the same files: bench/bench_pose_graph.py.) The C++ solve over Ceres
(examples/cpp/pose_graph.cpp: chasles::CeresManifold, chasles::BetweenCost),
an independent solver, reaches the same minimum on the benchmark graphs and
refuses the same malformed lines; tests/run.sh passes its program in
CHASLES_POSE_GRAPH_EXAMPLE (unset, those tests skip).
"""

from __future__ import annotations

import copy
import os
import pickle
import re
import subprocess

import numpy as np
import pytest

import chasles

EXAMPLE = os.environ.get("CHASLES_POSE_GRAPH_EXAMPLE")
needs_example = pytest.mark.skipif(
    not EXAMPLE,
    reason="CHASLES_POSE_GRAPH_EXAMPLE is unset (tests/run.sh sets it to examples/cpp/pose_graph.cpp's program)",
)


@pytest.fixture(scope="module")
def sphere():
    return chasles.pose_graph_sphere(8, 8, radius=10.0, seed=1)


@pytest.fixture(scope="module")
def grid():
    return chasles.pose_graph_grid(300, 8, seed=2)


def chi2_by_hand(graph):
    cls = chasles.SE3 if graph.group == "se3" else chasles.SE2
    total = 0.0
    for (i, j), Z, omega in zip(graph.edges, graph.measurements, graph.information):
        e = np.asarray(
            (
                cls.from_matrix(Z).inverse()
                @ cls.from_matrix(graph.poses[i]).inverse()
                @ cls.from_matrix(graph.poses[j])
            ).log()
        )
        total += e @ omega @ e
    return total


@pytest.mark.parametrize("which", ["sphere", "grid"])
def test_chi2_is_the_sum_over_edges(which, request):
    graph, truth = request.getfixturevalue(which)
    assert graph.chi2() == pytest.approx(chi2_by_hand(graph), rel=1e-12)
    assert graph.residuals().shape == (graph.edges.shape[0], 6 if graph.group == "se3" else 3)


@pytest.mark.parametrize("which", ["sphere", "grid"])
def test_the_solve_reaches_a_minimum(which, request):
    graph, truth = request.getfixturevalue(which)
    result = graph.solve()
    d = 6 if graph.group == "se3" else 3
    n = graph.poses.shape[0]
    assert result.converged and 2 <= result.iterations < 50
    assert result.initial_chi2 == pytest.approx(graph.chi2(), rel=1e-15)
    assert result.final_chi2 == pytest.approx(result.graph.chi2(), rel=1e-15)
    # the optimum: below the truth's chi2, near its expectation (E d - (V - 1) d residual degrees of freedom)
    dof = graph.edges.shape[0] * d - (n - 1) * d
    assert result.final_chi2 < graph.with_poses(truth).chi2()
    assert abs(result.final_chi2 - dof) < 6 * np.sqrt(2 * dof)
    # the first pose held fixed
    assert np.array_equal(result.graph.poses[0], graph.poses[0])
    # optimal: chi2's central differences along every coordinate of a few free poses vanish
    solved = result.graph
    exp = chasles.se3_exp if graph.group == "se3" else chasles.se2_exp
    compose = chasles.se3_compose if graph.group == "se3" else chasles.se2_compose
    h = 1e-6
    for k in (1, n // 2, n - 1):
        for c in range(d):
            step = np.zeros(d)
            step[c] = h
            plus, minus = solved.poses.copy(), solved.poses.copy()
            plus[k] = compose(plus[k], exp(step))
            minus[k] = compose(minus[k], exp(-step))
            gradient = (solved.with_poses(plus).chi2() - solved.with_poses(minus).chi2()) / (2 * h)
            # against the scale of the gradient's terms, 2 |Omega e| for the pose's edges
            assert abs(gradient) < 1e-4 * (1 + np.abs(graph.information).max())


def test_g2o_round_trip(sphere, grid, tmp_path):
    for graph, _ in (sphere, grid):
        path = tmp_path / f"{graph.group}.g2o"
        chasles.write_g2o(path, graph)
        back = chasles.read_g2o(path)
        assert back.group == graph.group
        assert np.array_equal(back.ids, graph.ids) and np.array_equal(back.edges, graph.edges)
        assert np.array_equal(back.information, graph.information)
        # poses through (x, y, z, quaternion) or (x, y, theta): to rounding
        assert np.abs(back.poses - graph.poses).max() < 1e-14 * max(1.0, np.abs(graph.poses).max())
        assert back.chi2() == pytest.approx(graph.chi2(), rel=1e-9)
        # the numbers of the file are written to 17 digits: read back as written
        chasles.write_g2o(tmp_path / "again.g2o", back)
        again = chasles.read_g2o(tmp_path / "again.g2o")
        assert np.abs(again.poses - back.poses).max() < 1e-15 * max(1.0, np.abs(graph.poses).max())


def test_g2o_text(tmp_path):
    text = """# a comment
VERTEX_SE2 10 0 0 0
VERTEX_SE2 20 1 0 1.5707963267948966
FIX 10

EDGE_SE2 10 20 1 0 1.5707963267948966 100 0 0 100 0 400
"""
    (tmp_path / "a.g2o").write_text(text)
    g = chasles.read_g2o(tmp_path / "a.g2o")
    assert g.group == "se2" and list(g.ids) == [10, 20] and g.edges.tolist() == [[0, 1]]
    assert np.allclose(g.information[0], np.diag([100.0, 100.0, 400.0]))
    assert g.chi2() == pytest.approx(0.0, abs=1e-20)
    se3 = "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 1 2 3 0 0 0.7071067811865476 0.7071067811865476\n"
    info = " ".join(str(x) for x in np.eye(6)[np.triu_indices(6)])
    (tmp_path / "b.g2o").write_text(se3 + f"EDGE_SE3:QUAT 0 1 1 2 3 0 0 0.7071067811865476 0.7071067811865476 {info}\n")
    b = chasles.read_g2o(str(tmp_path / "b.g2o"))
    assert np.allclose(b.poses[1][:3, 3], [1, 2, 3]) and np.allclose(b.poses[1][:2, :2], [[0, -1], [1, 0]])
    assert b.chi2() < 1e-25


MALFORMED = [
    ("VERTEX_XYZ 0 1 2 3", "line 2: unknown tag 'VERTEX_XYZ'"),
    ("VERTEX_SE2 1 0 0", "line 2: VERTEX_SE2 expects 4 values, got 3"),
    ("VERTEX_SE2 1 0 zero 0", "line 2: could not convert"),
    ("VERTEX_SE2 1.5 0 0 0", "line 2: invalid literal for int"),
    ("VERTEX_SE2 0 0 0 0", "line 2: vertex 0 is defined twice"),
    ("VERTEX_SE2 1 0 nan 0", "line 2: expected finite numbers"),
    ("VERTEX_SE2 1 0 1e400 0", "line 2: expected finite numbers"),
    ("VERTEX_SE2 " + "9" * 400 + " 0 0 0", "line 2: a vertex id beyond 64 bits"),
    ("EDGE_SE2 0 7 1 0 0 1 0 0 1 0 1", "line 2: an edge to vertex 7, not defined"),
    ("VERTEX_SE3:QUAT 1 0 0 0 0 0 0 1", "line 2: a se3 line in a se2 graph"),
    ("EDGE_SE2 0 0 1 0 0 1 0 0 -1 0 1", "information): expected positive definite"),
]


@pytest.mark.parametrize("line, message", MALFORMED)
def test_malformed_lines_are_refused_with_their_number(line, message, tmp_path):
    path = tmp_path / "bad.g2o"
    path.write_text("VERTEX_SE2 0 0 0 0\n" + line + "\n")
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        chasles.read_g2o(path)


def run_example(*args):
    assert os.access(EXAMPLE, os.X_OK), f"CHASLES_POSE_GRAPH_EXAMPLE={EXAMPLE!r} is not an executable program"
    return subprocess.run([EXAMPLE, *map(str, args)], capture_output=True, text=True, timeout=120, check=False)


@needs_example
@pytest.mark.parametrize("which", ["sphere", "grid"])
def test_the_cpp_ceres_solve_reaches_the_same_minimum(which, tmp_path):
    graph, _ = chasles.pose_graph_sphere() if which == "sphere" else chasles.pose_graph_grid()
    path, out = tmp_path / "graph.g2o", tmp_path / "solved.g2o"
    chasles.write_g2o(path, graph)
    r = run_example(path, "--out", out)
    assert r.returncode == 0 and "all checks passed" in r.stdout, r.stdout + r.stderr
    printed = {k: float(re.search(rf"^{k}: (\S+)$", r.stdout, re.M).group(1)) for k in ("initial chi2", "final chi2")}
    python = graph.solve()
    assert printed["initial chi2"] == pytest.approx(graph.chi2(), rel=1e-13)
    assert printed["final chi2"] == pytest.approx(python.final_chi2, rel=1e-9)
    solved = chasles.read_g2o(out)
    assert solved.chi2() == pytest.approx(printed["final chi2"], rel=1e-12)
    assert np.array_equal(solved.ids, graph.ids) and np.array_equal(solved.edges, graph.edges)
    # The same poses, to what the stopping rule leaves free: a step that lowers
    # chi2 by 1e-12 relative (1.5e-8 here) ends either solve, and the graph's
    # softest modes (bending the sphere, 50 m across) move poses by ~1e-5 for it.
    assert np.abs(solved.poses - python.graph.poses).max() < 1e-4


@needs_example
@pytest.mark.parametrize(
    "first, line",
    [("VERTEX_SE2 0 0 0 0", line) for line, _ in MALFORMED]
    + [("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1", "VERTEX_SE3:QUAT 1 1 2 3 0 0 0 0")],
)
def test_the_cpp_example_refuses_malformed_lines_with_their_number(first, line, tmp_path):
    path = tmp_path / "bad.g2o"
    path.write_text(first + "\n" + line + "\n")
    r = run_example(path)
    assert r.returncode == 1 and f"{path}: line 2: " in r.stderr, r.stdout + r.stderr


def test_a_quaternion_of_zero_norm_is_refused(tmp_path):
    path = tmp_path / "bad.g2o"
    path.write_text("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 1 2 3 0 0 0 0\n")
    with pytest.raises(ValueError, match="line 2: a quaternion of zero norm"):
        chasles.read_g2o(path)


def test_value_semantics_and_bad_arguments(grid, tmp_path):
    graph, _ = grid
    for h in (pickle.loads(pickle.dumps(graph)), copy.deepcopy(graph)):
        assert np.array_equal(h.poses, graph.poses) and np.array_equal(h.information, graph.information)
    with pytest.raises(ValueError):
        graph.poses[0, 0, 0] = 2.0  # read-only
    assert repr(graph) == "PoseGraph('se2', 300 poses, 537 edges)"
    with pytest.raises(ValueError, match="poses\\): expected shape"):
        graph.with_poses(graph.poses[:-1])
    with pytest.raises(ValueError, match="expected finite"):
        graph.with_poses(graph.poses * np.nan)
    with pytest.raises(ValueError, match="group\\): expected 'se3' or 'se2'"):
        chasles.PoseGraph("so3", graph.ids, graph.poses, graph.edges, graph.measurements, graph.information)
    with pytest.raises(TypeError, match="max_iterations"):
        graph.solve(max_iterations=2.5)
    with pytest.raises(ValueError, match="tolerance"):
        graph.solve(tolerance=-1.0)
    with pytest.raises(TypeError, match="write_g2o\\(graph\\): expected a PoseGraph"):
        chasles.write_g2o(tmp_path / "x.g2o", "graph")
    with pytest.raises(TypeError, match="read_g2o\\(path\\)"):
        chasles.read_g2o(3)
    with pytest.raises(ValueError, match="sigma"):
        chasles.pose_graph_grid(sigma=(0.1, -1.0))
    with pytest.raises(ValueError, match="rings"):
        chasles.pose_graph_sphere(rings=1)
    # a pose that no edge ties to the others
    lonely = chasles.PoseGraph("se2", [0, 1, 2], np.stack([np.eye(3)] * 3), [[0, 1]], [np.eye(3)], [np.eye(3)])
    result = lonely.solve()  # the damping keeps the normal equations regular: the lonely pose stays put
    assert result.converged and np.array_equal(result.graph.poses[2], np.eye(3))
    alone = chasles.PoseGraph("se2", [0], [np.eye(3)], np.zeros((0, 2), int), np.zeros((0, 3, 3)), np.zeros((0, 3, 3)))
    result = alone.solve()
    assert result.converged and result.iterations == 0 and result.final_chi2 == 0.0
