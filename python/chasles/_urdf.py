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

Hostile input (the contract shared with the C++ loader, src/urdf.cpp: the
same files load in both or are refused by both with the same text after the
prefixes "Chain.from_urdf: " and "chain_from_urdf: "):

- The source is XML text when, after an optional byte-order mark and
  whitespace, it starts with '<'; otherwise it is a path, which must name a
  regular file of at most 64 MiB (read with that bound: never more than
  64 MiB + 1 bytes); text longer than 64 MiB is refused too.
- Before the XML parser sees the document, a linear scan refuses elements
  nested more than 64 deep (a URDF nests about 6 deep).
- The link tree is walked with an explicit stack, never by recursion.
- Every number of every <link> and <joint> is checked, on the chain or not
  (finite; masses >= 0), and so are the numbers combined (poses composed
  from the root, masses summed), each refusal naming the
  joint or link; the Chain constructor's validation comes last, its
  refusal named after the joint.
- Not refused (a decision): physically impossible inertias (not positive
  semidefinite, or violating the triangle inequality). 48 of the 1,985 link
  inertias of example-robot-data are such (tiago's antennas have an
  eigenvalue at -39% of the trace, anymal's hatch is diag(0, 0, 0.003),
  icub's legs have entries of 1e-18 with negative eigenvalues), and those
  robots must load.
"""

from __future__ import annotations

import itertools
import math
import os
import pyexpat
import re
import stat
import xml.etree.ElementTree as ET

import numpy as np

from . import _core

MOVING = ("revolute", "continuous", "prismatic")

MAX_BYTES = 64 * 1024 * 1024  # the bound on a description, file or text (64 MiB)
MAX_DEPTH = 64  # the bound on element nesting (a URDF nests about 6 deep)

_TOO_LARGE = "the description is larger than 64 MiB, the bound on a URDF description"
_TOO_DEEP = "the XML nests elements more than 64 deep, the bound on a URDF description"

# XML text: an optional byte-order mark, whitespace, then '<'.
_TEXT_START = re.compile("\ufeff?[ \t\r\n\f\v]*(?=<)")
_BYTES_TEXT_START = re.compile(b"(?:\xef\xbb\xbf)?[ \t\r\n\f\v]*(?=<)")

# The depth scan: each match is one piece of markup, which findall reports by
# its one group: '' for a piece that does not nest (a comment, CDATA, a
# processing instruction, another <!...> declaration, a self-closing start
# tag: quoted attribute values may hold '>' and '/>'), '/' for an end tag,
# and for any other start tag the first character of its name. Linear time:
# a comment, CDATA or an instruction runs to its end or to the end of the
# text; a tag is matched up to the next '<' at most. Bounded memory: the
# only repetition of a group is bounded (256 quoted values or '/' in a tag;
# beyond, the tag counts as a start tag: one more, never one less). The scan
# never counts less than the parser's nesting over the part of the text the
# parser accepts: what it misreads is markup that is not well-formed, where
# the parser stops.
_MARKUP = re.compile(
    r"<(?:"
    r"!--(?:.*?-->|.*)"  # a comment
    r"|!\[CDATA\[(?:.*?\]\]>|.*)"  # CDATA
    r"|\?(?:.*?\?>|.*)"  # a processing instruction
    r"|!"  # another declaration (the document type: see _depth_ok)
    r"|[^<>\"'/!?][^<>\"'/]*(?:(?:/(?!>)|\"[^<\"]*\"|'[^<']*')[^<>\"'/]*){0,256}/>"  # a self-closing tag
    r"|(.)"  # '/': an end tag; anything else: a start tag
    r")",
    re.DOTALL,
)
_STEP = {"": 0, "/": -1}


class _TooDeep(Exception):
    pass


def _expat_depth_ok(text):
    """The nesting as the parser sees it, with the entities a document type
    declares expanded: expat's streaming events, stopped at depth 65."""
    parser = pyexpat.ParserCreate()
    depth = 0

    def start(name, attributes):
        nonlocal depth
        depth += 1
        if depth > MAX_DEPTH:
            raise _TooDeep

    def end(name):
        nonlocal depth
        depth -= 1

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    try:
        parser.Parse(text, True)
    except _TooDeep:
        return False
    except pyexpat.ExpatError:
        pass  # not well-formed: the parser refuses it with its own reason
    return True


def _depth_ok(text):
    """Whether the elements of the XML text nest at most MAX_DEPTH deep,
    before the parser sees the text: a linear scan of the markup (one regular
    expression, then a running sum of +1 per start tag and -1 per end tag,
    whose maximum D bounds the nesting: it is the deepest open element, and a
    self-closing one may sit one deeper). D < 64: accepted. D >= 64, and a
    document type declaration (which may declare entities whose text holds
    elements, invisible to the scan; rare in URDF): measured exactly by
    expat's streaming events, which stop at depth 65 (at once for a document
    that nests deep)."""
    if "<!DOCTYPE" not in text:
        steps = map(_STEP.get, _MARKUP.findall(text), itertools.repeat(1))
        if max(itertools.accumulate(steps), default=0) < MAX_DEPTH:
            return True
    return _expat_depth_ok(text)


def _error(message):
    return ValueError("Chain.from_urdf: " + message)


def _q(name):
    """A name as the messages quote it (as the C++ loader does)."""
    return f"'{name}'"


def _number(x):
    """A number as the messages print it: the shortest text that reads back
    as the same float (repr), without a trailing '.0' (-1.5, 1, 1e-05)."""
    text = repr(float(x))
    return text[:-2] if text.endswith(".0") else text


def _floats(text, count, what):
    parts = text.split()
    try:
        # float() also reads '1_0' and other scripts' digits: refused here as in XML
        if len(parts) != count or not text.isascii() or "_" in text:
            raise ValueError
        values = [float(x) for x in parts]
    except ValueError:
        raise _error(f"{what}: expected {count} numbers, got {text!r}") from None
    if not all(map(math.isfinite, values)):
        raise _error(f"{what}: expected finite numbers")
    return values


_IDENTITY = np.eye(4)


def _pose(element, what):
    """The 4x4 pose of an <origin> element (identity when it is None)."""
    T = _IDENTITY.copy()
    if element is None:
        return T
    xyz, rpy = element.get("xyz"), element.get("rpy")
    if xyz is not None:
        T[:3, 3] = _floats(xyz, 3, f"{what} <origin xyz>")
    if rpy is not None:
        rpy = _floats(rpy, 3, f"{what} <origin rpy>")
        if rpy[0] or rpy[1] or rpy[2]:
            T[:3, :3] = _core.SO3.from_rpy(rpy).as_matrix()
    return T


def _compose(T_parent, joint, name):
    """The pose of a joint's child link at home: its parent's, T_parent,
    composed with the joint's <origin>."""
    origin = joint.find("origin")
    if origin is None:
        return T_parent  # (poses are never changed in place)
    return T_parent @ _pose(origin, f"joint {_q(name)}")


def _attribute(element, name, what, default=None):
    text = element.get(name)
    if text is None:
        if default is None:
            raise _error(f"{what}: missing attribute {name!r}")
        return default
    try:
        if not text.isascii() or "_" in text:
            raise ValueError
        value = float(text)
    except ValueError:
        raise _error(f"{what} {name}: expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise _error(f"{what}: expected finite numbers")
    return value


def _read_file(path):
    """The text of the file at path (str or bytes): a regular file of at
    most MAX_BYTES, read with that bound, in UTF-8."""
    shown = _q(os.fsdecode(path))
    flags = os.O_RDONLY | getattr(os, "O_BINARY", 0) | getattr(os, "O_CLOEXEC", 0)
    # O_NONBLOCK: opening a FIFO does not wait for a writer (it is refused below)
    try:
        fd = os.open(path, flags | getattr(os, "O_NONBLOCK", 0))
    except (OSError, ValueError):  # ValueError: a NUL character in the path
        try:
            mode = os.stat(path).st_mode
        except (OSError, ValueError):
            mode = None
        if mode is not None and stat.S_ISDIR(mode):
            raise _error(f"{shown} is a directory, not a URDF file") from None
        if mode is not None and not stat.S_ISREG(mode):  # a socket cannot be opened
            raise _error(f"{shown} is not a regular file") from None
        raise _error(f"cannot open the file {shown}") from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise _error(f"{shown} is a directory, not a URDF file")
        if not stat.S_ISREG(info.st_mode):
            raise _error(f"{shown} is not a regular file")
        if info.st_size > MAX_BYTES:
            raise _error(f"{shown} is larger than 64 MiB, the bound on a URDF description")
        # The size fstat gives, plus one byte to see the end (the file may
        # change meanwhile: then pieces, never beyond MAX_BYTES + 1 bytes).
        chunks, total, want = [], 0, info.st_size + 1
        while total <= MAX_BYTES:
            chunk = os.read(fd, min(max(want - total, 1 << 16), MAX_BYTES + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
    finally:
        os.close(fd)
    if total > MAX_BYTES:
        raise _error(f"{shown} is larger than 64 MiB, the bound on a URDF description")
    data = chunks[0] if len(chunks) == 1 else b"".join(chunks)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise _error(f"{shown} is not UTF-8 text (byte {e.start}: {e.reason})") from None


def _text(source):
    """The XML text of the source (str), its byte-order mark and leading
    whitespace removed: the text itself, or the content of the file it names."""
    if isinstance(source, os.PathLike):
        text = _read_file(os.fspath(source))
    elif isinstance(source, str):
        start = _TEXT_START.match(source)
        if start is None:
            text = _read_file(source)
        else:
            if len(source) > MAX_BYTES or (
                len(source) > MAX_BYTES // 4
                and not source.isascii()
                and len(source.encode("utf-8", "surrogatepass")) > MAX_BYTES
            ):
                raise _error(_TOO_LARGE)
            return source[start.end() :] if start.end() else source
    elif isinstance(source, (bytes, bytearray)):
        source = bytes(source)
        if _BYTES_TEXT_START.match(source) is None:
            text = _read_file(source)
        else:
            if len(source) > MAX_BYTES:
                raise _error(_TOO_LARGE)
            try:
                text = source.decode("utf-8")
            except UnicodeDecodeError as e:
                raise _error(f"the description is not UTF-8 text (byte {e.start}: {e.reason})") from None
    else:
        raise TypeError(
            "Chain.from_urdf(source): expected a path or the XML text (a str, UTF-8 bytes or an os.PathLike), "
            f"got {type(source).__name__}"
        )
    start = _TEXT_START.match(text)
    return text[start.end() :] if start is not None and start.end() else text


def _read(source):
    text = _text(source)
    if not _depth_ok(text):
        raise _error(_TOO_DEEP)
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
    what = f"link {_q(link.get('name'))}"
    mass_el = inertial.find("mass")
    mass = 0.0 if mass_el is None else _attribute(mass_el, "value", f"{what} <mass>")  # >= 0: _check_numbers
    T = T_link @ _pose(inertial.find("origin"), f"{what} <inertial>")
    I_el = inertial.find("inertia")
    I = np.zeros((3, 3))
    if I_el is not None:
        ixx, ixy, ixz, iyy, iyz, izz = (
            _attribute(I_el, k, f"{what} <inertia>", 0.0) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
        )
        I = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
    R = T[:3, :3]
    return mass, T[:3, 3].copy(), R @ I @ R.T


def _parallel_axis(m, d):
    """m (|d|^2 1 - d d^T) = -m [d]^2 entry by entry, as src/urdf.cpp writes
    it: the diagonal as sums of two squares, m (d_y^2 + d_z^2), ..., never
    |d|^2 - d_z^2, which cancels where one component dominates (a link 13 m
    up the z axis lost 5e-14 of a 0.2 kg m^2 moment that way)."""
    x, y, z = d
    return m * np.array(
        [[y * y + z * z, -x * y, -x * z], [-x * y, x * x + z * z, -y * z], [-x * z, -y * z, x * x + y * y]]
    )


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
        inertia += I + _parallel_axis(m, c - com)
    return mass, com, inertia


def _finite(values):
    return bool(np.isfinite(values).all())


def _chain(path_names, screws, home, **kwargs):
    """The Chain constructor, its refusal (which names joints by index)
    restated with the joint's name."""
    try:
        return _core.Chain(np.array(screws), home, **kwargs)
    except ValueError as e:
        match = re.match(r"Chain\([^)]*\): (?:joint (\d+)(?:: | ))?(.*)", str(e), re.DOTALL)
        index = int(match.group(1)) if match and match.group(1) else len(path_names) - 1
        reason = match.group(2) if match else str(e)
        reason = reason.split("; these rows read as")[0].split("; the table reads as")[0]
        raise _error(f"joint {_q(path_names[index])}: {reason}") from None


def chain_from_urdf(source, tip_link, base_link=None):
    root = _read(source)
    with np.errstate(over="ignore", invalid="ignore"):  # overflow is checked for, and refused by name
        return _chain_from_tree(root, tip_link, base_link)


def _check_origin(element, what):
    """Refuses a non-finite number in element's <origin xyz rpy>."""
    origin = element.find("origin")
    if origin is not None:
        for key in ("xyz", "rpy"):
            if origin.get(key) is not None:
                _floats(origin.get(key), 3, f"{what} <origin {key}>")


def _check_numbers(element, what):
    """Refuses a non-finite or negative-mass number anywhere in a <link> or
    <joint>, on the chain or not (as the C++ loader does: a hostile number is
    refused wherever it is, not only where this chain reads it)."""
    if element.tag == "link":
        inertial = element.find("inertial")
        if inertial is None:
            return
        _check_origin(inertial, f"{what} <inertial>")
        mass_el = inertial.find("mass")
        if mass_el is not None:
            mass = _attribute(mass_el, "value", f"{what} <mass>")
            if mass < 0:
                raise _error(f"{what} <mass>: negative mass {_number(mass)} (a mass is >= 0)")
        inertia = inertial.find("inertia")
        if inertia is not None:
            for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
                _attribute(inertia, key, f"{what} <inertia>", 0.0)
        return
    _check_origin(element, what)
    axis = element.find("axis")
    if axis is not None and axis.get("xyz") is not None:
        _floats(axis.get("xyz"), 3, f"{what} <axis xyz>")
    limit = element.find("limit")
    if limit is not None:
        for key in ("lower", "upper", "velocity", "effort"):
            _attribute(limit, key, f"{what} <limit>", 0.0)


_LINK_NUMBERS = {"origin": ("xyz", "rpy"), "mass": ("value",), "inertia": ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
_JOINT_NUMBERS = {"origin": ("xyz", "rpy"), "axis": ("xyz",), "limit": ("lower", "upper", "velocity", "effort")}


def _numbers_plainly_fine(elements, numbers):
    """Whether every number _check_numbers reads in these elements (the
    children of each named in `numbers`, with their attributes) is a finite
    ASCII float and every mass is >= 0: one pass with no call per number (a
    URDF has hundreds), so that the common case costs little; on False,
    _check_numbers finds the element and says what."""
    texts, masses = [], []
    for element in elements:
        for child in element:
            keys = numbers.get(child.tag)
            if keys is None:
                continue
            get = child.get
            texts.extend(t for t in map(get, keys) if t is not None)
            if child.tag == "mass":
                masses.append(get("value") or "0")
    joined = " ".join(texts)
    if not joined.isascii() or "_" in joined:
        return False
    try:
        return all(map(math.isfinite, map(float, joined.split()))) and min(map(float, masses), default=0) >= 0
    except ValueError:
        return False


def _chain_from_tree(root, tip_link, base_link):
    links = {}
    for link in root.iterfind("link"):
        name = link.get("name")
        if name is None:
            raise _error("a <link> without a name")
        if name in links:
            raise _error(f"duplicate link name {_q(name)}")
        links[name] = link
    inertials = (i for i in (link.find("inertial") for link in links.values()) if i is not None)
    if not _numbers_plainly_fine(inertials, _LINK_NUMBERS):
        for name, link in links.items():
            _check_numbers(link, f"link {_q(name)}")
    parent_joint = {}  # child link -> (its joint element, the joint's name, the parent link)
    children = {}  # link -> [(joint element, joint name, child link)] in document order
    joint_names = set()
    for joint in root.iterfind("joint"):
        name = joint.get("name")
        if name is None:
            raise _error("a <joint> without a name")
        if name in joint_names:
            raise _error(f"duplicate joint name {_q(name)}")
        joint_names.add(name)
        parent, child = joint.find("parent"), joint.find("child")
        p = None if parent is None else parent.get("link")
        c = None if child is None else child.get("link")
        if p is None or c is None:
            raise _error(f"joint {_q(name)}: expected <parent link=...> and <child link=...>")
        if p not in links or c not in links:
            raise _error(f"joint {_q(name)} names a missing link {_q(p if p not in links else c)}")
        if c in parent_joint:
            raise _error(
                f"link {_q(c)} is the child of joints {_q(parent_joint[c][1])} and {_q(name)}: "
                "a loop (URDF describes trees)"
            )
        parent_joint[c] = (joint, name, p)
        children.setdefault(p, []).append((joint, name, c))
    if not _numbers_plainly_fine((joint for joint, _, _ in parent_joint.values()), _JOINT_NUMBERS):
        for joint in root.iterfind("joint"):
            _check_numbers(joint, f"joint {_q(joint.get('name'))}")
    for label, link in (("tip_link", tip_link), ("base_link", base_link)):
        if link is not None and not isinstance(link, str):
            raise TypeError(f"Chain.from_urdf({label}): expected a link name (str), got {type(link).__name__}")
        if link is not None and link not in links:
            raise ValueError(f"Chain.from_urdf({label}): no link named {link!r} in the description")
    roots = [name for name in links if name not in parent_joint]
    if base_link is None:
        if len(roots) != 1:
            if not roots:
                raise _error("the description has no root link (a loop)")
            raise _error(f"several root links {roots}: pass base_link")
        base_link = roots[0]
    # From the tip up to the base.
    path, link, seen = [], tip_link, set()
    while link != base_link:
        if link in seen:
            raise _error(f"a loop through link {_q(link)}")
        seen.add(link)
        if link not in parent_joint:
            raise _error(f"tip_link {_q(tip_link)} is not below base_link {_q(base_link)}")
        joint, name, parent = parent_joint[link]
        path.append((joint, name, link))
        link = parent
    path.reverse()
    # Links hanging off the chain (side branches, and what is below the tip)
    # ride rigidly on the chain link they hang from: fixed joints as they
    # are, moving joints off the chain at zero (as Pinocchio's
    # buildReducedModel at the neutral configuration).
    on_path = {base_link} | {child for _, _, child in path}

    def hanging_parts(link, T_link, parts):
        """Appends the parts of the links below link that are off the chain,
        depth first in document order, with an explicit stack (a branch may
        be tens of thousands of links long)."""
        stack = [(joint, name, child, T_link) for joint, name, child in reversed(children.get(link, ()))]
        visited = set()
        while stack:
            joint, name, child, T_parent = stack.pop()
            if child in on_path:
                continue
            if child in visited:  # only through a loop (each link has one parent)
                raise _error(f"a loop through link {_q(child)}")
            visited.add(child)
            T_child = _compose(T_parent, joint, name)
            if not _finite(T_child[:3, 3]):  # massless or not: a hostile number, refused where it overflows
                raise _error(f"joint {_q(name)}: the pose of link {_q(child)} at home is not finite (overflow)")
            part = _inertial(links[child], T_child)
            if part is not None:
                parts.append(part)
            below = children.get(child)
            if below:
                stack.extend((j, n, c, T_child) for j, n, c in reversed(below))

    screws, types, names, lower, upper, velocity, effort = [], [], [], [], [], [], []
    bodies = []  # per moving joint, the (mass, com, inertia) of the links it moves
    T = np.eye(4)
    for joint, name, child in path:
        kind = joint.get("type")
        what = f"joint {_q(name)}"
        if kind in ("floating", "planar"):
            raise _error(f"{what} is {kind}: a serial chain has joints of one degree of freedom")
        if kind not in MOVING + ("fixed",):
            raise _error(f"{what}: unknown joint type {kind!r}")
        if joint.find("mimic") is not None:
            raise _error(f"{what}: <mimic> joints are not supported")
        T = _compose(T, joint, name)
        if not _finite(T[:3, 3]):
            raise _error(f"{what}: the pose of link {_q(child)} at home is not finite (overflow)")
        if kind in MOVING:
            axis_el = joint.find("axis")
            axis = np.array(
                _floats(axis_el.get("xyz", "1 0 0"), 3, f"{what} <axis xyz>") if axis_el is not None else [1.0, 0, 0]
            )
            # a direction: scaled by its largest component first, so that
            # (1e308, 1e308, 0) is normalized without overflow
            largest = np.abs(axis).max()
            if not largest > 0:
                raise _error(f"{what}: <axis xyz> is zero")
            axis = axis / largest
            w = T[:3, :3] @ (axis / np.linalg.norm(axis))
            w /= np.linalg.norm(w)
            if kind == "prismatic":
                screw = np.concatenate([w, np.zeros(3)])
            else:
                screw = np.concatenate([-np.cross(w, T[:3, 3]), w])
            if not _finite(screw):
                raise _error(f"{what}: its screw at home is not finite (overflow)")
            screws.append(screw)
            limit = joint.find("limit")
            if kind != "continuous" and limit is None:
                raise _error(f"{what}: a {kind} joint needs a <limit>")
            if limit is not None:
                lo = _attribute(limit, "lower", f"{what} <limit>", 0.0)
                hi = _attribute(limit, "upper", f"{what} <limit>", 0.0)
                vel = _attribute(limit, "velocity", f"{what} <limit>", math.inf)
                eff = _attribute(limit, "effort", f"{what} <limit>", math.inf)
                if kind != "continuous" and lo > hi:
                    raise _error(f"{what} <limit>: lower {_number(lo)} > upper {_number(hi)}")
                if vel < 0:
                    raise _error(f"{what} <limit>: negative velocity {_number(vel)}")
                if eff < 0:
                    raise _error(f"{what} <limit>: negative effort {_number(eff)}")
            else:
                vel = eff = math.inf
            if kind == "continuous":
                lo, hi = -math.inf, math.inf
            types.append(kind)
            names.append(name)
            lower.append(lo)
            upper.append(hi)
            velocity.append(vel)
            effort.append(eff)
            bodies.append([])
        if bodies:  # links before the first moving joint belong to the base
            part = _inertial(links[child], T)
            if part is not None:
                bodies[-1].append(part)
            hanging_parts(child, T, bodies[-1])
    if not screws:
        raise _error(f"no revolute, continuous or prismatic joint from {_q(base_link)} to {_q(tip_link)}")
    inertias = np.zeros((len(bodies), 10))
    for i, parts in enumerate(bodies):
        m, c, I = _merge(parts) if parts else (0.0, np.zeros(3), np.zeros((3, 3)))
        inertias[i] = [m, *c, I[0, 0], I[0, 1], I[0, 2], I[1, 1], I[1, 2], I[2, 2]]
        if not _finite(inertias[i]):
            raise _error(f"joint {_q(names[i])}: the mass properties of the links it moves are not finite (overflow)")
    return _chain(
        names,
        screws,
        T,
        joint_types=types,
        joint_names=names,
        lower=lower,
        upper=upper,
        velocity_limits=velocity,
        effort_limits=effort,
        link_inertias=inertias,
    )
