"""Chain.from_urdf: a serial chain from a URDF robot description.

Parsed with the standard library's xml.etree: URDF's kinematic and inertial
elements (<link>, <joint> with <parent>, <child>, <origin xyz rpy>, <axis>,
<limit>, <mimic>; <inertial> with <origin>, <mass>, <inertia>) are all a
chain needs, and the parsers on PyPI that read more (yourdfpy pulls in
trimesh for the meshes; urdf_parser_py needs ROS' packaging) would add heavy
dependencies for nothing used here. The chain itself is the C++ one.

Conventions (URDF, https://wiki.ros.org/urdf/XML/joint): a joint's <origin>
is the pose of its child link's frame in its parent link's frame at zero
joint position, translation xyz then rotation R = Rz(yaw) Ry(pitch) Rx(roll)
(chasles.SO3.from_rpy); <axis> (default (1, 0, 0)) is in the joint frame
(= the child link frame) and is normalized here; <limit> gives lower, upper
(revolute, prismatic), velocity and effort. A continuous joint has no
position limits (-inf, inf).
"""

from __future__ import annotations

import math
import os
import xml.etree.ElementTree as ET

import numpy as np

from . import _core

MOVING = ("revolute", "continuous", "prismatic")


def _floats(text, count, what):
    try:
        values = [float(x) for x in text.split()]
    except ValueError:
        raise ValueError(f"Chain.from_urdf: {what}: expected {count} numbers, got {text!r}") from None
    if len(values) != count or not all(math.isfinite(x) for x in values):
        raise ValueError(f"Chain.from_urdf: {what}: expected {count} finite numbers, got {text!r}")
    return np.array(values)


def _pose(element, what):
    """The 4x4 pose of an <origin> element (identity when it is None)."""
    T = np.eye(4)
    if element is None:
        return T
    T[:3, 3] = _floats(element.get("xyz", "0 0 0"), 3, f"{what} <origin xyz>")
    rpy = _floats(element.get("rpy", "0 0 0"), 3, f"{what} <origin rpy>")
    T[:3, :3] = _core.SO3.from_rpy(rpy).as_matrix()
    return T


def _attribute(element, name, what, default=None):
    text = element.get(name)
    if text is None:
        if default is None:
            raise ValueError(f"Chain.from_urdf: {what}: missing attribute {name!r}")
        return default
    return _floats(text, 1, f"{what} {name}")[0]


def _read(source):
    if isinstance(source, os.PathLike) or (isinstance(source, str) and not source.lstrip().startswith("<")):
        with open(source, encoding="utf-8") as f:
            text = f.read()
    elif isinstance(source, (str, bytes)):
        text = source
    else:
        raise TypeError(
            f"Chain.from_urdf(source): expected a path or the XML text, got {type(source).__name__}"
        )
    try:
        root = ET.fromstring(text)
    except ET.ParseError as e:
        raise ValueError(f"Chain.from_urdf(source): not well-formed XML: {e}") from None
    if root.tag != "robot":
        raise ValueError(f"Chain.from_urdf(source): expected a <robot> element, got <{root.tag}>")
    return root


def _inertial(link, T_link):
    """(mass, com (3,), inertia about com (3, 3)) of a link's <inertial>, in
    the base frame at home (T_link: the link frame there), or None."""
    inertial = link.find("inertial")
    if inertial is None:
        return None
    what = f"link {link.get('name')!r}"
    mass_el = inertial.find("mass")
    mass = 0.0 if mass_el is None else _attribute(mass_el, "value", f"{what} <mass>")
    T = T_link @ _pose(inertial.find("origin"), what)
    I_el = inertial.find("inertia")
    I = np.zeros((3, 3))
    if I_el is not None:
        ixx, ixy, ixz, iyy, iyz, izz = (
            _attribute(I_el, k, f"{what} <inertia>", 0.0)
            for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
        )
        I = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
    R = T[:3, :3]
    return mass, T[:3, 3].copy(), R @ I @ R.T


def _merge(parts):
    """One body from several (mass, com, inertia about com), all in one frame:
    the total mass, the mass-weighted center, and each inertia moved to it by
    the parallel-axis theorem, I + m (|d|^2 1 - d d^T)."""
    mass = sum(m for m, _, _ in parts)
    if mass <= 0:
        return 0.0, np.zeros(3), sum((I for _, _, I in parts), np.zeros((3, 3)))
    com = sum(m * c for m, c, _ in parts) / mass
    inertia = np.zeros((3, 3))
    for m, c, I in parts:
        d = c - com
        inertia += I + m * (d @ d * np.eye(3) - np.outer(d, d))
    return mass, com, inertia


def chain_from_urdf(source, tip_link, base_link=None):
    root = _read(source)
    links = {}
    for link in root.findall("link"):
        name = link.get("name")
        if name is None:
            raise ValueError("Chain.from_urdf: a <link> without a name")
        links[name] = link
    parent_joint = {}  # child link -> its joint element
    for joint in root.findall("joint"):
        name = joint.get("name")
        what = f"joint {name!r}"
        parent, child = joint.find("parent"), joint.find("child")
        if parent is None or child is None or parent.get("link") is None or child.get("link") is None:
            raise ValueError(f"Chain.from_urdf: {what}: expected <parent link=...> and <child link=...>")
        for end in (parent.get("link"), child.get("link")):
            if end not in links:
                raise ValueError(f"Chain.from_urdf: {what} names a missing link {end!r}")
        c = child.get("link")
        if c in parent_joint:
            raise ValueError(
                f"Chain.from_urdf: link {c!r} is the child of joints {parent_joint[c].get('name')!r} "
                f"and {name!r}: a loop (URDF describes trees)"
            )
        parent_joint[c] = joint
    for label, link in (("tip_link", tip_link), ("base_link", base_link)):
        if link is not None and not isinstance(link, str):
            raise TypeError(f"Chain.from_urdf({label}): expected a link name (str), got {type(link).__name__}")
        if link is not None and link not in links:
            raise ValueError(f"Chain.from_urdf({label}): no link named {link!r} in the description")
    roots = [name for name in links if name not in parent_joint]
    if base_link is None:
        if len(roots) != 1:
            raise ValueError(
                "Chain.from_urdf: the description has no root link (a loop)"
                if not roots
                else f"Chain.from_urdf: several root links {roots}: pass base_link"
            )
        base_link = roots[0]
    # From the tip up to the base.
    path, link, seen = [], tip_link, set()
    while link != base_link:
        if link in seen:
            raise ValueError(f"Chain.from_urdf: a loop through link {link!r}")
        seen.add(link)
        joint = parent_joint.get(link)
        if joint is None:
            raise ValueError(
                f"Chain.from_urdf: tip_link {tip_link!r} is not below base_link {base_link!r}"
            )
        path.append(joint)
        link = joint.find("parent").get("link")
    path.reverse()
    # Links hanging off the chain (side branches, and what is below the tip)
    # ride rigidly on the chain link they hang from: fixed joints as they
    # are, moving joints off the chain at zero (as Pinocchio's
    # buildReducedModel at the neutral configuration).
    children = {}
    for joint in root.findall("joint"):
        children.setdefault(joint.find("parent").get("link"), []).append(joint)
    on_path = {base_link} | {joint.find("child").get("link") for joint in path}

    def hanging_parts(link, T_link):
        parts = []
        for joint in children.get(link, []):
            child = joint.find("child").get("link")
            if child in on_path:
                continue
            T_child = T_link @ _pose(joint.find("origin"), f"joint {joint.get('name')!r}")
            part = _inertial(links[child], T_child)
            if part is not None:
                parts.append(part)
            parts += hanging_parts(child, T_child)
        return parts

    screws, types, names, lower, upper, velocity, effort = [], [], [], [], [], [], []
    bodies = []  # per moving joint, the (mass, com, inertia) of the links it moves
    T = np.eye(4)
    for joint in path:
        name, kind = joint.get("name"), joint.get("type")
        what = f"joint {name!r}"
        if kind in ("floating", "planar"):
            raise ValueError(
                f"Chain.from_urdf: {what} is {kind}: a serial chain has joints of one degree of freedom"
            )
        if kind not in MOVING + ("fixed",):
            raise ValueError(f"Chain.from_urdf: {what}: unknown joint type {kind!r}")
        if joint.find("mimic") is not None:
            raise ValueError(f"Chain.from_urdf: {what}: <mimic> joints are not supported")
        T = T @ _pose(joint.find("origin"), what)
        if kind in MOVING:
            axis_el = joint.find("axis")
            axis = _floats(axis_el.get("xyz", "1 0 0"), 3, f"{what} <axis xyz>") if axis_el is not None else np.array([1.0, 0, 0])
            norm = np.linalg.norm(axis)
            if not norm > 0:
                raise ValueError(f"Chain.from_urdf: {what}: <axis xyz> is zero")
            w = T[:3, :3] @ (axis / norm)
            w /= np.linalg.norm(w)
            if kind == "prismatic":
                screws.append(np.concatenate([w, np.zeros(3)]))
            else:
                screws.append(np.concatenate([-np.cross(w, T[:3, 3]), w]))
            limit = joint.find("limit")
            if kind == "continuous":
                lo, hi = -math.inf, math.inf
            elif limit is None:
                raise ValueError(f"Chain.from_urdf: {what}: a {kind} joint needs a <limit>")
            else:
                lo = _attribute(limit, "lower", f"{what} <limit>", 0.0)
                hi = _attribute(limit, "upper", f"{what} <limit>", 0.0)
            vel = math.inf if limit is None else _attribute(limit, "velocity", f"{what} <limit>", math.inf)
            eff = math.inf if limit is None else _attribute(limit, "effort", f"{what} <limit>", math.inf)
            types.append(kind)
            names.append(name)
            lower.append(lo)
            upper.append(hi)
            velocity.append(vel)
            effort.append(eff)
            bodies.append([])
        if bodies:  # links before the first moving joint belong to the base
            child = joint.find("child").get("link")
            part = _inertial(links[child], T)
            if part is not None:
                bodies[-1].append(part)
            bodies[-1] += hanging_parts(child, T)
    if not screws:
        raise ValueError(
            f"Chain.from_urdf: no revolute, continuous or prismatic joint from {base_link!r} to {tip_link!r}"
        )
    inertias = np.zeros((len(bodies), 10))
    for i, parts in enumerate(bodies):
        m, c, I = _merge(parts) if parts else (0.0, np.zeros(3), np.zeros((3, 3)))
        inertias[i] = [m, *c, I[0, 0], I[0, 1], I[0, 2], I[1, 1], I[1, 2], I[2, 2]]
    return _core.Chain(
        np.array(screws),
        T,
        joint_types=types,
        names=names,
        lower=lower,
        upper=upper,
        velocity_limits=velocity,
        effort_limits=effort,
        link_inertias=inertias,
    )
