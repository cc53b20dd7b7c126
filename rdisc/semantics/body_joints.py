"""The body's joints (rdisc.semantics.body): each joint, its mimic, and the tree of links they make."""

from __future__ import annotations

from collections import deque

from rdisc.diagnostics import Label
from rdisc.semantics import model as m
from rdisc.semantics.body_links import BodyLinks
from rdisc.semantics.body_values import _KINDS, _LIMITED, reserved_name
from rdisc.semantics.resolve import suggest
from rdisc.syntax import ast


class BodyJoints(BodyLinks):
    """The rules of `joint` declarations and of the tree."""

    def joint(self, decl: ast.JointDecl) -> m.Joint | None:
        kind = _KINDS.get(decl.kind.text)
        if kind is None:
            self.d.report("E603", decl.kind.span, f"unknown joint kind `{decl.kind.text}`",
                          help=suggest(decl.kind.text, _KINDS) or "joints are " + ", ".join(_KINDS))
            return None
        items = decl.items
        at, rpy = self.once(items, "at", decl.name), self.once(items, "rpy", decl.name)
        origin = self.pose(at, rpy)
        limit = self.first([i for i in items if isinstance(i, ast.JointLimit)], "limit", decl.name)
        moving = {"axis", "velocity", "effort", "damping", "friction"}
        if kind is m.JointKind.FIXED:
            for item in items:
                if not isinstance(item, ast.BodyValue) or item.key in moving:
                    key = item.key if isinstance(item, ast.BodyValue) else \
                        "limit" if isinstance(item, ast.JointLimit) else "mimic"
                    self.d.report("E603", item.span, f"a fixed joint does not move: it has no `{key}`")
            return None if origin is None else m.Joint(decl.name.text, kind, decl.parent.text, decl.child.text,
                                                       origin, doc=decl.doc, span=decl.span,
                                                       expressions=self.written(at=at, rpy=rpy))
        axis = (1.0, 0.0, 0.0)
        axis_expr = self.once(items, "axis", decl.name)
        if axis_expr is not None:
            given = self.vector(axis_expr, "an axis")
            if given is not None and not any(given):
                self.d.report("E603", axis_expr.span, "an axis must not be zero",
                              help="the unit vector the joint turns about or slides along: `axis [0, 0, 1]`")
                given = None
            axis = given or axis
        lower = upper = None
        if limit is not None:
            if kind not in _LIMITED:
                self.d.report("E603", limit.span, f"a {kind.value} joint has no position limit",
                              help="a joint that turns within limits is `revolute`" if kind is m.JointKind.CONTINUOUS
                              else None)
            else:
                lower, upper = self.number(limit.low, "a joint's limit"), self.number(limit.high, "a joint's limit")
                if lower is not None and upper is not None and not lower < upper:
                    self.d.report("E603", limit.span, f"a joint's limits are ordered, low < high, not "
                                  f"{lower:g}..{upper:g}")
                    lower = upper = None
        elif kind in _LIMITED:
            self.d.report("E603", decl.name.span, f"{kind.value} joint `{decl.name.text}` has no `limit LOW..HIGH`",
                          help="a continuous joint turns without limits" if kind is m.JointKind.REVOLUTE
                          else "the range it slides over, in metres")
        bounds: dict[str, float | None] = {}
        clauses: dict[str, ast.Expr | None] = {}
        for key, zero in (("velocity", False), ("effort", False), ("damping", True), ("friction", True)):
            expr = clauses[key] = self.once(items, key, decl.name)
            bounds[key] = None if expr is None else self.positive(expr, f"a joint's {key}", "E603", zero)
            if expr is None and key in ("velocity", "effort") and kind in _LIMITED:
                self.d.report("E603", decl.name.span, f"{kind.value} joint `{decl.name.text}` has no `{key}`",
                              help="URDF needs a moving joint's largest velocity and effort")
        mimic = self.mimic(decl)
        if origin is None or isinstance(mimic, bool):
            return None
        follows = next((i for i in items if isinstance(i, ast.JointMimic)), None) if mimic else None
        written = self.written(at=at, rpy=rpy, axis=axis_expr, limit=None if limit is None or lower is None
                               else (limit.low, limit.high), **clauses,
                               multiplier=None if follows is None else follows.multiplier,
                               offset=None if follows is None else follows.offset)
        return m.Joint(decl.name.text, kind, decl.parent.text, decl.child.text, origin, axis, lower, upper,
                       bounds["velocity"], bounds["effort"], bounds["damping"] or 0.0, bounds["friction"] or 0.0,
                       decl.doc, decl.span, mimic, written)

    def mimic(self, decl: ast.JointDecl) -> m.Mimic | None | bool:  # False: refused
        """`mimic JOINT multiplier M offset O` (1 and 0 when left out): None without one, False when
        refused (reported). The joint it names is checked with the tree (`mimics`)."""
        given = self.first([i for i in decl.items if isinstance(i, ast.JointMimic)], "mimic", decl.name)
        if given is None:
            return None
        multiplier = 1.0 if given.multiplier is None else self.number(given.multiplier, "a mimic's multiplier")
        offset = 0.0 if given.offset is None else self.number(given.offset, "a mimic's offset")
        if multiplier is None or offset is None:
            return False
        if multiplier == 0:
            self.d.report("E603", given.multiplier.span if given.multiplier else given.span,
                          "a mimic's multiplier is not 0", help="a joint that does not follow is a `fixed` one")
            return False
        return m.Mimic(given.joint.text, multiplier, offset)

    def mimics(self, joints: dict[str, m.Joint]) -> None:
        """Each mimic follows a moving joint of the body that is not itself a mimic: URDF's tools
        and MuJoCo's equalities follow one leader, never a chain or a loop."""
        for joint in joints.values():
            if joint.mimic is None:
                continue
            span = next(i.joint.span for i in self.s.joints[joint.name].items if isinstance(i, ast.JointMimic))
            leader = joints.get(joint.mimic.joint)
            if joint.mimic.joint == joint.name:
                self.d.report("E603", span, f"joint `{joint.name}` cannot mimic itself")
            elif leader is None:
                continue  # unknown (E102) or refused: reported where it is
            elif not leader.moves():
                self.d.report("E603", span, f"joint `{leader.name}` is fixed: there is nothing to mimic")
            elif leader.mimic is not None:
                self.d.report("E603", span, f"joint `{leader.name}` mimics `{leader.mimic.joint}` itself",
                              help=f"mimic `{leader.mimic.joint}` (with the multipliers multiplied)")

    def portable_names(self) -> None:
        """Names every model format can carry as written, so URDF, SDF, MJCF, ros2_control and a
        JointState name a joint alike: SDF gives links and joints one namespace, where a joint named
        like a link is refused (`ign sdf -k`), and reserves `world`."""
        for kind, decls in (("link", self.s.links), ("joint", self.s.joints)):
            for name, decl in decls.items():
                if reserved_name(name):
                    self.d.report("E607", decl.name.span, f"`{name}` is reserved by SDF: a {kind} cannot take it",
                                  help=f"name the {kind} `{name}_{kind}`")
        for name, decl in self.s.joints.items():
            link = self.s.links.get(name)
            if link is not None and not reserved_name(name):
                self.d.report("E607", decl.name.span, f"joint `{name}` is named like a link",
                              labels=(Label(link.name.span, f"link `{name}`"),),
                              help=f"SDF and Gazebo give links and joints one namespace: name the joint "
                              f"`{name}_joint`, or the link `{name}_link`")

    def tree(self, links: dict[str, m.Link], joints: dict[str, m.Joint]) -> dict[str, m.Joint]:
        """One tree with one root: every link moved by at most one joint, reachable from the root,
        no cycle. The joints come back parents first. A link is reported detached only when every
        joint was understood: a joint refused or naming an unknown link may be the one missing."""
        decls = self.s.joints
        moved_by: dict[str, m.Joint] = {}
        for joint in joints.values():
            decl = decls[joint.name]
            if joint.parent == joint.child:
                self.d.report("E601", decl.child.span, f"joint `{joint.name}` joins link `{joint.child}` to itself")
                continue
            first = moved_by.get(joint.child)
            if first is not None:
                self.d.report("E601", decl.child.span, f"link `{joint.child}` is the child of two joints",
                              labels=(Label(decls[first.name].child.span, f"also of joint `{first.name}`"),),
                              help="a link hangs from one parent; join the other with a link of its own")
                continue
            moved_by[joint.child] = joint
        if not links:
            return {}
        roots = [name for name in links if name not in moved_by]
        if not roots:
            name = next(iter(links))
            self.d.report("E601", self.s.links[name].name.span, "the links form a cycle with no root",
                          help="one link, the base, is the child of no joint")
            return {}
        complete = len(joints) == len(decls) and all(j.parent in links and j.child in links for j in joints.values())
        for extra in roots[1:] if complete else ():
            self.d.report("E601", self.s.links[extra].name.span, f"link `{extra}` is not joined to the tree of "
                          f"`{roots[0]}`", labels=(Label(self.s.links[roots[0]].name.span, "the root"),),
                          help="join it with a joint (`fixed` if it does not move): a robot is one tree")
        children: dict[str, list[m.Joint]] = {}
        for joint in moved_by.values():
            children.setdefault(joint.parent, []).append(joint)
        order: dict[str, m.Joint] = {}
        reached: set[str] = set()
        for root in roots:  # the root's tree first: its joints are the body's; then the detached trees
            frontier = deque([root])
            while frontier:
                for joint in children.get(frontier.popleft(), ()):
                    if root == roots[0]:
                        order[joint.name] = joint
                    reached.add(joint.child)
                    frontier.append(joint.child)
        self.cycles({link: joint for link, joint in moved_by.items() if link not in reached and link in links},
                    roots[0])
        return order

    def carried(self, links: dict[str, m.Link], joints: dict[str, m.Joint]) -> None:
        """Every link a moving joint carries has a mass and an inertia: libsdformat gives a link
        without them 1 kg, and `ign sdf -p` drops it, so the simulated body is not this one."""
        for joint in joints.values():
            link = links.get(joint.child)
            if not joint.moves() or link is None or link.inertial is not None:
                continue
            decl = self.s.links[link.name]
            if any(isinstance(i, ast.BodyValue) and i.key in ("mass", "inertia") for i in decl.items):
                continue  # given but refused: reported where it is
            self.d.report("E611", decl.name.span, f"link `{link.name}` is moved by joint `{joint.name}` but has no "
                          "mass and inertia", labels=(Label(self.s.joints[joint.name].child.span, "moved here"),),
                          help="give it `mass` (kg) and `inertia` (kg m²): a simulator needs them to move it, "
                          "and libsdformat silently gives a link without them 1 kg")

    def cycles(self, unreached: dict[str, m.Joint], root: str) -> None:
        """Report each cycle among links no root reaches, once, at its first joint declared: each such
        link hangs from its parent, so following parents ends on a cycle or on an unknown link."""
        state: dict[str, int] = {}  # 1: on the path being followed, 2: done
        declared = {name: i for i, name in enumerate(self.s.joints)}
        for start in unreached:
            path: list[str] = []
            link: str | None = start
            while link is not None and link in unreached and link not in state:
                state[link] = 1
                path.append(link)
                link = unreached[link].parent
            if link is not None and state.get(link) == 1:
                ring = path[path.index(link):]
                names = [unreached[x].name for x in ring]
                first = min(names, key=declared.__getitem__)
                self.d.report("E601", self.s.joints[first].name.span,
                              f"joint `{first}` closes a cycle: links " + ", ".join(f"`{x}`" for x in ring)
                              + f" hang from each other, not from the root `{root}`",
                              help="a robot is one tree: every link hangs from the root through one joint")
            for x in path:
                state[x] = 2
