"""The console's page, written from the Model: the graph, a form for every input,
interface and primitive, a panel for every output, the state table, the errors and
the byte trace; with a simulation, a view of its body. Everything the page shows of the description is escaped here; the
script (assets/console.js) only fills in values as they are pushed."""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from html import escape
from typing import Any

from rdisc.emit.graph import GraphvizMissing, dot, nodes, svg
from rdisc.emit.mjcf import quaternion
from rdisc.semantics import model as m
from rdisc.source import Span

SIMULATED = ('<span class="badge" data-rdis-sim title="a MuJoCo simulation of the body, on the wall clock: '
             'no device is attached">simulation</span>')


def render(model: m.Model, where: Callable[[Span | None], str | None], *, simulated: bool = False) -> str:
    """The whole page, as HTML; `where` gives a span's `file:line`. A `simulated` robot's page
    says so in its title and with a badge beside the status, so it is not taken for the device,
    and shows its body as the simulation has it (a device's page shows none: what a device
    reports of its joints is its outputs')."""
    name = escape(model.robot.name)
    badge, simulation = (f" {SIMULATED}", " (simulation)") if simulated else ("", "")
    try:
        graph = _inline(svg(dot(model, where)))
    except GraphvizMissing as err:
        graph = f'<p class="note">{escape(str(err))}</p>'
    details = _json(_details(model, where))
    body = shapes = ""
    if simulated and model.links:
        body = _body_view(model)
        shapes = f'<script type="application/json" id="rdis-body">{_json(_body_shapes(model))}</script>\n'
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{name}{simulation} — rdisc console</title>
<link rel="stylesheet" href="/console.css">
</head>
<body>
<header><h1>{name}</h1>{badge} <span class="status" data-rdis-status>connecting…</span></header>
<main>
<section class="graph" data-rdis-graph><h2>Description</h2>{graph}
<div class="details" data-rdis-details><p class="note">Click an element of the graph for its details.</p></div>
</section>
<section class="inputs"><h2>Inputs</h2>{''.join(_input_form(model, i) for i in model.inputs.values()) or _none}</section>
{body}<section class="outputs"><h2>Outputs</h2>{''.join(_output_panel(model, o) for o in model.outputs.values()) or _none}
</section>
<section class="state"><h2>State</h2>{_state_table(model)}</section>
<section class="errors"><h2>Errors</h2><ol data-rdis-errors></ol></section>
<section class="calls"><h2>Interfaces</h2>
{''.join(_call_form("interface", i.name, i.params, i.doc) for i in model.interfaces.values()) or _none}
<h2>Primitives</h2>
{''.join(_call_form("primitive", p.name, p.params, p.doc) for p in model.primitives.values()) or _none}</section>
{_raw_terminal(model)}
<section class="trace"><h2>Byte trace</h2>
<p class="controls"><button type="button" data-rdis-trace-pause>Pause</button>
<span class="held" data-rdis-trace-held></span>
<label>primitive <select data-rdis-trace-filter><option value="">all</option>{_primitive_options(model)}</select></label></p>
<table data-rdis-trace><thead><tr><th>time (s)</th><th>connection</th><th></th><th>bytes (hex)</th><th>primitive</th></tr>
</thead><tbody></tbody></table></section>
</main>
<script type="application/json" id="rdis-details">{details}</script>
{shapes}<script src="/console.js"></script>
</body>
</html>
"""


_none = '<p class="note">none</p>'


def _raw_terminal(model: m.Model) -> str:
    """The raw terminal, as miniterm's: bytes typed as hex sent on a connection (through its
    port's lock, as a call), and each send and the device's answer, in hex and ASCII."""
    options = "".join(f'<option value="{escape(c)}">{escape(c)}</option>' for c in model.connections)
    return (f'<section class="raw"><h2>Raw terminal <span class="type">bytes as typed, the answer as it '
            f'came</span></h2><form data-rdis-raw><label><span class="name">connection</span> '
            f'<select name="connection">{options}</select></label><label><span class="name">bytes</span> '
            f'<input type="text" name="hex" placeholder="hex: 8e 16" required></label>'
            f'<button type="submit">Send</button> <span class="result"></span></form>'
            f'<ol class="raw-log" data-rdis-raw-log></ol></section>')


def _primitive_options(model: m.Model) -> str:
    return "".join(f'<option value="{escape(p)}">{escape(p)}</option>' for p in model.primitives)


def _json(value: object) -> str:
    """JSON for a `<script>` element: no "</script>" in a name can end it early."""
    return json.dumps(value).replace("<", "\\u003c")


VIEWS = (("top", "top (x–y)"), ("side", "side (x–z)"))
PANEL, GAP, HEAD = 300, 20, 18  # px: each view's square, between the views, above them


def _body_view(model: m.Model) -> str:
    """A top and a side view of the body (one `<g data-rdis-link>` a link and one `<line
    data-rdis-joint>` a joint in each, a `<polygon data-rdis-shape>` a shape), and a row a
    moving joint for its position; console.js places them as the simulation's poses come."""
    views = []
    for n, (view, title) in enumerate(VIEWS):
        shapes = "".join(f'<polygon data-rdis-shape="{escape(link)}"></polygon>'
                         for link, drawn in _drawn(model) for _ in drawn)
        joints = "".join(f'<line data-rdis-joint="{escape(j.name)}"></line>' for j in model.joints.values())
        links = "".join(f'<g data-rdis-link="{escape(k)}"><title>{escape(k)}</title><circle r="3"></circle></g>'
                        for k in model.links)
        views.append(f'<g data-view="{view}" transform="translate({n * (PANEL + GAP)},0)">'
                     f'<text x="2" y="13">{title}</text><text class="scale" x="{PANEL - 2}" y="13" '
                     f'text-anchor="end" data-scale></text><rect class="frame" x="0" y="{HEAD}" width="{PANEL}" '
                     f'height="{PANEL}"></rect><path class="ground"></path>{shapes}{joints}{links}</g>')
    rows = "".join(f'<tr data-name="{escape(j.name)}"><th>{escape(j.name)}</th><td data-value>–</td>'
                   f'<td class="unit">{"m" if j.kind is m.JointKind.PRISMATIC else "rad"}</td>'
                   f'<td class="type">{j.kind.value}, {escape(j.parent)} → {escape(j.child)}</td></tr>'
                   for j in model.joints.values() if j.moves())
    width = 2 * PANEL + GAP
    return (f'<section class="body" data-rdis-body><h2>Body <span class="type">as the simulation has it now, '
            f'not as a device measures it</span></h2>'
            f'<svg viewBox="0 0 {width} {PANEL + HEAD}" width="{width}" height="{PANEL + HEAD}">{"".join(views)}</svg>'
            f'<table data-rdis-joints>{rows}</table></section>\n')


def _drawn(model: m.Model) -> list[tuple[str, tuple[m.Shape, ...]]]:
    """The shapes drawn of each link: its visuals, or its collision shapes when it has none
    (a mesh is not drawn: only its link's origin is)."""
    return [(link.name, tuple(s for s in (link.visuals or link.collisions) if s.kind is not m.ShapeKind.MESH))
            for link in model.links.values()]


def _body_shapes(model: m.Model) -> dict[str, object]:
    """What console.js needs to draw the body: each drawn shape (its kind, size and frame in its
    link's, the orientation a quaternion w, x, y, z) in the order of the page's polygons, and
    each joint's parent and child link."""
    shapes = [{"link": link, "kind": s.kind.value, "size": list(s.size), "at": list(s.origin.xyz),
               "quat": list(quaternion(s.origin.rpy))} for link, drawn in _drawn(model) for s in drawn]
    joints = {j.name: [j.parent, j.child] for j in model.joints.values()}
    return {"shapes": shapes, "joints": joints}


def _inline(text: str) -> str:
    """Graphviz's SVG document as an element of the page (without its XML prologue)."""
    start = text.find("<svg")
    return text[start:] if start >= 0 else text


def _range(low: float | None, high: float | None) -> str:
    return f"{low:g}..{high:g}" if low is not None and high is not None else ""


def _field(name: str, type_: m.AnyType, unit: str | None = None, low: float | None = None,
           high: float | None = None, default: m.Value | None = None) -> str:
    """A labelled `<input name=NAME>` for a value of `type_`; its unit and range beside it."""
    kind = type_.value
    if type_ is m.Type.BOOL:
        checked = " checked" if default else ""
        control = f'<input type="checkbox" name="{escape(name)}" data-kind="bool"{checked}>'
    else:
        numeric = type_ in (m.Type.INT, m.Type.FLOAT)
        attributes = ' type="number" step="any"' if numeric else ' type="text"'
        if numeric and low is not None and high is not None:
            attributes += f' min="{low:g}" max="{high:g}"'
        value = "" if default is None else _text(default)
        hint = "[a, b, …]" if isinstance(type_, m.Array) else {m.Type.BYTES: "hex", m.Type.STRING: "text"}.get(type_, "")
        placeholder = f' placeholder="{escape(hint)}"' if hint else ""
        control = (f'<input{attributes} name="{escape(name)}" data-kind="{escape(kind)}" '
                   f'value="{escape(value)}"{placeholder} required>')
    extra = " ".join(x for x in (escape(unit or ""), _range(low, high)) if x)
    return (f'<label><span class="name">{escape(name)}</span> {control} '
            f'<span class="unit">{extra}</span> <span class="type">{escape(kind)}</span></label>')


def _text(value: m.Value) -> str:
    if isinstance(value, bytes):
        return value.hex()
    if isinstance(value, tuple):
        return "[" + ", ".join(_text(v) for v in value) + "]"
    return str(value)


def _doc(doc: str | None) -> str:
    return f'<p class="doc">{escape(doc)}</p>' if doc else ""


def _input_form(model: m.Model, d: m.DomainInput) -> str:
    adapter = model.adapters[d.adapter]
    fields = "".join(_field(f.name, f.type, f.unit) for f in adapter.fields)
    return (f'<form data-rdis-input="{escape(d.name)}"><h3>{escape(d.name)} '
            f'<span class="type">{escape(adapter.name)} → {escape(d.interface)}()</span></h3>'
            f'{_doc(d.doc)}{fields}<button type="submit">Send</button> <span class="result"></span></form>')


def _call_form(kind: str, name: str, params: tuple[m.Parameter, ...], doc: str | None) -> str:
    fields = "".join(_field(p.name, p.type, None, p.low, p.high, p.default) for p in params)
    return (f'<form data-rdis-{kind}="{escape(name)}"><h3>{escape(name)}()</h3>{_doc(doc)}{fields}'
            f'<button type="submit">Call</button> <span class="result"></span></form>')


def _output_panel(model: m.Model, o: m.DomainOutput) -> str:
    adapter = model.adapters[o.adapter]
    rows = "".join(f'<tr><th>{escape(f.name)}</th><td data-field="{escape(f.name)}">–</td>'
                   f'<td class="unit">{escape(f.unit or "")}</td></tr>' for f in adapter.fields)
    return (f'<div class="output" data-rdis-output="{escape(o.name)}"><h3>{escape(o.name)} '
            f'<span class="type">{escape(adapter.name)}</span> <span class="count" data-count>0</span></h3>'
            f'{_doc(o.doc)}<table>{rows}</table><canvas width="480" height="140" data-plot></canvas></div>')


def _state_table(model: m.Model) -> str:
    rows = [(s.name, s.type, "setting") for s in model.settings.values()]
    rows += [(s.name, s.type, "state") for s in model.states.values() if s.name not in model.settings]
    rows += [(s.name, s.type, f"sensor, kept {s.cache_ms:g} ms") for s in model.sensors.values()]
    if not rows:
        return _none
    body = "".join(f'<tr data-name="{escape(n)}"><th>{escape(n)}</th><td data-value></td>'
                   f'<td class="type">{escape(t.value)} {kind}</td></tr>' for n, t, kind in rows)
    return f"<table data-rdis-state>{body}</table>"


def _details(model: m.Model, where: Callable[[Span | None], str | None]) -> dict[str, dict[str, object]]:
    """What the page shows when a node of the graph (id `kind:name`) is clicked."""
    found: dict[str, dict[str, object]] = {}
    for kind, name, span in nodes(model):
        found[f"{kind}:{name}"] = {"kind": kind, "name": name, "place": where(span), "doc": _doc_of(model, kind, name),
                                   "facts": _facts(model, kind, name)}
    return found


def _doc_of(model: m.Model, kind: str, name: str) -> str | None:
    """The element's `///` text (constants and tables keep none)."""
    elements: dict[str, Mapping[str, Any]] = {
        "connection": model.connections, "frame": model.frames, "primitive": model.primitives,
        "interface": model.interfaces, "input": model.inputs, "output": model.outputs, "adapter": model.adapters,
        "state": model.states, "setting": model.settings, "link": model.links, "joint": model.joints,
        "transmission": model.transmissions}
    doc = getattr(elements.get(kind, {}).get(name), "doc", None)
    return doc if isinstance(doc, str) else None


def _params(params: tuple[m.Parameter, ...]) -> str:
    return ", ".join(f"{p.name}: {p.type.value}" + (f" in {_range(p.low, p.high)}" if _range(p.low, p.high) else "")
                     for p in params) or "none"


def _facts(model: m.Model, kind: str, name: str) -> list[str]:
    """A few lines on the element: what it takes, what it is made of, what it refers to."""
    if kind == "connection":
        c = model.connections[name]
        hooks = [f"{event}: {hook.interface}()" for event, hook in
                 (("startup", c.startup), ("terminate", c.terminate)) if hook is not None]
        if c.keepalive is not None:
            hooks.append(f"keepalive: {c.keepalive.call.interface}() every {c.keepalive.interval_ms:g} ms")
        return [f"{c.kind}, {c.baud} baud, {c.frequency_hz:g} Hz", *hooks]
    if kind == "primitive":
        p = model.primitives[name]
        facts = [f"parameters: {_params(p.params)}", f"on {p.connection}"]
        if isinstance(p.encoding, m.Pack):
            facts.append(f'pack "{p.encoding.format}"')
        elif isinstance(p.encoding, m.Format):
            facts.append(f'format "{p.encoding.template}"')
        if isinstance(p.decoding, m.Unpack):
            facts.append(f'unpack "{p.decoding.format}"')
        elif isinstance(p.decoding, m.Regex):
            facts.append(f'regex "{p.decoding.pattern}"')
        if p.frame is not None:
            facts.append(f"frame {p.frame.frame}")
        facts += [f"sets {a.target}" for a in p.post_actions()]
        return facts
    if kind == "interface":
        i = model.interfaces[name]
        facts = [f"parameters: {_params(i.params)}"] + (["periodic"] if i.periodic else [])
        facts += [f"calls {c.primitive}()" + (f", then waits {c.delay_ms:g} ms" if c.delay_ms else "")
                  for c in i.run_order()]
        return facts + [f"triggers {o}" for o in i.triggers]
    if kind == "input":
        d = model.inputs[name]
        return [f"takes {d.adapter}", f"calls {d.interface}()"]
    if kind in ("output", "adapter"):
        adapter = model.adapters[model.outputs[name].adapter if kind == "output" else name]
        head = [f"sends {adapter.name}"] if kind == "output" else ([f'ROS "{adapter.ros}"'] if adapter.ros else [])
        return head + [f"{f.name}: {f.type.value}" + (f" ({f.unit})" if f.unit else "") for f in adapter.fields]
    if kind == "state":
        s = model.states[name]
        return [f"{s.type.value}, initially {_text(s.initial)}"]
    if kind == "setting":
        g = model.settings[name]
        return [f"{g.type.value}, default {_text(g.default)}"
                + (f", in {_range(g.low, g.high)}" if _range(g.low, g.high) else "")]
    return []
