"""chasles.Chain: product-of-exponentials kinematics. Forward kinematics of a
UR5 (Modern Robotics, example 4.5) against a product of scipy.linalg.expm,
both Jacobians against central differences, batches against single calls,
shapes, errors and the docstring examples."""

import numpy as np
import pytest
from helpers import hat6
from hypothesis import given
from hypothesis import strategies as st
from scipy.linalg import expm

import chasles
from chasles import SE3, Chain

W1, W2, L1, L2, H1, H2 = 0.109, 0.082, 0.425, 0.392, 0.089, 0.095

# Space screws (v, w), one row per joint (Modern Robotics lists (w, v)).
UR5_SCREWS = np.array(
    [
        [0, 0, 0, 0, 0, 1],
        [-H1, 0, 0, 0, 1, 0],
        [-H1, 0, L1, 0, 1, 0],
        [-H1, 0, L1 + L2, 0, 1, 0],
        [-W1, L1 + L2, 0, 0, 0, -1],
        [H2 - H1, 0, L1 + L2, 0, 1, 0],
    ],
    dtype=float,
)
UR5_HOME = np.array([[-1, 0, 0, L1 + L2], [0, 0, 1, W1 + W2], [0, 1, 0, H1 - H2], [0, 0, 0, 1]], dtype=float)
# The UR5 on a linear rail along (1, 2, 0) / sqrt(5): 7 joints, a prismatic one first.
RAIL_SCREWS = np.vstack([[1 / np.sqrt(5), 2 / np.sqrt(5), 0, 0, 0, 0], UR5_SCREWS])

EPS = float(np.finfo(float).eps)

joint_angles = st.floats(-3.3, 3.3, allow_nan=False, allow_infinity=False)


def vee6(X):
    return np.array([X[0, 3], X[1, 3], X[2, 3], X[2, 1], X[0, 2], X[1, 0]])


def fk_expm(screws, home, theta):
    g = np.eye(4)
    for s, t in zip(screws, theta):
        g = g @ expm(hat6(s * t))
    return g @ home


def fk_derivative(screws, home, theta, i, h=1e-3):
    """dg/dth_i by the five-point stencil: truncation h^4/30 |g^(5)| ~ 1e-13,
    rounding ~ eps / h ~ 2e-13 for these arms."""

    def at(d):
        t = np.array(theta, dtype=float)
        t[i] += d
        return fk_expm(screws, home, t)

    return (-at(2 * h) + 8 * at(h) - 8 * at(-h) + at(-2 * h)) / (12 * h)


# Tolerances: the library's result is exact to a few hundred eps (2 n exps and
# compositions of "a few ulps" each, as in tests/cpp/test_kinematics.cpp);
# scipy's expm (Pade) is good to ~1e-15 per factor; the five-point difference
# to ~1e-12 (above: expm rounding ~1e-15 amplified by 18 / (12 h) ~ 1.5e3).
FK_TOL = 1e-13
JAC_TOL = 1e-11


@pytest.mark.parametrize("screws", [UR5_SCREWS, RAIL_SCREWS], ids=["ur5", "ur5_on_rail"])
@given(data=st.data())
def test_forward_matches_product_of_expm(screws, data):
    n = len(screws)
    theta = np.array(data.draw(st.lists(joint_angles, min_size=n, max_size=n)))
    arm = Chain(screws, UR5_HOME)
    expected = fk_expm(screws, UR5_HOME, theta)
    np.testing.assert_allclose(arm.forward(theta), expected, rtol=0, atol=FK_TOL)
    np.testing.assert_allclose(arm.forward_body(theta), expected, rtol=0, atol=FK_TOL)


def test_ur5_published_pose():
    arm = Chain(UR5_SCREWS, SE3.from_matrix(UR5_HOME))
    T = arm.forward([0, -np.pi / 2, 0, 0, np.pi / 2, 0])
    expected = [[0, -1, 0, 0.095], [1, 0, 0, 0.109], [0, 0, 1, 0.988], [0, 0, 0, 1]]
    np.testing.assert_allclose(T, expected, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(arm.forward(np.zeros(6)), UR5_HOME)


@pytest.mark.parametrize("screws", [UR5_SCREWS, RAIL_SCREWS], ids=["ur5", "ur5_on_rail"])
@given(data=st.data())
def test_jacobians_match_finite_differences(screws, data):
    n = len(screws)
    theta = np.array(data.draw(st.lists(joint_angles, min_size=n, max_size=n)))
    arm = Chain(screws, UR5_HOME)
    Js, Jb = arm.jacobian_space(theta), arm.jacobian_body(theta)
    assert Js.shape == Jb.shape == (6, n)
    g = fk_expm(screws, UR5_HOME, theta)
    g_inv = np.linalg.inv(g)
    for i in range(n):
        dg = fk_derivative(screws, UR5_HOME, theta, i)
        np.testing.assert_allclose(Js[:, i], vee6(dg @ g_inv), rtol=0, atol=JAC_TOL)
        np.testing.assert_allclose(Jb[:, i], vee6(g_inv @ dg), rtol=0, atol=JAC_TOL)
    # J_s = Ad_g J_b, to the C++ suite's bound k eps scale, k = 2 n 16: the
    # entries p x R w grow with the lever arm |p| (up to ~4 m on the rail).
    AdJb = chasles.se3_adjoint(arm.forward(theta)) @ Jb
    scale = max(1.0, np.abs(Js).max(), np.abs(AdJb).max())
    np.testing.assert_allclose(Js, AdJb, rtol=0, atol=2 * n * 16 * EPS * scale)


@given(
    thetas=st.lists(st.lists(joint_angles, min_size=7, max_size=7), min_size=0, max_size=8),
)
def test_batch_equals_per_element(thetas):
    arm = Chain(RAIL_SCREWS, UR5_HOME)
    th = np.array(thetas, dtype=float).reshape(-1, 7)
    N = len(th)
    F, Fb = arm.forward(th), arm.forward_body(th)
    Js, Jb = arm.jacobian_space(th), arm.jacobian_body(th)
    assert F.shape == Fb.shape == (N, 4, 4)
    assert Js.shape == Jb.shape == (N, 6, 7)
    for k in range(N):
        np.testing.assert_array_equal(F[k], arm.forward(th[k]))
        np.testing.assert_array_equal(Fb[k], arm.forward_body(th[k]))
        np.testing.assert_array_equal(Js[k], arm.jacobian_space(th[k]))
        np.testing.assert_array_equal(Jb[k], arm.jacobian_body(th[k]))


def test_strided_and_integer_input():
    arm = Chain(UR5_SCREWS, UR5_HOME)
    th = np.linspace(-1, 1, 24).reshape(4, 6)
    np.testing.assert_array_equal(arm.forward(th[::2]), arm.forward(np.ascontiguousarray(th[::2])))
    np.testing.assert_array_equal(arm.jacobian_space(th.T.copy().T), arm.jacobian_space(th))
    np.testing.assert_array_equal(arm.jacobian_body([1, 0, 0, 0, 0, 0]), arm.jacobian_body([1.0, 0, 0, 0, 0, 0]))
    fortran = np.asfortranarray(UR5_SCREWS)
    np.testing.assert_array_equal(Chain(fortran, UR5_HOME).space_screws, UR5_SCREWS)


def test_screws_and_properties():
    for axis, point, s in zip(
        [[0, 0, 1], [0, 1, 0], [0, 1, 0], [0, 1, 0], [0, 0, -1], [0, 1, 0]],
        [[0, 0, 0], [0, 0, H1], [L1, 0, H1], [L1 + L2, 0, H1], [L1 + L2, W1, 0], [L1 + L2, 0, H1 - H2]],
        UR5_SCREWS,
    ):
        screw = Chain.revolute_screw(point, np.array(axis) * 2.5)
        np.testing.assert_allclose(screw, s, rtol=0, atol=4 * EPS)
    np.testing.assert_allclose(Chain.prismatic_screw([0, 3, 4]), [0, 0.6, 0.8, 0, 0, 0], rtol=0, atol=EPS)
    arm = Chain(UR5_SCREWS, UR5_HOME)
    assert arm.n_joints == 6
    np.testing.assert_array_equal(arm.space_screws, UR5_SCREWS)
    assert arm.space_screws.shape == arm.body_screws.shape == (6, 6)
    np.testing.assert_array_equal(arm.home.as_matrix(), UR5_HOME)
    M_inv = np.linalg.inv(UR5_HOME)
    for s, b in zip(UR5_SCREWS, arm.body_screws):
        np.testing.assert_allclose(b, vee6(M_inv @ hat6(s) @ UR5_HOME), rtol=0, atol=4 * EPS)
    assert repr(arm) == "Chain(n_joints=6)"
    # 32 joints (a zero screw, accepted before the screws were checked
    # against their joint types, is refused now: test_model_validation)
    assert Chain(np.tile(UR5_SCREWS, (6, 1))[:32], np.eye(4)).n_joints == 32


def test_methods_are_array_functions():
    """Any batch shape (..., n) in, (..., 4, 4) or (..., 6, n) out, by
    numpy's rules: a NaN gives NaN in its own element only, out= is not
    needed for a fresh result, and one configuration gives one array."""
    arm = Chain(UR5_SCREWS, UR5_HOME)
    rng = np.random.default_rng(5)
    th = rng.uniform(-np.pi, np.pi, size=(2, 3, 6))
    assert arm.forward(th).shape == (2, 3, 4, 4)
    assert arm.jacobian_body(th).shape == (2, 3, 6, 6)
    np.testing.assert_array_equal(arm.forward(th)[1, 2], arm.forward(th[1, 2]))
    np.testing.assert_array_equal(arm.jacobian_space(th)[0, 1], arm.jacobian_space(th[0, 1]))
    bad = th.copy()
    bad[0, 1, 2] = np.nan
    F = arm.forward_body(bad)
    assert np.isnan(F[0, 1]).any() and np.isfinite(np.delete(F.reshape(6, 16), 1, axis=0)).all()
    assert arm.forward(th.astype(np.float32)).dtype == np.float64  # the chain is float64
    assert isinstance(arm.forward(th[0, 0]), np.ndarray)


def test_errors_name_expected_and_received_shapes():
    arm = Chain(UR5_SCREWS, UR5_HOME)
    expected = r"Chain.forward\(theta\): expected shape \(6,\) or \(\.\.\., 6\).*got \(5,\)"
    with pytest.raises(ValueError, match=expected):
        arm.forward(np.zeros(5))
    with pytest.raises(ValueError, match=r"expected shape \(6,\) or \(\.\.\., 6\).*got \(2, 3, 5\)"):
        arm.jacobian_space(np.zeros((2, 3, 5)))
    with pytest.raises(ValueError, match=r"Chain.jacobian_body\(theta\).*got \(\)"):
        arm.jacobian_body(1.0)
    with pytest.raises(ValueError, match=r"Chain\(screws\): expected shape \(n, 6\).*got \(6, 5\)"):
        Chain(np.zeros((6, 5)), UR5_HOME)
    with pytest.raises(ValueError, match=r"Chain\(screws\): expected shape \(n, 6\).*got \(0, 6\)"):
        Chain(np.zeros((0, 6)), UR5_HOME)
    with pytest.raises(ValueError, match=r"at most 32 joints, got 33"):
        Chain(np.zeros((33, 6)), UR5_HOME)
    with pytest.raises(ValueError, match=r"Chain\(home\): expected shape \(4, 4\), got \(3, 3\)"):
        Chain(UR5_SCREWS, np.eye(3))
    with pytest.raises(ValueError, match=r"Chain\(home\): not a rigid motion"):
        Chain(UR5_SCREWS, 2 * np.eye(4))
    with pytest.raises(ValueError, match=r"Chain.forward\(theta\).*got \(\)"):
        arm.forward("abc")
    with pytest.raises(TypeError, match=r"Chain.forward\(theta\): .*not supported for the input types"):
        arm.forward(np.zeros(6, complex))
    with pytest.raises(ValueError, match=r"nonzero"):
        Chain.revolute_screw([1, 2, 3], [0, 0, 0])
    with pytest.raises(ValueError, match=r"nonzero"):
        Chain.prismatic_screw([0, 0, 0])


def member_doc(member):
    fget = getattr(member, "fget", None)
    return getattr(member, "__doc__", None) or getattr(fget, "__doc__", None)


def test_exported_and_documented():
    assert "Chain" in chasles.__all__
    for name in [
        "forward",
        "forward_body",
        "jacobian_space",
        "jacobian_body",
        "revolute_screw",
        "prismatic_screw",
        "screws",
        "body_screws",
        "home",
        "n_joints",
    ]:
        member = vars(Chain)[name]
        doc = member_doc(member)
        assert doc and doc.strip() and "arg0" not in doc, name


# ---- the robot model ------------------------------------------------------------


def test_model_keywords_properties_and_folding():
    arm = Chain(UR5_SCREWS, UR5_HOME)
    assert arm.joint_types == ("revolute",) * 6 and arm.joint_names is None and arm.link_inertias is None
    assert np.isinf(arm.lower).all() and (arm.lower < 0).all() and (arm.upper > 0).all()
    np.testing.assert_array_equal(arm.gravity, [0, 0, -9.81])
    base = SE3.exp([0.5, -0.2, 1.0, 0.3, -0.1, 0.7])
    tool = SE3(translation=[0, 0, 0.1])
    names = [f"j{i}" for i in range(7)]
    lo, hi = -np.arange(1.0, 8.0), np.arange(1.0, 8.0)
    lo[6], hi[6] = -np.inf, np.inf
    types = ["prismatic"] + ["revolute"] * 5 + ["continuous"]
    model = Chain(
        RAIL_SCREWS,
        UR5_HOME,
        joint_types=types,
        joint_names=names,
        lower=lo,
        upper=hi,
        velocity_limits=np.full(7, 2.0),
        effort_limits=np.arange(7.0),
        base=base,
        tool=tool,
        gravity=[0, 0.1, -9.8],
        link_inertias=np.ones((7, 10)),
    )
    assert model.joint_types == tuple(types) and model.joint_names == tuple(names)
    np.testing.assert_array_equal(model.lower, lo)
    np.testing.assert_array_equal(model.upper, hi)
    np.testing.assert_array_equal(model.velocity_limits, np.full(7, 2.0))
    np.testing.assert_array_equal(model.effort_limits, np.arange(7.0))
    np.testing.assert_array_equal(model.gravity, [0, 0.1, -9.8])
    np.testing.assert_array_equal(model.link_inertias, np.ones((7, 10)))
    assert model.base.is_approx(base, 1e-15) and model.tool.is_approx(tool, 1e-15)
    assert repr(model) == "Chain(n_joints=7, joint_names=('j0', 'j1', 'j2', 'j3', 'j4', 'j5', 'j6'))"
    plain = Chain(RAIL_SCREWS, UR5_HOME)
    rng = np.random.default_rng(8)
    for q in rng.uniform(-3, 3, (10, 7)):
        expected = base.as_matrix() @ plain.forward(q) @ tool.as_matrix()
        np.testing.assert_allclose(model.forward(q), expected, rtol=0, atol=1e-14)
        np.testing.assert_allclose(model.forward_body(q), expected, rtol=0, atol=1e-14)
        np.testing.assert_allclose(
            model.jacobian_space(q), chasles.se3_adjoint(base.as_matrix()) @ plain.jacobian_space(q), rtol=0, atol=1e-14
        )
    import copy
    import pickle

    for other in (pickle.loads(pickle.dumps(model)), copy.deepcopy(model)):
        assert other == model and other.joint_names == model.joint_names
        np.testing.assert_array_equal(other.link_inertias, model.link_inertias)
    assert pickle.loads(pickle.dumps(arm)) == arm
    assert model != plain


def test_one_vocabulary_space_screws_and_joint_names_with_deprecated_aliases():
    """space_screws and joint_names are the names (C++ Chain::space_screws(),
    UrdfChain::joint_names), the constructor's keyword too; screws and names
    stay for one release, warning."""
    arm = Chain(UR5_SCREWS, UR5_HOME, joint_names=[f"j{i}" for i in range(6)])
    np.testing.assert_array_equal(arm.space_screws, UR5_SCREWS)
    assert arm.space_screws.shape == (6, 6) and arm.joint_names == tuple(f"j{i}" for i in range(6))
    with pytest.warns(DeprecationWarning, match=r"Chain.screws is deprecated: use Chain.space_screws"):
        np.testing.assert_array_equal(arm.screws, arm.space_screws)
    with pytest.warns(DeprecationWarning, match=r"Chain.names is deprecated: use Chain.joint_names"):
        assert arm.names == arm.joint_names
    with pytest.warns(DeprecationWarning, match=r"Chain\(names=...\) is deprecated: use Chain\(joint_names=...\)"):
        old = Chain(UR5_SCREWS, UR5_HOME, names=[f"j{i}" for i in range(6)])
    assert old == arm and repr(old) == repr(arm)
    with pytest.raises(TypeError, match=r"give joint_names only"):
        Chain(UR5_SCREWS, UR5_HOME, joint_names=["a"] * 6, names=["a"] * 6)
    # a pickle of the constructor's arguments made while the keyword was `names` loads
    screws, home, arguments = arm.__reduce__()[1][1:]
    arguments["names"] = arguments.pop("joint_names")
    assert arm.__reduce__()[0](Chain, screws, home, arguments) == arm


def test_link_inertias_as_spatial_inertias_or_packed_rows_give_equal_chains():
    bodies = [
        chasles.SpatialInertia(
            1.0 + i, [0.1 * i, 0.0, 0.05], [[0.02, 0.001, 0.0], [0.001, 0.03, 0.0], [0.0, 0.0, 0.04]]
        )
        for i in range(6)
    ]
    rows = [
        [
            b.mass,
            *b.com,
            b.inertia[0, 0],
            b.inertia[0, 1],
            b.inertia[0, 2],
            b.inertia[1, 1],
            b.inertia[1, 2],
            b.inertia[2, 2],
        ]
        for b in bodies
    ]
    base = SE3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
    a = Chain(UR5_SCREWS, UR5_HOME, link_inertias=bodies, base=base)
    b = Chain(UR5_SCREWS, UR5_HOME, link_inertias=np.array(rows), base=base)
    assert a == b
    np.testing.assert_array_equal(a.link_inertias, b.link_inertias)
    q = np.linspace(-1.0, 1.0, 6)
    np.testing.assert_array_equal(a.mass_matrix(q), b.mass_matrix(q))
    np.testing.assert_array_equal(a.inverse_dynamics(q, q, q), b.inverse_dynamics(q, q, q))
    with pytest.raises(ValueError, match=r"Chain\(link_inertias\): expected shape \(6, 10\)"):
        Chain(UR5_SCREWS, UR5_HOME, link_inertias=bodies[:5])


def test_the_model_is_the_extensions_chain_and_old_pickles_name_it():
    """chasles.Chain subclasses the private extension class that holds the C++
    chain; the computing methods are the extension's own (no Python frame per
    call); chasles 0.1.0's pickles name chasles._core.Chain, which is it."""
    from chasles import _core

    assert issubclass(Chain, _core._Chain) and _core.Chain is Chain
    for name in (
        "forward",
        "forward_body",
        "jacobian_space",
        "jacobian_body",
        "inverse_dynamics",
        "forward_dynamics",
        "mass_matrix",
        "gravity_torques",
        "coriolis",
    ):
        assert vars(Chain)[name] is vars(_core._Chain)[name]


def test_model_validation():
    with pytest.raises(ValueError, match=r"joint 0 is prismatic but its linear part v is not a unit"):
        Chain(np.zeros((1, 6)), np.eye(4))
    s = UR5_SCREWS.copy()
    s[2, 4] = 1 + 3e-8
    with pytest.raises(ValueError, match=r"joint 2 is revolute but its angular part w is not a unit vector"):
        Chain(s, UR5_HOME)
    s[2, 4] = 1 + 1e-8  # within the tolerance, 1.5e-8
    Chain(s, UR5_HOME)
    # a screw with a pitch is a helical joint (inferred), not a revolute one (given)
    assert Chain([[0, 0, 0.5, 0, 0, 1]], np.eye(4)).joint_types == ("helical",)
    with pytest.raises(ValueError, match=r"joint 0 is revolute but its screw has a pitch.*'helical'"):
        Chain([[0, 0, 0.5, 0, 0, 1]], np.eye(4), joint_types=["revolute"])
    with pytest.raises(ValueError, match=r"joint 0 is helical but its angular part w is not a unit vector"):
        Chain([[0, 0, 0.5, 0, 0, 2]], np.eye(4))
    # any nonzero norm with unit_screws=False (the joint variable in other units), but not zero
    assert Chain([[0, 0, 0.5, 0, 0, 2], [0, 0, 3, 0, 0, 0]], np.eye(4), unit_screws=False).joint_types == (
        "helical",
        "prismatic",
    )
    with pytest.raises(ValueError, match=r"joint 1: expected a nonzero screw"):
        Chain([[0, 0, 0, 0, 0, 2], [0, 0, 0, 0, 0, 0]], np.eye(4), unit_screws=False)
    with pytest.raises(TypeError, match=r"Chain\(unit_screws\): expected a bool"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), unit_screws=1)
    with pytest.raises(ValueError, match=r"joint 0 is prismatic but its angular part w is not zero"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_types=["prismatic"])
    with pytest.raises(ValueError, match=r"Chain\(lower, upper\): joint 0"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), lower=[1], upper=[0])
    with pytest.raises(ValueError, match=r"Chain\(lower, upper\): joint 0.*continuous"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_types=["continuous"], lower=[-1])
    with pytest.raises(ValueError, match=r"Chain\(velocity_limits, effort_limits\): joint 0"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), velocity_limits=[-1])
    with pytest.raises(ValueError, match=r"Chain\(joint_types\): expected 'revolute'"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_types=["hinge"])
    with pytest.raises(ValueError, match=r"Chain\(joint_names\): expected 1 names"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_names=["a", "b"])
    with pytest.raises(TypeError, match=r"Chain\(joint_names\): expected strings"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_names=[1])
    with pytest.raises(ValueError, match=r"Chain\(gravity\): expected finite"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), gravity=[0, 0, np.nan])
    with pytest.raises(ValueError, match=r"Chain\(link_inertias\): expected shape \(1, 10\)"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), link_inertias=np.ones((1, 9)))
    with pytest.raises(ValueError, match=r"masses >= 0"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), link_inertias=-np.ones((1, 10)))
    # finite as given, infinite once the base frame moves it (the C++ chain's validate)
    far = np.eye(4)
    far[0, 3] = 1e308
    with pytest.raises(ValueError, match=r"Chain\(link_inertias\): joint 0: expected finite numbers"):
        Chain([[1, 0, 0, 0, 0, 0]], np.eye(4), base=far, link_inertias=[[1, 1e308, 0, 0, 1, 0, 0, 1, 0, 1]])
    assert (
        Chain([[1, 0, 0, 0, 0, 0]], np.eye(4), base=far, link_inertias=[[1, 0, 0, 0, 1, 0, 0, 1, 0, 1]]).n_joints == 1
    )
    with pytest.raises(ValueError, match=r"Chain\(base\): not a rigid motion"):
        Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), base=2 * np.eye(4))


def test_home_is_projected_and_body_agrees_with_space_at_large_angles():
    # a home pose off a rotation by 1e-9 (accepted, inside sqrt(eps)) is projected
    M = UR5_HOME.copy()
    M[0, 0] *= 1 + 1e-9
    arm = Chain(UR5_SCREWS, M)
    R = arm.home.rotation.as_matrix()
    assert np.abs(R.T @ R - np.eye(3)).max() <= 2 * EPS
    # an exact one is kept bit for bit
    np.testing.assert_array_equal(Chain(UR5_SCREWS, UR5_HOME).home.as_matrix(), UR5_HOME)
    # body against space, |theta| up to 1000, on the UR5 with a tilted base (axes not exact)
    tilted = Chain(RAIL_SCREWS, UR5_HOME, base=SE3.exp([0, 0, 0, 0.3, -0.2, 0.1]))
    rng = np.random.default_rng(34)
    for scale in (3.3, 50.0, 1000.0):
        q = rng.uniform(-scale, scale, (300, 7))
        diff = np.abs(tilted.forward_body(q) - tilted.forward(q)).max()
        assert diff <= 4 * EPS * (16 + scale), (scale, diff)
