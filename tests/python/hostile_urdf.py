"""Hostile URDF descriptions for the two loaders (Chain.from_urdf in Python,
chain_from_urdf in C++), from their shared contract: long side branches,
deep and odd nesting, loops, huge and non-finite numbers, negative masses,
duplicate names, byte-order marks, and sources that are not URDF files.

Each Case says what both loaders must do with it: load it, or refuse it with
`error`, the text after the loaders' prefixes ("Chain.from_urdf: ",
"chain_from_urdf: "). Every description is valid for urdfdom (the C++
loader's parser) in everything but what the case is about: a robot name,
<limit> with effort and velocity, <inertial> with <mass> and all six
<inertia> attributes, one root link.

`agree` is how closely the two loaders must agree:
  "exact"   both load, or both refuse with `error` (the contract's text);
  "prefix"  both refuse, their texts equal up to the end of `error` (the
            contract leaves the rest open: how a number is printed);
  "refuse"  both refuse, for reasons the contract leaves to each parser
            (urdfdom's own rules, not well-formed XML);
  "either"  the contract leaves the outcome open: each loader only loads it
            or refuses it cleanly; `error` is the Python loader's text.
"""

from __future__ import annotations

import os
import stat
from dataclasses import dataclass

MAX_BYTES = 64 * 1024 * 1024
LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'


@dataclass(frozen=True)
class Case:
    name: str
    text: str
    tip: str
    error: str | None = None  # None: loads
    agree: str = "exact"
    base: str | None = None

    @property
    def argv_ok(self) -> bool:
        """Small enough to pass as a command-line argument (Linux: 128 KiB)."""
        return len(self.text.encode("utf-8")) < 100_000 and "\0" not in self.text


def inertial(mass, xyz="0 0 0", inertia=("0.1", "0", "0", "0.1", "0", "0.1"), rpy=None):
    names = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    origin = f'<origin xyz="{xyz}"' + (f' rpy="{rpy}"' if rpy else "") + "/>"
    values = " ".join(f'{k}="{v}"' for k, v in zip(names, inertia))
    return f'<inertial>{origin}<mass value="{mass}"/><inertia {values}/></inertial>'


def link(name, mass=None, body="", **kw):
    inside = (inertial(mass, **kw) if mass is not None else "") + body
    return f'<link name="{name}">{inside}</link>' if inside else f'<link name="{name}"/>'


def joint(name, kind, parent, child, xyz=None, rpy=None, axis="0 0 1", limit=LIMIT, extra=""):
    origin = ""
    if xyz is not None or rpy is not None:
        origin = "<origin" + (f' xyz="{xyz}"' if xyz is not None else "") + (f' rpy="{rpy}"' if rpy is not None else "")
        origin += "/>"
    moving = kind in ("revolute", "continuous", "prismatic")
    axis_el = f'<axis xyz="{axis}"/>' if moving and axis is not None else ""
    limit_el = limit if kind in ("revolute", "prismatic") or (kind == "continuous" and limit != LIMIT) else ""
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f"{origin}{axis_el}{limit_el}{extra}</joint>"
    )


def robot(*parts, name="r"):
    return f'<robot name="{name}">' + "".join(parts) + "</robot>"


def arm(j1="", j2="", a="", b="", c="", extra=""):
    """a -j1-> b -j2-> c, both revolute (tip c); keyword texts replace parts."""
    return robot(
        a or link("a", 5.0),
        b or link("b", 1.0, xyz="0.1 0 0"),
        c or link("c", 2.0, xyz="0 0 0.2"),
        j1 or joint("j1", "revolute", "a", "b", xyz="0 0 0.5"),
        j2 or joint("j2", "revolute", "b", "c", xyz="0.3 0 0", axis="0 1 0"),
        extra,
    )


def side_branch(n):
    """The two-joint arm with a side branch of n fixed links hanging from b,
    each 1 mm above the last (the last one, n mm above b, of mass 1 kg)."""
    parts = []
    for i in range(1, n + 1):
        parent = "b" if i == 1 else f"s{i - 1}"
        parts.append(link(f"s{i}", 1.0) if i == n else f'<link name="s{i}"/>')
        parts.append(
            f'<joint name="sj{i}" type="fixed"><parent link="{parent}"/><child link="s{i}"/>'
            '<origin xyz="0 0 0.001"/></joint>'
        )
    return arm(extra="".join(parts))


def nested(depth, inner="<x></x>"):
    """The arm with link c holding elements nested so that the deepest is at
    `depth` (robot = 1, link = 2): depth - 3 levels of <x>, then inner."""
    k = depth - 3
    return arm(c=f'<link name="c">{"<x>" * k}{inner}{"</x>" * k}</link>')


def cases():
    out = [Case("two joints", arm(), "c")]

    # long side branches: walked without recursion
    out += [Case(f"side branch of {n} links", side_branch(n), "c") for n in (1000, 25_000)]

    # depth: 64 loads, 65 is refused; markup that does not nest
    deep = "the XML nests elements more than 64 deep, the bound on a URDF description"
    lots = "<x>" * 100
    out += [
        Case("nested 64 deep", nested(64, "<x></x>"), "c"),
        Case("nested 65 deep", nested(65, "<x></x>"), "c", deep),
        Case("nested 10,000 deep", nested(10_000, "<x></x>"), "c", deep),
        Case("nested 200,000 deep, unclosed", arm(c='<link name="c">' + "<x>" * 200_000), "c", deep),
        Case("nested 64 deep with attributes", nested(64, "<x a='>' b=\"/>\"></x>"), "c"),
        Case("comments and CDATA do not nest", nested(64, f"<!-- {lots} --><![CDATA[{lots}]]>"), "c"),
        # valid XML, which urdfdom's TinyXML2 misreads (an instruction ends at its first '>')
        Case("processing instructions do not nest", nested(64, f"<?pi {lots} ?>"), "c", None, "either"),
        Case("self-closing tags at depth 64", nested(64, "<x/>" * 3), "c"),
        # "self-closing tags do not nest": whether one at depth 65 counts is left open
        Case("a self-closing tag at depth 65", nested(65, "<x/>"), "c", deep, "either"),
        Case(
            "elements nested in links and joints are ignored",
            arm(c='<link name="c"><link name="zz"/><joint name="q"/></link>'),
            "c",
        ),
    ]

    # byte-order mark and whitespace before the text
    out += [
        Case("byte-order mark", "\ufeff" + arm(), "c"),
        Case("byte-order mark, whitespace, declaration", '\ufeff \n\t<?xml version="1.0"?>\n' + arm(), "c"),
        Case("whitespace before the text", "\n\n   " + arm(), "c"),
    ]

    # names
    out += [
        Case("duplicate link name", arm(extra=link("b")), "c", "duplicate link name 'b'"),
        Case(
            "duplicate joint name",
            arm(extra=link("d") + joint("j2", "fixed", "c", "d")),
            "c",
            "duplicate joint name 'j2'",
        ),
        Case(
            "a link with two parents",
            arm(extra=joint("j3", "fixed", "a", "c")),
            "c",
            "link 'c' is the child of joints 'j2' and 'j3': a loop (URDF describes trees)",
        ),
        Case(
            "a loop of two links below the root",
            arm(extra=link("d") + link("e") + joint("j3", "fixed", "d", "e") + joint("j4", "fixed", "e", "d")),
            "c",
            None,
            "either",  # a loop off the chain: not the chain's concern; urdfdom may refuse it
        ),
    ]

    # negative masses: on the chain and in a link fixed to it
    out += [
        Case(
            "negative mass on the chain",
            arm(b=link("b", -1.5)),
            "c",
            "link 'b' <mass>: negative mass -1.5 (a mass is >= 0)",
        ),
        Case(
            "negative mass in a fixed child",
            arm(extra=link("sensor", -1.5) + joint("s", "fixed", "b", "sensor", xyz="1 0 0")),
            "c",
            "link 'sensor' <mass>: negative mass -1.5 (a mass is >= 0)",
        ),
        Case(
            "negative mass below the tip",
            arm(extra=link("tool", -0.25) + joint("t", "fixed", "c", "tool")),
            "c",
            "link 'tool' <mass>: negative mass -0.25 (a mass is >= 0)",
        ),
        Case("negative integer mass", arm(c=link("c", -2)), "c", "link 'c' <mass>: negative mass -", "prefix"),
        Case("tiny negative mass", arm(c=link("c", "-1e-300")), "c", "link 'c' <mass>: negative mass -", "prefix"),
    ]

    # non-finite numbers, each where it is read
    def on_j1(**kw):
        return arm(j1=joint("j1", kw.pop("kind", "revolute"), "a", "b", **kw))

    def on_j2(**kw):
        return arm(j2=joint("j2", kw.pop("kind", "revolute"), "b", "c", **kw))

    def limit(lower="-1", upper="1", effort="1", velocity="1"):
        return f'<limit lower="{lower}" upper="{upper}" effort="{effort}" velocity="{velocity}"/>'

    finite = "expected finite numbers"
    # too small for a double: the nearest double, zero; too large: refused
    out += [
        Case(
            "1e-400 in an origin and a mass (zero)",
            arm(b=link("b", "1e-400"), j2=joint("j2", "revolute", "b", "c", xyz="0.3 -1e-400 0", axis="0 1 0")),
            "c",
        ),
        Case(
            "100e-402 and 0.001e-398 (zero)",
            arm(j2=joint("j2", "revolute", "b", "c", xyz="0.3 100e-402 0.001e-398", axis="0 1 0")),
            "c",
        ),
        Case(
            "1000...0e-50 (400 digits) overflows",
            on_j2(xyz="0 1" + "0" * 400 + "e-50 0"),
            "c",
            f"joint 'j2' <origin xyz>: {finite}",
        ),
    ]
    for bad in ("nan", "inf", "-inf", "1e400"):
        side = link("d", 1.0) + joint("jd", "fixed", "b", "d", xyz=f"{bad} 0 0")
        out += [
            Case(f"{bad} origin xyz", on_j2(xyz=f"0 {bad} 0"), "c", f"joint 'j2' <origin xyz>: {finite}"),
            Case(f"{bad} origin rpy", on_j2(rpy=f"{bad} 0 0"), "c", f"joint 'j2' <origin rpy>: {finite}"),
            Case(f"{bad} axis", on_j1(axis=f"0 0 {bad}"), "c", f"joint 'j1' <axis xyz>: {finite}"),
            Case(f"{bad} limit", on_j1(limit=limit(upper=bad)), "c", f"joint 'j1' <limit>: {finite}"),
            Case(f"{bad} velocity", on_j1(limit=limit(velocity=bad)), "c", f"joint 'j1' <limit>: {finite}"),
            Case(f"{bad} mass", arm(b=link("b", bad)), "c", f"link 'b' <mass>: {finite}"),
            Case(
                f"{bad} inertia",
                arm(b=link("b", 1.0, inertia=("0.1", "0", bad, "0.1", "0", "0.1"))),
                "c",
                f"link 'b' <inertia>: {finite}",
            ),
            Case(
                f"{bad} inertial origin",
                arm(c=link("c", 1.0, xyz=f"{bad} 0 0")),
                "c",
                f"link 'c' <inertial> <origin xyz>: {finite}",
            ),
            Case(
                f"{bad} inertial rpy",
                arm(c=link("c", 1.0, rpy=f"0 0 {bad}")),
                "c",
                f"link 'c' <inertial> <origin rpy>: {finite}",
            ),
            Case(f"{bad} origin in a side branch", arm(extra=side), "c", f"joint 'jd' <origin xyz>: {finite}"),
        ]

    # limits
    out += [
        Case("lower > upper", on_j1(limit=limit("1", "0")), "c", "joint 'j1' <limit>: lower 1 > upper 0"),
        Case(
            "lower > upper, fractions",
            on_j1(kind="prismatic", limit=limit("0.5", "0.25")),
            "c",
            "joint 'j1' <limit>: lower 0.5 > upper 0.25",
        ),
        Case("negative velocity", on_j1(limit=limit(velocity="-1")), "c", "joint 'j1' <limit>: negative velocity -1"),
        Case(
            "negative effort",
            on_j2(kind="continuous", limit='<limit effort="-1" velocity="1"/>'),
            "c",
            "joint 'j2' <limit>: negative effort -1",
        ),
        Case("zero axis", on_j1(axis="0 0 0"), "c", "joint 'j1': <axis xyz> is zero"),
    ]

    # huge numbers: finite in the file, overflowing when combined
    huge = 1e308
    out += [
        Case("axis of 1e308", on_j1(axis=f"{huge} {huge} 0"), "c"),
        Case("tiny axis", on_j1(kind="prismatic", axis="0 3e-320 4e-320"), "c"),
        Case(
            "origin of 1e308 once",
            arm(b=link("b"), c=link("c"), j1=joint("j1", "prismatic", "a", "b", xyz=f"{huge} 0 0")),
            "c",
        ),
        Case(
            "origin of 1e308 composed along the chain",
            arm(
                j1=joint("j1", "prismatic", "a", "b", xyz=f"{huge} 0 0"),
                j2=joint("j2", "prismatic", "b", "c", xyz=f"{huge} 0 0"),
            ),
            "c",
            "joint 'j2': the pose of link 'c' at home is not finite (overflow)",
        ),
        # off the chain, a pose that overflows matters only through a mass there
        Case(
            "origin of 1e308 composed in a side branch",
            arm(
                extra=link("d")
                + link("e", 1.0)
                + joint("jd", "fixed", "b", "d", xyz=f"0 {huge} 0")
                + joint("je", "fixed", "d", "e", xyz=f"0 {huge} 0")
            ),
            "c",
            "joint 'je': the pose of link 'e' at home is not finite (overflow)",
        ),
        Case(
            "origin of 1e308 composed in a massless side branch",
            arm(
                extra=link("d")
                + link("e")
                + joint("jd", "fixed", "b", "d", xyz=f"0 {huge} 0")
                + joint("je", "fixed", "d", "e", xyz=f"0 {huge} 0")
            ),
            "c",
            "joint 'je': the pose of link 'e' at home is not finite (overflow)",
        ),
        Case("mass of 1e308", arm(c=link("c", huge)), "c"),
        Case(
            "masses of 1e308 summed",
            arm(c=link("c", huge), extra=link("d", huge) + joint("jd", "fixed", "c", "d")),
            "c",
            "joint 'j2': the mass properties of the links it moves are not finite (overflow)",
        ),
    ]

    # hostile numbers off the chain: refused wherever they are
    off = joint("jz", "fixed", "a", "z")
    out += [
        Case(
            "negative mass on the base link",
            arm(a=link("a", -1.0)),
            "c",
            "link 'a' <mass>: negative mass -1 (a mass is >= 0)",
        ),
        Case(
            "NaN mass on a link off the chain",
            arm(extra=link("z", "nan") + off),
            "c",
            "link 'z' <mass>: expected finite numbers",
        ),
        Case(
            "infinite origin on a joint off the chain",
            arm(extra=link("z") + joint("jz", "fixed", "a", "z", xyz="0 inf 0")),
            "c",
            "joint 'jz' <origin xyz>: expected finite numbers",
        ),
        Case(
            "NaN limit on a joint below the tip",
            arm(
                extra=link("z")
                + joint("jz", "revolute", "c", "z", limit='<limit lower="nan" upper="1" effort="1" velocity="1"/>')
            ),
            "c",
            "joint 'jz' <limit>: expected finite numbers",
        ),
    ]

    # for each parser to refuse in its own words
    out += [
        Case("not well-formed", "<robot name='r'><link name='a'/>", "a", None, "refuse"),
        Case("a number with an underscore", on_j2(xyz="0 1_0 0"), "c", None, "refuse"),
        Case("two numbers for three", on_j2(xyz="0 1"), "c", None, "refuse"),
        Case(
            "an entity expanding to deep nesting",
            '<!DOCTYPE robot [<!ENTITY e "' + "<x>" * 70 + "</x>" * 70 + '">]>' + arm(c='<link name="c">&e;</link>'),
            "c",
            deep,
            "either",
        ),  # urdfdom does not expand entities
    ]
    return out


def path_cases(directory):
    """(name, path, error) for sources that are paths but not URDF files:
    the text after the prefixes. `directory` is an empty temporary one."""
    directory = os.fspath(directory)
    missing = os.path.join(directory, "missing.urdf")
    large = os.path.join(directory, "large.urdf")
    with open(large, "wb") as f:  # sparse: 64 MiB + 1 byte read as zeros
        f.truncate(MAX_BYTES + 1)
    out = [
        ("missing file", missing, f"cannot open the file '{missing}'"),
        ("directory", directory, f"'{directory}' is a directory, not a URDF file"),
        ("larger than 64 MiB", large, f"'{large}' is larger than 64 MiB, the bound on a URDF description"),
        ("empty path", "", "cannot open the file ''"),
    ]
    if os.path.exists("/dev/zero"):
        out.append(("/dev/zero", "/dev/zero", "'/dev/zero' is not a regular file"))
    if hasattr(os, "mkfifo"):
        fifo = os.path.join(directory, "fifo.urdf")
        os.mkfifo(fifo)
        out.append(("FIFO", fifo, f"'{fifo}' is not a regular file"))
    return out


def is_regular(path):
    return stat.S_ISREG(os.stat(path).st_mode)
