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
from chasles import SE3, Screw, Twist

if TYPE_CHECKING:
    from matplotlib.text import Text
    from mpl_toolkits.mplot3d.art3d import Line3D

__all__ = [
    "AXIS_COLORS",
    "FrameArtists",
    "FramesArtists",
    "ScrewArtists",
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


def _draw_frame(
    ax: Axes3D, g: np.ndarray, label: str | None, length: float, linewidth: float
) -> FrameArtists:
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
    drawn = [
        _draw_frame(ax, g, None if labels is None else labels[i], length, linewidth)
        for i, g in enumerate(m)
    ]
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
