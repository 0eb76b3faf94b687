"""Pictures of rigid motions with matplotlib: frames, trajectories and screws.

Needs matplotlib (``pip install chasles[plot]``); ``import chasles`` alone
never imports it. Every function draws into an existing 3D Axes (``ax``) or,
without one, into a new figure of ``matplotlib.pyplot``, and returns the
artists it made, so that a program can restyle them or read their data.

- ``frame(g)``: the frame of a pose g = g_wb as three axes from its origin,
  x red, y green, z blue (its rotation's columns), with an optional label.
- ``frames(gs)``: many frames at once, a trajectory, with the path of their
  origins.
- ``screw(xi)``: the screw of Chasles' theorem for a twist xi = (v, w): its
  axis as a line in space, its pitch as a label, and the helix that a point
  follows under exp([xi] theta) for theta in a range (computed with
  ``chasles.se3_exp`` and ``chasles.se3_act``).
- ``chain(arm, q)``: a serial arm (a ``chasles.Chain``) at joint positions q:
  its links as a stick figure through points on the joint axes (the feet of
  the common normals of successive axes, Denavit and Hartenberg's
  construction), each joint's axis, and the base and tool frames.

Call ``ax.set_aspect("equal", adjustable="datalim")`` after drawing so that
right angles look right.

Example:
    >>> import numpy as np
    >>> import chasles
    >>> from chasles import plot
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot(projection="3d")
    >>> g = chasles.SE3.from_screw([0.0, 2.0, 0.0], [0.0, 0.0, 1.0], 0.0, np.pi / 2)
    >>> axes = plot.frame(g, ax=ax, label="b")
    >>> np.round(axes.x.get_data_3d(), 12) + 0.0  # from the origin (2, 2, 0) along R e_x = e_y
    array([[2., 2.],
           [2., 3.],
           [0., 0.]])
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, NamedTuple, Union

import numpy as np

try:
    import matplotlib  # noqa: F401
    from mpl_toolkits.mplot3d import Axes3D  # also registers the "3d" projection
except ImportError as error:  # pragma: no cover - exercised in a subprocess by the tests
    raise ImportError(
        "chasles.plot needs matplotlib, which is an optional dependency: pip install chasles[plot]"
    ) from error

import chasles
from chasles import SE3, Chain, Screw, Twist

if TYPE_CHECKING:
    from matplotlib.text import Text
    from mpl_toolkits.mplot3d.art3d import Line3D

__all__ = [
    "AXIS_COLORS",
    "ChainArtists",
    "FrameArtists",
    "FramesArtists",
    "PARALLEL_SINE",
    "ScrewArtists",
    "chain",
    "frame",
    "frames",
    "screw",
]

#: Colors of a frame's x, y and z axes.
AXIS_COLORS = ("tab:red", "tab:green", "tab:blue")

PoseLike = Union[SE3, np.ndarray, Sequence[Sequence[float]]]


class FrameArtists(NamedTuple):
    """What ``frame`` drew: one line per axis, and the label (None without one)."""

    x: Line3D
    y: Line3D
    z: Line3D
    label: Text | None


class FramesArtists(NamedTuple):
    """What ``frames`` drew: the frames in order, and the path of their origins
    (None when ``path=False``)."""

    frames: list[FrameArtists]
    path: Line3D | None


class ScrewArtists(NamedTuple):
    """What ``screw`` drew, and the screw itself.

    ``axis``: the screw axis, a segment of the line through ``screw.point``
    along ``screw.direction`` (for a pure translation, pitch inf, the line of
    the translation through the moving point). ``helix``: the path of the point
    under exp([xi] theta). ``start`` and ``end``: markers at the path's ends.
    ``pitch``: the label on the axis.
    """

    axis: Line3D
    helix: Line3D
    start: Line3D
    end: Line3D
    pitch: Text
    screw: Screw


def _axes(ax: Axes3D | None) -> Axes3D:
    """ax, or the 3D axes of a new pyplot figure."""
    if ax is not None:
        if not isinstance(ax, Axes3D):
            raise TypeError(f"ax must be a 3D Axes (projection='3d'), not {type(ax).__name__}")
        return ax
    import matplotlib.pyplot as plt

    return plt.figure().add_subplot(projection="3d")


def _poses(gs: SE3 | Sequence[PoseLike] | np.ndarray) -> np.ndarray:
    """Homogeneous matrices of shape (N, 4, 4) from an SE3, a sequence of SE3
    or 4x4 matrices, or an array of shape (4, 4) or (N, 4, 4)."""
    if isinstance(gs, SE3):
        return gs.as_matrix()[None]
    if not isinstance(gs, np.ndarray):
        gs = [np.asarray(g.as_matrix() if isinstance(g, SE3) else g, dtype=float) for g in gs]
    m = np.asarray(gs, dtype=float)
    if m.ndim == 2:
        m = m[None]
    if m.ndim != 3 or m.shape[1:] != (4, 4):
        raise ValueError(f"poses must have shape (4, 4) or (N, 4, 4), not {np.shape(gs)}")
    if not np.all(np.isfinite(m)):
        raise ValueError("poses must be finite")
    return m


def _draw_frame(ax: Axes3D, g: np.ndarray, label: str | None, length: float, linewidth: float) -> FrameArtists:
    origin = g[:3, 3]
    lines = []
    for i, color in enumerate(AXIS_COLORS):
        tip = origin + length * g[:3, i]
        (line,) = ax.plot(*np.stack([origin, tip], axis=1), color=color, linewidth=linewidth)
        lines.append(line)
    text = ax.text(*origin, f" {label}", zorder=5) if label is not None else None
    return FrameArtists(lines[0], lines[1], lines[2], text)


def frame(
    g: PoseLike,
    *,
    ax: Axes3D | None = None,
    label: str | None = None,
    length: float = 1.0,
    linewidth: float = 2.0,
) -> FrameArtists:
    """Draw a coordinate frame: three axes from its origin, x red, y green, z blue.

    For g = g_wb (frame b in the world frame w), the origin is g's translation
    and the axes are the columns of its rotation, b's axes written in w.

    Args:
        g: SE3 or array_like of shape (4, 4), the pose of the frame.
        ax: the 3D Axes to draw into; a new pyplot figure when None.
        label: text written at the origin (none when None).
        length: the length of each axis line.
        linewidth: the width of the axis lines.

    Returns:
        FrameArtists: the x, y and z lines (``Line3D``: ``line.get_data_3d()``
        gives the origin and the tip) and the label's ``Text`` (or None).

    Raises:
        ValueError: g is not of shape (4, 4), or not finite.
        TypeError: ax is not a 3D Axes.

    Example:
        >>> from matplotlib.figure import Figure
        >>> ax = Figure().add_subplot(projection="3d")
        >>> f = frame(SE3(translation=[1.0, 2.0, 3.0]), ax=ax, label="tool", length=0.5)
        >>> f.z.get_data_3d()
        (array([1., 1.]), array([2., 2.]), array([3. , 3.5]))
        >>> f.label.get_text()
        ' tool'
    """
    m = _poses(g)
    if m.shape[0] != 1:
        raise ValueError(f"frame draws one pose; use frames for {m.shape[0]}")
    return _draw_frame(_axes(ax), m[0], label, length, linewidth)


def frames(
    gs: Sequence[PoseLike] | np.ndarray,
    *,
    ax: Axes3D | None = None,
    labels: Sequence[str | None] | None = None,
    length: float = 1.0,
    linewidth: float = 1.5,
    path: bool = True,
    path_color: str = "0.4",
) -> FramesArtists:
    """Draw many frames at once, a trajectory, and the path of their origins.

    Args:
        gs: a sequence of SE3 (or of 4x4 matrices), or an array of shape
            (N, 4, 4), such as the output of ``chasles.se3_exp`` or
            ``Chain.forward`` on a batch.
        ax: the 3D Axes to draw into; a new pyplot figure when None.
        labels: one label per frame (None entries for no label), or None.
        length: the length of each axis line.
        linewidth: the width of the axis lines.
        path: whether to draw the polyline through the origins, in order.
        path_color: its color.

    Returns:
        FramesArtists: the FrameArtists of each frame, in order, and the path
        (a ``Line3D``, or None).

    Raises:
        ValueError: a pose is not 4x4 or not finite, or labels has another
            length than gs.
        TypeError: ax is not a 3D Axes.

    Example:
        >>> from matplotlib.figure import Figure
        >>> ax = Figure().add_subplot(projection="3d")
        >>> xi = np.array([1.0, 0.0, 0.0, 0.0, 0.0, 1.0])
        >>> t = frames(chasles.se3_exp(np.linspace(0, 1, 5)[:, None] * xi), ax=ax)
        >>> len(t.frames), round(float(t.path.get_data_3d()[0][-1]), 6)  # x of exp([xi]): sin 1
        (5, 0.841471)
    """
    m = _poses(gs)
    if labels is not None and len(labels) != len(m):
        raise ValueError(f"{len(labels)} labels for {len(m)} poses")
    ax = _axes(ax)
    drawn = [_draw_frame(ax, g, None if labels is None else labels[i], length, linewidth) for i, g in enumerate(m)]
    line = None
    if path:
        (line,) = ax.plot(*m[:, :3, 3].T, color=path_color, linewidth=1.0, linestyle=":")
    return FramesArtists(drawn, line)


def _twist(xi: Twist | Screw | np.ndarray | Sequence[float]) -> Twist:
    if isinstance(xi, Twist):
        return xi
    if isinstance(xi, Screw):
        return Twist.from_screw(xi.point, xi.direction, xi.pitch, xi.magnitude)
    return Twist.from_vector(np.asarray(xi, dtype=float))


def _perpendicular(d: np.ndarray) -> np.ndarray:
    """A unit vector perpendicular to the unit vector d."""
    e = np.zeros(3)
    e[np.argmin(np.abs(d))] = 1.0
    u = np.cross(d, e)
    return u / np.linalg.norm(u)


def screw(
    xi: Twist | Screw | np.ndarray | Sequence[float],
    *,
    ax: Axes3D | None = None,
    theta: tuple[float, float] = (0.0, 1.0),
    point: np.ndarray | Sequence[float] | None = None,
    samples: int = 200,
    axis_margin: float = 0.5,
    color: str = "tab:purple",
    axis_color: str = "k",
) -> ScrewArtists:
    """Draw the screw of a twist: its axis, its pitch and the helix of a point.

    By Chasles' theorem exp([xi] theta) is a rotation by theta |w| about the
    screw axis together with a slide of pitch * theta |w| along it. The helix is
    the path p(theta) = exp([xi] theta) p, computed with ``chasles.se3_exp``
    and ``chasles.se3_act`` over ``samples`` values of theta. The axis is drawn
    over the helix's extent along it, plus ``axis_margin`` at each end.

    Args:
        xi: the twist: a Twist, a 6-vector (v, w) (linear part first) or a
            Screw (its twist, ``Twist.from_screw(*s)``).
        ax: the 3D Axes to draw into; a new pyplot figure when None.
        theta: the range of theta; the default (0, 1) goes from the identity to
            exp([xi]).
        point: the point p that moves; by default the point at distance 1 from
            the axis (from the origin, for a pure translation).
        samples: the number of thetas, at least 2.
        axis_margin: how far the axis line extends beyond the helix.
        color: the helix's color.
        axis_color: the axis line's color.

    Returns:
        ScrewArtists: the axis line, the helix, the start and end markers,
        the pitch label and the Screw of xi.

    Raises:
        ValueError: xi is the zero twist (it has no axis), or a shape or a
            theta range is not valid.
        TypeError: ax is not a 3D Axes.

    Example:
        >>> from matplotlib.figure import Figure
        >>> ax = Figure().add_subplot(projection="3d")
        >>> xi = Twist(v=[2.0, 0.0, 0.1], w=[0.0, 0.0, 1.0])  # axis through (0, 2, 0), pitch 0.1
        >>> s = screw(xi, ax=ax, theta=(0.0, 2 * np.pi), point=[0.0, 0.0, 0.0])
        >>> s.screw.point, s.screw.pitch
        (array([0., 2., 0.]), 0.1)
        >>> round(float(s.helix.get_data_3d()[2][-1]), 12)  # one turn slides by 2 pi h
        0.628318530718
        >>> s.pitch.get_text()
        'pitch h = 0.1'
    """
    twist = _twist(xi)
    s = twist.screw()
    if s.magnitude == 0.0:
        raise ValueError("the zero twist has no screw axis")
    if samples < 2:
        raise ValueError(f"samples must be at least 2, not {samples}")
    t0, t1 = (float(t) for t in theta)
    if not (np.isfinite(t0) and np.isfinite(t1)) or t0 == t1:
        raise ValueError(f"theta must be a range of two different finite numbers, not {theta}")
    finite_pitch = bool(np.isfinite(s.pitch))
    d = s.direction
    if point is None:
        p = s.point + _perpendicular(d) if finite_pitch else np.zeros(3)
    else:
        p = np.asarray(point, dtype=float)
        if p.shape != (3,) or not np.all(np.isfinite(p)):
            raise ValueError(f"point must be a finite 3-vector, not {point!r}")

    thetas = np.linspace(t0, t1, samples)
    motions = chasles.se3_exp(thetas[:, None] * twist.vector)  # (samples, 4, 4)
    helix = chasles.se3_act(motions, p)  # (samples, 3)

    through = s.point if finite_pitch else p
    along = (helix - through) @ d
    lo, hi = along.min() - axis_margin, along.max() + axis_margin
    ends = through + np.outer([lo, hi], d)

    ax = _axes(ax)
    (axis_line,) = ax.plot(*ends.T, color=axis_color, linewidth=1.2, linestyle="--")
    (helix_line,) = ax.plot(*helix.T, color=color, linewidth=1.5)
    (start,) = ax.plot(*helix[:1].T, color=color, marker="o", linestyle="none")
    (end,) = ax.plot(*helix[-1:].T, color=color, marker="s", linestyle="none")
    pitch_text = "pitch h = inf" if not finite_pitch else f"pitch h = {s.pitch:.3g}"
    label = ax.text(*ends[1], pitch_text, color=axis_color)
    return ScrewArtists(axis_line, helix_line, start, end, label, s)


#: Below this sine of the angle between two successive joint axes they count as
#: parallel in ``chain``: their common normal is then not unique (the one
#: through the previous point is taken), and above it the feet of the normal are
#: at most (distance between the axes) / 1e-6 away, which arms do not come near
#: (their parallel axes, from URDF angles rounded to 1e-7 or so, are below it).
PARALLEL_SINE = 1e-6


class ChainArtists(NamedTuple):
    """What ``chain`` drew, and the points it drew through.

    ``links``: the stick figure, one polyline through ``points`` in order.
    ``joints``: markers at the joints' origins, ``points[1:-1:2]``.
    ``joint_axes``: one line per joint along its current axis, centered on its
    origin. ``base`` and ``tool``: the two frames (``frame``'s artists).
    ``points``: shape (2 n + 2, 3), the base origin; for each joint i its
    origin (where the previous link meets its axis) and the point where the
    link it moves leaves its axis; the tool origin. ``directions``: shape (n, 3),
    the unit directions of the joint axes at q. ``ax``: the Axes drawn into.
    """

    links: Line3D
    joints: Line3D
    joint_axes: list[Line3D]
    base: FrameArtists
    tool: FrameArtists
    points: np.ndarray
    directions: np.ndarray
    ax: Axes3D


def _project(point: np.ndarray, through: np.ndarray, d: np.ndarray) -> np.ndarray:
    """The point of the line through ``through`` along unit d nearest to point."""
    return through + ((point - through) @ d) * d


def _common_normal(a: np.ndarray, da: np.ndarray, b: np.ndarray, db: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The feet, on line A (through a, unit da) and on line B (through b, unit db),
    of their common normal; for parallel lines the normal through a."""
    c = float(da @ db)
    if np.linalg.norm(np.cross(da, db)) < PARALLEL_SINE:
        return a, _project(a, b, db)
    # Minimize |a + s da - b - t db|^2: s - c t = -da.r, c s - t = -db.r, r = a - b.
    r = a - b
    s = (c * (db @ r) - da @ r) / (1.0 - c * c)
    t = db @ r + c * s
    return a + s * da, b + t * db


def _home_geometry(arm: Chain) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """At home, in the world frame: each joint's origin and exit point on its
    axis, and the axis' unit direction; shapes (n, 3) each (see ``chain``)."""
    screws = arm.space_screws
    n = len(screws)
    origins, exits, directions = np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3))
    for i, (v, w) in enumerate(zip(screws[:, :3], screws[:, 3:])):
        previous = arm.base.translation if i == 0 else origins[i - 1]
        nw, nv = np.linalg.norm(w), np.linalg.norm(v)
        if nw > 0.0:  # a rotation about the screw axis through w x v / |w|^2 along w
            directions[i], through = w / nw, np.cross(w, v) / (nw * nw)
        elif nv > 0.0:  # a translation along v: the slide through the previous point
            directions[i], through = v / nv, previous
        else:
            raise ValueError(f"joint {i} has the zero screw: it has no axis to draw")
        if i == 0:
            origins[0] = _project(previous, through, directions[0])
        else:
            exits[i - 1], origins[i] = _common_normal(origins[i - 1], directions[i - 1], through, directions[i])
    if n:
        exits[n - 1] = _project(arm.home.translation, origins[n - 1], directions[n - 1])
    return origins, exits, directions


def chain(
    arm: Chain,
    q: np.ndarray | Sequence[float],
    *,
    ax: Axes3D | None = None,
    length: float | None = None,
    color: str = "0.3",
    linewidth: float = 3.0,
    axis_color: str = "tab:orange",
    labels: bool = True,
) -> ChainArtists:
    """Draw a serial arm at joint positions q: its links, its joint axes, its base and tool frames.

    The links are drawn as a stick figure through points on the joint axes,
    chosen at home by Denavit and Hartenberg's construction and then carried
    by the joints:

    - joint i's axis at home is the screw axis of its space screw S_i (a
      revolute joint: the line through w x v / |w|^2 along w; a prismatic
      joint: the line along v through joint i-1's origin, or the base origin);
    - joint 1's origin is the point of its axis nearest to the base origin;
      joint i+1's origin and joint i's exit point are the feet, on the two
      axes, of the common normal of axes i and i+1 (for parallel axes, sine of
      their angle below ``PARALLEL_SINE``, the normal through joint i's
      origin); joint n's exit point is the point of its axis nearest to the tool
      origin;
    - at q, joint i's origin moves with the links before it,
      ``exp([S_1] q_1) ... exp([S_(i-1)] q_(i-1))``, and its exit point with
      joint i too, ``exp([S_1] q_1) ... exp([S_i] q_i)``: both stay on joint
      i's current axis, the segment between them slides with a prismatic
      joint, and each segment keeps its length under revolute joints.

    The polyline goes base origin, then for each joint its origin and its exit
    point, then the tool origin (``chain.forward(q)``); the segments along an
    axis are Denavit-Hartenberg's offsets, those between axes its link lengths.
    Each joint's axis is a segment of ``length`` along its current direction
    (the w, or v for a prismatic joint, of ``chain.jacobian_space(q)``'s
    column), centered on its origin.

    Args:
        arm: the chain (a ``chasles.Chain``, e.g. from ``Chain.from_urdf``).
        q: array_like of shape (n,), the joint positions (radians or lengths).
        ax: the 3D Axes to draw into; a new pyplot figure when None.
        length: the length of the joint axis lines and of the frames' axes;
            None: a tenth of the stick figure's length at home (1 if that is 0).
        color: the links' color.
        linewidth: the links' width.
        axis_color: the joint axes' color.
        labels: whether to write "base" and "tool" at those frames.

    Returns:
        ChainArtists: the links' polyline, the joint markers, the joint axis
        lines, the base and tool frames' artists, the points drawn through,
        the axis directions at q and the Axes.

    Raises:
        TypeError: arm is not a Chain, q is not real numbers, or ax is not a
            3D Axes.
        ValueError: q is not of shape (n,) or not finite, length is not
            positive, or a joint has the zero screw.

    Example:
        >>> from matplotlib.figure import Figure
        >>> ax = Figure().add_subplot(projection="3d")
        >>> screws = [Chain.revolute_screw([0, 0, 0], [0, 0, 1]),
        ...           Chain.revolute_screw([1, 0, 0], [0, 0, 1])]
        >>> arm = Chain(screws, SE3(translation=[2.0, 0.0, 0.0]))
        >>> drawn = chain(arm, [np.pi / 2, 0.0], ax=ax)
        >>> np.round(drawn.points, 12) + 0.0  # base, joint 1 (origin, exit), joint 2, tool
        array([[0., 0., 0.],
               [0., 0., 0.],
               [0., 0., 0.],
               [0., 1., 0.],
               [0., 1., 0.],
               [0., 2., 0.]])
        >>> np.round(drawn.tool.x.get_data_3d()[1], 12) + 0.0  # the tool's x axis along y
        array([2. , 2.2])
    """
    if not isinstance(arm, Chain):
        raise TypeError(f"arm must be a chasles.Chain, not {type(arm).__name__}")
    n = arm.n_joints
    try:
        qs = np.asarray(q, dtype=float)
    except (TypeError, ValueError) as error:
        raise TypeError(f"q must be real numbers of shape ({n},), not {q!r}") from error
    if qs.shape != (n,):
        raise ValueError(f"q must have shape ({n},) for a chain of {n} joints, not {qs.shape}")
    if not np.all(np.isfinite(qs)):
        raise ValueError(f"q must be finite, not {qs}")

    origins, exits, directions = _home_geometry(arm)
    # prefix[k] = exp([S_1] q_1) ... exp([S_k] q_k), k = 0 .. n.
    prefix = np.empty((n + 1, 4, 4))
    prefix[0] = np.eye(4)
    for k, step in enumerate(chasles.se3_exp(arm.space_screws * qs[:, None])):
        prefix[k + 1] = prefix[k] @ step
    tool = np.asarray(arm.forward(qs))
    base = arm.base.as_matrix()

    points = np.empty((2 * n + 2, 3))
    points[0], points[-1] = base[:3, 3], tool[:3, 3]
    if n:
        points[1:-1:2] = chasles.se3_act(prefix[:-1], origins)
        points[2:-1:2] = chasles.se3_act(prefix[1:], exits)
    moved = np.einsum("kij,kj->ki", prefix[:-1, :3, :3], directions)

    if length is None:
        at_home = np.concatenate(
            [base[None, :3, 3], np.stack([origins, exits], axis=1).reshape(-1, 3), arm.home.translation[None]]
        )
        span = float(np.sum(np.linalg.norm(np.diff(at_home, axis=0), axis=1)))
        length = 0.1 * span if span > 0.0 else 1.0
    elif not (np.isfinite(length) and length > 0.0):
        raise ValueError(f"length must be a positive number, not {length!r}")

    ax = _axes(ax)
    (links,) = ax.plot(*points.T, color=color, linewidth=linewidth, solid_capstyle="round")
    (joints,) = ax.plot(*points[1:-1:2].T, color="k", marker="o", markersize=5, linestyle="none")
    axes = []
    for p, d in zip(points[1:-1:2], moved):
        ends = np.stack([p - 0.5 * length * d, p + 0.5 * length * d])
        (line,) = ax.plot(*ends.T, color=axis_color, linewidth=2.0)
        axes.append(line)
    base_frame = _draw_frame(ax, base, "base" if labels else None, length, 2.0)
    tool_frame = _draw_frame(ax, tool, "tool" if labels else None, length, 2.0)
    return ChainArtists(links, joints, axes, base_frame, tool_frame, points, moved, ax)
