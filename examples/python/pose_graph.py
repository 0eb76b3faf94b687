"""A pose graph solved end to end: read a g2o file, solve, write the result.

    python examples/python/pose_graph.py PATH.g2o [--out OUT.g2o]

reads a 3D (VERTEX_SE3:QUAT / EDGE_SE3:QUAT) or 2D (VERTEX_SE2 / EDGE_SE2)
pose graph, holds its first vertex fixed and minimizes

    chi2 = sum over edges of e^T Omega e,  e = log(Z_ij^-1 X_i^-1 X_j)

(twice GTSAM's graph error for its BetweenFactor) by Levenberg-Marquardt
with chasles' analytic Jacobians, assembled as one sparse matrix per
iteration. Without PATH it makes the benchmark sphere (2500 poses on a
sphere, 4949 edges, as g2o's sphere2500) and the grid world (3500 planar
poses with loop closures, as the Manhattan dataset), writes them as g2o
files and solves both.
"""

import argparse
import tempfile
import time
from pathlib import Path

import chasles


def solve(path: Path, out: Path | None) -> None:
    graph = chasles.read_g2o(path)
    start = time.perf_counter()
    result = graph.solve()
    seconds = time.perf_counter() - start
    print(f"{path.name}: {graph}")
    print(f"initial chi2: {result.initial_chi2:.10g}")
    print(f"final chi2: {result.final_chi2:.10g}")
    print(f"iterations: {result.iterations}")
    print(f"converged: {result.converged} in {seconds:.2f} s")
    if out is not None:
        chasles.write_g2o(out, result.graph)
        print(f"wrote {out}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("path", nargs="?", type=Path, help="a g2o file (default: the generated sphere and grid)")
    parser.add_argument("--out", type=Path, help="where to write the solved graph (g2o)")
    args = parser.parse_args()
    if args.path is not None:
        solve(args.path, args.out)
        return
    with tempfile.TemporaryDirectory() as directory:
        for name, (graph, truth) in (
            ("sphere2500.g2o", chasles.pose_graph_sphere()),
            ("grid3500.g2o", chasles.pose_graph_grid()),
        ):
            path = Path(directory) / name
            chasles.write_g2o(path, graph)
            solve(path, None)
            # the truth's chi2, for scale: about the number of residuals
            print(f"chi2 of the true poses: {graph.with_poses(truth).chi2():.10g}")


if __name__ == "__main__":
    main()
