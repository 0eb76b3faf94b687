"""The chasles demo: ``python -m chasles [--seed N] [--l1 L] [--theta T] [--png PATH | --no-png]``.

1. The worked example of the documentation (Murray, Li and Sastry, ch. 2):
   the rotation by theta about the z axis through q = (0, l1, 0), pitch 0.
   Prints the twist xi = (v, w) = (l1, 0, 0, 0, 0, 1), its matrix [xi] and
   g(theta) = exp([xi] theta), and checks g against the closed form
   [[cos, -sin, 0, l1 sin], [sin, cos, 0, l1 (1 - cos)], [0, 0, 1, 0], [0, 0, 0, 1]]
   and that the points of the axis stay put.
2. Chasles' theorem on a random rigid motion (fixed seed): g = exp([xi]) with
   xi = log(g); the screw of xi (axis point, direction, pitch, magnitude);
   and SE3.from_screw of that screw gives g back.
3. A picture of both, written to a PNG file (``--png``, default
   chasles_demo.png; needs matplotlib, ``pip install chasles[plot]``):
   the body frame at several theta about the screw axis through (0, l1, 0)
   and the circle its origin follows; and the random motion as a screw
   motion, its axis, its pitch and the helix of the origin from the identity
   to g. Without matplotlib the demo prints its numbers and says how to get
   the picture.

The exit status is 0 when every check passes, 1 otherwise.
"""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from chasles import SE3, SO3, Twist, se3_exp

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from chasles.plot import FramesArtists, ScrewArtists

# The file the picture goes to when --png is not given.
DEFAULT_PNG = "chasles_demo.png"

# Agreement asked of the checks: a few hundred ulps of the entries' scale.
TOLERANCE = 1e-12


def _fmt(a: np.ndarray) -> str:
    """An array printed with 6 decimals, -0 shown as 0, indented under a label."""
    a = np.asarray(a, dtype=float) + 0.0
    text = np.array2string(a, precision=6, suppress_small=True, floatmode="fixed", sign=" ")
    return text.replace("\n", "\n    ")


def _check(label: str, error: float, tol: float = TOLERANCE) -> bool:
    ok = bool(error <= tol)
    print(f"  {'ok' if ok else 'FAILED'}: {label} (max difference {error:.1e}, tolerance {tol:.0e})")
    return ok


def worked_example(l1: float, theta: float) -> bool:
    """Part 1: the seed's screw motion, printed and checked. True if it agrees."""
    print("1. Worked example: rotation by theta about the z axis through q = (0, l1, 0), pitch h = 0")
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

    ok = _check("exp(log(g)) equals g", float(np.max(np.abs(SE3.exp(xi).as_matrix() - g.as_matrix()))))
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


class Picture(NamedTuple):
    """The demo's figure and what was drawn in it (the artists of chasles.plot)."""

    figure: Figure
    worked_frames: FramesArtists
    worked_screw: ScrewArtists
    random_frames: FramesArtists
    random_screw: ScrewArtists


# The angles of the worked example's frames, and their labels.
_ANGLES = np.arange(7) * (np.pi / 4)
_ANGLE_LABELS = ("0", "π/4", "π/2", "3π/4", "π", "5π/4", "3π/2")


def picture(l1: float, seed: int) -> Picture:
    """Draws the worked example and the screw of the random motion (needs matplotlib).

    Left: the body frame g(theta) = exp([xi] theta) at theta = 0, pi/4, ...,
    3 pi/2 for xi = (l1, 0, 0, 0, 0, 1), the screw axis through (0, l1, 0)
    along z (pitch 0) and the circle the body origin follows. Right: the
    random motion g of ``random_motion(seed)`` as the screw motion
    exp([xi] t), t in [0, 1], xi = log(g): frames along it, its axis, its
    pitch and the helix of the origin. Uses matplotlib's Figure directly, not
    pyplot, so no display or backend is involved.
    """
    from matplotlib.figure import Figure

    from chasles import plot

    fig = Figure(figsize=(11.0, 5.4), layout="constrained")
    left = fig.add_subplot(1, 2, 1, projection="3d")
    xi = Twist(v=[l1, 0.0, 0.0], w=[0.0, 0.0, 1.0])
    scale = max(abs(l1), 1.0)
    worked_frames = plot.frames(
        se3_exp(_ANGLES[:, None] * xi.vector),
        ax=left,
        labels=[f"θ = {a}" for a in _ANGLE_LABELS],
        length=0.4 * scale,
        path=False,
    )
    worked_screw = plot.screw(xi, ax=left, theta=(0.0, 2.0 * np.pi), point=[0.0, 0.0, 0.0], axis_margin=1.2 * scale)
    left.plot([0.0], [l1], [0.0], color="k", marker="o", linestyle="none")
    left.text(0.0, l1, 0.0, "  q = (0, l1, 0)")
    left.set_title(
        f"Rotation about the z axis through q = (0, l1, 0), l1 = {l1:g}:\n"
        "g(θ) = exp([ξ] θ), ξ = (l1, 0, 0, 0, 0, 1), and the path of the origin",
        fontsize=10,
    )

    right = fig.add_subplot(1, 2, 2, projection="3d")
    g = random_motion(seed)
    log_g = g.log()
    random_frames = plot.frames(
        se3_exp(np.linspace(0.0, 1.0, 6)[:, None] * log_g),
        ax=right,
        labels=["identity", None, None, None, None, "g"],
        length=0.6,
        path=False,
    )
    random_screw = plot.screw(log_g, ax=right, point=[0.0, 0.0, 0.0], axis_margin=1.0)
    s = random_screw.screw
    right.set_title(
        f"Chasles: a random motion g (seed {seed}) is a screw motion,\n"
        f"θ = {s.magnitude:.3f} rad about the axis, slide h θ = {s.pitch * s.magnitude:.3f}",
        fontsize=10,
    )
    for ax in (left, right):
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
        ax.set_aspect("equal", adjustable="datalim")
    return Picture(fig, worked_frames, worked_screw, random_frames, random_screw)


def write_picture(path: str, l1: float, seed: int) -> bool:
    """Part 3: the picture, written to path. False if matplotlib is missing."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print(
            "3. Picture: not drawn, matplotlib is missing. Install it with "
            "`pip install chasles[plot]` (or `pip install matplotlib`) and run again."
        )
        return False
    picture(l1, seed).figure.savefig(path, dpi=80)
    print(f"3. Picture of both written to {path}")
    return True


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m chasles",
        description="The worked screw-motion example, and the screw of a random rigid motion.",
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of the random motion (default 0)")
    parser.add_argument("--l1", type=float, default=2.0, help="distance of the axis from the origin (default 2)")
    parser.add_argument("--theta", type=float, default=np.pi / 3, help="rotation angle in radians (default pi/3)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument(
        "--png",
        default=DEFAULT_PNG,
        metavar="PATH",
        help=f"where to write the picture (default {DEFAULT_PNG}; needs matplotlib)",
    )
    where.add_argument("--no-png", action="store_true", help="do not draw the picture")
    args = parser.parse_args(argv)

    ok = worked_example(args.l1, args.theta)
    print()
    ok &= screw_of_random_motion(args.seed)
    print()
    if not args.no_png:
        write_picture(args.png, args.l1, args.seed)
        print()
    print("All checks passed." if ok else "Some checks FAILED.")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
