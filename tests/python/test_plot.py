"""chasles.plot: the drawn artists hold the right data (checked against
independent formulas and scipy's rotations, not against chasles), matplotlib
stays optional, and the docstring examples run."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg", force=True)  # before pyplot is imported: no display needed

import matplotlib.pyplot as plt
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from scipy.spatial.transform import Rotation

from chasles import SE3, SO3, Chain, Screw, Twist, plot

TOL = 1e-12


@pytest.fixture
def ax():
    return Figure().add_subplot(projection="3d")


def run_python(code: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def data(line) -> np.ndarray:
    """The points of a Line3D, shape (n, 3)."""
    return np.stack(line.get_data_3d(), axis=1)


def random_pose(rng) -> SE3:
    R = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
    return SE3(SO3.from_matrix(R), rng.uniform(-3.0, 3.0, size=3))


# ---- matplotlib stays optional ---------------------------------------------


def test_import_chasles_does_not_import_matplotlib():
    r = run_python(
        """
        import sys
        import chasles
        import chasles.__main__  # the demo imports it only to draw
        print(sorted(m for m in sys.modules if m.split(".")[0] in ("matplotlib", "mpl_toolkits")))
        """
    )
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def test_import_plot_without_matplotlib_names_the_extra():
    r = run_python(
        """
        import sys
        sys.modules["matplotlib"] = None  # makes `import matplotlib` raise ImportError
        import chasles
        try:
            import chasles.plot
        except ImportError as e:
            print("ImportError:", e)
        else:
            print("imported")
        """
    )
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("ImportError:"), r.stdout
    assert "pip install chasles[plot]" in r.stdout
    assert "matplotlib" in r.stdout


# ---- frame ------------------------------------------------------------------


def test_frame_draws_the_rotation_columns_from_the_origin(ax):
    rng = np.random.default_rng(1)
    for _ in range(20):
        g = random_pose(rng)
        R, p = g.rotation.as_matrix(), g.translation
        f = plot.frame(g, ax=ax, label="b", length=0.7)
        for i, (line, color) in enumerate(zip((f.x, f.y, f.z), ("tab:red", "tab:green", "tab:blue"))):
            pts = data(line)
            assert np.allclose(pts[0], p, atol=TOL, rtol=0)
            assert np.allclose(pts[1], p + 0.7 * R[:, i], atol=TOL, rtol=0)
            assert to_rgba(line.get_color()) == to_rgba(color)
        assert f.label.get_text().strip() == "b"
        assert np.allclose(f.label.get_position_3d(), p, atol=TOL, rtol=0)


def test_frame_accepts_a_matrix_and_no_label(ax):
    g = SE3.exp([0.1, 0.2, 0.3, 0.4, -0.5, 0.6])
    a = plot.frame(g.as_matrix(), ax=ax)
    b = plot.frame(g, ax=ax)
    assert a.label is None
    for la, lb in zip(a[:3], b[:3]):
        assert np.array_equal(data(la), data(lb))
    # Red x axis: the colors are those of AXIS_COLORS, in order.
    assert [to_rgba(c) for c in plot.AXIS_COLORS] == [to_rgba(line.get_color()) for line in a[:3]]


def test_frame_makes_a_pyplot_figure_without_ax():
    try:
        f = plot.frame(SE3())
        assert f.x.axes.name == "3d"
        assert f.x.axes.figure in [plt.figure(n) for n in plt.get_fignums()]
    finally:
        plt.close("all")


@pytest.mark.parametrize("bad", [np.eye(3), np.zeros((2, 4, 4)), np.full((4, 4), np.nan), [[1.0, 2.0]]])
def test_frame_refuses_what_is_not_one_pose(ax, bad):
    with pytest.raises(ValueError):
        plot.frame(bad, ax=ax)


def test_a_2d_axes_is_refused():
    with pytest.raises(TypeError, match="3D Axes"):
        plot.frame(SE3(), ax=Figure().add_subplot())


# ---- frames -----------------------------------------------------------------


def test_frames_of_an_array_and_of_a_list_agree(ax):
    rng = np.random.default_rng(2)
    poses = [random_pose(rng) for _ in range(6)]
    stacked = np.stack([g.as_matrix() for g in poses])
    a = plot.frames(stacked, ax=ax, labels=[str(i) for i in range(6)], length=0.3)
    b = plot.frames(poses, ax=ax, length=0.3, path=False)
    assert len(a.frames) == len(b.frames) == 6
    assert b.path is None
    for g, fa, fb in zip(poses, a.frames, b.frames):
        for i in range(3):
            assert np.array_equal(data(fa[i]), data(fb[i]))
            assert np.allclose(data(fa[i])[1] - g.translation, 0.3 * g.rotation.as_matrix()[:, i])
    assert [f.label.get_text().strip() for f in a.frames] == [str(i) for i in range(6)]
    assert np.allclose(data(a.path), stacked[:, :3, 3], atol=0, rtol=0)


def test_frames_checks_its_labels(ax):
    with pytest.raises(ValueError, match="2 labels for 3 poses"):
        plot.frames(np.stack([np.eye(4)] * 3), ax=ax, labels=["a", "b"])


# ---- screw ------------------------------------------------------------------


def screw_motion(q, d, h, theta, p):
    """exp of the screw (axis through q along unit d, pitch h) by theta, on p:
    q + Rot(d, theta) (p - q) + h theta d, with scipy's rotation."""
    Rs = Rotation.from_rotvec(np.outer(theta, d)).as_matrix()
    return q + (Rs @ (p - q)) + np.outer(h * theta, d)


def distance_to_line(points, q, d):
    r = points - q
    return np.linalg.norm(r - np.outer(r @ d, d), axis=1)


def test_screw_of_a_twist_axis_pitch_and_helix(ax):
    rng = np.random.default_rng(3)
    for _ in range(20):
        v, w = rng.uniform(-2.0, 2.0, size=3), rng.uniform(-2.0, 2.0, size=3)
        p = rng.uniform(-2.0, 2.0, size=3)
        s = plot.screw(Twist(v=v, w=w), ax=ax, theta=(-0.5, 2.0), point=p, samples=50)
        # The axis and pitch of the twist, from their formulas.
        n2 = w @ w
        q, d, h = np.cross(w, v) / n2, w / np.sqrt(n2), (w @ v) / n2
        assert np.allclose(s.screw.point, q, atol=1e-12)
        assert np.allclose(s.screw.direction, d, atol=1e-14)
        assert s.screw.pitch == pytest.approx(h, rel=1e-13, abs=1e-15)
        axis = data(s.axis)
        assert np.max(distance_to_line(axis, q, d)) < 1e-12
        # exp([xi] theta) is the screw motion by theta |w|.
        thetas = np.linspace(-0.5, 2.0, 50)
        expected = screw_motion(q, d, h, thetas * np.sqrt(n2), p)
        helix = data(s.helix)
        assert helix.shape == (50, 3)
        assert np.allclose(helix, expected, atol=1e-12, rtol=0)
        assert np.allclose(data(s.start)[0], expected[0]) and np.allclose(data(s.end)[0], expected[-1])
        # The axis covers the helix's extent along it.
        along_axis, along_helix = (axis - q) @ d, (helix - q) @ d
        assert along_axis.min() < along_helix.min() and along_axis.max() > along_helix.max()
        assert s.pitch.get_text() == f"pitch h = {s.screw.pitch:.3g}"


def test_screw_default_point_circles_the_axis_at_distance_one(ax):
    xi = Twist(v=[3.0, 0.0, 0.0], w=[0.0, 0.0, 1.5])  # axis through (0, 2, 0) along z, pitch 0
    s = plot.screw(xi, ax=ax, theta=(0.0, 2 * np.pi / 1.5))
    helix = data(s.helix)
    assert np.allclose(distance_to_line(helix, np.array([0.0, 2.0, 0.0]), np.array([0.0, 0.0, 1.0])), 1.0)
    assert np.allclose(helix[0], helix[-1], atol=1e-12)  # one full turn
    assert np.allclose(helix[:, 2], 0.0, atol=1e-15)
    assert s.pitch.get_text() == "pitch h = 0"


def test_screw_of_a_screw_object_and_of_a_vector_agree_with_the_twist(ax):
    xi = Twist(v=[0.3, -1.0, 0.7], w=[0.2, 0.5, -0.4])
    by_twist = plot.screw(xi, ax=ax, point=[1.0, 1.0, 1.0])
    by_vector = plot.screw(xi.vector, ax=ax, point=[1.0, 1.0, 1.0])
    by_screw = plot.screw(xi.screw(), ax=ax, point=[1.0, 1.0, 1.0])
    assert np.array_equal(data(by_twist.helix), data(by_vector.helix))
    assert np.allclose(data(by_twist.helix), data(by_screw.helix), atol=1e-12)
    assert by_screw.screw.is_approx(by_twist.screw, 1e-12)


def test_screw_of_a_translation_is_a_straight_line(ax):
    s = plot.screw([0.0, 3.0, 4.0, 0.0, 0.0, 0.0], ax=ax, theta=(0.0, 2.0), point=[1.0, 0.0, 0.0])
    helix = data(s.helix)
    assert np.isinf(s.screw.pitch)
    assert np.allclose(helix[-1], [1.0, 6.0, 8.0], atol=1e-14)
    d = np.array([0.0, 0.6, 0.8])
    assert np.max(distance_to_line(helix, np.array([1.0, 0.0, 0.0]), d)) < 1e-14
    assert np.max(distance_to_line(data(s.axis), np.array([1.0, 0.0, 0.0]), d)) < 1e-14
    assert s.pitch.get_text() == "pitch h = inf"


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"xi": np.zeros(6)}, "zero twist"),
        ({"xi": Screw([0, 0, 0], [0, 0, 1], 0.0, 0.0)}, "zero twist"),
        ({"samples": 1}, "samples"),
        ({"theta": (1.0, 1.0)}, "theta"),
        ({"theta": (0.0, np.inf)}, "theta"),
        ({"point": [1.0, 2.0]}, "point"),
    ],
)
def test_screw_refuses_bad_input(ax, kwargs, message):
    args = {"xi": [1.0, 0.0, 0.0, 0.0, 0.0, 1.0], **kwargs}
    with pytest.raises(ValueError, match=message):
        plot.screw(args.pop("xi"), ax=ax, **args)


# ---- chain -----------------------------------------------------------------


def example_robot_chain(suffix: str, tip: str) -> Chain:
    """A chain of an arm of the example-robot-data package (skips without it)."""
    metadata = pytest.importorskip("importlib.metadata")
    try:
        files = metadata.files("example-robot-data") or []
    except metadata.PackageNotFoundError:
        pytest.skip("example-robot-data is not installed")
    for f in files:
        if str(f).endswith(suffix):
            return Chain.from_urdf(f.locate(), tip)
    pytest.skip(f"example-robot-data has no {suffix}")


def ur5() -> Chain:
    return example_robot_chain("ur_description/urdf/ur5_robot.urdf", "tool0")


def panda() -> Chain:
    return example_robot_chain("panda_description/urdf/panda.urdf", "panda_hand_tcp")


def rail_arm() -> Chain:
    """A revolute joint, a prismatic one along its link and two revolute joints
    (one axis parallel to the first), on a moved base and with a tool offset."""
    screws = [
        Chain.revolute_screw([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        Chain.prismatic_screw([1.0, 0.0, 0.0]),
        Chain.revolute_screw([0.8, 0.0, 0.3], [0.0, 0.0, 1.0]),
        Chain.revolute_screw([1.2, 0.1, 0.3], [0.0, 1.0, 0.0]),
    ]
    base = SE3.exp([0.2, -0.1, 0.5, 0.0, 0.0, 0.4])
    tool = SE3(translation=[0.0, 0.0, 0.1])
    return Chain(screws, SE3(translation=[1.5, 0.1, 0.3]), base=base, tool=tool)


ARMS = {"ur5": ur5, "panda": panda, "rail": rail_arm}


def random_q(arm: Chain, rng) -> np.ndarray:
    lo, hi = np.maximum(arm.lower, -np.pi), np.minimum(arm.upper, np.pi)
    return rng.uniform(lo, hi)


def current_axis(arm: Chain, q, i: int) -> tuple[np.ndarray | None, np.ndarray]:
    """Joint i's axis at q from the space Jacobian's column i (its screw moved by
    the joints before it): a point of it (None for a prismatic joint) and its
    unit direction."""
    column = arm.jacobian_space(q)[:, i]
    v, w = column[:3], column[3:]
    if np.linalg.norm(w) == 0.0:
        return None, v / np.linalg.norm(v)
    return np.cross(w, v) / (w @ w), w / np.linalg.norm(w)


@pytest.mark.parametrize("name", sorted(ARMS))
def test_chain_points_move_as_the_partial_chains(ax, name):
    arm = ARMS[name]()
    n = arm.n_joints
    home = plot.chain(arm, np.zeros(n), ax=ax).points
    assert home.shape == (2 * n + 2, 3)
    rng = np.random.default_rng(4)
    for _ in range(10):
        q = random_q(arm, rng)
        drawn = plot.chain(arm, q, ax=ax)
        assert np.array_equal(data(drawn.links), drawn.points)
        assert np.array_equal(data(drawn.joints), drawn.points[1:-1:2])
        assert np.allclose(drawn.points[0], arm.base.translation, atol=TOL, rtol=0)
        # Joint i's origin rides on the first i joints, its exit point on the first i + 1.
        for k in range(1, 2 * n + 1):
            m = k // 2  # the number of joints that move point k
            if m == 0:
                expected = home[k]
            else:
                partial = Chain(arm.space_screws[:m], SE3(translation=home[k]))
                expected = partial.forward(q[:m])[:3, 3]
            assert np.allclose(drawn.points[k], expected, atol=TOL, rtol=0), (k, m)
        # The tool frame at chain.forward(q), the base frame at chain.base.
        g = arm.forward(q)
        assert np.allclose(drawn.points[-1], g[:3, 3], atol=TOL, rtol=0)
        for i in range(3):
            assert np.allclose(data(drawn.tool[i])[0], g[:3, 3], atol=TOL, rtol=0)
            direction = data(drawn.tool[i])[1] - data(drawn.tool[i])[0]
            assert np.allclose(direction / np.linalg.norm(direction), g[:3, i], atol=TOL)
            assert np.allclose(
                data(drawn.base[i])[1] - data(drawn.base[i])[0],
                np.linalg.norm(direction) * arm.base.rotation.as_matrix()[:, i],
                atol=TOL,
            )
        assert drawn.tool.label.get_text().strip() == "tool"
        assert drawn.base.label.get_text().strip() == "base"
        assert drawn.ax is ax


@pytest.mark.parametrize("name", sorted(ARMS))
def test_chain_points_are_on_the_joint_axes_and_links_are_common_normals(ax, name):
    arm = ARMS[name]()
    n = arm.n_joints
    rng = np.random.default_rng(5)
    for _ in range(10):
        q = random_q(arm, rng)
        drawn = plot.chain(arm, q, ax=ax, length=0.2)
        origins, exits = drawn.points[1:-1:2], drawn.points[2:-1:2]
        for i in range(n):
            point, d = current_axis(arm, q, i)
            assert np.allclose(drawn.directions[i], d, atol=TOL, rtol=0)
            if point is not None:
                for p in (origins[i], exits[i]):
                    assert np.max(distance_to_line(p[None], point, d)) < TOL
            else:  # the slide: from the origin along the axis
                r = exits[i] - origins[i]
                assert np.linalg.norm(r - (r @ d) * d) < TOL
            # The joint's axis line: length 0.2 along d, centered on its origin.
            ends = data(drawn.joint_axes[i])
            assert np.allclose(ends, [origins[i] - 0.1 * d, origins[i] + 0.1 * d], atol=TOL)
        # Between successive axes the links are perpendicular to both (when the
        # axes are not parallel the common normal is unique); the first and
        # last reach the base and tool origins perpendicularly.
        d = drawn.directions
        for i in range(n - 1):
            link = origins[i + 1] - exits[i]
            assert abs(link @ d[i]) < TOL and abs(link @ d[i + 1]) < TOL, i
        assert abs((origins[0] - drawn.points[0]) @ d[0]) < TOL
        assert abs((drawn.points[-1] - exits[-1]) @ d[-1]) < TOL


def test_chain_of_the_ur5_is_its_denavit_hartenberg_table(ax):
    """The stick figure at home has UR's published DH parameters (d1, a2, a3,
    d4, d5, d6 of the UR5) as its segments."""
    d1, a2, a3, d4, d5, d6 = 0.089159, 0.425, 0.39225, 0.10915, 0.09465, 0.0823
    expected = [
        [0.0, 0.0, 0.0],  # base
        [0.0, 0.0, 0.0],  # shoulder pan: origin, exit
        [0.0, 0.0, d1],
        [0.0, 0.0, d1],  # shoulder lift (parallel to the next two)
        [0.0, 0.0, d1],
        [a2, 0.0, d1],  # elbow
        [a2, 0.0, d1],
        [a2 + a3, 0.0, d1],  # wrist 1
        [a2 + a3, d4, d1],
        [a2 + a3, d4, d1],  # wrist 2, along -z
        [a2 + a3, d4, d1 - d5],
        [a2 + a3, d4, d1 - d5],  # wrist 3
        [a2 + a3, d4 + d6, d1 - d5],
        [a2 + a3, d4 + d6, d1 - d5],  # tool0
    ]
    drawn = plot.chain(ur5(), np.zeros(6), ax=ax)
    # The URDF writes pi/2 as 1.57079632679 (4.9e-12 short): its axes are off
    # by that angle, which moves points of this 1 m arm by a few 1e-12.
    assert np.allclose(drawn.points, expected, atol=1e-11, rtol=0)
    # Its default length: a tenth of the figure's, which revolute joints keep.
    figure = np.sum(np.linalg.norm(np.diff(expected, axis=0), axis=1))
    ends = data(drawn.joint_axes[0])
    assert np.linalg.norm(ends[1] - ends[0]) == pytest.approx(0.1 * figure, rel=1e-12)
    moved = plot.chain(ur5(), [0.3, -1.0, 1.2, 0.4, -0.5, 2.0], ax=ax).points
    moved_length = np.sum(np.linalg.norm(np.diff(moved, axis=0), axis=1))
    assert moved_length == pytest.approx(figure, rel=1e-12)


def test_chain_prismatic_segment_slides_by_q(ax):
    arm = rail_arm()
    for slide in (0.0, 0.25, -0.4):
        drawn = plot.chain(arm, [0.7, slide, -0.3, 0.2], ax=ax)
        origin, exit_ = drawn.points[3], drawn.points[4]  # joint 2, the prismatic one
        at_zero = plot.chain(arm, [0.7, 0.0, -0.3, 0.2], ax=ax).points
        assert np.allclose(exit_ - origin, at_zero[4] - at_zero[3] + slide * drawn.directions[1])


def test_chain_without_labels_and_into_a_new_figure():
    try:
        drawn = plot.chain(rail_arm(), np.zeros(4), labels=False)
        assert drawn.ax.name == "3d"
        assert drawn.tool.label is None and drawn.base.label is None
        assert drawn.ax.figure in [plt.figure(n) for n in plt.get_fignums()]
    finally:
        plt.close("all")


@pytest.mark.parametrize(
    "q, kwargs, error, message",
    [
        (np.zeros(3), {}, ValueError, r"shape \(4,\) for a chain of 4 joints, not \(3,\)"),
        (np.zeros((2, 4)), {}, ValueError, r"shape \(4,\) for a chain of 4 joints, not \(2, 4\)"),
        (0.0, {}, ValueError, r"not \(\)"),
        ([0.0, np.nan, 0.0, 0.0], {}, ValueError, "finite"),
        ([0.0, np.inf, 0.0, 0.0], {}, ValueError, "finite"),
        (["a", "b", "c", "d"], {}, TypeError, "real numbers"),
        (np.zeros(4), {"length": 0.0}, ValueError, "length"),
        (np.zeros(4), {"length": np.nan}, ValueError, "length"),
    ],
)
def test_chain_refuses_bad_input(ax, q, kwargs, error, message):
    with pytest.raises(error, match=message):
        plot.chain(rail_arm(), q, ax=ax, **kwargs)


def test_chain_refuses_what_is_not_a_chain_or_a_3d_axes(ax):
    with pytest.raises(TypeError, match="Chain"):
        plot.chain(np.eye(4), np.zeros(1), ax=ax)
    with pytest.raises(TypeError, match="3D Axes"):
        plot.chain(rail_arm(), np.zeros(4), ax=Figure().add_subplot())
