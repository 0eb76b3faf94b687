"""Euler angles and RPY (SO3.from_euler / as_euler / from_rpy / as_rpy and the
array functions so3_from_euler / so3_as_euler / so3_from_rpy / so3_as_rpy)
against scipy's Rotation.from_euler / as_euler, for all 24 sequences, near
and at the gimbal lock on both sides."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import chasles

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

BASES = ("xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz")
SEQUENCES = BASES + tuple(s.upper() for s in BASES)
EPS = np.finfo(np.float64).eps


def proper(seq: str) -> bool:
    return seq[0].lower() == seq[2].lower()


def locks(seq: str) -> tuple:
    """The middle angles of the gimbal lock."""
    return (0.0, np.pi) if proper(seq) else (np.pi / 2, -np.pi / 2)


def scipy_as_euler(seq, R):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # scipy's "Gimbal lock detected"
        return Rotation.from_matrix(R).as_euler(seq)


def wrapped(a):
    """Angles mapped to (-pi, pi], to compare angles that may differ by 2 pi."""
    return np.remainder(np.asarray(a) + np.pi, 2 * np.pi) - np.pi


outer = st.floats(-3.1, 3.1)
sequences = st.sampled_from(SEQUENCES)


@st.composite
def generic_angles(draw):
    """A sequence and angles inside scipy's ranges, the middle angle at least
    1e-3 from the lock (conditioning of the outer angles below 1e3)."""
    seq = draw(sequences)
    middle = draw(st.floats(1e-3, np.pi - 1e-3) if proper(seq) else st.floats(-1.57, 1.57))
    return seq, np.array([draw(outer), middle, draw(outer)])


@st.composite
def near_lock_angles(draw):
    """A sequence and angles whose middle angle is within 1e-6 of a lock, on
    either side, 0 included."""
    seq = draw(sequences)
    lock = draw(st.sampled_from(locks(seq)))
    offset = draw(st.sampled_from([0.0, 1e-17, 1e-16, 1e-15, 1e-12, 1e-9, 5e-8, 1e-7, 3e-7, 1e-6]))
    sign = draw(st.sampled_from([1.0, -1.0]))
    return seq, np.array([draw(outer), lock + sign * offset, draw(outer)])


# ---- from_euler -----------------------------------------------------------------------


@given(generic_angles())
def test_from_euler_matches_scipy(case):
    seq, t = case
    ours = chasles.so3_from_euler(seq, t)
    np.testing.assert_allclose(ours, Rotation.from_euler(seq, t).as_matrix(), rtol=0, atol=2e-15)
    assert chasles.SO3.from_euler(seq, t).as_matrix().tobytes() == ours.tobytes()


@pytest.mark.parametrize("seq", SEQUENCES)
def test_from_euler_degrees_and_batches(seq):
    rng = np.random.default_rng(5)
    t = rng.uniform(-180, 180, size=(4, 5, 3))
    ours = chasles.so3_from_euler(seq, t, degrees=True)
    assert ours.shape == (4, 5, 3, 3)
    ref = Rotation.from_euler(seq, t.reshape(-1, 3), degrees=True).as_matrix().reshape(4, 5, 3, 3)
    np.testing.assert_allclose(ours, ref, rtol=0, atol=2e-15)
    # in the loop, the conversion of numpy's deg2rad: the same numbers
    assert np.array_equal(ours, chasles.so3_from_euler(seq, np.deg2rad(t)))
    assert np.array_equal(chasles.SO3.from_euler(seq, t[1, 2], True).as_matrix(), ours[1, 2])


# ---- as_euler -------------------------------------------------------------------------


@given(generic_angles())
def test_as_euler_agrees_with_scipy_away_from_the_lock(case):
    seq, t = case
    R = chasles.so3_from_euler(seq, t)
    ours = chasles.so3_as_euler(seq, R)
    # the outer angles' conditioning: 1 / |cos t2| (Tait-Bryan), 1 / |sin t2| (proper)
    cond = 1 / abs(np.sin(t[1]) if proper(seq) else np.cos(t[1]))
    np.testing.assert_allclose(wrapped(ours - scipy_as_euler(seq, R)), 0, atol=16 * EPS * cond)
    np.testing.assert_allclose(wrapped(ours - t), 0, atol=16 * EPS * cond)
    assert np.array_equal(chasles.SO3.from_matrix_unchecked(R).as_euler(seq), ours)


@given(sequences, st.integers(0, 2**32 - 1))
def test_as_euler_rebuilds_every_rotation(seq, seed):
    R = Rotation.random(20, random_state=seed).as_matrix()
    t = chasles.so3_as_euler(seq, R)
    assert np.abs(chasles.so3_from_euler(seq, t) - R).max() <= 1e-15
    assert np.abs(Rotation.from_euler(seq, t).as_matrix() - R).max() <= 2e-15


@given(near_lock_angles())
def test_as_euler_at_and_near_the_lock(case):
    # Next to the lock the outer angles are ill-determined, but the angles
    # returned rebuild R to 1e-15, where scipy (which declares the lock
    # within 1e-7 of it and sets the third angle to zero) loses up to 1e-7.
    seq, t = case
    R = chasles.so3_from_euler(seq, t)
    ours, lock = chasles.so3_as_euler(seq, R, return_gimbal_lock=True)
    # without the flag asked for, the same angles, and scipy's warning at the lock only
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert np.array_equal(chasles.so3_as_euler(seq, R), ours)
    assert len(caught) == int(bool(lock))
    assert np.abs(chasles.so3_from_euler(seq, ours) - R).max() <= 1e-15
    assert np.abs(Rotation.from_euler(seq, ours).as_matrix() - R).max() <= 2e-15
    lo, hi = (0, np.pi) if proper(seq) else (-np.pi / 2, np.pi / 2)
    assert lo <= ours[1] <= hi
    assert np.all(np.abs(ours) <= np.pi)
    if t[1] in locks(seq):
        # at the lock, scipy's choice: the third angle zero, the first one then
        # determined; as scipy's up to 2 pi
        assert ours[2] == 0.0
        theirs = scipy_as_euler(seq, R)
        assert theirs[2] == 0.0
        np.testing.assert_allclose(wrapped(ours - theirs), 0, atol=1e-14)


def scipy_warning(seq, R):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        Rotation.from_matrix(R).as_euler(seq)
    assert len(caught) == 1
    return caught[0]


@pytest.mark.parametrize("seq", SEQUENCES)
def test_the_gimbal_lock_warning_is_scipys(seq):
    """At the lock, the object method and the array functions warn as scipy
    does (category and text: a filter on scipy's catches chasles'), once per
    call and at the caller's line; return_gimbal_lock=True returns the flag
    instead; off the lock, no warning."""
    at = chasles.so3_from_euler(seq, [0.4, locks(seq)[0], -1.2])
    theirs = scipy_warning(seq, at)
    batch = np.stack([at, chasles.so3_from_euler(seq, [0.1, 0.2, 0.3]), at])
    calls = [
        lambda: chasles.so3_as_euler(seq, batch),
        lambda: chasles.so3_as_euler(seq, batch, out=np.empty((3, 3))),
        lambda: chasles.SO3.from_matrix(at).as_euler(seq),
    ]
    if seq == "xyz":
        calls += [lambda: chasles.so3_as_rpy(batch), lambda: chasles.SO3.from_matrix(at).as_rpy()]
    for call in calls:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            call()
        assert [(w.category, str(w.message)) for w in caught] == [(theirs.category, str(theirs.message))]
        assert caught[0].filename == __file__
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        angles, lock = chasles.so3_as_euler(seq, batch, return_gimbal_lock=True)
        assert lock.tolist() == [True, False, True]
        assert chasles.SO3.from_matrix(at).as_euler(seq, return_gimbal_lock=True)[1] is True
        chasles.so3_as_euler(seq, batch[1])  # off the lock: silent


@pytest.mark.parametrize("seq", SEQUENCES)
def test_scipy_loses_what_we_keep_next_to_the_lock(seq):
    # 5e-8 from the lock: scipy's angles rebuild R to about 5e-8 only; ours to 1e-15.
    t = np.array([0.7, locks(seq)[0] + 5e-8, -1.9])
    R = chasles.so3_from_euler(seq, t)
    theirs = Rotation.from_euler(seq, scipy_as_euler(seq, R)).as_matrix()
    assert np.abs(theirs - R).max() > 1e-8
    assert np.abs(chasles.so3_from_euler(seq, chasles.so3_as_euler(seq, R)) - R).max() <= 1e-15


@pytest.mark.parametrize("seq", SEQUENCES)
def test_as_euler_degrees(seq):
    R = Rotation.random(50, random_state=3).as_matrix()
    deg = chasles.so3_as_euler(seq, R, degrees=True)
    assert np.array_equal(deg, np.rad2deg(chasles.so3_as_euler(seq, R)))
    np.testing.assert_allclose(deg, Rotation.from_matrix(R).as_euler(seq, degrees=True), atol=1e-10)
    one = chasles.SO3.from_matrix_unchecked(R[7])
    assert np.array_equal(one.as_euler(seq, degrees=True), deg[7])


def test_float32():
    rng = np.random.default_rng(9)
    t = rng.uniform(-1.5, 1.5, size=(100, 3)).astype(np.float32)
    for seq in ("xyz", "ZXZ"):
        t[:, 1] = np.abs(t[:, 1]) + 0.05 if proper(seq) else t[:, 1]
        R = chasles.so3_from_euler(seq, t)
        assert R.dtype == np.float32
        ref = Rotation.from_euler(seq, t.astype(np.float64)).as_matrix()
        np.testing.assert_allclose(R, ref, atol=1e-6)
        back = chasles.so3_as_euler(seq, R)
        assert back.dtype == np.float32
        np.testing.assert_allclose(chasles.so3_from_euler(seq, back), R, atol=1e-6)


# ---- RPY ------------------------------------------------------------------------------


def test_rpy_is_urdfs_fixed_xyz():
    roll, pitch, yaw = 0.3, -1.2, 2.5
    c, s = np.cos, np.sin
    Rx = np.array([[1, 0, 0], [0, c(roll), -s(roll)], [0, s(roll), c(roll)]])
    Ry = np.array([[c(pitch), 0, s(pitch)], [0, 1, 0], [-s(pitch), 0, c(pitch)]])
    Rz = np.array([[c(yaw), -s(yaw), 0], [s(yaw), c(yaw), 0], [0, 0, 1]])
    R = chasles.SO3.from_rpy([roll, pitch, yaw])
    np.testing.assert_allclose(R.as_matrix(), Rz @ Ry @ Rx, rtol=0, atol=1e-15)
    np.testing.assert_allclose(R.as_rpy(), [roll, pitch, yaw], rtol=0, atol=1e-15)
    assert np.array_equal(chasles.so3_from_rpy([roll, pitch, yaw]), R.as_matrix())
    assert np.array_equal(chasles.so3_as_rpy(R.as_matrix()), R.as_rpy())
    deg = np.rad2deg([roll, pitch, yaw])
    assert np.array_equal(chasles.so3_from_rpy(deg, degrees=True), chasles.so3_from_euler("xyz", deg, True))
    assert np.array_equal(chasles.SO3.from_rpy(deg, degrees=True).as_matrix(), chasles.so3_from_rpy(deg, degrees=True))
    assert np.array_equal(chasles.so3_as_rpy(R.as_matrix(), degrees=True), R.as_rpy(degrees=True))
    np.testing.assert_allclose(R.as_rpy(degrees=True), deg, atol=1e-12)


# ---- ufunc keywords and errors ----------------------------------------------------------


def test_out_and_ufunc_keywords_pass_through():
    t = np.array([[0.1, 0.2, 0.3], [0.4, -0.5, 0.6]])
    out = np.empty((2, 3, 3))
    res = chasles.so3_from_euler("ZYX", t, out=out)
    assert res is out
    assert np.array_equal(out, chasles.so3_from_euler("ZYX", t))
    angles = np.empty((2, 3))
    assert chasles.so3_as_euler("ZYX", out, out=angles) is angles
    np.testing.assert_allclose(angles, t, atol=1e-15)
    # axes=: angles along the first axis
    np.testing.assert_array_equal(
        chasles.so3_from_euler("xyz", t.T, axes=[(0,), (-2, -1)]), chasles.so3_from_euler("xyz", t)
    )
    assert chasles.so3_from_euler("xyz", t, dtype=np.float32).dtype == np.float32


@pytest.mark.parametrize(
    "call",
    [
        lambda s: chasles.so3_from_euler(s, [0.1, 0.2, 0.3]),
        lambda s: chasles.so3_as_euler(s, np.eye(3)),
        lambda s: chasles.SO3.from_euler(s, [0.1, 0.2, 0.3]),
        lambda s: chasles.SO3().as_euler(s),
    ],
)
def test_bad_sequences(call):
    for bad in ("xxy", "xYz", "xy", "xyzx", "abc", "", "XYz"):
        with pytest.raises(ValueError, match=r"(?i)euler\(seq\).*three axes.*got"):
            call(bad)
    for bad in (None, 3, b"xyz", ["x", "y", "z"]):
        with pytest.raises(TypeError, match=r"euler\(seq\).*str"):
            call(bad)


def test_shape_errors_name_the_function():
    with pytest.raises(ValueError, match="so3_from_euler"):
        chasles.so3_from_euler("xyz", [0.1, 0.2])
    with pytest.raises(ValueError, match="so3_as_euler"):
        chasles.so3_as_euler("xyz", np.eye(4))
    with pytest.raises(ValueError, match=r"SO3.from_euler\(angles\).*shape \(3,\)"):
        chasles.SO3.from_euler("xyz", [0.1, 0.2])
    with pytest.raises(ValueError, match=r"SO3.from_rpy\(rpy\).*finite"):
        chasles.SO3.from_rpy([0.1, np.nan, 0.2])


# ---- the gimbal lock flag, and one ufunc for every sequence ----------------------


@pytest.mark.parametrize("seq", SEQUENCES)
def test_the_gimbal_lock_flag_reaches_python(seq):
    """as_euler's flag (C++ EulerAngles::gimbal_lock) is returned on request,
    for the array functions and the methods; the angles are unchanged."""
    lock = locks(seq)[0]
    angles = np.array([[0.3, lock, 0.2], [0.3, 0.7 if not proper(seq) else 1.1, 0.2]])
    R = chasles.so3_from_euler(seq, angles)
    got, flag = chasles.so3_as_euler(seq, R, return_gimbal_lock=True)
    assert flag.dtype == np.bool_ and flag.shape == (2,) and flag.tolist() == [True, False]
    with pytest.warns(UserWarning, match="Gimbal lock detected"):  # without the flag: scipy's warning
        assert np.array_equal(got, chasles.so3_as_euler(seq, R))
    deg, flag_deg = chasles.so3_as_euler(seq, R, degrees=True, return_gimbal_lock=True)
    with pytest.warns(UserWarning, match="Gimbal lock detected"):
        assert np.array_equal(deg, chasles.so3_as_euler(seq, R, degrees=True)) and np.array_equal(flag, flag_deg)
    for k in range(2):
        one, locked = chasles.SO3.from_matrix(R[k]).as_euler(seq, return_gimbal_lock=True)
        assert locked is bool(flag[k]) and np.array_equal(one, got[k])
    out = np.empty((2, 3))
    with pytest.warns(UserWarning, match="Gimbal lock detected"):
        assert chasles.so3_as_euler(seq, R, out=out) is out and np.array_equal(out, got)


def test_the_rpy_gimbal_lock_flag():
    R = chasles.so3_from_rpy([[0.1, np.pi / 2, 0.3], [0.1, 0.2, 0.3]])
    rpy, flag = chasles.so3_as_rpy(R, return_gimbal_lock=True)
    with pytest.warns(UserWarning, match="Gimbal lock detected"):
        assert flag.tolist() == [True, False] and np.array_equal(rpy, chasles.so3_as_rpy(R))
    one, locked = chasles.SO3.from_matrix(R[0]).as_rpy(degrees=True, return_gimbal_lock=True)
    with pytest.warns(UserWarning, match="Gimbal lock detected"):
        assert locked is True and np.array_equal(one, chasles.so3_as_rpy(R[0], degrees=True))
    assert chasles.SO3().as_rpy(return_gimbal_lock=True)[1] is False


def test_a_sequence_per_element_gives_each_elements_kernel():
    """The private ufuncs take the sequence and unit as an operand (the
    sequence's index, plus 24 for degrees): an array of codes (runs of equal
    ones, or all different) gives, per element, the bits of that sequence's
    and unit's kernel; a code outside [0, 48) gives NaN."""
    core = chasles._core
    rng = np.random.default_rng(3)
    t = rng.uniform(-1.0, 1.0, size=(96, 3))
    codes = np.array([k % 48 for k in range(96)], dtype=np.intc)
    codes[10:20] = 5  # a run
    R = core._so3_from_euler(t, codes)
    back = core._so3_as_euler(R, codes)
    back_lock, lock = core._so3_as_euler_lock(R, codes)
    assert np.array_equal(back, back_lock) and lock.dtype == np.bool_
    for i in range(96):
        s, degrees = SEQUENCES_IN_ENUM_ORDER[codes[i] % 24], bool(codes[i] >= 24)
        assert np.array_equal(R[i], chasles.so3_from_euler(s, t[i], degrees=degrees))
        assert np.array_equal(back[i], chasles.so3_as_euler(s, R[i], degrees=degrees))
    for bad in (48, -1):
        assert np.isnan(core._so3_from_euler(t[:2], np.intc(bad))).all()
        assert np.isnan(core._so3_as_euler(R[:2], np.intc(bad))).all()


SEQUENCES_IN_ENUM_ORDER = [s for s in SEQUENCES if s.islower()] + [s for s in SEQUENCES if s.isupper()]


def test_from_rpy_with_three_numbers_gets_chasles_error():
    """SO3.from_rpy(0.1, 0.2, 0.3): chasles' TypeError naming the expected
    shape, not pybind11's list of overloads."""
    with pytest.raises(
        TypeError,
        match=r"SO3\.from_rpy\(rpy, degrees=False\): expected rpy, one array_like of "
        r"shape \(3,\).*Three angles are one argument: SO3\.from_rpy\(\[roll, pitch, yaw\]\)",
    ) as e:
        chasles.SO3.from_rpy(0.1, 0.2, 0.3)
    assert "incompatible function arguments" not in str(e.value) and "Invoked with" not in str(e.value)
    with pytest.raises(TypeError, match=r"SO3\.from_rpy\(rpy, degrees=False\).*got \(\)"):
        chasles.SO3.from_rpy()
    assert chasles.SO3.from_rpy([0.1, 0.2, 0.3]) == chasles.SO3.from_euler("xyz", [0.1, 0.2, 0.3])
    assert "args" not in str(__import__("inspect").signature(chasles.SO3.from_rpy))
