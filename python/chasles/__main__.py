"""The chasles demo: ``python -m chasles [--seed N] [--l1 L] [--theta T]``.

1. The worked example of the documentation (Murray, Li and Sastry, ch. 2):
   the rotation by theta about the z axis through q = (0, l1, 0), pitch 0.
   Prints the twist xi = (v, w) = (l1, 0, 0, 0, 0, 1), its matrix [xi] and
   g(theta) = exp([xi] theta), and checks g against the closed form
   [[cos, -sin, 0, l1 sin], [sin, cos, 0, l1 (1 - cos)], [0, 0, 1, 0], [0, 0, 0, 1]]
   and that the points of the axis stay put.
2. Chasles' theorem on a random rigid motion (fixed seed): g = exp([xi]) with
   xi = log(g); the screw of xi (axis point, direction, pitch, magnitude);
   and SE3.from_screw of that screw gives g back.

The exit status is 0 when every check passes, 1 otherwise.
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from chasles import SE3, SO3, Twist

# Agreement asked of the checks: a few hundred ulps of the entries' scale.
TOLERANCE = 1e-12


def _fmt(a: np.ndarray) -> str:
    """An array printed with 6 decimals, -0 shown as 0, indented under a label."""
    a = np.asarray(a, dtype=float) + 0.0
    text = np.array2string(a, precision=6, suppress_small=True, floatmode="fixed", sign=" ")
    return text.replace("\n", "\n    ")


def _check(label: str, error: float, tol: float = TOLERANCE) -> bool:
    ok = bool(error <= tol)
    print(
        f"  {'ok' if ok else 'FAILED'}: {label} (max difference {error:.1e}, tolerance {tol:.0e})"
    )
    return ok


def worked_example(l1: float, theta: float) -> bool:
    """Part 1: the seed's screw motion, printed and checked. True if it agrees."""
    print(
        "1. Worked example: rotation by theta about the z axis through q = (0, l1, 0), pitch h = 0"
    )
    print(f"   l1 = {l1}, theta = {theta}")
    q = np.array([0.0, l1, 0.0])
    w = np.array([0.0, 0.0, 1.0])
    v = -np.cross(w, q)  # v = -w x q + h w with h = 0
    xi = Twist(v=v, w=w)
    print("   twist xi = (v, w), linear part first:")
    print("    " + _fmt(xi.vector))
    print("   its matrix [xi] = [[ [w], v ], [0, 0]]:")
    print("    " + _fmt(xi.hat()))

    g = SE3.exp(xi.vector * theta)
    print("   g(theta) = exp([xi] theta):")
    print("    " + _fmt(g.as_matrix()))

    c, s = np.cos(theta), np.sin(theta)
    closed_form = np.array(
        [
            [c, -s, 0.0, l1 * s],
            [s, c, 0.0, l1 * (1.0 - c)],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]
    )
    scale = max(1.0, abs(l1))
    ok = _check(
        "g(theta) equals the closed form",
        float(np.max(np.abs(g.as_matrix() - closed_form))),
        TOLERANCE * scale,
    )
    axis_points = np.array([[0.0, l1, z] for z in (-2.0, 0.0, 3.5)])
    ok &= _check(
        "points (0, l1, z) of the axis stay put",
        float(np.max(np.abs(g @ axis_points - axis_points))),
        TOLERANCE * scale,
    )
    same = SE3.from_screw(q, w, 0.0, theta)
    ok &= _check(
        "SE3.from_screw(q, w, 0, theta) gives the same g",
        float(np.max(np.abs(same.as_matrix() - g.as_matrix()))),
        TOLERANCE * scale,
    )
    return ok


def random_motion(seed: int) -> SE3:
    """A random rigid motion: a uniform rotation and a translation in [-2, 2]^3."""
    rng = np.random.default_rng(seed)
    rotation = SO3.from_quat(rng.normal(size=4))  # a normal 4-vector's direction is uniform
    return SE3(rotation, rng.uniform(-2.0, 2.0, size=3))


def screw_of_random_motion(seed: int) -> bool:
    """Part 2: Chasles' theorem on a random motion. True if it checks out."""
    print(f"2. Chasles' theorem on a random rigid motion (seed {seed})")
    g = random_motion(seed)
    print("   g =")
    print("    " + _fmt(g.as_matrix()))
    xi = Twist.from_vector(g.log())
    print("   its twist xi = log(g) = (v, w):")
    print("    " + _fmt(xi.vector))
    screw = xi.screw()
    print("   the screw of xi: g rotates about this axis while sliding along it")
    print(f"     axis point (nearest the origin): {_fmt(screw.point)}")
    print(f"     axis direction:                  {_fmt(screw.direction)}")
    print(f"     pitch h (length per radian):     {screw.pitch: .6f}")
    print(f"     magnitude theta (radians):       {screw.magnitude: .6f}")
    print(f"     slide along the axis, h theta:   {screw.pitch * screw.magnitude: .6f}")

    ok = _check(
        "exp(log(g)) equals g", float(np.max(np.abs(SE3.exp(xi).as_matrix() - g.as_matrix())))
    )
    rebuilt = SE3.from_screw(screw.point, screw.direction, screw.pitch, screw.magnitude)
    print("   SE3.from_screw(point, direction, pitch, theta) =")
    print("    " + _fmt(rebuilt.as_matrix()))
    ok &= _check(
        "SE3.from_screw reproduces g",
        float(np.max(np.abs(rebuilt.as_matrix() - g.as_matrix()))),
    )
    on_axis = screw.point + 1.7 * screw.direction
    slid = on_axis + screw.pitch * screw.magnitude * screw.direction
    ok &= _check(
        "a point of the axis slides by h theta along it",
        float(np.max(np.abs(g @ on_axis - slid))),
    )
    return ok


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m chasles",
        description="The worked screw-motion example, and the screw of a random rigid motion.",
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of the random motion (default 0)")
    parser.add_argument(
        "--l1", type=float, default=2.0, help="distance of the axis from the origin (default 2)"
    )
    parser.add_argument(
        "--theta", type=float, default=np.pi / 3, help="rotation angle in radians (default pi/3)"
    )
    args = parser.parse_args(argv)

    ok = worked_example(args.l1, args.theta)
    print()
    ok &= screw_of_random_motion(args.seed)
    print()
    print("All checks passed." if ok else "Some checks FAILED.")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
