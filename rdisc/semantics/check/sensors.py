"""Sensors (thesis §7.2.4): a primitive's one reply value, kept for a cache time. Its type is
known before any expression is typed (outputs and interfaces read it as they read state); its
primitive and cache time are checked once the primitives are."""

from __future__ import annotations

from rdisc.diagnostics import Label
from rdisc.semantics import model as m
from rdisc.semantics.check.pieces import Pieces, counted
from rdisc.syntax import ast


class Sensors(Pieces):
    def sensor(self, decl: ast.SensorDecl, type_: m.AnyType | None) -> m.Sensor | None:
        """A sensor of a checked primitive: one without parameters whose reply is one value of
        a type that flows into the sensor's, and a positive cache time."""
        name = decl.name.text
        for other, what in ((self.s.states.get(name), "a state variable"), (self.s.settings.get(name), "a setting")):
            if other is not None:
                self.d.report("E101", decl.name.span, f"`{name}` is declared as {what} and as a sensor",
                              labels=(Label(other.name.span, what[2:]),), help="expressions read both by name: rename one")
        cache = self.duration(decl.cache, "a sensor's cache time")
        if cache is not None and cache <= 0:
            self.d.report("E230", decl.cache.span, f"sensor `{name}` has a cache time of {cache:g} ms",
                          label="not positive", help="a sensor keeps its value for a time: give one, e.g. `cache 100 ms`")
            cache = None
        primitive = self.primitives.get(decl.primitive.text)
        if primitive is None:  # unknown: reported when the names were bound
            return None
        slot = _one_value(primitive)
        if primitive.params:
            self.d.report("E230", decl.primitive.span, f"sensor `{name}` reads primitive `{primitive.name}`, "
                          f"which takes {counted(len(primitive.params), 'parameter')}",
                          help="a sensor's primitive takes no arguments: declare one that reads this value alone")
        elif slot is None:
            self.d.report("E230", decl.primitive.span, f"sensor `{name}` reads primitive `{primitive.name}`, "
                          "whose reply is not one value",
                          help="a sensor holds the one value its primitive's reply decodes, such as `unpack \"B\"`")
        else:
            before = self.d.error_count
            self.flow(m.ReplyValue(0, slot.type), type_, decl.type.span, f"sensor `{name}`")
            if self.d.error_count == before and type_ is not None and cache is not None:
                noise = None
                if decl.noise is not None:  # its rules imported only for a description that states noise
                    from rdisc.semantics.check.noise import value_noise

                    noise = value_noise(self.d, decl.noise, name, type_, "sensor")
                return m.Sensor(name, type_, m.PrimitiveRef(primitive.name), cache, decl.doc, decl.span, noise)
        return None


def _one_value(p: m.Primitive) -> m.Slot | None:
    """The one value a primitive's reply decodes, read as it is (no table, listed or repeated
    replies, records or groups); None when its reply is not one such value."""
    decoding = p.decoding
    if not isinstance(decoding, m.Unpack) or p.table or p.listed or p.replies or p.records or p.each:
        return None
    layout = decoding.layout
    if len(layout.slots) != 1 or layout.rest or layout.varying or layout.groups or layout.slots[0].repeat:
        return None
    return layout.slots[0]
