"""A visual shape's colour (`visual SHAPE ... color [r, g, b]` or `[r, g, b, a]`, each 0 to 1),
carried to every model format as that format says colours, and read back by the tools that
read them: urchin (URDF material), libsdformat (`ign sdf -k` on the SDF's material) and MuJoCo
(a geom's rgba); through the canonical JSON both ways; refused (E602) out of range."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rdisc.compile import compile_text
from rdisc.emit.canonical import to_json
from rdisc.emit.mjcf import to_mjcf
from rdisc.emit.sdf import to_sdf
from rdisc.emit.urdf import to_urdf
from tests.emit.body_tools import ign_sdf_check, require_module

COLOURED = """\
robot colours { description "a coloured arm" }
link base { visual box(0.1, 0.1, 0.02) color [0.2, 0.25, 0.3]  mass 1  inertia [0.001, 0.001, 0.001] }
link arm {
    visual box(0.02, 0.02, 0.2) at [0, 0, 0.1] color [0.9, 0.1, 0.1, 0.5]
    visual sphere(0.02)
    collision box(0.02, 0.02, 0.2) at [0, 0, 0.1]
    mass 0.1  inertia [0.0004, 0.0004, 0.00001]
}
joint lift: revolute base -> arm { at [0, 0, 0.02] axis [0, 1, 0] limit -1..1 velocity 1 effort 1 }
"""
COLOURS = {"base": [(0.2, 0.25, 0.3, 1.0)], "arm": [(0.9, 0.1, 0.1, 0.5), None]}


def _model():  # type: ignore[no-untyped-def]
    compilation = compile_text("colours.rdis", COLOURED)
    assert compilation.model is not None and compilation.diagnostics.items == []
    return compilation.model


def test_the_model_holds_each_visual_s_colour_alpha_1_when_not_given() -> None:
    model = _model()
    assert {name: [s.color for s in link.visuals] for name, link in model.links.items()} == COLOURS


def test_urchin_reads_each_colour_from_the_urdf(tmp_path: Path) -> None:
    urchin = require_module("urchin")
    path = tmp_path / "colours.urdf"
    path.write_text(to_urdf(_model(), "colours.rdis"), encoding="utf-8")
    robot = urchin.URDF.load(str(path), lazy_load_meshes=True)
    read = {link.name: [None if v.material is None else tuple(float(c) for c in v.material.color) for v in link.visuals]
            for link in robot.links}
    assert read == COLOURS


def test_libsdformat_takes_the_sdf_s_materials(tmp_path: Path) -> None:
    path = tmp_path / "colours.sdf"
    path.write_text(to_sdf(_model(), "colours.rdis"), encoding="utf-8")
    assert ign_sdf_check(path) == (0, "Valid.")
    visuals = ET.parse(path).getroot().iter("visual")
    assert [(v.findtext("material/ambient"), v.findtext("material/diffuse")) for v in visuals] == [
        ("0.2 0.25 0.3 1", "0.2 0.25 0.3 1"), ("0.9 0.1 0.1 0.5", "0.9 0.1 0.1 0.5"), (None, None)]


def test_mujoco_reads_each_geom_s_rgba() -> None:
    mujoco = require_module("mujoco")
    physics = mujoco.MjModel.from_xml_string(to_mjcf(_model()))
    rgba = {physics.geom(i).name: tuple(round(float(c), 6) for c in physics.geom_rgba[i]) for i in range(physics.ngeom)}
    assert rgba["base_visual0"] == (0.2, 0.25, 0.3, 1.0)
    assert rgba["arm_visual0"] == (0.9, 0.1, 0.1, 0.5)
    assert rgba["arm_visual1"] == (0.5, 0.5, 0.5, 1.0)  # MuJoCo's own grey where none is said


def test_the_colours_go_through_the_canonical_json_and_back() -> None:
    model = _model()
    text = to_json(model)
    links = {link["name"]: link for link in json.loads(text)["links"]}
    assert [v.get("color") for v in links["arm"]["visuals"]] == [[0.9, 0.1, 0.1, 0.5], None]
    again = compile_text("colours.json", text)
    assert again.model is not None and again.diagnostics.items == []
    assert {n: [s.color for s in link.visuals] for n, link in again.model.links.items()} == COLOURS


@pytest.mark.parametrize(("colour", "where"), [("[1.2, 0, 0]", "[1.2, 0, 0]"), ("[0, 0]", "[0, 0]"),
                                               ("[0, 0, 0, 0, 1]", "[0, 0, 0, 0, 1]"), ("[-0.1, 0, 0]", "[-0.1, 0, 0]")])
def test_a_colour_out_of_range_or_of_the_wrong_size_is_e602(colour: str, where: str) -> None:
    text = COLOURED.replace("color [0.2, 0.25, 0.3]", f"color {colour}")
    compilation = compile_text("colours.rdis", text)
    assert [(d.code, text[d.span.start:d.span.end], d.message, d.help) for d in compilation.diagnostics.items] == [
        ("E602", where, "a colour is `[red, green, blue]` or `[red, green, blue, alpha]`, each from 0 to 1",
         "`color [0.8, 0.1, 0.1]` is red; `[0, 0, 1, 0.5]` a see-through blue")]
