"""Broken bodies are refused by rdisc before any tool sees them, with the diagnostic at the
offending line; and the same body written by hand is refused by an independent tool, or read
wrongly by it (urdfdom drops unreachable links without a word), which shows that each check
stands for a real fault. What the tools said here:

- check_urdf refuses a rootless cycle, a detached link and a missing parent; it accepts a link
  with two parents (and shows it twice), drops a cycle beside the tree, and accepts a zero axis,
  a negative mass, an impossible inertia and unordered limits;
- libsdformat (`ign sdf -k`, reading the URDF) refuses the zero axis, the negative mass and
  the impossible inertia, and turns unordered limits round with a warning;
- urchin refuses the cycle, the detached link, the cycle beside the tree and the missing
  parent, and takes the others (a tree of three links with three joints among them).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.emit.body_tools import Tree, check_urdf, ign_sdf_check, require_module

HEADER = """\
robot r { description "x" }
link base { mass 1  inertia [0.1, 0.1, 0.1] }
link a { mass 1  inertia [0.1, 0.1, 0.1] }
link b { mass 1  inertia [0.1, 0.1, 0.1] }
"""
MOVES = "limit -1..1 velocity 1 effort 1"


def link(name: str, mass: str = "1", inertia: str = "0.1 0.1 0.1") -> str:
    xx, yy, zz = inertia.split()
    return (f'<link name="{name}"><inertial><mass value="{mass}"/>'
            f'<inertia ixx="{xx}" iyy="{yy}" izz="{zz}" ixy="0" ixz="0" iyz="0"/></inertial></link>')


def joint(name: str, parent: str, child: str, axis: str = "0 0 1", limit: str = "-1 1") -> str:
    lower, upper = limit.split()
    return (f'<joint name="{name}" type="revolute"><parent link="{parent}"/><child link="{child}"/>'
            f'<axis xyz="{axis}"/><limit lower="{lower}" upper="{upper}" effort="1" velocity="1"/></joint>')


def urdf(*parts: str) -> str:
    return '<?xml version="1.0"?>\n<robot name="r">' + "".join(parts) + "</robot>\n"


LINKS = (link("base"), link("a"), link("b"))


@dataclass(frozen=True)
class Case:
    name: str
    joints: str  # RDIS, after HEADER (lines 5 on); a case may rewrite HEADER's links
    errors: list[tuple[str, str, str]]  # (code, file:line:column, message)
    urdf: str  # the same body, written by hand
    check_urdf: Tree | str  # what check_urdf makes of it: a tree, or its error
    ign: tuple[int, str] | None = None  # `ign sdf -k`'s exit code and a line it says, where check_urdf is fooled


CASES = [
    Case("a cycle", f"joint j1: revolute a -> b {{ {MOVES} }}\njoint j2: revolute b -> a {{ {MOVES} }}\n"
                    f"joint j3: revolute b -> base {{ {MOVES} }}\n",
         [("E601", "d.rdis:2:6", "the links form a cycle with no root")],
         urdf(*LINKS, joint("j1", "a", "b"), joint("j2", "b", "a"), joint("j3", "b", "base")),
         "Error:   Failed to find root link: No root link found. The robot xml is not a valid tree."),
    Case("two parents", f"joint j1: revolute base -> a {{ {MOVES} }}\njoint j2: revolute base -> b {{ {MOVES} }}\n"
                        f"joint j3: revolute a -> b {{ {MOVES} }}\n",
         [("E601", "d.rdis:7:25", "link `b` is the child of two joints")],
         urdf(*LINKS, joint("j1", "base", "a"), joint("j2", "base", "b"), joint("j3", "a", "b")),
         Tree("r", "base", [("a", "b"), ("base", "a"), ("base", "b")]),  # b twice: 4 links shown, 3 declared
         (255, "Error Code 2: Msg: link with name[b] already exists.")),
    Case("a detached link", f"joint j1: revolute base -> a {{ {MOVES} }}\n",
         [("E601", "d.rdis:4:6", "link `b` is not joined to the tree of `base`")],
         urdf(*LINKS, joint("j1", "base", "a")),
         "Error:   Failed to find root link: Two root links found: [b] and [base]"),
    Case("a cycle beside the tree", f"joint j1: revolute a -> b {{ {MOVES} }}\njoint j2: revolute b -> a {{ {MOVES} }}\n",
         [("E601", "d.rdis:5:7", ("joint `j1` closes a cycle: links `b`, `a` hang from each other, not from the "
                                  "root `base`"))],
         urdf(*LINKS, joint("j1", "a", "b"), joint("j2", "b", "a")),
         Tree("r", "base", []),  # a and b silently dropped
         (0, "Valid.")),  # and libsdformat takes it too
    Case("a missing parent", f"joint j1: revolute base -> a {{ {MOVES} }}\njoint j2: revolute nowhere -> b {{ {MOVES} }}\n",
         [("E102", "d.rdis:6:20", "unknown link `nowhere`")],
         urdf(*LINKS, joint("j1", "base", "a"), joint("j2", "nowhere", "b")),
         "Error:   Failed to build tree: parent link [nowhere] of joint [j2] not found.  This is not valid according "
         "to the URDF spec. Every link you refer to from a joint needs to be explicitly defined in the robot "
         "description. To fix this problem you can either remove this joint [j2] from your urdf file, or add "
         '"<link name="nowhere" />" to your urdf file.'),
    Case("a zero axis", f"joint j1: revolute base -> a {{ {MOVES} }}\n"
                        f"joint j2: revolute base -> b {{ axis [0, 0, 0] {MOVES} }}\n",
         [("E603", "d.rdis:6:37", "an axis must not be zero")],
         urdf(*LINKS, joint("j1", "base", "a"), joint("j2", "base", "b", axis="0 0 0")),
         Tree("r", "base", [("base", "a"), ("base", "b")]),
         (255, "Error Code 9: Msg: The norm of the xyz vector cannot be zero")),
    Case("a negative mass", f"link c {{ mass -1  inertia [0.1, 0.1, 0.1] }}\njoint j1: revolute base -> c {{ {MOVES} }}\n"
                            f"joint j2: revolute base -> a {{ {MOVES} }}\njoint j3: revolute a -> b {{ {MOVES} }}\n",
         [("E604", "d.rdis:5:15", "a link's mass must be more than 0, not -1")],
         urdf(*LINKS, link("c", mass="-1"), joint("j1", "base", "c"), joint("j2", "base", "a"), joint("j3", "a", "b")),
         Tree("r", "base", [("a", "b"), ("base", "a"), ("base", "c")]),
         (255, "Error Code 18: Msg: A link named c has invalid inertia.")),
    Case("an impossible inertia", f"link c {{ mass 1  inertia [0.1, 0.1, 0.3] }}\n"
                                  f"joint j1: revolute base -> c {{ {MOVES} }}\n"
                                  f"joint j2: revolute base -> a {{ {MOVES} }}\njoint j3: revolute a -> b {{ {MOVES} }}\n",
         [("E604", "d.rdis:5:26", "the inertia breaks the triangle inequality: its principal moments 0.1 + 0.1 < 0.3")],
         urdf(*LINKS, link("c", inertia="0.1 0.1 0.3"), joint("j1", "base", "c"), joint("j2", "base", "a"),
              joint("j3", "a", "b")),
         Tree("r", "base", [("a", "b"), ("base", "a"), ("base", "c")]),
         (255, "Error Code 18: Msg: A link named c has invalid inertia.")),
    Case("unordered limits", f"joint j1: revolute base -> a {{ {MOVES} }}\n"
                             "joint j2: revolute base -> b { limit 1..-1 velocity 1 effort 1 }\n",
         [("E603", "d.rdis:6:32", "a joint's limits are ordered, low < high, not 1..-1")],
         urdf(*LINKS, joint("j1", "base", "a"), joint("j2", "base", "b", limit="1 -1")),
         Tree("r", "base", [("base", "a"), ("base", "b")]),
         # no tool refuses it: libsdformat turns the limits round, and says so
         (0, ("Warning [parser_urdf.cc:3023] urdf2sdf: revolute joint [j2] with limits: lowStop[1] > highStop[-1], "
             "switching the two."))),
]


def _errors(stderr: str) -> list[tuple[str, str, str]]:
    """Each diagnostic's code, place and message, from the text rendering."""
    found = re.findall(r"^error\[(\w+)\]: (.*)\n +--> (\S+)$", stderr, re.MULTILINE)
    return [(code, place, message) for code, message, place in found]


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
@pytest.mark.parametrize("verb", ["emit-urdf", "emit-sdf"])
def test_rdisc_refuses_it_and_writes_nothing(case: Case, verb: str, tmp_path: Path, rdisc) -> None:
    (tmp_path / "d.rdis").write_text(HEADER + case.joints, encoding="utf-8")
    result = rdisc(verb, "d.rdis", "-o", "out.xml", cwd=tmp_path)
    assert (result.returncode, result.stdout) == (1, "")
    assert _errors(result.stderr) == case.errors, result.stderr
    assert not (tmp_path / "out.xml").exists()


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_the_same_body_in_urdf_is_refused_or_misread_by_the_tools(case: Case, tmp_path: Path) -> None:
    path = tmp_path / "hand.urdf"
    path.write_text(case.urdf, encoding="utf-8")
    read = check_urdf(path)
    if isinstance(read, Tree):  # in an order of urdfdom's
        read = Tree(read.name, read.root, sorted(read.edges))
    assert read == case.check_urdf
    if isinstance(case.check_urdf, Tree):  # check_urdf took it: what it shows is not the description
        shown = {case.check_urdf.root} | {child for _, child in case.check_urdf.edges}
        declared = set(re.findall(r'<link name="(\w+)"', case.urdf))
        assert case.ign is not None
        fooled = len(case.check_urdf.edges) != len(declared) - 1 or shown != declared
        assert fooled or case.ign[0] != 0 or "switching the two" in case.ign[1]
    if case.ign is not None:
        code, said = ign_sdf_check(path)
        assert code == case.ign[0] and case.ign[1] in said.splitlines(), said


# What urchin says of each body by hand: the first line of its error, or None when it takes it.
URCHIN = {
    "a cycle": "There are cycles in the link graph",
    "a detached link": "Links are not all connected. Connected components are:",
    "a cycle beside the tree": "Links are not all connected. Connected components are:",
    "a missing parent": "Joint j2 has invalid parent link name nowhere",
}


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_what_urchin_makes_of_the_same_body(case: Case, tmp_path: Path) -> None:
    urchin = require_module("urchin")
    path = tmp_path / "hand.urdf"
    path.write_text(case.urdf, encoding="utf-8")
    try:
        robot = urchin.URDF.load(str(path), lazy_load_meshes=True)
    except ValueError as err:
        assert str(err).splitlines()[0] == URCHIN.get(case.name)
    else:
        assert case.name not in URCHIN
        assert (len(robot.links), len(robot.joints)) == (len(re.findall("<link ", case.urdf)),
                                                         len(re.findall("<joint ", case.urdf)))
