"""The description as a graph (thesis Fig. 3.3): its elements, and an edge for each
reference between them, in Graphviz's DOT language; `svg` lays it out with Graphviz's
`dot`.

The body is drawn as its tree (link, joint, link) with each transmission's edges to the
joint it drives, the primitive or interface that commands it and the state that measures it.

Every node's `id` is `kind:name`, its label the kind and the name, and its tooltip the
place in the source it was declared (`file:line`), so an SVG can be searched and points
back to the text. Constants, enums and tables are folded into the expressions that use
them when the Model is built, so they stand as nodes without edges.
"""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Callable, Iterator

from rdisc.semantics import model as m
from rdisc.source import Span

# kind -> (shape, fill colour): one look per kind, as in a legend
_STYLE = {
    "connection": ("box3d", "#dbe9f6"),
    "frame": ("component", "#eeeeee"),
    "primitive": ("box", "#fde9c8"),
    "interface": ("box", "#d9f2d9"),
    "input": ("cds", "#e8dcf4"),
    "output": ("cds", "#f6dce8"),
    "adapter": ("note", "#ffffff"),
    "state": ("ellipse", "#ffffff"),
    "sensor": ("ellipse", "#fff4d6"),
    "setting": ("ellipse", "#f0f0f0"),
    "constant": ("plaintext", "#ffffff"),
    "table": ("plaintext", "#ffffff"),
    "link": ("box", "#e4e4f7"),
    "joint": ("circle", "#e4e4f7"),
    "transmission": ("hexagon", "#f7f0d4"),
}


class GraphvizMissing(RuntimeError):
    """Graphviz's `dot` is not installed: the SVG needs its layout."""


def dot(model: m.Model, where: Callable[[Span | None], str | None]) -> str:
    """The Model as a DOT digraph; `where` gives a span's `file:line`."""
    lines = [f"digraph {_quote(model.robot.name)} {{",
             '  graph [rankdir=LR, fontname="Helvetica", fontsize=11];',
             '  node [fontname="Helvetica", fontsize=10, style=filled];',
             '  edge [fontname="Helvetica", fontsize=9];']
    for kind, name, span in nodes(model):
        shape, fill = _STYLE[kind]
        attributes = {"id": f"{kind}:{name}", "label": f"{kind}\n{name}", "shape": shape, "fillcolor": fill}
        place = where(span)
        if place is not None:
            attributes["tooltip"] = place
        lines.append(f"  {_quote(f'{kind}:{name}')} [{_attributes(attributes)}];")
    edges: dict[tuple[str, str, str], int] = {}
    for edge in _edges(model):  # a call made in every round of a loop: one edge, counted
        edges[edge] = edges.get(edge, 0) + 1
    for (source, target, label), count in edges.items():
        shown = label if count == 1 else f"{label} ×{count}"
        lines.append(f"  {_quote(source)} -> {_quote(target)} [{_attributes({'label': shown})}];")
    lines.append("}")
    return "\n".join(lines) + "\n"


def svg(dot_text: str) -> str:
    """DOT laid out by Graphviz's `dot` as SVG."""
    program = shutil.which("dot")
    if program is None:
        raise GraphvizMissing("rdisc graph needs Graphviz's `dot` for SVG (Debian: apt-get install graphviz); "
                              "`-o FILE.dot` writes the DOT text without it")
    done = subprocess.run([program, "-Tsvg"], input=dot_text, capture_output=True, text=True, check=False,
                          timeout=120)
    if done.returncode != 0:
        raise GraphvizMissing(f"Graphviz's dot failed: {done.stderr.strip()}")
    return done.stdout


def nodes(model: m.Model) -> Iterator[tuple[str, str, Span | None]]:
    """(kind, name, span) of every element drawn, in the order drawn (the console lists them too)."""
    yield from (("connection", c.name, c.span) for c in model.connections.values())
    yield from (("frame", f.name, f.span) for f in model.frames.values())
    yield from (("primitive", p.name, p.span) for p in model.primitives.values())
    yield from (("interface", i.name, i.span) for i in model.interfaces.values())
    yield from (("input", i.name, i.span) for i in model.inputs.values())
    yield from (("output", o.name, o.span) for o in model.outputs.values())
    used = {i.adapter for i in model.inputs.values()} | {o.adapter for o in model.outputs.values()}
    yield from (("adapter", a.name, a.span) for a in model.adapters.values() if a.name in used or not a.standard)
    yield from (("setting", s.name, s.span) for s in model.settings.values())
    yield from (("state", s.name, s.span) for s in model.states.values() if s.name not in model.settings)
    yield from (("sensor", s.name, s.span) for s in model.sensors.values())
    yield from (("link", link.name, link.span) for link in model.links.values())
    yield from (("joint", j.name, j.span) for j in model.joints.values())
    yield from (("transmission", t.name, t.span) for t in model.transmissions.values())
    yield from (("constant", name, None) for name in model.constants)
    yield from (("table", name, None) for name in model.tables)


def _edges(model: m.Model) -> Iterator[tuple[str, str, str]]:
    """(from, to, label): what each element refers to."""
    def variable(name: str) -> str:
        if name in model.sensors:
            return f"sensor:{name}"
        return f"setting:{name}" if name in model.settings else f"state:{name}"

    for s in model.sensors.values():
        yield f"sensor:{s.name}", f"primitive:{s.primitive}", f"reads, kept {s.cache_ms:g} ms"
    for c in model.connections.values():
        for event, hook in (("startup", c.startup), ("terminate", c.terminate),
                            ("keepalive", c.keepalive.call if c.keepalive else None)):
            if hook is not None:
                yield f"connection:{c.name}", f"interface:{hook.interface}", event
        for i in model.interfaces.values():
            if i.periodic and model.owner(i) == c.name:
                yield f"connection:{c.name}", f"interface:{i.name}", f"every tick ({c.rate_of(i):g} Hz)"
    for p in model.primitives.values():
        yield f"primitive:{p.name}", f"connection:{p.connection}", "on"
        if p.frame is not None:
            yield f"primitive:{p.name}", f"frame:{p.frame.frame}", "frame"
        if p.reply_frames:
            said = f"{p.replies} replies" if p.each is None else f"a reply each of {p.each.over}"
            yield f"primitive:{p.name}", f"frame:{p.reply_frames[0].frame}", said
        listed = [r.frame for r in p.listed if r.frame is not None]
        for frame in dict.fromkeys(use.frame for use in listed):
            yield f"primitive:{p.name}", f"frame:{frame}", f"{len(p.listed)} replies"
        actions = p.post_actions()
        for target in dict.fromkeys(a.target for a in actions):
            yield f"primitive:{p.name}", variable(target), "writes"
        for name in _reads(*p.args, *(p.frame.args if p.frame else ()),
                           *(a for use in (*p.reply_frames, *listed) for a in use.args),
                           *(a.value for a in actions)):
            if name not in {a.target for a in actions}:
                yield variable(name), f"primitive:{p.name}", "read by"
    for i in model.interfaces.values():
        for call in i.calls:
            kind = "interface" if call.interface else "primitive"
            label = [f"delay {call.delay_ms:g} ms"] if call.delay_ms else []
            label += [f"priority {call.priority}"] if call.priority else []
            label += ["when ..."] if call.when is not None else []
            label += ["until ..."] if call.until is not None else []
            yield f"interface:{i.name}", f"{kind}:{call.primitive}", ", ".join(label) or "calls"
        for output in i.triggers:
            yield f"interface:{i.name}", f"output:{output}", "triggers"
    for d in model.inputs.values():
        yield f"input:{d.name}", f"adapter:{d.adapter}", "takes"
        yield f"input:{d.name}", f"interface:{d.interface}", "calls"
    for o in model.outputs.values():
        yield f"output:{o.name}", f"adapter:{o.adapter}", "sends"
        if o.frame is not None:  # the link its data belongs to, as written (the base's is not drawn)
            yield f"output:{o.name}", f"link:{o.frame}", "in frame"
        for name in _reads(*(e for _, e in o.fields)):
            yield variable(name), f"output:{o.name}", "read by"
    for j in model.joints.values():  # the body as a tree: parent link, joint, child link
        yield f"link:{j.parent}", f"joint:{j.name}", j.kind.value
        yield f"joint:{j.name}", f"link:{j.child}", "child"
    for t in model.transmissions.values():
        yield f"transmission:{t.name}", f"joint:{t.joint}", "drives"
        for b in t.commands:
            kind = "interface" if b.interface else "primitive"
            yield f"transmission:{t.name}", f"{kind}:{b.target}", f"commands {b.quantity.value} as {b.place()}"
        for b in t.measures:
            yield variable(b.target), f"transmission:{t.name}", f"measures {b.quantity.value} as {b.place()}"


def _reads(*exprs: m.Expr) -> list[str]:
    """The state variables (and settings) the expressions read, in order, once each."""
    return list(dict.fromkeys(v.name for e in exprs for v in m.variables(e) if v.scope is m.Scope.STATE))


def _attributes(items: dict[str, str]) -> str:
    return ", ".join(f"{key}={_quote(value)}" for key, value in items.items())


def _quote(text: str) -> str:
    """A DOT string: backslashes and quotes escaped, a line break as DOT's `\\n`."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
