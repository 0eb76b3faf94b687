"""Chain.from_urdf on the real arms of the example-robot-data package: forward
kinematics against an independent composition of each URDF's joint
transforms (written here with numpy: origin, then the rotation about the axis
by Rodrigues' formula or the translation along it), joint counts, names and
limits as in the file, the inertias of the links; and the errors for the
descriptions a serial chain cannot be made of (small URDF strings here)."""

import importlib.metadata
import math
import os
import xml.etree.ElementTree as ET
from pathlib import Path

import hostile_urdf
import numpy as np
import pytest

from chasles import Chain, _urdf

# (file name under robots/, tip link, base link or None)
ARMS = {
    "ur3": ("ur_description/urdf/ur3_robot.urdf", "tool0", None),
    "ur5": ("ur_description/urdf/ur5_robot.urdf", "tool0", None),
    "ur10": ("ur_description/urdf/ur10_robot.urdf", "tool0", None),
    "panda": ("panda_description/urdf/panda.urdf", "panda_hand", None),
    "xarm7": ("xarm_description/urdf/xarm7.urdf", "link7", None),
    "z1": ("z1_description/urdf/z1.urdf", "link06", None),
    "kinova": ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector", None),
    "talos_left_arm": ("talos_data/robots/talos_left_arm.urdf", "gripper_left_base_link", None),
}


def robots_dir():
    try:
        files = importlib.metadata.files("example-robot-data") or []
    except importlib.metadata.PackageNotFoundError:
        return None
    for f in files:
        if str(f).endswith("ur_description/urdf/ur5_robot.urdf"):
            return f.locate().parents[2]
    return None


ROBOTS = robots_dir()
needs_data = pytest.mark.skipif(ROBOTS is None, reason="example-robot-data is not installed")


# ---- the independent reference: numpy over the parsed XML -------------------


def rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    Ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def origin(joint):
    T = np.eye(4)
    o = joint.find("origin")
    if o is not None:
        T[:3, 3] = [float(x) for x in o.get("xyz", "0 0 0").split()]
        T[:3, :3] = rpy_matrix(*[float(x) for x in o.get("rpy", "0 0 0").split()])
    return T


def axis_motion(kind, axis, q):
    """exp of the joint in its own frame: Rodrigues' rotation about the unit
    axis by q, or the translation q axis."""
    T = np.eye(4)
    if kind == "prismatic":
        T[:3, 3] = q * axis
    else:
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        T[:3, :3] = np.eye(3) + math.sin(q) * K + (1 - math.cos(q)) * K @ K
    return T


def joint_path(root, tip, base):
    joints = {j.find("child").get("link"): j for j in root.findall("joint")}
    path, link = [], tip
    while link in joints and link != base:
        path.append(joints[link])
        link = joints[link].find("parent").get("link")
    return path[::-1]


def reference_fk(path, q):
    T, k = np.eye(4), 0
    for j in path:
        T = T @ origin(j)
        if j.get("type") != "fixed":
            a = j.find("axis")
            axis = np.array([float(x) for x in (a.get("xyz") if a is not None else "1 0 0").split()])
            T = T @ axis_motion(j.get("type"), axis / np.linalg.norm(axis), q[k])
            k += 1
    return T


@pytest.fixture(scope="module")
def arms():
    """Each arm parsed once per module: (chain, moving joints of the XML, path)."""
    out = {}
    for key, (rel, tip, base) in ARMS.items():
        path = ROBOTS / rel
        if not path.exists():
            continue
        root = ET.parse(path).getroot()
        jp = joint_path(root, tip, base)
        out[key] = (Chain.from_urdf(path, tip, base), [j for j in jp if j.get("type") != "fixed"], jp)
    return out


@needs_data
@pytest.mark.parametrize("key", list(ARMS))
def test_forward_matches_composition_of_urdf_transforms(arms, key):
    if key not in arms:
        pytest.skip(f"{ARMS[key][0]} is not in this version of example-robot-data")
    chain, moving, path = arms[key]
    rng = np.random.default_rng(13)
    assert chain.n_joints == len(moving)
    for _ in range(20):
        q = rng.uniform(-np.pi, np.pi, chain.n_joints)
        expected = reference_fk(path, q)
        np.testing.assert_allclose(chain.forward(q), expected, rtol=0, atol=1e-12)
        np.testing.assert_allclose(chain.forward_body(q), expected, rtol=0, atol=1e-12)


@needs_data
@pytest.mark.parametrize("key", list(ARMS))
def test_names_types_and_limits_as_in_the_file(arms, key):
    if key not in arms:
        pytest.skip(f"{ARMS[key][0]} is not in this version of example-robot-data")
    chain, moving, _ = arms[key]
    assert chain.joint_names == tuple(j.get("name") for j in moving)
    assert chain.joint_types == tuple(j.get("type") for j in moving)
    for i, j in enumerate(moving):
        limit = j.find("limit")
        if j.get("type") == "continuous":
            assert chain.lower[i] == -np.inf and chain.upper[i] == np.inf
        else:
            assert chain.lower[i] == float(limit.get("lower", 0))
            assert chain.upper[i] == float(limit.get("upper", 0))
        if limit is not None:
            assert chain.velocity_limits[i] == float(limit.get("velocity", "inf"))
            assert chain.effort_limits[i] == float(limit.get("effort", "inf"))


@needs_data
def test_ur5_values_and_link_inertias(arms):
    chain = arms["ur5"][0]
    assert chain.n_joints == 6
    assert chain.joint_names[0] == "shoulder_pan_joint"
    np.testing.assert_array_equal(chain.upper[:2], [6.28318530718, 6.28318530718])
    np.testing.assert_array_equal(chain.effort_limits, [150, 150, 150, 28, 28, 28])
    inertias = chain.link_inertias
    assert inertias.shape == (6, 10)
    # shoulder_link: mass 3.7 at its frame origin, 0.089159 above the base
    np.testing.assert_allclose(inertias[0, :4], [3.7, 0, 0, 0.089159], rtol=0, atol=1e-15)
    np.testing.assert_allclose(inertias[0, 4:], [0.010267495893, 0, 0, 0.010267495893, 0, 0.00666], atol=1e-15)
    # upper_arm_link: 8.393 kg, com 0.28 along its z, which is the base x at home
    # (rpy 0 pi/2 0), with ixx and izz exchanged
    np.testing.assert_allclose(inertias[1, :4], [8.393, 0.28, 0.13585, 0.089159], rtol=0, atol=1e-11)
    np.testing.assert_allclose(inertias[1, [4, 7, 9]], [0.0151074, 0.22689067591, 0.22689067591], atol=1e-11)
    # the wrist_3 link and tool0 (fixed, no inertial): one body
    assert inertias[5, 0] == pytest.approx(0.1879)


@needs_data
def test_panda_folds_the_fixed_hand_and_keeps_the_tool(arms):
    chain, moving, path = arms["panda"]
    assert chain.n_joints == 7 and len(path) > 7  # joint8 and the hand joint are fixed
    # the tool is the hand: 0.107 + 0.1034 m beyond joint 7's origin along its z at home
    np.testing.assert_allclose(chain.forward(np.zeros(7)), reference_fk(path, np.zeros(7)), atol=1e-15)


@needs_data
def test_body_against_space_at_large_angles(arms):
    rng = np.random.default_rng(21)
    eps = np.finfo(float).eps
    for key, (chain, _, _) in arms.items():
        for scale in (3.3, 50.0, 1000.0):
            q = rng.uniform(-scale, scale, (200, chain.n_joints))
            diff = np.abs(chain.forward_body(q) - chain.forward(q)).max()
            # both within 2 eps (1 + |theta|) of the exact pose (the C++ suite's
            # LargeAnglesBodyAgreesWithSpace): at most twice that apart
            assert diff <= 4 * eps * (16 + scale), (key, scale, diff)


def test_modern_robotics_table_is_converted_and_the_raw_one_refused():
    mr = pytest.importorskip("modern_robotics")
    W1, W2, L1, L2, H1, H2 = 0.109, 0.082, 0.425, 0.392, 0.089, 0.095
    # Modern Robotics, example 4.5: Slist 6 x n, columns (w, v)
    Slist = np.array(
        [
            [0, 0, 1, 0, 0, 0],
            [0, 1, 0, -H1, 0, 0],
            [0, 1, 0, -H1, 0, L1],
            [0, 1, 0, -H1, 0, L1 + L2],
            [0, 0, -1, -W1, L1 + L2, 0],
            [0, 1, 0, H2 - H1, 0, L1 + L2],
        ]
    ).T
    M = np.array([[-1, 0, 0, L1 + L2], [0, 0, 1, W1 + W2], [0, 1, 0, H1 - H2], [0, 0, 0, 1]])
    from chasles import Twist

    screws = np.array([Twist.from_modern_robotics(s).vector for s in Slist.T])
    arm = Chain(screws, M)
    rng = np.random.default_rng(3)
    for _ in range(10):
        q = rng.uniform(-np.pi, np.pi, 6)
        np.testing.assert_allclose(arm.forward(q), mr.FKinSpace(M, Slist, q), rtol=0, atol=1e-13)
    with pytest.raises(ValueError, match=r"Slist.*Twist\.from_modern_robotics\(s\)\.vector for s in Slist\.T"):
        Chain(Slist, M)
    with pytest.raises(ValueError, match=r"\(w, v\) order.*Twist\.from_modern_robotics\(row\)\.vector"):
        Chain(Slist.T, M)
    with pytest.raises(ValueError, match=r"transposed.*screws\.T"):
        Chain(screws.T, M)
    with pytest.raises(ValueError, match=r"got \(6, 5\).*transposed.*Slist"):
        Chain(Slist[:, :5], M)


# ---- the bad descriptions ------------------------------------------------------


def urdf(joints, links=("a", "b", "c")):
    body = "".join(f'<link name="{n}"/>' for n in links)
    return f'<robot name="r">{body}{joints}</robot>'


def joint(name, kind, parent, child, extra='<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'):
    return f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>{extra}</joint>'


GOOD = joint("j1", "revolute", "a", "b") + joint("j2", "continuous", "b", "c", '<axis xyz="0 2 0"/>')


def test_small_description_parses():
    arm = Chain.from_urdf(urdf(GOOD), "c")
    assert arm.joint_names == ("j1", "j2") and arm.joint_types == ("revolute", "continuous")
    np.testing.assert_array_equal(arm.space_screws[1], [0, 0, 0, 0, 1, 0])  # the axis normalized
    np.testing.assert_array_equal(arm.lower, [-1, -np.inf])
    assert arm.link_inertias.shape == (2, 10)
    assert Chain.from_urdf(urdf(GOOD), "c", "b").joint_names == ("j2",)


def test_links_hanging_off_the_chain_ride_on_their_chain_link():
    # a -j1-> b -j2-> c (the chain, tip c); b carries a sensor (fixed, 1 m up
    # x) and c a finger (prismatic, off the chain: at zero, 1 m along y).
    def link(name, mass):
        return (
            f'<link name="{name}"><inertial><origin xyz="0 0 0"/><mass value="{mass}"/>'
            f'<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>'
        )

    text = (
        '<robot name="r">'
        + link("a", 5.0)
        + link("b", 1.0)
        + link("c", 2.0)
        + link("sensor", 1.0)
        + link("finger", 2.0)
        + joint("j1", "revolute", "a", "b")
        + joint("j2", "revolute", "b", "c")
        + joint("s", "fixed", "b", "sensor", '<origin xyz="1 0 0"/>')
        + joint(
            "f",
            "prismatic",
            "c",
            "finger",
            '<origin xyz="0 1 0"/><axis xyz="1 0 0"/><limit lower="0" upper="1" effort="1" velocity="1"/>',
        )
        + "</robot>"
    )
    arm = Chain.from_urdf(text, "c")
    (m1, *c1), (m2, *c2) = arm.link_inertias[:, :4]
    assert (m1, m2) == (2.0, 4.0)  # b + sensor, c + finger (the base link a is the base's)
    np.testing.assert_allclose(c1, [0.5, 0, 0], atol=1e-15)
    np.testing.assert_allclose(c2, [0, 0.5, 0], atol=1e-15)
    # parallel axis: each part 0.5 m from the merged center
    np.testing.assert_allclose(arm.link_inertias[0, 4:], [0.2, 0, 0, 0.2 + 0.5, 0, 0.2 + 0.5], atol=1e-15)


@needs_data
def test_panda_hand_carries_its_fingers(arms):
    chain, moving, path = arms["panda"]
    root = ET.parse(ROBOTS / ARMS["panda"][0]).getroot()
    mass = {
        link.get("name"): float(link.find("inertial/mass").get("value"))
        for link in root.findall("link")
        if link.find("inertial") is not None
    }
    # joint 7 moves link7, link8 and the hand (fixed), and the fingers (off the chain)
    expected = sum(
        mass.get(k, 0.0) for k in ("panda_link7", "panda_link8", "panda_hand", "panda_leftfinger", "panda_rightfinger")
    )
    assert chain.link_inertias[6, 0] == pytest.approx(expected, rel=1e-15)
    assert mass.get("panda_leftfinger", 0.0) > 0


@pytest.mark.parametrize(
    "text,tip,base,error",
    [
        (urdf(GOOD + joint("j3", "floating", "c", "d", ""), ("a", "b", "c", "d")), "d", None, "joint 'j3' is floating"),
        (urdf(GOOD + joint("j3", "planar", "c", "d", ""), ("a", "b", "c", "d")), "d", None, "joint 'j3' is planar"),
        (
            urdf(
                GOOD
                + joint(
                    "j3",
                    "revolute",
                    "c",
                    "d",
                    '<mimic joint="j2"/><limit lower="0" upper="1" effort="1" velocity="1"/>',
                ),
                ("a", "b", "c", "d"),
            ),
            "d",
            None,
            "joint 'j3': <mimic>",
        ),
        (urdf(joint("j1", "revolute", "a", "x")), "b", None, "joint 'j1' names a missing link 'x'"),
        (urdf(GOOD + joint("j3", "fixed", "c", "b", "")), "c", None, "link 'b' is the child of joints"),
        (urdf(GOOD), "nowhere", None, r"tip_link\): no link named 'nowhere'"),
        (urdf(GOOD), "c", "nowhere", r"base_link\): no link named 'nowhere'"),
        (urdf(GOOD), "b", "c", "tip_link 'b' is not below base_link 'c'"),
        (
            urdf(joint("j1", "revolute", "a", "b", '<axis xyz="0 0 1"/>'), ("a", "b")),
            "b",
            None,
            "joint 'j1': a revolute joint needs a <limit>",
        ),
        (
            urdf(joint("j1", "revolute", "a", "b", '<axis xyz="0 0 0"/><limit effort="1" velocity="1"/>'), ("a", "b")),
            "b",
            None,
            "<axis xyz> is zero",
        ),
        (urdf(joint("j1", "fixed", "a", "b", ""), ("a", "b")), "b", None, "no revolute, continuous or prismatic joint"),
        (urdf(joint("j1", "screwy", "a", "b", ""), ("a", "b")), "b", None, "unknown joint type 'screwy'"),
        ("<robot><link name='a'/>", "a", None, "not well-formed XML"),
        ("<model/>", "a", None, "expected a <robot> element"),
        (urdf(GOOD + joint("j3", "fixed", "a", "d", ""), ("a", "b", "c", "d", "e")), "c", None, "several root links"),
    ],
)
def test_bad_descriptions_name_the_element(text, tip, base, error):
    with pytest.raises(ValueError, match=error):
        Chain.from_urdf(text, tip, base)


def test_source_may_be_a_path(tmp_path):
    p = tmp_path / "arm.urdf"
    p.write_text(urdf(GOOD))
    assert Chain.from_urdf(p, "c") == Chain.from_urdf(str(p), "c") == Chain.from_urdf(urdf(GOOD), "c")
    with pytest.raises(TypeError, match="expected a path or the XML text"):
        Chain.from_urdf(3.0, "c")


# ---- hostile input (the contract shared with the C++ loader; the cases are in hostile_urdf.py) ----

PREFIX = "Chain.from_urdf: "
HOSTILE = {case.name: case for case in hostile_urdf.cases()}


def refusal(source, tip, base=None):
    """The text after the prefix of the loader's refusal."""
    with pytest.raises(ValueError) as info:
        Chain.from_urdf(source, tip, base)
    message = str(info.value)
    assert message.startswith(PREFIX), message
    return message[len(PREFIX) :]


@pytest.mark.parametrize(
    "name",
    # (the side branches: test_long_side_branch_rides_on_its_link)
    [n for n, c in HOSTILE.items() if c.error is None and c.agree == "exact" and not n.startswith("side branch")],
)
def test_hostile_descriptions_that_load(name):
    case = HOSTILE[name]
    arm = Chain.from_urdf(case.text, case.tip, case.base)
    assert arm.n_joints >= 1
    assert np.isfinite(arm.space_screws).all() and np.isfinite(arm.link_inertias).all()


@pytest.mark.parametrize("name", [n for n, c in HOSTILE.items() if c.error is not None])
def test_hostile_descriptions_refused_with_the_contracts_text(name):
    case = HOSTILE[name]
    text = refusal(case.text, case.tip, case.base)
    if case.agree == "prefix":
        assert text.startswith(case.error), text
    else:
        assert text == case.error


@pytest.mark.parametrize("n", [1000, 25_000])
def test_long_side_branch_rides_on_its_link(n, tmp_path):
    # b (1 kg, com 0.1 m along x) carries a branch of n fixed links 1 mm apart,
    # the last of 1 kg: n mm above b's frame, which is 0.5 m above the base
    text = hostile_urdf.side_branch(n)
    path = tmp_path / "branch.urdf"
    path.write_text(text)
    for source in (text, path):
        arm = Chain.from_urdf(source, "c")
        m, *com = arm.link_inertias[0, :4]
        assert m == 2.0
        np.testing.assert_allclose(com, [0.05, 0, 0.5 + n * 0.001 / 2], rtol=1e-12, atol=1e-15)


def test_a_side_branch_of_25000_links_is_a_few_megabytes():
    assert 2_000_000 < len(hostile_urdf.side_branch(25_000)) < 4_000_000


def test_nesting_bound_is_64():
    assert Chain.from_urdf(hostile_urdf.nested(64), "c").n_joints == 2
    deep = "the XML nests elements more than 64 deep, the bound on a URDF description"
    assert refusal(hostile_urdf.nested(65), "c") == deep
    # deeper than the parser's own recursion could go, closed or not
    assert refusal(hostile_urdf.nested(100_000), "c") == deep
    assert refusal('<robot name="r"><link name="c">' + "<x>" * 1_000_000, "c") == deep
    # self-closing elements at 64 load; one at 65 is an element 65 deep
    assert Chain.from_urdf(hostile_urdf.nested(64, "<x/><x a='/>'/>"), "c").n_joints == 2
    assert refusal(hostile_urdf.nested(65, "<x/>"), "c") == deep
    # markup that does not nest: comments, CDATA, instructions, quoted '>' and '/>'
    lots = "<x>" * 100
    inner = f"<!-- {lots} --><![CDATA[{lots}]]><?pi {lots} ?><x a='>' b=\"/>\"></x>"
    assert Chain.from_urdf(hostile_urdf.nested(64, inner), "c").n_joints == 2
    # a tag of many attributes (the scan counts it as a start tag; the parser's
    # events tell, exactly, that it nests no deeper)
    many = "<x" + "".join(f" a{i}='/>'" for i in range(1000)) + "/>"
    assert Chain.from_urdf(hostile_urdf.nested(64, many), "c").n_joints == 2


def test_entities_count_in_the_nesting():
    # expat expands the entities a document type declares: what it would
    # build is measured, not the text
    deep = "the XML nests elements more than 64 deep, the bound on a URDF description"
    assert refusal(HOSTILE["an entity expanding to deep nesting"].text, "c") == deep
    shallow = '<!DOCTYPE robot [<!ENTITY e "<x><x></x></x>">]>' + hostile_urdf.arm(c='<link name="c">&e;</link>')
    assert Chain.from_urdf(shallow, "c").n_joints == 2


def test_the_depth_scan_is_linear_on_unterminated_markup():
    # each of these would cost a quadratic time to a scan that looks for the
    # end of each piece of markup from each '<', or memory per repetition to
    # a regular expression that repeats a group without bound; here they are
    # a few MB each (refused as not well-formed XML: only that they finish is
    # asserted)
    for piece in ("<!--", "<![CDATA[", "<?", "<a x='", '<a x="', "<a ", "<a/", "<", "<a x=''"):
        with pytest.raises(ValueError):
            Chain.from_urdf("<robot>" + piece * 300_000, "c")


def test_numbers_are_printed_shortest_without_a_trailing_zero():
    case = HOSTILE["negative integer mass"]
    assert refusal(case.text, "c") == "link 'c' <mass>: negative mass -2 (a mass is >= 0)"
    case = HOSTILE["tiny negative mass"]
    assert refusal(case.text, "c") == "link 'c' <mass>: negative mass -1e-300 (a mass is >= 0)"


def test_huge_axis_and_origin():
    arm = Chain.from_urdf(HOSTILE["axis of 1e308"].text, "c")
    np.testing.assert_allclose(arm.space_screws[0, 3:], [2**-0.5, 2**-0.5, 0], rtol=0, atol=1e-16)
    arm = Chain.from_urdf(HOSTILE["tiny axis"].text, "c")  # subnormal components: scaled before the norm
    np.testing.assert_allclose(arm.space_screws[0, :3], [0, 0.6, 0.8], rtol=0, atol=1e-16)
    arm = Chain.from_urdf(HOSTILE["origin of 1e308 once"].text, "c")
    assert np.asarray(arm.home)[0, 3] == 1e308 + 0.3


def test_chain_validation_names_the_joint(monkeypatch):
    # the Chain constructor refuses by joint index: restated with the name
    real = _urdf._core.Chain

    def upper_below_lower(screws, home, **kw):
        kw["upper"] = [kw["upper"][0], kw["lower"][1] - 1]
        return real(screws, home, **kw)

    monkeypatch.setattr(_urdf._core, "Chain", upper_below_lower)
    text = refusal(hostile_urdf.arm(), "c")
    assert text.startswith("joint 'j2': expected lower <= upper"), text
    assert "Chain(" not in text and "joint 1" not in text


def test_text_or_path(tmp_path):
    text = hostile_urdf.arm()
    assert Chain.from_urdf("\ufeff \n" + text, "c") == Chain.from_urdf(text, "c")
    assert Chain.from_urdf(b"\xef\xbb\xbf\n" + text.encode(), "c") == Chain.from_urdf(text, "c")
    path = tmp_path / "arm.urdf"
    path.write_bytes(b"\xef\xbb\xbf\n" + text.encode())
    for source in (path, str(path), os.fsencode(path)):
        assert Chain.from_urdf(source, "c") == Chain.from_urdf(text, "c")
    # a path whose file name starts with a byte-order mark is still a path
    odd = tmp_path / "\ufeffarm.urdf"
    odd.write_text(text)
    assert Chain.from_urdf(str(odd), "c") == Chain.from_urdf(text, "c")


@pytest.mark.parametrize("kind", ["missing file", "directory", "larger than 64 MiB", "empty path", "/dev/zero", "FIFO"])
def test_sources_that_are_not_urdf_files(kind, tmp_path):
    cases = {name: (path, error) for name, path, error in hostile_urdf.path_cases(tmp_path)}
    if kind not in cases:
        pytest.skip(f"no {kind} on this system")
    path, error = cases[kind]
    assert refusal(path, "c") == error
    if path:
        assert refusal(Path(path), "c") == error


def test_text_larger_than_64_mib():
    head = '<robot name="r"><link name="c"/>'
    text = head + " " * (64 * 1024 * 1024 + 1 - len(head) - len("</robot>")) + "</robot>"
    assert len(text) == 64 * 1024 * 1024 + 1
    too_large = "the description is larger than 64 MiB, the bound on a URDF description"
    assert refusal(text, "c") == too_large
    assert refusal(text.encode(), "c") == too_large
    # the bound is on the UTF-8 bytes: 'é' is two
    accented = head + "é" * (32 * 1024 * 1024) + "</robot>"
    assert refusal(accented, "c") == too_large


def test_a_file_that_is_not_utf8(tmp_path):
    path = tmp_path / "latin1.urdf"
    path.write_bytes(hostile_urdf.arm(extra="<!-- caf\xe9 -->").encode("latin-1"))
    assert refusal(path, "c").startswith(f"'{path}' is not UTF-8 text")


def test_physically_impossible_inertias_are_not_refused():
    # the contract's decision: 48 link inertias of example-robot-data are not
    # positive semidefinite or violate the triangle inequality, and load
    # (diag(0, 0, 0.003) as anymal's hatch; moments 1, 1, 3; a negative moment)
    for inertia in (
        ("0", "0", "0", "0", "0", "0.003"),
        ("1", "0", "0", "1", "0", "3"),
        ("-0.1", "0", "0", "0.1", "0", "0.1"),
    ):
        arm = Chain.from_urdf(hostile_urdf.arm(c=hostile_urdf.link("c", 1.0, inertia=inertia)), "c")
        assert arm.link_inertias[1, 9] == float(inertia[5])
