#!/usr/bin/env python3
"""Prints the benchmark tables of chasles, one per language, in markdown, and
writes them into docs/performance.md.

    python3 bench/report.py --write docs/performance.md   # everything, into the page
    python3 bench/report.py              # C++ (builds bench/ with CMake) and Python, printed only
    python3 bench/report.py --cpp-only   # or --python-only
    python3 bench/report.py --latency    # only the worst-case latency table

C++: runs the Google Benchmark binaries (portable -O3 and -march=native) with
repetitions and reports the median ns/op of every chasles operation beside
the best Eigen baseline measured in the same run, the floor (one sincos, one
atan2, a 3x3 product) and the target of the benchmark issue; for exp and log,
also the kernel's worst error on the inputs it was timed on (in eps of the
scalar: rotation entries and rotation vectors absolute, translations
relative), against the long double reference of the C++ tests. Python: runs
bench/bench_python.py (per-call latency of the objects, per-element time of
the array functions, against scipy, numpy, and pin / pytransform3d when
installed). Latency: bench/latency.cpp times each of 1e6 calls on its own and
reports the median, p99, p99.99 and maximum per operation, on a shuffled mix
of generic, zero, tiny, cutoff, near-pi and pi inputs. Medians, and ratios against a peer measured in the same run:
machines are shared and noisy, absolute numbers move, ratios much less.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# op -> (Eigen baselines that do the same job, floor, target ns for double).
CPP_OPS: dict[str, tuple[list[str], str | None, float | None]] = {
    "SO3/exp": (
        ["Eigen/AngleAxis_to_matrix", "Eigen/quaternion_exp_to_matrix", "Eigen/quaternion_exp"],
        "floor/sincos",
        17,
    ),
    "SO3/log": (["Eigen/AngleAxis_from_matrix", "Eigen/AngleAxis_from_quaternion"], "floor/atan2", 22),
    "SO3/compose": (["Eigen/quaternion_compose"], "floor/matmul_3x3_3x3", 4),
    "SO3/inverse": ([], None, None),
    "SO3/act": (["Eigen/quaternion_act"], "floor/matmul_3x3_3", 2.2),
    "SO3/as_quaternion": (["Eigen/matrix_to_quaternion"], None, None),
    "SO3/from_quaternion": (["Eigen/quaternion_to_matrix"], None, None),
    "SO3/interpolate": (["Eigen/quaternion_slerp"], None, None),
    "SO3/normalized": ([], None, None),
    "SO3/from_euler_ZYX": (["Eigen/AngleAxis_product_ZYX"], "floor/sincos", None),
    "SO3/as_euler_ZYX": (["Eigen/eulerAngles_ZYX"], "floor/atan2", None),
    "SO3/as_euler_ZXZ": (["Eigen/eulerAngles_ZXZ"], "floor/atan2", None),
    "SE3/exp": ([], "floor/sincos", 30),
    "SE3/log": ([], "floor/atan2", 45),
    "SE3/compose": (["Eigen/Isometry3_compose"], "floor/matmul_3x3_3x3", 7),
    "SE3/inverse": (["Eigen/Isometry3_inverse"], "floor/matmul_3x3_3", 3),
    "SE3/act": (["Eigen/Isometry3_act"], "floor/matmul_3x3_3", 2.2),
    "SE3/adjoint": ([], "floor/matmul_3x3_3x3", 15),
    "SE3/act_twist": ([], "floor/matmul_3x3_3", None),
    "SE3/act_wrench": ([], "floor/matmul_3x3_3", None),
    "SE3/interpolate": ([], None, None),
}


def build_cpp(build_dir: Path) -> None:
    """Configures and builds bench/ (both benchmark binaries and the latency table)."""
    subprocess.run(
        ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release", "-DCHASLES_BUILD_BENCH=ON"],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    subprocess.run(
        ["cmake", "--build", str(build_dir), "-j", str(os.cpu_count() or 2)], check=True, stdout=subprocess.DEVNULL
    )


def run_cpp(build_dir: Path, repetitions: int, min_time: float) -> dict[str, dict[str, float]]:
    """Builds and runs both benchmark binaries; returns {variant: {name: median ns}}."""
    build_cpp(build_dir)
    results: dict[str, dict[str, float]] = {}
    for variant in ("portable", "native"):
        exe = build_dir / "bench" / f"chasles_bench_{variant}"
        out = subprocess.run(
            [
                str(exe),
                "--benchmark_format=json",
                f"--benchmark_repetitions={repetitions}",
                f"--benchmark_min_time={min_time}",
                "--benchmark_report_aggregates_only=true",
            ],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
        medians = {}
        for b in json.loads(out)["benchmarks"]:
            if b.get("aggregate_name") == "median":
                medians[b["run_name"]] = b["real_time"] if b["time_unit"] == "ns" else float("nan")
                if "err_eps" in b:  # the kernel's worst error on the same inputs (bench_ops.cpp, add_measured)
                    medians["err_eps:" + b["run_name"]] = b["err_eps"]
        results[variant] = medians
    return results


def cpp_table(medians: dict[str, float], scalar: str) -> str:
    rows = [
        "| op | input | chasles ns | worst error (eps) | best Eigen peer | peer ns | ratio | floor ns | x floor | "
        "target ns |",
        "| --- | --- | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: |",
    ]
    for op, (peers, floor, target) in CPP_OPS.items():
        for kind in ("generic", "tiny", "near_pi"):
            name = f"{op}/{kind}/{scalar}"
            if name not in medians:
                continue
            t = medians[name]
            peer_times = [
                (medians[f"{p}/{kind}/{scalar}"], p.split("/", 1)[1])
                for p in peers
                if f"{p}/{kind}/{scalar}" in medians
            ]
            best = min(peer_times) if peer_times else None
            f = medians.get(f"{floor}/generic/{scalar}") if floor else None
            err = medians.get("err_eps:" + name)
            rows.append(
                "| {} | {} | {:.1f} | {} | {} | {} | {} | {} | {} | {} |".format(
                    op,
                    kind,
                    t,
                    f"{err:.2f}" if err is not None else "",
                    best[1] if best else "",
                    f"{best[0]:.1f}" if best else "",
                    f"{t / best[0]:.2f}" if best else "",
                    f"{f:.1f}" if f else "",
                    f"{t / f:.1f}" if f else "",
                    (f"{target:g}" if target and scalar == "double" and kind == "generic" else ""),
                )
            )
    return "\n".join(rows)


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


# docs/performance.md: this text, then the tables of the run (--write).
PAGE_HEADER = """\
# Performance

Written by `python3 bench/report.py --write docs/performance.md` (C++: builds
`bench/` with CMake; Python: runs `bench/bench_python.py`, which needs
`pip install . scipy` and measures Pinocchio, pytransform3d and
modern_robotics when they are installed). Every table below is of one run,
every peer measured in the same run. Medians; ratios below 1 mean chasles is
faster. Machines are shared and noisy: absolute numbers move, ratios much
less.

How to read the tables:

- **C++ throughput** (`bench/bench_ops.cpp`, Google Benchmark, `-O3
  -DNDEBUG`, portable and `-march=native`): ns per operation beside Eigen's
  own types and the floors (one `sincos`, one `atan2`, a 3x3 product);
  `quaternion_exp` is Eigen's `Quaterniond(AngleAxisd(|w|, w / |w|))` (four
  numbers out, no matrix) and `AngleAxis_from_quaternion` its log from a
  stored quaternion. For exp and log, the worst error on the very inputs
  timed, in eps (rotation entries and rotation vectors absolute,
  translations relative), against the long double reference of the C++
  tests.
- **Worst-case latency** (`bench/latency.cpp`): every call timed on its own
  (the time-stamp counter, its own cost subtracted), 10^6 calls per
  operation on a shuffled mix of generic, zero, tiny, Taylor-cutoff,
  near-pi and exactly-pi inputs; the tail beside the median and the median
  of the slowest kind of input. A single call costs more than the throughput
  figures (there, calls overlap in the processor's pipeline; here each is
  fenced). There is no slow path near 0 or pi, and no iteration but the
  projection's Jacobi sweeps, which stop after at most 12. The log's
  rotations past pi/2 are its slowest kind: below pi/2 its atan takes one
  division, past it two in a row (the angle, then its ratio to |u_v|), and
  zero and tiny rotations take no quaternion at all. Inverse kinematics is
  the one operation whose cost depends on its input: its worst case is its
  iteration bound (`IKOptions::max_iterations`, 100), which every
  "unreachable" problem reaches; the dynamics have no data-dependent path.
  The p99.99 and maximum columns measure the machine as much as the code: on
  a shared machine the maximum is a preemption or an interrupt (tens of
  microseconds to milliseconds). Pin the thread to an isolated core for
  controller-grade tails.
- **Python** (`bench/bench_python.py`): objects one element per call, in
  microseconds, each less the harness's own cost per call (a loop calling an
  empty lambda); the floors are a method that returns a new object and does
  no math. Array functions per element, in nanoseconds, at each N. `Chain`
  per call and per configuration batched over N joint vectors, against
  numpy loops over `scipy.linalg.expm`, the `modern_robotics` package and
  Pinocchio.
"""


def write_page(path: Path, tables: str) -> None:
    """Writes the page: PAGE_HEADER, then the tables of the run under a heading."""
    path.write_text(PAGE_HEADER + "\n## The run\n\n" + tables.strip() + "\n", encoding="utf-8")


class Report:
    """What the run prints, kept for --write."""

    def __init__(self) -> None:
        self.parts: list[str] = []

    def emit(self, text: str = "") -> None:
        print(text, flush=True)
        self.parts.append(text)

    def run(self, cmd: list[str], check: bool) -> int:
        """Runs a program that prints tables: its output is printed and kept."""
        r = subprocess.run(cmd, check=check, stdout=subprocess.PIPE, text=True)
        self.emit(r.stdout.rstrip("\n"))
        return r.returncode

    def text(self) -> str:
        return "\n".join(self.parts)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cpp-only", action="store_true")
    ap.add_argument("--python-only", action="store_true")
    ap.add_argument("--latency", action="store_true", help="only the worst-case latency table (C++)")
    ap.add_argument("--calls", type=int, default=1_000_000, help="calls per op for the latency table")
    ap.add_argument("--build-dir", type=Path, default=ROOT / "build" / "bench")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--min-time", type=float, default=0.1, help="seconds per repetition (C++)")
    ap.add_argument(
        "--write",
        type=Path,
        metavar="PAGE",
        help="also write the page (docs/performance.md) with the tables of this run",
    )
    args = ap.parse_args()
    report = Report()
    report.emit(f"Machine: {machine()}\n")
    latency = [str(args.build_dir / "bench" / "chasles_latency"), "--calls", str(args.calls)]
    status = 0
    if args.latency:
        build_cpp(args.build_dir)
        status = report.run(latency, check=False)
    else:
        if not args.python_only:
            results = run_cpp(args.build_dir, args.repetitions, args.min_time)
            for variant, medians in results.items():
                for scalar in ("double", "float"):
                    flags = "-O3 -DNDEBUG" + (" -march=native" if variant == "native" else "")
                    report.emit(f"### C++, {scalar}, {flags} (median of {args.repetitions}, ns/op)\n")
                    report.emit(cpp_table(medians, scalar))
                    report.emit()
            report.run(latency, check=True)
        if not args.cpp_only:
            status = report.run([sys.executable, str(ROOT / "bench" / "bench_python.py")], check=False)
    if args.write and status == 0:
        write_page(args.write, report.text())
        print(f"wrote {args.write}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main())
