"""chasles.plot: the drawn artists hold the right data (checked against
independent formulas and scipy's rotations, not against chasles), matplotlib
stays optional, and the docstring examples run."""

from __future__ import annotations

import doctest
import subprocess
import sys
import textwrap

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg", force=True)  # before pyplot is imported: no display needed

import matplotlib.pyplot as plt
from chasles import SE3, SO3, Screw, Twist, plot
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from scipy.spatial.transform import Rotation

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
        for i, (line, color) in enumerate(
            zip((f.x, f.y, f.z), ("tab:red", "tab:green", "tab:blue"))
        ):
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


@pytest.mark.parametrize(
    "bad", [np.eye(3), np.zeros((2, 4, 4)), np.full((4, 4), np.nan), [[1.0, 2.0]]]
)
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
            assert np.allclose(
                data(fa[i])[1] - g.translation, 0.3 * g.rotation.as_matrix()[:, i]
            )
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
        assert np.allclose(data(s.start)[0], expected[0]) and np.allclose(
            data(s.end)[0], expected[-1]
        )
        # The axis covers the helix's extent along it.
        along_axis, along_helix = (axis - q) @ d, (helix - q) @ d
        assert along_axis.min() < along_helix.min() and along_axis.max() > along_helix.max()
        assert s.pitch.get_text() == f"pitch h = {s.screw.pitch:.3g}"


def test_screw_default_point_circles_the_axis_at_distance_one(ax):
    xi = Twist(v=[3.0, 0.0, 0.0], w=[0.0, 0.0, 1.5])  # axis through (0, 2, 0) along z, pitch 0
    s = plot.screw(xi, ax=ax, theta=(0.0, 2 * np.pi / 1.5))
    helix = data(s.helix)
    assert np.allclose(
        distance_to_line(helix, np.array([0.0, 2.0, 0.0]), np.array([0.0, 0.0, 1.0])), 1.0
    )
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


def test_docstring_examples_run():
    # Each example runs in (a copy of) the module's own namespace.
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    tests = [t for t in doctest.DocTestFinder().find(plot) if t.examples]
    assert {t.name for t in tests} >= {
        "chasles.plot",
        "chasles.plot.frame",
        "chasles.plot.frames",
        "chasles.plot.screw",
    }
    for t in tests:
        runner.run(t)
    assert runner.summarize(verbose=False).failed == 0
