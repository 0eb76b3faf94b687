"""Inverse kinematics on real arms: success rates and time per solve.

For each arm of example-robot-data (UR5, Panda, xArm7, Kinova Jaco2
j2s6s200), loaded with chasles.Chain.from_urdf: 1000 targets forward(q*) of
q* uniform within the joint limits (clipped to [-pi, pi]), solved
- from seeds 0.3 rad away (each joint q*_i + U(-0.3, 0.3), clamped into the
  limits) with no restart, and
- from seeds uniform within the limits with up to 10 restarts,
to the default tolerances (3.7e-11 m and rad on the body error twist). It
reports the share solved, the iterations of all attempts (median, 99th percentile) and the
time per solve: the median over single calls (Python's call overhead
included) and the mean over one batched call (the C++ loop with the GIL
released, the closest to a C++ solve).

    python bench/bench_ik.py            # needs chasles and example-robot-data
"""

from __future__ import annotations

import importlib.metadata
import time

import numpy as np

from chasles import Chain

ARMS = {
    "UR5": ("ur_description/urdf/ur5_robot.urdf", "tool0"),
    "Panda": ("panda_description/urdf/panda.urdf", "panda_hand"),
    "xArm7": ("xarm_description/urdf/xarm7.urdf", "link7"),
    "Jaco2": ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector"),
}
N = 1000


def robots_dir():
    for f in importlib.metadata.files("example-robot-data") or []:
        if str(f).endswith("ur_description/urdf/ur5_robot.urdf"):
            return f.locate().parents[2]
    raise SystemExit("example-robot-data is not installed (pip install example-robot-data)")


def uniform_within(chain: Chain, rng: np.random.Generator, size: int) -> np.ndarray:
    lo, hi = np.maximum(chain.lower, -np.pi), np.minimum(chain.upper, np.pi)
    return rng.uniform(lo, hi, (size, chain.n_joints))


def per_call_median(chain: Chain, targets: np.ndarray, seeds: np.ndarray, **kw) -> float:
    times = []
    for T, q0 in zip(targets, seeds):
        t0 = time.perf_counter()
        chain.inverse_kinematics(T, q0, **kw)
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def batched_mean(chain: Chain, targets: np.ndarray, seeds: np.ndarray, **kw) -> tuple[float, object]:
    best, result = np.inf, None
    for _ in range(3):
        t0 = time.perf_counter()
        result = chain.inverse_kinematics(targets, seeds, **kw)
        best = min(best, (time.perf_counter() - t0) / len(targets))
    return best, result


def main() -> None:
    root = robots_dir()
    print(f"{N} targets per arm, tolerance 3.7e-11; times in microseconds per solve")
    print(f"{'arm':7} {'seeds':28} {'solved':>8} {'iter med/p99':>13} {'per call':>9} {'batched':>8}")
    for name, (rel, tip) in ARMS.items():
        chain = Chain.from_urdf(root / rel, tip)
        rng = np.random.default_rng(0)
        q_true = uniform_within(chain, rng, N)
        targets = chain.forward(q_true)
        near = np.clip(q_true + rng.uniform(-0.3, 0.3, q_true.shape), chain.lower, chain.upper)
        far = uniform_within(chain, rng, N)
        for label, seeds, kw in (("0.3 rad away", near, {}), ("random, <= 10 restarts", far, {"restarts": 10})):
            mean, r = batched_mean(chain, targets, seeds, **kw)
            median = per_call_median(chain, targets[:200], seeds[:200], **kw)
            its = np.asarray(r.total_iterations)
            print(
                f"{name:7} {label:28} {100 * np.mean(r.converged):7.1f}% "
                f"{int(np.median(its)):>6}/{int(np.percentile(its, 99)):<6} {1e6 * median:9.1f} {1e6 * mean:8.1f}"
            )


if __name__ == "__main__":
    main()
