"""Serial chains: ``chasles.Chain``, the robot model.

The model is the C++ ``chasles::Chain`` (include/chasles/kinematics.hpp),
held once, in the private extension class ``chasles._core._Chain``; its
dynamics are free functions of it (include/chasles/dynamics.hpp), its
inverse kinematics too (inverse_kinematics.hpp). ``Chain`` subclasses that
class, the pattern of ``numpy.linalg`` over ``_umath_linalg``: what computes
(forward kinematics, the Jacobians, the dynamics) are the extension's
methods, taken over as they are, so that one configuration costs one C++
call (no Python frame in between: a Python method around it would add a
tenth of a microsecond to a call of a few tenths), and a batch goes to the
private gufuncs ``chasles._core._chain_forward``, ``_inverse_dynamics``,
``_inverse_kinematics``, ... What is Python's is here: the joint names, the
validation messages and their diagnosis, the properties, pickling
(``__reduce__``: the constructor's arguments), ``from_urdf``; and the
inverse kinematics' result type (chasles._results.IKResult).
"""

from __future__ import annotations

import math
import warnings
from typing import Any, Optional

import numpy as np

from chasles import _core
from chasles._results import IKResult

_TYPES = ("revolute", "continuous", "prismatic", "helical")
_MAX_JOINTS = 32
_SCREW_TOLERANCE = 1.4901161193847656e-08  # Thresholds<double>::screw_tolerance (constants.hpp)
_DEFAULT_GRAVITY = (0.0, 0.0, -9.81)
_NONE = object()


def _short(x: float) -> str:
    return f"{x:.3g}"


def _tp_name(x: Any) -> str:
    t = type(x)
    return t.__name__ if t.__module__ == "builtins" else f"{t.__module__}.{t.__qualname__}"


def _joint_count(screws: Any) -> Optional[int]:
    """n when screws reads as an (n, 6) table of 1 <= n <= 32 rows, else None
    (the extension then refuses them with its message)."""
    try:
        shape = np.shape(screws)
    except Exception:
        return None
    if len(shape) == 2 and shape[1] == 6 and 1 <= shape[0] <= _MAX_JOINTS:
        return int(shape[0])
    return None


def _is_sequence(x: Any) -> bool:
    """PySequence_Check, as the constructor's checks were written: a str is one, a dict is not."""
    return not isinstance(x, dict) and hasattr(type(x), "__getitem__") and hasattr(type(x), "__len__")


def _type_codes(joint_types: Any, n: int) -> tuple:
    if isinstance(joint_types, str) or not _is_sequence(joint_types):
        raise TypeError(
            f"Chain(joint_types): expected a sequence of {n} of 'revolute', 'continuous', 'prismatic', "
            f"'helical', got {_tp_name(joint_types)}"
        )
    items = list(joint_types)
    if len(items) != n:
        raise ValueError(f"Chain(joint_types): expected {n} types (one per joint), got {len(items)}")
    codes = []
    for i, t in enumerate(items):
        if not isinstance(t, str):
            raise TypeError(f"Chain(joint_types): expected strings, got {_tp_name(t)} for joint {i}")
        if t not in _TYPES:
            raise ValueError(
                f"Chain(joint_types): expected 'revolute', 'continuous', 'prismatic' or 'helical', got '{t}' for "
                f"joint {i}"
            )
        codes.append(_TYPES.index(t))
    return tuple(codes)


def _inertia_rows(link_inertias: Any) -> Any:
    """A sequence of SpatialInertia as the packed (n, 10) rows (mass, com,
    ixx, ixy, ixz, iyy, iyz, izz); anything else as it is."""
    if (
        isinstance(link_inertias, (list, tuple))
        and link_inertias
        and all(isinstance(x, _core.SpatialInertia) for x in link_inertias)
    ):
        rows = []
        for body in link_inertias:
            I = body.inertia
            rows.append([body.mass, *body.com, I[0, 0], I[0, 1], I[0, 2], I[1, 1], I[1, 2], I[2, 2]])
        return np.array(rows, dtype=np.float64)
    return link_inertias


def _pose_array(g: Any) -> Optional[np.ndarray]:
    """A pose argument as given, as a (4, 4) float64 array (None stays None)."""
    if g is None:
        return None
    a = np.array(np.asarray(g, dtype=np.float64))
    a.flags.writeable = False
    return a


def _frozen(x: Any) -> Optional[np.ndarray]:
    if x is None:
        return None
    a = np.array(x, dtype=np.float64)
    a.flags.writeable = False
    return a


def _model_valid(screws: np.ndarray, codes: Optional[tuple]) -> bool:
    """Whether these screws with these types (None: inferred) make a valid chain."""
    c = _core._Chain.__new__(_core._Chain)
    _core._Chain.__init__(c, screws, np.eye(4), codes, None, None, None, None, None, None, None, None, True, True)
    return c._check()[0] == 0


def _invalid(chain: Any, status: int, joint: int, screws: np.ndarray, codes: Optional[tuple]) -> ValueError:
    with np.errstate(all="ignore"):  # |w| of w = 1e300 is inf, as the C++ check computed it
        return _invalid_message(chain, status, joint, screws, codes)


def _invalid_message(chain: Any, status: int, joint: int, screws: np.ndarray, codes: Optional[tuple]) -> ValueError:
    """The ValueError of Chain::validate()'s status (ChainStatus), naming the
    joint, the rule, and the conversion when the screws read as Modern
    Robotics' (w, v) order or as a transposed 6 x 6 table would be valid."""
    j = f"joint {joint}"
    v, w = screws[joint, :3], screws[joint, 3:] if joint >= 0 else (None, None)
    kind = _TYPES[chain._arrays()[2][joint]] if joint >= 0 else ""
    if status == 1:
        message = (
            f"Chain(screws): {j} is {kind} but its angular part w is not a unit vector "
            f"(|w| = {_short(math.sqrt(w @ w))}; unit_screws=False accepts a screw of any norm)"
        )
    elif status == 2:
        message = (
            f"Chain(screws): {j} is {kind} but its screw has a pitch: w . v = {_short(w @ v)} "
            f"(a revolute screw is (-w x q, w); a joint that turns and slides is 'helical')"
        )
    elif status == 3:
        message = f"Chain(screws): {j} is prismatic but its angular part w is not zero"
    elif status == 4:
        message = (
            f"Chain(screws): {j} is prismatic but its linear part v is not a unit vector "
            f"(|v| = {_short(math.sqrt(v @ v))}; unit_screws=False accepts a screw of any norm)"
        )
    elif status == 9:
        return ValueError(f"Chain(screws): {j}: expected a nonzero screw, got zero")
    else:
        arrays = chain._arrays()
        if status == 5:
            return ValueError(
                f"Chain(lower, upper): {j}: expected lower <= upper (-inf and inf for a continuous "
                f"joint), got {float(arrays[3][joint])!r} and {float(arrays[4][joint])!r}"
            )
        if status == 6:
            return ValueError(
                f"Chain(velocity_limits, effort_limits): {j}: expected limits >= 0, got "
                f"{float(arrays[5][joint])!r} and {float(arrays[6][joint])!r}"
            )
        if status == 8:
            return ValueError(
                f"Chain(link_inertias): {j}: expected finite numbers and a mass >= 0 (moved into the "
                f"world frame by the base frame)"
            )
        return ValueError("Chain(gravity): expected finite numbers")
    message += f" (tolerance {_short(_SCREW_TOLERANCE)})"
    swapped = np.concatenate([screws[:, 3:], screws[:, :3]], axis=1)
    if _model_valid(swapped, codes):
        message += (
            "; these rows read as Modern Robotics' (w, v) order: convert each with "
            "Twist.from_modern_robotics(row).vector"
        )
    elif screws.shape[0] == 6:
        T = np.ascontiguousarray(screws.T)
        if _model_valid(T, codes):
            message += "; the table reads as transposed (one column per joint): pass screws.T"
        elif _model_valid(np.concatenate([T[:, 3:], T[:, :3]], axis=1), codes):
            message += (
                "; the table reads as Modern Robotics' Slist (6 x n, one column (w, v) per joint): pass "
                "[Twist.from_modern_robotics(s).vector for s in Slist.T]"
            )
    return ValueError(message)


class _Deprecated:
    """A deprecated alias of a property (one release): reading it warns (DeprecationWarning) and
    gives the property it names."""

    def __init__(self, new: str) -> None:
        self.new = new
        self.__doc__ = f"Deprecated: the old name of ``{new}``."

    def __set_name__(self, owner: type, name: str) -> None:
        self.old = name

    def __get__(self, obj: Any, owner: Optional[type] = None) -> Any:
        if obj is None:
            return self
        warnings.warn(f"Chain.{self.old} is deprecated: use Chain.{self.new}", DeprecationWarning, stacklevel=2)
        return getattr(obj, self.new)


def _chain_from(cls: type, screws: Any, home: Any, arguments: dict) -> Any:
    """A chain of class cls from its constructor's arguments (unpickling, copies)."""
    chain = cls.__new__(cls)
    if "names" in arguments:  # pickled before the keyword was renamed joint_names
        arguments["joint_names"] = arguments.pop("names")
    _make(chain, screws, home, home_as_given=arguments.pop("_home_as_given", False), **arguments)
    return chain


class Chain(_core._Chain):
    """Forward kinematics, Jacobians, inverse kinematics and dynamics of a serial chain by the product of
    exponentials (Murray, Li and Sastry, ch. 3; Lynch and Park, Modern Robotics, ch. 4-5, 8).

    The chain is given by its space screws S_i (the joint twists at the home
    configuration in the base frame, one row (v, w) per joint, linear part first)
    and its home pose M = g(0); it keeps the body screws B_i = Ad_{M^-1} S_i.
    Revolute joints about the axis through q along w have the screw
    (-w x q, w) (``Chain.revolute_screw(point, direction)``: the point first, as
    in ``SE3.from_screw``), prismatic joints along v the screw (v, 0)
    (``Chain.prismatic_screw``). At most 32 joints. Its methods forward,
    forward_body, jacobian_space and jacobian_body are array functions: joint
    positions of shape (..., n) in, arrays out. The C++ ``chasles::Chain`` is
    the same model: ``space_screws`` is (n, 6) here, one row per joint, and 6 x n
    in C++, one column per joint.

    Example:
        >>> screws = [Chain.revolute_screw([0, 0, 0], [0, 0, 1]),
        ...           Chain.revolute_screw([1, 0, 0], [0, 0, 1])]
        >>> arm = Chain(screws, SE3(translation=[2.0, 0.0, 0.0]))
        >>> np.round(arm.forward([np.pi / 2, 0.0])[:3, 3], 12) + 0.0
        array([0., 2., 0.])
        >>> arm.jacobian_space([0.0, 0.0]).shape
        (6, 2)
        >>> Chain.revolute_screw([1, 0, 0], [0, 0, 2]) + 0.0
        array([ 0., -1.,  0.,  0.,  0.,  1.])
        >>> Chain.prismatic_screw([0, 3, 4])
        array([0. , 0.6, 0.8, 0. , 0. , 0. ])
        >>> slide = Chain([Chain.prismatic_screw([1, 0, 0])], np.eye(4))
        >>> slide.forward([0.5])[:3, 3], slide.forward([[0.5], [1.0]]).shape
        (array([0.5, 0. , 0. ]), (2, 4, 4))
        >>> turn = Chain([Chain.revolute_screw([1, 0, 0], [0, 0, 1])], np.eye(4))
        >>> np.allclose(turn.forward_body([0.3]), turn.forward([0.3]), rtol=0, atol=1e-15)
        True
        >>> turn = Chain([Chain.revolute_screw([0, 0, 0], [0, 0, 1])], SE3(translation=[1.0, 0.0, 0.0]))
        >>> turn.jacobian_space([0.3])[:, 0], np.round(turn.jacobian_body([0.3])[:, 0], 12) + 0.0
        (array([0., 0., 0., 0., 0., 1.]), array([0., 1., 0., 0., 0., 1.]))

    Conventions: those of every chasles class (``help(chasles.SE3)``); values
    are immutable, ``==`` is the exact equality of the model's numbers, and a
    chain pickles and copies bit-exactly.
    """

    __array_ufunc__ = None  # numpy defers operators (np.float64(1.0) == c) to us

    # The extension's methods, as they are (one configuration: one C++ call).
    forward = vars(_core._Chain)["forward"]
    forward_body = vars(_core._Chain)["forward_body"]
    jacobian_space = vars(_core._Chain)["jacobian_space"]
    jacobian_body = vars(_core._Chain)["jacobian_body"]
    jacobian_space_dot = vars(_core._Chain)["jacobian_space_dot"]
    jacobian_body_dot = vars(_core._Chain)["jacobian_body_dot"]
    inverse_dynamics = vars(_core._Chain)["inverse_dynamics"]
    forward_dynamics = vars(_core._Chain)["forward_dynamics"]
    mass_matrix = vars(_core._Chain)["mass_matrix"]
    gravity_torques = vars(_core._Chain)["gravity_torques"]
    coriolis = vars(_core._Chain)["coriolis"]
    inverse_dynamics_derivatives = vars(_core._Chain)["inverse_dynamics_derivatives"]
    forward_dynamics_derivatives = vars(_core._Chain)["forward_dynamics_derivatives"]
    mass_matrix_inverse = vars(_core._Chain)["mass_matrix_inverse"]
    inverse_kinematics = vars(_core._Chain)["inverse_kinematics"]
    home = vars(_core._Chain)["home"]
    revolute_screw = vars(_core._Chain)["revolute_screw"]
    prismatic_screw = vars(_core._Chain)["prismatic_screw"]

    def __init__(
        self,
        screws,
        home,
        *,
        joint_types=None,
        joint_names=None,
        lower=None,
        upper=None,  # type: ignore[no-untyped-def]
        velocity_limits=None,
        effort_limits=None,
        base=None,
        tool=None,
        gravity=None,
        link_inertias=None,
        unit_screws=True,
        names=None,
    ):
        # (no annotations: help() and inspect.signature show the parameters as the documentation writes
        # them, as for the extension's functions)
        """A serial chain from its space screws and its home pose, with its robot model.

        The base and tool frames are folded in: the chain's ``space_screws`` are
        Ad_base S_i and its ``home`` is base M tool (projected onto SE(3)), so that
        forward kinematics and the Jacobians are in the world frame and end at the
        tool; ``base`` and ``tool`` stay available.

        Each screw is checked against its joint's type: a revolute or continuous
        joint's angular part w must be a unit vector and its pitch w . v zero, a
        helical joint's w a unit vector (its pitch h = w . v, metres per radian, any),
        a prismatic joint's w zero and its linear part v a unit vector (to 1.5e-8).
        With ``unit_screws=False`` a screw may have any nonzero norm k: the joint
        then turns k radians (or slides k metres) per unit of its variable, as in
        Modern Robotics' chapter 8 example (a screw of norm sqrt(2)).
        A table in Modern Robotics' (w, v) order, or transposed (one column per
        joint, as MR's Slist), is refused with the conversion in the message.

        Args:
            screws: shape (n, 6), 1 <= n <= 32: row i is the space screw S_i = (v, w)
                of joint i at the home configuration, in the base frame, finite.
            home: SE3 or shape (4, 4), M = g(0), the tool frame at home (before
                ``tool``), in the base frame.
            joint_types: n of "revolute", "continuous", "prismatic", "helical"; None
                infers them (prismatic where w = 0, helical where the pitch w . v is
                not zero, revolute elsewhere).
            joint_names: n joint names (str), or None.
            lower: shape (n,), lower position limits (radians or metres); None: -inf.
            upper: shape (n,), upper position limits; None: inf. A continuous joint
                has -inf and inf.
            velocity_limits: shape (n,), >= 0; None: inf.
            effort_limits: shape (n,), >= 0 (N m or N); None: inf.
            base: SE3 or shape (4, 4), the base frame in the world frame; None: identity.
            tool: SE3 or shape (4, 4), the tool frame after M; None: identity.
            gravity: shape (3,), in the world frame, m/s^2; None: (0, 0, -9.81).
            link_inertias: per joint the inertia of the link it moves, in the base
                frame at home: a sequence of n SpatialInertia, or shape (n, 10)
                (mass, center of mass (3), ixx, ixy, ixz, iyy, iyz, izz about the
                center of mass; ``Chain.from_urdf`` fills it), or None.
            unit_screws: True (the default) requires unit screws (|w| = 1, or |v| = 1 for
                a prismatic joint); False accepts any nonzero norm.
            names: deprecated, the old name of ``joint_names`` (warns).

        Raises:
            ValueError: a shape other than (n, 6), more than 32 joints, a non-finite
                entry, a home, base or tool matrix that is not a rigid motion, a
                screw that does not match its joint type, lower > upper, a negative
                velocity or effort limit, a negative mass.
            TypeError: joint types or names that are not strings.

        Example:
            >>> arm = Chain([[0, 0, 0, 0, 0, 1]], np.eye(4))
            >>> arm.n_joints
            1
            >>> arm = Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_types=["revolute"],
            ...             joint_names=["shoulder"], lower=[-1.5], upper=[1.5])
            >>> arm
            Chain(n_joints=1, joint_names=('shoulder',))
        """
        if names is not None:
            if joint_names is not None:
                raise TypeError("Chain: give joint_names only (names is its deprecated old name)")
            warnings.warn(
                "Chain(names=...) is deprecated: use Chain(joint_names=...)", DeprecationWarning, stacklevel=2
            )
            joint_names = names
        _make(
            self,
            screws,
            home,
            joint_types=joint_types,
            joint_names=joint_names,
            lower=lower,
            upper=upper,
            velocity_limits=velocity_limits,
            effort_limits=effort_limits,
            base=base,
            tool=tool,
            gravity=gravity,
            link_inertias=link_inertias,
            unit_screws=unit_screws,
        )

    # ---- properties ------------------------------------------------------------------------

    @property
    def space_screws(self) -> np.ndarray:
        """numpy.ndarray: shape (n, 6), the space screws S_i, one row (v, w) per joint (a copy; the
        C++ Chain::space_screws() is the same numbers as 6 x n, one column per joint)."""
        return _m(self)[0].copy()

    screws = _Deprecated("space_screws")

    @property
    def body_screws(self) -> np.ndarray:
        """numpy.ndarray: shape (n, 6), the body screws B_i = Ad_{M^-1} S_i (a copy)."""
        return _m(self)[1].copy()

    @property
    def n_joints(self) -> int:
        """int: n, the number of joints."""
        return len(_m(self)[2])

    @property
    def joint_types(self) -> tuple:
        """tuple[str, ...]: each joint's type: "revolute", "continuous", "prismatic" or "helical"."""
        return tuple(_TYPES[c] for c in _m(self)[2])

    @property
    def joint_names(self) -> Optional[tuple]:
        """tuple[str, ...] | None: the joint names, or None when none were given."""
        _require(self)
        return self._names

    names = _Deprecated("joint_names")

    @property
    def lower(self) -> np.ndarray:
        """numpy.ndarray: shape (n,), the lower position limits (-inf where none; a copy)."""
        return _m(self)[3].copy()

    @property
    def upper(self) -> np.ndarray:
        """numpy.ndarray: shape (n,), the upper position limits (inf where none; a copy)."""
        return _m(self)[4].copy()

    @property
    def velocity_limits(self) -> np.ndarray:
        """numpy.ndarray: shape (n,), the velocity limits (inf where none; a copy)."""
        return _m(self)[5].copy()

    @property
    def effort_limits(self) -> np.ndarray:
        """numpy.ndarray: shape (n,), the effort limits, N m or N (inf where none; a copy)."""
        return _m(self)[6].copy()

    @property
    def base(self) -> Any:
        """SE3: the base frame in the world frame (already folded into space_screws and home)."""
        return _m(self)[7]

    @property
    def tool(self) -> Any:
        """SE3: the tool frame after the last link (already folded into home)."""
        return _m(self)[8]

    @property
    def gravity(self) -> np.ndarray:
        """numpy.ndarray: shape (3,), gravity in the world frame, m/s^2 (a copy)."""
        return _m(self)[9].copy()

    @property
    def link_inertias(self) -> Optional[np.ndarray]:
        """numpy.ndarray | None: shape (n, 10), per joint the inertia of the link it moves
        (with the links that ride on it): mass, center of mass (3), then ixx, ixy, ixz,
        iyy, iyz, izz of the rotational inertia about the center of mass, both in
        the base frame at home; None when not given (a copy)."""
        _require(self)
        return None if self._inertias is None else self._inertias.copy()

    # ---- URDF --------------------------------------------------------------------------------

    @staticmethod
    def from_urdf(source: Any, tip_link: str, base_link: Optional[str] = None) -> Chain:
        """The chain from base_link to tip_link of a URDF robot description.

        Revolute, continuous and prismatic joints become the chain's joints (their
        names, types, limits); fixed joints are folded into the next joint's screw
        or into the home pose; each moving joint's child link's ``<inertial>``,
        with those of the links that ride on it, goes to ``link_inertias``: links
        after it up to the next moving joint, and links hanging off the chain (side
        branches, and the links below tip_link), fixed joints as they are and
        moving joints off the chain at zero, as Pinocchio's buildReducedModel at
        the neutral configuration. The home pose is
        tip_link's frame at zero joint positions. Parsed with the standard
        library's xml.etree (chasles/_urdf.py): URDF's kinematic and inertial
        elements only, no meshes.

        The source is XML text when, after an optional byte-order mark and
        whitespace, it starts with '<'; otherwise it is a path, which must name a
        regular file of at most 64 MiB (read with that bound; UTF-8). Elements may
        nest at most 64 deep (checked before the parser sees the text). A
        refusal names the joint, link or path, in the words the C++ loader
        chain_from_urdf uses too. Physically impossible inertias (not positive
        semidefinite, or violating the triangle inequality) are not refused:
        48 of the 1,985 link inertias of example-robot-data are such (tiago's
        antennas, anymal's hatch, icub's legs), and those robots load; their
        mass matrix may then not be positive definite (the C++
        SpatialInertia::is_physical() tells which inertias are physical).

        Args:
            source: a path (str, bytes or os.PathLike) to a .urdf file, or the XML
                text (str, or UTF-8 bytes).
            tip_link: the name of the last link (the tool).
            base_link: the name of the base link; None: the root of the tree.

        Returns:
            Chain.

        Raises:
            ValueError: a malformed description; a floating or planar joint, or a
                mimic joint, between base and tip; a joint naming a missing link; a
                loop; duplicate link or joint names; an unknown tip or base link, or
                a tip not below the base; a number that is not finite in the file or
                overflows when combined (poses composed along the chain, masses
                summed); a negative mass, lower > upper, a negative velocity or
                effort limit, a zero axis; a path that is not a regular file, a file
                or text larger than 64 MiB, elements nested more than 64 deep.

        Example:
            >>> urdf = \"\"\"<robot name="r"><link name="a"/><link name="b"/>
            ...   <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
            ...     <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
            ...     <limit lower="-1" upper="1" effort="10" velocity="2"/></joint></robot>\"\"\"
            >>> arm = Chain.from_urdf(urdf, "b")
            >>> arm.joint_names, arm.joint_types, arm.upper
            (('j',), ('revolute',), array([1.]))
        """
        from chasles._urdf import chain_from_urdf

        return chain_from_urdf(source, tip_link, base_link)

    # ---- value protocol ----------------------------------------------------------------------

    def __eq__(self, other: object) -> Any:
        """Exact equality of the model's numbers (the space screws, home pose, types, limits, base,
        tool, gravity, names and link inertias), compared as floats; chains are unhashable."""
        _require(self)
        if not isinstance(other, Chain):
            return NotImplemented
        _require(other)
        a, b = self._model, other._model
        same = lambda x, y: x is None and y is None or x is not None and y is not None and np.array_equal(x, y)  # noqa: E731
        return (
            a[2] == b[2]
            and all(np.array_equal(a[k], b[k]) for k in (0, 3, 4, 5, 6, 9))
            and all(
                np.array_equal(np.asarray(x), np.asarray(y))
                for x, y in ((self.home, other.home), (a[7], b[7]), (a[8], b[8]))
            )
            and self._names == other._names
            and same(self._inertias, other._inertias)
        )

    def __ne__(self, other: object) -> Any:
        """The negation of ``==``."""
        equal = Chain.__eq__(self, other)
        return equal if equal is NotImplemented else not equal

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        _is_chain(self)
        if "_model" not in self.__dict__:
            return "<uninitialized Chain>"
        out = f"Chain(n_joints={self.n_joints}"
        if self._names is not None:
            out += f", joint_names={self._names!r}"
        return out + ")"

    def __reduce__(self) -> tuple:
        """Pickle support (every protocol) and copy: the constructor's arguments."""
        _require(self)
        screws, home, arguments = self._given
        return (_chain_from, (type(self), screws, home, dict(arguments)))

    def __reduce_ex__(self, protocol: int) -> tuple:
        """Pickle support at every protocol: as __reduce__."""
        return Chain.__reduce__(self)

    def __copy__(self) -> Chain:
        """A Chain equal to this one (of the class Chain, as the extension's copies were)."""
        f, args = Chain.__reduce__(self)
        return f(Chain, *args[1:])

    def __deepcopy__(self, memo: dict) -> Chain:
        return Chain.__copy__(self)

    def __getstate__(self) -> tuple:
        """The state of chasles 0.1.0's pickles (which still load: __setstate__). A chain without a
        model (types inferred, no limits, names or inertias, identity base and tool, default
        gravity): its space screws row by row, then the home pose's rotation row by row and
        translation, 6 n + 12 floats. Any other: (numbers, names, inertias), numbers the screws
        and home as given, the type codes, the four limits, base and tool as given and gravity
        (11 n + 39 floats), names None or n str, inertias None or 10 n floats. A chain made
        with unit_screws=False (which 0.1.0 could not make): (numbers, names, inertias, False)."""
        _require(self)
        S, _, codes, lower, upper, velocity, effort, base, tool, gravity = self._model
        screws, home, arguments = self._given
        inferred = tuple(0 if np.any(row[3:] != 0) else 2 for row in S)

        def pose(g: Any) -> list:
            m = np.eye(4) if g is None else np.asarray(g)
            return [float(x) for x in m[:3, :3].ravel()] + [float(x) for x in m[:3, 3]]

        identity = lambda g: g is None or np.array_equal(np.asarray(g)[:3], np.eye(4)[:3])  # noqa: E731
        unit = arguments["unit_screws"]
        plain = (
            unit
            and self._names is None
            and self._inertias is None
            and identity(arguments["base"])
            and identity(arguments["tool"])
            and tuple(gravity) == _DEFAULT_GRAVITY
            and codes == inferred
            and np.all(lower == -np.inf)
            and np.all(upper == np.inf)
            and np.all(velocity == np.inf)
            and np.all(effort == np.inf)
        )
        if plain:
            return tuple(float(x) for x in S.ravel()) + tuple(pose(self.home))
        numbers = [float(x) for x in screws.ravel()] + pose(home) + [float(c) for c in codes]
        for v in (lower, upper, velocity, effort):
            numbers += [float(x) for x in v]
        numbers += pose(arguments["base"]) + pose(arguments["tool"]) + [float(x) for x in gravity]
        inertias = None if self._inertias is None else tuple(float(x) for x in self._inertias.ravel())
        return (tuple(numbers), self._names, inertias) + (() if unit else (False,))

    def __setstate__(self, state: Any) -> None:
        """Unpickling a state of chasles 0.1.0 (__getstate__'s layouts), checked as the
        constructor checks its arguments (a pickle is data from outside); the chain is rebuilt from
        them by the same arithmetic, so bit for bit."""
        _is_chain(self)
        try:
            _setstate(self, state)
        except (TypeError, ValueError) as e:
            text = str(e)
            for prefix in ("Chain.__setstate__: ", "Chain.__init__: "):  # the constructor's own name
                if text.startswith(prefix):
                    text = text[len(prefix) :]
                    break
            raise type(e)(f"Chain.__setstate__: {text}") from None


def _make(
    self: Any,
    screws: Any,
    home: Any,
    *,
    home_as_given: bool = False,
    joint_types: Any = None,
    joint_names: Any = None,
    lower: Any = None,
    upper: Any = None,
    velocity_limits: Any = None,
    effort_limits: Any = None,
    base: Any = None,
    tool: Any = None,
    gravity: Any = None,
    link_inertias: Any = None,
    unit_screws: bool = True,
) -> None:
    if not isinstance(unit_screws, (bool, np.bool_)):
        raise TypeError(f"Chain(unit_screws): expected a bool, got {_tp_name(unit_screws)}")
    unit_screws = bool(unit_screws)
    n = _joint_count(screws)
    codes = None if joint_types is None or n is None else _type_codes(joint_types, n)
    inertias = _inertia_rows(link_inertias)
    _core._Chain.__init__(
        self,
        screws,
        home,
        codes,
        lower,
        upper,
        velocity_limits,
        effort_limits,
        base,
        tool,
        gravity,
        inertias,
        home_as_given,
        unit_screws,
    )
    given = np.array(screws, dtype=np.float64)
    status, joint = self._check()
    if status != 0:
        raise _invalid(self, status, joint, given, codes)
    n = given.shape[0]
    names = joint_names
    if names is not None:
        if isinstance(names, str) or not _is_sequence(names):
            raise TypeError(f"Chain(joint_names): expected a sequence of {n} strings, got {_tp_name(names)}")
        if len(names) != n:
            raise ValueError(f"Chain(joint_names): expected {n} names (one per joint), got {len(names)}")
        for i in range(n):
            if not isinstance(names[i], str):
                raise TypeError(f"Chain(joint_names): expected strings, got {_tp_name(names[i])} for joint {i}")
        names = tuple(str(x) for x in names)
    arrays = self._arrays()
    for a in arrays:
        if isinstance(a, np.ndarray):
            a.flags.writeable = False
    self._model = arrays
    self._names = names
    self._inertias = None if inertias is None else _frozen(inertias)
    given.flags.writeable = False
    self._given = (
        given,
        _pose_array(home),
        {
            "_home_as_given": home_as_given,
            "joint_types": None if joint_types is None else tuple(_TYPES[c] for c in codes),
            "joint_names": names,
            "lower": _frozen(lower),
            "upper": _frozen(upper),
            "velocity_limits": _frozen(velocity_limits),
            "effort_limits": _frozen(effort_limits),
            "base": _pose_array(base),
            "tool": _pose_array(tool),
            "gravity": _frozen(gravity),
            "link_inertias": self._inertias,
            "unit_screws": unit_screws,
        },
    )


def _setstate(self: Any, state: Any) -> None:
    def bad() -> ValueError:
        return ValueError(
            f"Chain.__setstate__: expected a tuple of 6 n + 12 floats, 1 <= n <= {_MAX_JOINTS}, "
            f"or (numbers, names, inertias[, False]): a tuple of 11 n + 39 floats, None or n str, "
            f"None or 10 n floats, and False for screws of any norm (unit_screws=False)"
        )

    def floats(t: tuple) -> np.ndarray:
        for k, x in enumerate(t):
            if not isinstance(x, float):
                raise TypeError(f"Chain.__setstate__: expected a tuple of floats, got {_tp_name(x)} at position {k}")
        return np.array(t, dtype=np.float64)

    def pose(x: np.ndarray) -> np.ndarray:
        M = np.eye(4)
        M[:3, :3] = x[:9].reshape(3, 3)
        M[:3, 3] = x[9:12]
        return M

    model = isinstance(state, tuple) and len(state) in (3, 4) and isinstance(state[0], tuple)
    if not model:
        size = len(state) if isinstance(state, tuple) else -1
        n = (size - 12) // 6
        if size < 0 or (size - 12) % 6 != 0 or not 1 <= n <= _MAX_JOINTS:
            raise bad()
        x = floats(state)
        _make(self, x[: 6 * n].reshape(n, 6), pose(x[6 * n :]), home_as_given=True)
        return
    numbers, names, inertias = state[:3]
    if len(state) == 4 and state[3] is not False:
        raise bad()
    size = len(numbers)
    n = (size - 39) // 11
    if (size - 39) % 11 != 0 or not 1 <= n <= _MAX_JOINTS:
        raise bad()
    x = floats(numbers)
    k = 6 * n + 12
    codes = x[k : k + n]
    if not np.all((codes >= 0) & (codes < len(_TYPES)) & (codes == np.floor(codes))):
        raise bad()
    limits = [x[k + n + i * n : k + n + (i + 1) * n] for i in range(4)]
    k += 5 * n
    if inertias is not None:
        if not isinstance(inertias, tuple) or len(inertias) != 10 * n:
            raise bad()
        inertias = floats(inertias).reshape(n, 10)
    _make(
        self,
        x[: 6 * n].reshape(n, 6),
        pose(x[6 * n : 6 * n + 12]),
        joint_types=[_TYPES[int(c)] for c in codes],
        joint_names=names,
        lower=limits[0],
        upper=limits[1],
        velocity_limits=limits[2],
        effort_limits=limits[3],
        base=pose(x[k : k + 12]),
        tool=pose(x[k + 12 : k + 24]),
        gravity=x[k + 24 : k + 27],
        link_inertias=inertias,
        unit_screws=len(state) == 3,
    )


def _is_chain(chain: Any) -> None:
    if not isinstance(chain, Chain):
        raise TypeError(f"expected a Chain, got {_tp_name(chain)}")


def _require(chain: Any) -> None:
    _is_chain(chain)
    if "_model" not in chain.__dict__:
        raise TypeError("Chain object is not initialized: it was made by __new__ alone, without __init__")


def _m(chain: Any) -> tuple:
    """The chain's model arrays; TypeError for an object made by __new__ alone."""
    _require(chain)
    return chain.__dict__["_model"]


# The result type of the extension's inverse_kinematics (the bindings import nothing of the package).
_core._Chain._set_ik_result(IKResult)

# Pickles of chasles 0.1.0 name the class chasles._core.Chain: it is this one.
_core.Chain = Chain
