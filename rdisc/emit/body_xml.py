"""What the URDF and SDF emitters share: the body as XML text, numbers as they are written,
the description's words as comments, and the device a transmission drives, in words.

Both read only the Model, and both lay out the same elements the same way each time: the
text depends on the description alone (ElementTree, attributes in the order given,
indented by two spaces).
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

from rdisc.emit.canonical import expression_text
from rdisc.semantics import model as m

# What XML 1.0 cannot carry at all (its `Char` production), even in a comment.
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


class BodyError(ValueError):
    """The description has no body to write, or one the format cannot hold."""


def require_body(model: m.Model) -> m.Link:
    """The root link; a description without links has nothing to write."""
    root = model.root_link()
    if root is None:
        raise BodyError(f"robot `{model.robot.name}` has no body: declare its links (`link base {{ ... }}`) "
                        "and the joints between them")
    return root


def number(value: float) -> str:
    """A number as short as it reads back exactly: 3 for 3.0, 0.045, 1e-05."""
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return repr(float(value))


def numbers(values: tuple[float, ...]) -> str:
    return " ".join(number(v) for v in values)


def unit(axis: m.Vector) -> m.Vector:
    """The axis scaled to length 1, as both formats expect (the checker refuses a zero one)."""
    norm = math.sqrt(sum(v * v for v in axis))
    x, y, z = (v / norm for v in axis)
    return x, y, z


def comment(parent: ET.Element, words: str | None) -> None:
    """The description's words as one XML comment line (a comment cannot hold `--`, and a
    character XML cannot carry is written as its escape: `\\x00`)."""
    if not words:
        return
    line = " ".join(words.split())
    while "--" in line:
        line = line.replace("--", "- -")
    line = _NOT_XML.sub(lambda bad: bad.group().encode("unicode_escape").decode("ascii"), line)
    parent.append(ET.Comment(f" {line} "))


def child(parent: ET.Element, tag: str, content: str | None = None, **attributes: str) -> ET.Element:
    element = ET.SubElement(parent, tag, attributes)
    if content is not None:
        element.text = content
    return element


def document(root: ET.Element) -> str:
    ET.indent(root, "  ")
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


def binding_words(binding: m.Binding, role: str) -> str:
    """What a binding drives or reads on the device, and its two conversions, in words:
    `commands position through sync_goal.goal[0]: raw = ...; position = ...`."""
    name = binding.quantity.value
    way = "through" if role == "commands" else "from"
    return (f"{role} {name} {way} {binding.place()}: raw = {expression_text(binding.to_device)}; "
            f"{name} = {expression_text(binding.to_joint)}")
