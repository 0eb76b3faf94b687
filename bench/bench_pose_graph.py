#!/usr/bin/env python3
"""Pose-graph solves: chasles' Python solve beside GTSAM's, on the same g2o files, in one run.

    python bench/bench_pose_graph.py [--rounds 3] [--sphere 50 50] [--grid 3500 40] [--cpp PATH]

Makes the benchmark graphs (chasles.pose_graph_sphere: 2500 poses and 4949
edges, as g2o's sphere2500; chasles.pose_graph_grid: 3500 planar poses, as
the Manhattan dataset), writes them as g2o files, and solves each with

- chasles: ``chasles.read_g2o(path).solve()`` (Levenberg-Marquardt, the
  analytic Jacobians of every edge from the array functions, one sparse
  matrix, scipy's sparse LU), the first pose held fixed;
- chasles in C++ (with --cpp PATH, the program of examples/cpp/pose_graph.cpp,
  built when CMake finds Ceres): Ceres on chasles::CeresManifold and
  chasles::BetweenCost, timed as a whole process (start, read, solve);
- GTSAM (if importable): ``gtsam.readG2o(path, is3D)``, a prior of standard
  deviation 1e-9 on the first pose, LevenbergMarquardtOptimizer with the
  relative error tolerance 1e-12.

Prints a markdown table: initial and final chi2 (chasles' chi2 = twice
GTSAM's graph error), iterations, seconds (the best of --rounds rounds, the
contenders alternating within each round), and the ratios to GTSAM of the
final chi2 and of the time.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import chasles

try:
    import gtsam
except ImportError:  # the peer is optional
    gtsam = None


def solve_chasles(path: Path) -> tuple[float, float, int]:
    result = chasles.read_g2o(path).solve()
    return result.initial_chi2, result.final_chi2, result.iterations


def solve_gtsam(path: Path, is3d: bool) -> tuple[float, float, int]:
    graph, initial = gtsam.readG2o(str(path), is3d)
    first = initial.atPose3(0) if is3d else initial.atPose2(0)
    noise = gtsam.noiseModel.Diagonal.Sigmas(np.full(6 if is3d else 3, 1e-9))
    graph.add(gtsam.PriorFactorPose3(0, first, noise) if is3d else gtsam.PriorFactorPose2(0, first, noise))
    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(0.0)
    params.setMaxIterations(100)
    optimizer = gtsam.LevenbergMarquardtOptimizer(graph, initial, params)
    result = optimizer.optimize()
    return 2 * graph.error(initial), 2 * graph.error(result), optimizer.iterations()


def solve_cpp(program: Path, path: Path) -> tuple[float, float, int]:
    out = subprocess.run([str(program), str(path)], capture_output=True, text=True, check=True).stdout
    number = {k: re.search(rf"^{k}: (\S+)$", out, re.M).group(1) for k in ("initial chi2", "final chi2", "iterations")}
    return float(number["initial chi2"]), float(number["final chi2"]), int(number["iterations"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--sphere", type=int, nargs=2, default=(50, 50), metavar=("RINGS", "PER_RING"))
    parser.add_argument("--grid", type=int, nargs=2, default=(3500, 40), metavar=("POSES", "SIZE"))
    parser.add_argument("--cpp", type=Path, help="the program example_pose_graph (examples/cpp/pose_graph.cpp)")
    args = parser.parse_args()
    version = getattr(gtsam, "__version__", "?") if gtsam else "not installed"
    print(f"chasles {chasles.__version__}, gtsam {version}, numpy {np.__version__}\n")
    print("| graph | solver | initial chi2 | final chi2 | iterations | seconds |")
    print("| --- | --- | ---: | ---: | ---: | ---: |")
    ratios = []
    with tempfile.TemporaryDirectory() as directory:
        for name, (graph, _), is3d in (
            (f"sphere {args.sphere[0]}x{args.sphere[1]}", chasles.pose_graph_sphere(*args.sphere), True),
            (f"grid {args.grid[0]}", chasles.pose_graph_grid(*args.grid), False),
        ):
            path = Path(directory) / "graph.g2o"
            chasles.write_g2o(path, graph)
            label = f"{name} ({graph.poses.shape[0]} poses, {graph.edges.shape[0]} edges)"
            contenders = {"chasles": lambda p=path: solve_chasles(p)}
            if args.cpp is not None:
                contenders["chasles C++ (Ceres)"] = lambda p=path: solve_cpp(args.cpp, p)
            if gtsam is not None:
                contenders["gtsam"] = lambda p=path, d=is3d: solve_gtsam(p, d)
            best: dict[str, float] = dict.fromkeys(contenders, np.inf)
            outcome: dict[str, tuple] = {}
            for r in range(args.rounds):
                order = list(contenders)[r % len(contenders) :] + list(contenders)[: r % len(contenders)]
                for k in order:
                    start = time.perf_counter()
                    outcome[k] = contenders[k]()
                    best[k] = min(best[k], time.perf_counter() - start)
            for k, (initial, final, iterations) in outcome.items():
                print(f"| {label} | {k} | {initial:.10g} | {final:.10g} | {iterations} | {best[k]:.3f} |")
            if gtsam is not None:
                for k in contenders:
                    if k != "gtsam":
                        ratios.append((label, k, outcome[k][1] / outcome["gtsam"][1], best[k] / best["gtsam"]))
    if ratios:
        print("\n| graph | solver | final chi2 / gtsam's | time / gtsam's |")
        print("| --- | --- | ---: | ---: |")
        for label, k, chi2, seconds in ratios:
            print(f"| {label} | {k} | {chi2:.12f} | {seconds:.2f} |")


if __name__ == "__main__":
    main()
