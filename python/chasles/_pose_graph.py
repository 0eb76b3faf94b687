"""Pose graphs on SE(3) and SE(2): the g2o text format, the chi2 of a graph,
a sparse Levenberg-Marquardt solve with the analytic Jacobians, and the
generated benchmark graphs (a sphere of poses, a grid world).

An edge (i, j) with measurement Z and information Omega has the residual

    e = log(Z^-1 X_i^-1 X_j)

in the order of the group's tangent ((v, w) for SE3, (vx, vy, w) for SE2)
and contributes e^T Omega e to chi2 (twice GTSAM's error of its
BetweenFactor). The information matrix of a g2o file is taken over that
residual as it stands, in g2o's order (x, y, z, qx, qy, qz) = (v, w), as
GTSAM's readG2o takes it.

The residuals and their Jacobians are the array functions of every edge
at once (``se3_compose``, ``se3_log``, ``se3_between_jacobians``,
``se3_rminus_jacobians``: the C++ kernels); the solve assembles them into a
scipy.sparse matrix and factors the normal equations with scipy's sparse LU
(scipy is needed for ``solve``: ``pip install chasles[estimation]``).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, NamedTuple, Union

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core
from chasles._arrays import se3_from_quat, so3_as_quat, so3_from_euler
from chasles._least_squares import check_iterations, import_scipy, information_factor, levenberg_marquardt
from chasles._random import _asarray
from chasles._value import Value

PathLike = Union[str, Path]

# What each group's g2o lines hold: the tag of a vertex and of an edge, the
# numbers of a pose, the matrix size and the tangent dimension.
_FORMATS = {
    "se3": ("VERTEX_SE3:QUAT", "EDGE_SE3:QUAT", 7, 4, 6),
    "se2": ("VERTEX_SE2", "EDGE_SE2", 3, 3, 3),
}


def _poses_from_numbers(prefix: str, x: np.ndarray) -> np.ndarray:
    """(N, k, k) matrices from g2o's numbers: (x, y, z, qx, qy, qz, qw) or (x, y, theta)."""
    if prefix == "se3":
        return se3_from_quat(x[:, 3:7], x[:, :3])
    out = np.zeros((x.shape[0], 3, 3))
    out[:, :2, :2] = _core.so2_exp(x[:, 2])
    out[:, :2, 2] = x[:, :2]
    out[:, 2, 2] = 1.0
    return out


def _numbers_from_poses(prefix: str, g: np.ndarray) -> np.ndarray:
    if prefix == "se3":
        return np.concatenate([g[:, :3, 3], so3_as_quat(g[:, :3, :3])], axis=1)
    return np.concatenate([g[:, :2, 2], _core.so2_log(g[:, :2, :2])[:, None]], axis=1)


def _fn(group: str, name: str) -> Any:
    """The array function <group>_<name>: se3_compose, ..."""
    return getattr(_core, f"{group}_{name}")


def _residuals(group: str, X: np.ndarray, i: np.ndarray, j: np.ndarray, Zinv: np.ndarray) -> tuple:
    """(X_i^-1 X_j, e = log(Z^-1 X_i^-1 X_j)) of every edge (i, j), e of shape (E, d)."""
    relative = _fn(group, "compose")(_fn(group, "inverse")(X[i]), X[j])
    e = _fn(group, "log")(_fn(group, "compose")(Zinv, relative))
    return relative, e.reshape(i.shape[0], _FORMATS[group][4])


def _graph(self: Any, member: str) -> PoseGraph:
    """self, when it is a PoseGraph (TypeError otherwise, as a method of a bound class)."""
    if not isinstance(self, PoseGraph):
        raise TypeError(f"PoseGraph.{member}: expected a PoseGraph as self, got {type(self).__name__}")
    return self


class PoseGraph(Value):
    """A pose graph: poses (vertices, by id) and relative measurements (edges).

    Attributes (read-only numpy arrays):
        group: "se3" or "se2".
        ids: (V,) int64, the vertices' ids (as in the g2o file).
        poses: (V, n, n) float64, the poses' matrices (n = 4 for SE3, 3 for SE2).
        edges: (E, 2) int64, each edge's two vertices as indices into poses
            (not ids): the measurement is of X_i^-1 X_j.
        measurements: (E, n, n) float64, the measured Z_ij.
        information: (E, d, d) float64, the information matrices (d = 6 or 3),
            over the residual log(Z^-1 X_i^-1 X_j) in the tangent's order.

    A graph is an immutable value: it pickles and copies as its
    constructor's arguments. ``read_g2o`` reads one, ``pose_graph_sphere``
    and ``pose_graph_grid`` make the benchmark graphs.
    """

    _state = ("group", "ids", "poses", "edges", "measurements", "information")

    def __init__(
        self,
        group: str,
        ids: ArrayLike,
        poses: ArrayLike,
        edges: ArrayLike,
        measurements: ArrayLike,
        information: ArrayLike,
    ) -> None:
        """A graph from its arrays (see the class); they are copied.

        Raises:
            ValueError: group is not "se3" or "se2"; an array has the wrong
                shape or numbers that are not finite; an edge's index is not
                one of a pose; an information matrix is not symmetric
                positive definite.
        """
        if "information" in self.__dict__:
            raise TypeError("PoseGraph.__init__: the graph is already initialized (graphs are immutable)")
        if not isinstance(group, str) or group not in _FORMATS:
            raise ValueError(f"PoseGraph(group): expected 'se3' or 'se2', got {group!r}")
        _, _, _, n, d = _FORMATS[group]
        ids_, edges_ = _asarray(ids, "PoseGraph(ids)"), _asarray(edges, "PoseGraph(edges)")
        for name, a in (("ids", ids_), ("edges", edges_)):
            if a.dtype.kind not in "iu" and a.size:
                raise ValueError(f"PoseGraph({name}): expected integers, got dtype {a.dtype}")
        arrays = {
            "ids": ids_.astype(np.int64),
            "poses": _asarray(poses, "PoseGraph(poses)").astype(np.float64),
            "edges": edges_.astype(np.int64),
            "measurements": _asarray(measurements, "PoseGraph(measurements)").astype(np.float64),
            "information": _asarray(information, "PoseGraph(information)").astype(np.float64),
        }
        v = arrays["ids"].shape[0] if arrays["ids"].ndim else -1
        e = arrays["edges"].shape[0] if arrays["edges"].ndim else -1
        for name, shape in (
            ("ids", (v,)),
            ("poses", (v, n, n)),
            ("edges", (e, 2)),
            ("measurements", (e, n, n)),
            ("information", (e, d, d)),
        ):
            if arrays[name].shape != shape:
                raise ValueError(f"PoseGraph({name}): expected shape {shape}, got {arrays[name].shape}")
            if not np.all(np.isfinite(arrays[name])):
                raise ValueError(f"PoseGraph({name}): expected finite numbers")
        if e and (arrays["edges"].min() < 0 or arrays["edges"].max() >= v):
            raise ValueError(f"PoseGraph(edges): expected indices into the {v} poses")
        information_factor(arrays["information"], "PoseGraph(information)")
        self.group = group
        for name, a in arrays.items():
            a.flags.writeable = False
            setattr(self, name, a)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle support (every protocol) and copy: the constructor's arguments."""
        _graph(self, "__reduce__")
        return (PoseGraph, (self.group, self.ids, self.poses, self.edges, self.measurements, self.information))

    def __repr__(self) -> str:
        _graph(self, "__repr__")
        if "information" not in self.__dict__:
            return "<uninitialized PoseGraph>"
        return f"PoseGraph({self.group!r}, {self.ids.shape[0]} poses, {self.edges.shape[0]} edges)"

    def with_poses(self, poses: ArrayLike) -> PoseGraph:
        """The same graph with other poses (V, n, n)."""
        _graph(self, "with_poses")
        return PoseGraph(self.group, self.ids, poses, self.edges, self.measurements, self.information)

    def residuals(self) -> np.ndarray:
        """e_k = log(Z_k^-1 X_i^-1 X_j) of every edge, (E, d)."""
        _graph(self, "residuals")
        Zinv = _fn(self.group, "inverse")(self.measurements)
        return _residuals(self.group, self.poses, self.edges[:, 0], self.edges[:, 1], Zinv)[1]

    def chi2(self) -> float:
        """sum_k e_k^T Omega_k e_k (twice GTSAM's graph error)."""
        _graph(self, "chi2")
        e = self.residuals()
        return float(np.einsum("ki,kij,kj->", e, self.information, e))

    def solve(self, max_iterations: int = 100, tolerance: float = 1e-12) -> PoseGraphSolution:
        """Levenberg-Marquardt on the poses, the first one held fixed.

        Each iteration linearizes every residual at once (the Jacobians of
        e = log(Z^-1 X_i^-1 X_j) = rminus(X_i^-1 X_j, Z): ``rminus_jacobians``
        times ``between_jacobians`` of (X_i, X_j), right-local), whitens them by the
        Cholesky factor of Omega, and solves the damped normal equations
        (J^T J + lambda diag(J^T J)) dx = -J^T e with scipy's sparse LU (in
        symmetric mode, minimum degree ordering); a
        step that lowers chi2 is taken (X_i <- X_i exp(dx_i)) and lambda
        shrinks, else lambda grows. It stops when a step lowers chi2 by less
        than tolerance relative, or after max_iterations.

        A pose that no chain of edges ties to the first stays where it is
        (the damping keeps the equations regular).

        Raises:
            ValueError: the normal equations are singular all the same.

        Returns:
            PoseGraphSolution: the solved graph, the initial and final chi2,
            the iterations and whether it converged.
        """
        _graph(self, "solve")
        max_iterations, tolerance = check_iterations(max_iterations, tolerance, "PoseGraph.solve")
        import_scipy("PoseGraph.solve")
        import scipy.sparse as sparse

        _, _, _, _, d = _FORMATS[self.group]
        V, E = self.poses.shape[0], self.edges.shape[0]
        L = np.linalg.cholesky(self.information)  # Omega = L L^T: whitened e is L^T e
        Lt = np.swapaxes(L, 1, 2)
        Zinv = _fn(self.group, "inverse")(self.measurements)
        i, j = self.edges[:, 0], self.edges[:, 1]
        # The sparsity pattern of J: edge k's rows against the columns of poses i and j
        # (the first pose fixed: its columns are dropped).
        rows = np.broadcast_to(np.arange(E * d).reshape(E, d, 1), (E, d, d))
        cols_i = np.broadcast_to((i - 1)[:, None, None] * d + np.arange(d)[None, None, :], (E, d, d))
        cols_j = np.broadcast_to((j - 1)[:, None, None] * d + np.arange(d)[None, None, :], (E, d, d))
        keep_i, keep_j = i > 0, j > 0
        n = (V - 1) * d

        def linearize(X: np.ndarray) -> tuple[np.ndarray, Any]:
            relative, e = _residuals(self.group, X, i, j, Zinv)
            dlog, _ = _fn(self.group, "rminus_jacobians")(relative, self.measurements)
            Ja, Jb = _fn(self.group, "between_jacobians")(X[i], X[j])
            Ji, Jj = Lt @ dlog @ Ja, Lt @ dlog @ Jb
            J = sparse.coo_matrix(
                (
                    np.concatenate([Ji[keep_i].ravel(), Jj[keep_j].ravel()]),
                    (
                        np.concatenate([rows[keep_i].ravel(), rows[keep_j].ravel()]),
                        np.concatenate([cols_i[keep_i].ravel(), cols_j[keep_j].ravel()]),
                    ),
                ),
                shape=(E * d, n),
            ).tocsr()
            return (Lt @ e[..., None])[..., 0].ravel(), J

        def cost(X: np.ndarray) -> float:
            e = _residuals(self.group, X, i, j, Zinv)[1]
            return float(np.einsum("ki,kij,kj->", e, self.information, e))

        def step(X: np.ndarray, dx: np.ndarray) -> np.ndarray:
            moved = X.copy()  # the first pose stays
            delta = dx.reshape(V - 1, d)
            moved[1:] = _fn(self.group, "compose")(X[1:], _fn(self.group, "exp")(delta[:, 0] if d == 1 else delta))
            return moved

        if V < 2 or E == 0:
            chi2 = cost(self.poses)
            return PoseGraphSolution(self.with_poses(self.poses), chi2, chi2, 0, True)
        X, initial, chi2, iterations, converged = levenberg_marquardt(
            self.poses.copy(),
            cost,
            linearize,
            step,
            max_iterations=max_iterations,
            tolerance=tolerance,
            singular="PoseGraph.solve: the normal equations are singular: is every pose tied to the first by edges?",
        )
        return PoseGraphSolution(self.with_poses(X), initial, chi2, iterations, converged)


class PoseGraphSolution(NamedTuple):
    """What ``PoseGraph.solve`` returns."""

    graph: PoseGraph
    """The graph with the solved poses."""
    initial_chi2: float
    final_chi2: float
    iterations: int
    converged: bool


def read_g2o(path: PathLike) -> PoseGraph:
    """A pose graph from a g2o file: VERTEX_SE3:QUAT and EDGE_SE3:QUAT lines,
    or VERTEX_SE2 and EDGE_SE2 lines.

    Args:
        path: the file's path (str or os.PathLike).

    Vertices: ``VERTEX_SE3:QUAT id x y z qx qy qz qw`` or ``VERTEX_SE2 id x
    y theta``; edges: ``EDGE_SE3:QUAT i j x y z qx qy qz qw`` and the 21
    entries of the upper triangle of the information matrix, row by row
    (``EDGE_SE2 i j dx dy dtheta`` and 6). Blank lines, ``#`` comments and
    ``FIX`` lines are skipped (the solve holds the first vertex fixed).

    Raises:
        ValueError: a line that is not one of these (unknown tag, wrong count
            of numbers, not a number or not finite, an id beyond 64 bits, a
            quaternion of zero norm, an edge to an unknown vertex, a repeated
            vertex, both groups in one file), with its line number.
    """
    if not isinstance(path, (str, Path)):
        raise TypeError(f"read_g2o(path): expected a str or a pathlib.Path, got {type(path).__name__}")
    vertices: dict[int, list[float]] = {}
    edges: list[tuple[int, int, list[float], int]] = []
    group = None
    for number, line in enumerate(Path(path).read_text().splitlines(), start=1):
        words = line.split()
        if not words or words[0].startswith("#") or words[0] == "FIX":
            continue
        tag = words[0]
        kind = next((p for p, f in _FORMATS.items() if tag in f[:2]), None)
        if kind is None:
            raise ValueError(f"read_g2o: line {number}: unknown tag {tag!r} (expected VERTEX_SE3:QUAT, ...)")
        if group is not None and kind != group:
            raise ValueError(f"read_g2o: line {number}: a {kind} line in a {group} graph")
        group = kind
        vertex_tag, _, k, _, d = _FORMATS[kind]
        want = 1 + 1 + k if tag == vertex_tag else 1 + 2 + k + d * (d + 1) // 2
        if len(words) != want:
            raise ValueError(f"read_g2o: line {number}: {tag} expects {want - 1} values, got {len(words) - 1}")
        try:
            ints = [int(w) for w in words[1 : 2 if tag == vertex_tag else 3]]
            values = [float(w) for w in words[len(ints) + 1 :]]
        except ValueError as e:
            raise ValueError(f"read_g2o: line {number}: {e}") from None
        if not all(math.isfinite(x) for x in values):
            raise ValueError(f"read_g2o: line {number}: expected finite numbers")
        if not all(-(2**63) <= v < 2**63 for v in ints):
            raise ValueError(f"read_g2o: line {number}: a vertex id beyond 64 bits")
        if kind == "se3" and not sum(q * q for q in values[3:7]) > 0:
            raise ValueError(f"read_g2o: line {number}: a quaternion of zero norm")
        if tag == vertex_tag:
            if ints[0] in vertices:
                raise ValueError(f"read_g2o: line {number}: vertex {ints[0]} is defined twice")
            vertices[ints[0]] = values
        else:
            edges.append((ints[0], ints[1], values, number))
    if group is None:
        raise ValueError(f"read_g2o: {path}: no vertex or edge")
    _, _, k, _, d = _FORMATS[group]
    ids = np.array(list(vertices), dtype=np.int64)
    index = {v: n for n, v in enumerate(vertices)}
    pairs = []
    for a, b, _, number in edges:
        if a not in index or b not in index:
            raise ValueError(f"read_g2o: line {number}: an edge to vertex {a if a not in index else b}, not defined")
        pairs.append((index[a], index[b]))
    numbers = np.array([e[2] for e in edges]).reshape(len(edges), -1)
    upper = np.triu_indices(d)
    info = np.zeros((len(edges), d, d))
    info[:, upper[0], upper[1]] = numbers[:, k:]
    info[:, upper[1], upper[0]] = numbers[:, k:]
    poses = _poses_from_numbers(group, np.array(list(vertices.values())).reshape(len(vertices), k))
    measurements = _poses_from_numbers(group, numbers[:, :k])
    return PoseGraph(group, ids, poses, np.array(pairs).reshape(-1, 2), measurements, info)


def write_g2o(path: PathLike, graph: PoseGraph) -> None:
    """Writes the graph in the g2o text format (as read_g2o reads it), every
    number to 17 significant digits (read back exactly)."""
    if not isinstance(path, (str, Path)):
        raise TypeError(f"write_g2o(path): expected a str or a pathlib.Path, got {type(path).__name__}")
    if not isinstance(graph, PoseGraph) or "information" not in graph.__dict__:
        raise TypeError(f"write_g2o(graph): expected a PoseGraph, got {type(graph).__name__}")
    vertex_tag, edge_tag, _, _, d = _FORMATS[graph.group]
    upper = np.triu_indices(d)
    lines = []
    for v, x in zip(graph.ids, _numbers_from_poses(graph.group, graph.poses)):
        lines.append(" ".join([vertex_tag, str(int(v)), *(f"{c:.17g}" for c in x)]))
    z = _numbers_from_poses(graph.group, graph.measurements)
    for (a, b), x, info in zip(graph.edges, z, graph.information):
        values = [*x, *info[upper]]
        lines.append(
            " ".join([edge_tag, str(int(graph.ids[a])), str(int(graph.ids[b])), *(f"{c:.17g}" for c in values)])
        )
    Path(path).write_text("\n".join(lines) + "\n")


def _sizes(name: str, **sizes: Any) -> None:
    for key, value in sizes.items():
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            raise TypeError(f"{name}({key}): expected an int, got {type(value).__name__}")
        if not 2 <= value <= 100_000:
            raise ValueError(f"{name}({key}): expected 2 <= {key} <= 100000, got {value}")


def _sigma(name: str, sigma: ArrayLike) -> tuple[float, float]:
    s = _asarray(sigma, f"{name}(sigma)").astype(np.float64)
    if s.shape != (2,) or not np.all(np.isfinite(s)) or not np.all(s > 0):
        raise ValueError(f"{name}(sigma): expected two finite standard deviations > 0, got {s!r}")
    return float(s[0]), float(s[1])


def pose_graph_sphere(
    rings: int = 50, per_ring: int = 50, *, radius: float = 50.0, sigma: ArrayLike = (0.1, 0.02), seed: int = 0
) -> tuple[PoseGraph, np.ndarray]:
    """A sphere of poses, in the spirit of g2o's sphere2500: (graph, truth).

    rings x per_ring poses on a sphere of the radius, ring after ring, each
    facing along its ring; an odometry edge from each pose to the next and a
    loop closure from each pose to the one below it on the previous ring
    (rings * per_ring - 1 + (rings - 1) * per_ring edges: 4949 for 50 x 50).
    Each measurement is the true relative pose perturbed on the right by
    N(0, diag(sigma_t^2 I, sigma_r^2 I)), sigma = (sigma_t, sigma_r), and
    weighed by the matching information; the graph's poses are the
    composition of the noisy odometry from the first (true) pose.
    """
    _sizes("pose_graph_sphere", rings=rings, per_ring=per_ring)
    if isinstance(radius, (bool, np.bool_)) or not isinstance(radius, (int, float, np.integer, np.floating)):
        raise TypeError(f"pose_graph_sphere(radius): expected a float, got {type(radius).__name__}")
    if not 0 < radius < math.inf:
        raise ValueError(f"pose_graph_sphere(radius): expected a finite radius > 0, got {radius!r}")
    rng = np.random.default_rng(seed)
    st, sr = _sigma("pose_graph_sphere", sigma)
    n = rings * per_ring
    k = np.arange(n)
    ring, slot = k // per_ring, k % per_ring
    polar = np.pi * (ring + 0.5) / rings
    azimuth = 2 * np.pi * slot / per_ring
    truth = np.zeros((n, 4, 4))
    # R = Rz(azimuth) Ry(polar): z out of the sphere, x along the meridian, y along the ring
    truth[:, :3, :3] = so3_from_euler("xyz", np.stack([np.zeros(n), polar, azimuth], axis=1))
    truth[:, :3, 3] = radius * np.stack(
        [np.sin(polar) * np.cos(azimuth), np.sin(polar) * np.sin(azimuth), np.cos(polar)], axis=1
    )
    truth[:, 3, 3] = 1.0
    odometry = np.stack([k[:-1], k[1:]], axis=1)
    loops = np.stack([k[per_ring:] - per_ring, k[per_ring:]], axis=1)
    return _noisy_graph("se3", truth, np.concatenate([odometry, loops]), np.array([st] * 3 + [sr] * 3), rng), truth


def pose_graph_grid(
    poses: int = 3500, size: int = 40, *, sigma: ArrayLike = (0.05, 0.01), seed: int = 0
) -> tuple[PoseGraph, np.ndarray]:
    """A grid world of SE(2) poses, in the spirit of the Manhattan dataset: (graph, truth).

    A random walk on the unit grid of size x size cells (a step forward, or
    a turn of +-90 degrees and a step), an odometry edge between consecutive
    poses and a loop closure from each pose to an earlier one at the same
    cell (the latest, at most one per pose). Measurements and the graph's
    poses as for ``pose_graph_sphere``, sigma = (sigma_t, sigma_r).
    """
    _sizes("pose_graph_grid", poses=poses, size=size)
    rng = np.random.default_rng(seed)
    st, sr = _sigma("pose_graph_grid", sigma)
    x = y = heading = 0
    cells: dict[tuple[int, int], int] = {}
    states, loops = [], []
    for p in range(poses):
        if p:
            turn = rng.choice([0, 0, 1, -1])
            heading = (heading + turn) % 4
            dx, dy = ((1, 0), (0, 1), (-1, 0), (0, -1))[heading]
            if not (0 <= x + dx < size and 0 <= y + dy < size):
                heading = (heading + 2) % 4
                dx, dy = -dx, -dy
            x, y = x + dx, y + dy
        if (x, y) in cells and cells[(x, y)] < p - 1:
            loops.append((cells[(x, y)], p))
        cells[(x, y)] = p
        states.append((x, y, heading * np.pi / 2))
    s = np.array(states, dtype=np.float64)
    truth = _poses_from_numbers("se2", s)
    odometry = np.stack([np.arange(poses - 1), np.arange(1, poses)], axis=1)
    edges = np.concatenate([odometry, np.array(loops, dtype=np.int64).reshape(-1, 2)])
    return _noisy_graph("se2", truth, edges, np.array([st, st, sr]), rng), truth


def _noisy_graph(
    group: str, truth: np.ndarray, edges: np.ndarray, sd: np.ndarray, rng: np.random.Generator
) -> PoseGraph:
    """Measurements of truth's relative poses perturbed on the right by N(0, diag(sd^2)); poses from the odometry."""
    f = lambda name: getattr(_core, f"{group}_{name}")  # noqa: E731
    E, d = edges.shape[0], sd.shape[0]
    relative = f("compose")(f("inverse")(truth[edges[:, 0]]), truth[edges[:, 1]])
    measurements = f("compose")(relative, f("exp")(rng.standard_normal((E, d)) * sd))
    information = np.broadcast_to(np.diag(1.0 / sd**2), (E, d, d))
    # The initial guess: the first pose, then the noisy odometry composed (edges k, k+1 come first).
    n = truth.shape[0]
    poses = np.empty_like(truth)
    poses[0] = truth[0]
    for p in range(1, n):
        poses[p] = poses[p - 1] @ measurements[p - 1]
    return PoseGraph(group, np.arange(n), poses, edges, measurements, information)
