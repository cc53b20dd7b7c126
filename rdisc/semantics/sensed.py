"""What the sensors cost a link (rdisc.semantics.budget): each is read at the rate its readers
ask for it, and at most once per cache time (thesis §7.2.4)."""

from __future__ import annotations

from collections.abc import Iterator

from rdisc.semantics import model as m


def readers(model: m.Model, iface: m.Interface) -> set[str]:
    """The sensors one run of an interface reads: in its calls' arguments and conditions, and in
    the fields of the outputs it triggers."""
    exprs: list[m.Expr] = [e for c in iface.calls for e in (*c.args, c.when, c.until) if e is not None]
    exprs += [e for o in iface.triggers for _, e in model.outputs[o].fields]
    return {v.name for e in exprs for v in m.variables(e) if v.scope is m.Scope.STATE and v.name in model.sensors}


def read_rates(model: m.Model) -> Iterator[tuple[m.Sensor, float]]:
    """Each sensor some scheduled work reads, and how often it is read (Hz): its readers' rate
    (periodic interfaces every tick of their connection, keepalives every interval), at most
    once per cache time."""
    asked: dict[str, float] = {}
    for iface in model.interfaces.values():
        owner = model.owner(iface) if iface.periodic else None
        if owner is not None:
            for name in readers(model, iface):
                asked[name] = asked.get(name, 0.0) + model.connections[owner].frequency_hz
    for conn in model.connections.values():
        if conn.keepalive is not None and conn.keepalive.interval_ms > 0:
            for name in readers(model, model.interfaces[conn.keepalive.call.interface]):
                asked[name] = asked.get(name, 0.0) + 1000.0 / conn.keepalive.interval_ms
    for name, rate in asked.items():
        sensor = model.sensors[name]
        yield sensor, min(rate, 1000.0 / sensor.cache_ms)
