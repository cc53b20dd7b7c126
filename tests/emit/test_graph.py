"""`rdisc graph`: the description as a graph of what refers to what, as DOT (a golden) and
as SVG laid out by the real Graphviz `dot`, whose every element node names its kind and
name and points back to the source line."""

from __future__ import annotations

import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rdisc.compile import compile_path

REPO = Path(__file__).resolve().parents[2]
GOLDEN = REPO / "tests" / "golden" / "graphs"
SVG = "{http://www.w3.org/2000/svg}"
needs_dot = pytest.mark.skipif(shutil.which("dot") is None, reason="Graphviz's dot is not installed "
                                                                   "(.ci/run installs it)")


@pytest.mark.parametrize("name", ["create", "arm"])
def test_dot_golden(name: str, rdisc, golden) -> None:
    result = rdisc("graph", f"examples/{name}.rdis")
    assert (result.returncode, result.stderr) == (0, "")
    golden.check(GOLDEN / f"{name}.dot", result.stdout)


def test_a_loop_of_calls_is_one_edge_counted(rdisc) -> None:
    dot = rdisc("graph", "examples/maestro.rdis").stdout
    assert '"interface:read_joints" -> "primitive:get_position" [label="calls ×6"];' in dot


def test_replies_through_their_own_frame_are_one_edge(rdisc) -> None:
    dot = rdisc("graph", "examples/arm.rdis").stdout
    assert '"primitive:sync_read_present" -> "frame:status" [label="6 replies"];' in dot
    assert '"connection:bus" -> "interface:read_joints" [label="every tick (20 Hz)"];' in dot
    assert '"primitive:sync_read_present" -> "state:present" [label="writes"];' in dot
    assert '"state:present" -> "output:joints" [label="read by"];' in dot


@needs_dot
@pytest.mark.parametrize("name", ["create", "arm", "ax12", "koala"])
def test_the_svg_names_every_element_and_its_line(name: str, rdisc, tmp_path: Path) -> None:
    out = tmp_path / f"{name}.svg"
    result = rdisc("graph", f"examples/{name}.rdis", "-o", out)
    assert (result.returncode, result.stderr) == (0, "")
    root = ET.parse(out).getroot()  # well-formed SVG
    nodes = {g.get("id"): g for g in root.iter(f"{SVG}g") if g.get("class") == "node"}
    model = compile_path(str(REPO / "examples" / f"{name}.rdis")).model
    assert model is not None
    expected = {f"primitive:{p}" for p in model.primitives} | {f"interface:{i}" for i in model.interfaces} \
        | {f"connection:{c}" for c in model.connections} | {f"output:{o}" for o in model.outputs} \
        | {f"input:{i}" for i in model.inputs} | {f"frame:{f}" for f in model.frames}
    assert expected <= set(nodes)
    for element, g in nodes.items():
        kind, _, element_name = element.partition(":")
        assert [t.text for t in g.iter(f"{SVG}text")] == [kind, element_name]
    first = next(iter(model.primitives.values()))
    line = compile_path(str(REPO / "examples" / f"{name}.rdis")).sources[first.span.path].position(  # type: ignore[union-attr]
        first.span.start).line + 1  # type: ignore[union-attr]
    anchor = next(nodes[f"primitive:{first.name}"].iter(f"{SVG}a"))
    assert anchor.get("{http://www.w3.org/1999/xlink}title") == f"{name}.rdis:{line}"


@needs_dot
def test_a_json_description_draws_the_same_graph(rdisc, tmp_path: Path) -> None:
    built = tmp_path / "create.json"
    assert rdisc("build", "examples/create.rdis", "-o", built).returncode == 0
    from_json = rdisc("graph", built).stdout
    from_text = rdisc("graph", "examples/create.rdis").stdout
    strip = [line.split(", tooltip=")[0] for line in from_text.splitlines()]  # lines differ: the JSON's own
    assert [line.split(", tooltip=")[0] for line in from_json.splitlines()] == strip


def test_without_graphviz_the_svg_is_refused_and_dot_still_works(rdisc, tmp_path: Path) -> None:
    result = rdisc("graph", "examples/create.rdis", "-o", tmp_path / "m.svg", env={"PATH": str(tmp_path)})
    assert result.returncode == 2
    assert result.stderr == ("rdisc graph: rdisc graph needs Graphviz's `dot` for SVG (Debian: apt-get install "
                             "graphviz); `-o FILE.dot` writes the DOT text without it\n")
    assert not (tmp_path / "m.svg").exists()
    result = rdisc("graph", "examples/create.rdis", "-o", tmp_path / "m.dot", env={"PATH": str(tmp_path)})
    assert result.returncode == 0 and (tmp_path / "m.dot").read_text().startswith('digraph "irobot_create" {')


def test_a_broken_description_draws_nothing(rdisc, tmp_path: Path) -> None:
    broken = tmp_path / "broken.rdis"
    broken.write_text('robot r { author "x" }\nprimitive p() on nowhere pack "B" (1)\n', encoding="utf-8")
    result = rdisc("graph", broken, "-o", tmp_path / "m.dot")
    assert result.returncode == 1 and "error[E102]" in result.stderr
    assert not (tmp_path / "m.dot").exists()


def test_the_body_is_a_tree_with_its_transmissions(rdisc) -> None:
    """Links and joints drawn as the tree (parent, joint, child); a transmission's edges go to its
    joint, to what commands it and from the state that measures it."""
    dot = rdisc("graph", "tests/golden/json/body.rdis").stdout
    edges = [line.strip() for line in dot.splitlines() if "->" in line and ("link:" in line or "transmission:" in line)]
    assert edges == [
        '"link:base" -> "joint:shoulder" [label="revolute"];',
        '"joint:shoulder" -> "link:upper" [label="child"];',
        '"link:base" -> "joint:mount" [label="fixed"];',
        '"joint:mount" -> "link:camera" [label="child"];',
        '"link:upper" -> "joint:rail" [label="prismatic"];',
        '"joint:rail" -> "link:carriage" [label="child"];',
        '"transmission:shoulder_servo" -> "joint:shoulder" [label="drives"];',
        '"transmission:shoulder_servo" -> "primitive:servo" [label="commands position as servo.goal"];',
        '"state:present" -> "transmission:shoulder_servo" [label="measures position as present[0]"];',
        '"transmission:rail_drive" -> "joint:rail" [label="drives"];',
        '"transmission:rail_drive" -> "interface:slide" [label="commands velocity as slide.speed"];',
    ]
    assert ('"joint:rail" [id="joint:rail", label="joint\\nrail", shape="circle", fillcolor="#e4e4f7", '
            'tooltip="body.rdis:19"];') in dot


def test_an_output_s_frame_is_an_edge_to_its_link(rdisc) -> None:
    """`output detect_bump: Range frame bumper`: drawn to the link; `base_bump`, the base's by
    default, has no such edge."""
    dot = rdisc("graph", "tests/runtime/data/framed_create.rdis").stdout
    assert [line.strip() for line in dot.splitlines() if '"link:' in line and "output:" in line] == [
        '"output:detect_bump" -> "link:bumper" [label="in frame"];']


def test_replies_over_an_array_parameter_are_one_edge_named_by_it(rdisc, tmp_path: Path) -> None:
    source = tmp_path / "each.rdis"
    source.write_text("""\
robot r { author "tests" }
connection bus: serial { baud 115200 }
frame status(id: int in 0..253) { request { payload }  reply { header "\\xFE"  field id "B" = id  payload } }
state present: int[]
primitive read_each(ids: int[] in 0..253) on bus pack "<B*(B)" (0x82, ids)
    replies id in ids frame status(id) unpack "<H" { present = out[0] }
""", encoding="utf-8")
    dot = rdisc("graph", source).stdout
    assert '"primitive:read_each" -> "frame:status" [label="a reply each of ids"];' in dot
