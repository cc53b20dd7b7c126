"""A body a simulator cannot integrate ends the simulation with a message, never a loop for
ever, a traceback or MuJoCo's log in the user's folder (issue 20, item 7): what the checker can
tell is refused at check (a mass of 1e308, a chain deeper than MJCF nests), the rest is a
SimulationError when MuJoCo warns or its state stops being finite."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

mujoco = pytest.importorskip("mujoco")

from rdisc.compile import compile_path, compile_text
from rdisc.sim import Simulation, SimulationError
from tests.conftest import run_rdisc

ROOT = Path(__file__).resolve().parents[2]
CREATE2 = (ROOT / "examples" / "create2.rdis").read_text(encoding="utf-8")
WHEEL = "mass 0.15\n    inertia [0.0000536, 0.0000972, 0.0000536]"
JOINTS = "velocity 13.8\n    effort 0.5"


def _codes(text: str) -> list[tuple[str, str]]:
    compilation = compile_text("body.rdis", text)
    return [(d.code, d.message) for d in compilation.diagnostics.items]


def test_a_mass_or_inertia_no_simulator_integrates_is_refused_at_check() -> None:
    text = CREATE2.replace(WHEEL, "mass 1e308  inertia [1e300, 1e300, 1e300]", 1)
    assert _codes(text) == [
        ("E604", "a link's mass of 1e+308 kg is more than a simulator can integrate"),
        ("E604", "an inertia of 1e+300 kg m² is more than a simulator can integrate"),
    ]


def test_a_body_deeper_than_mjcf_nests_is_a_message_not_a_recursion_error(tmp_path: Path) -> None:
    lines = ['robot chain { author "tests" }', "link l0 { mass 1 inertia [0.1, 0.1, 0.1] }"]
    for i in range(1, 1200):
        lines.append(f"link l{i} {{ mass 1 inertia [0.1, 0.1, 0.1] }}")
        lines.append(f"joint j{i}: fixed l{i - 1} -> l{i} {{ at [0, 0, 0.1] }}")
    source = tmp_path / "chain.rdis"
    source.write_text("\n".join(lines), encoding="utf-8")
    assert _codes(source.read_text(encoding="utf-8")) == []  # the checker takes it; MJCF cannot nest it
    said = "the body is 1199 joints deep; MJCF nests each link in its parent's, and rdisc writes at most 256"
    result = run_rdisc("emit-mjcf", source)
    assert (result.returncode, result.stderr) == (1, f"rdisc emit-mjcf: {source}: {said}\n")
    result = run_rdisc("sim", source, "--duration", "0.01", cwd=tmp_path)
    assert (result.returncode, result.stderr) == (2, f"rdisc sim: chain: MuJoCo cannot simulate this body: {said}\n")


def test_an_unstable_simulation_ends_with_a_message_and_no_log(tmp_path: Path) -> None:
    """Gains of 1e14 on wheels of a milligram: accepted, and NaN at the first step."""
    text = CREATE2.replace(WHEEL, "mass 1e-6  inertia [1e-12, 1e-12, 1e-12]").replace(JOINTS, "velocity 1e-6 effort 1e6")
    source = tmp_path / "unstable.rdis"
    source.write_text(text, encoding="utf-8")
    result = run_rdisc("sim", source, "--call", "set_velocity", "linear=0.5", "angular=0", "--duration", "5",
                       cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    assert re.fullmatch(r"rdisc run: SimulationError: create2: the simulation became unstable near t = 0\.\d{4} s: "
                        r"Nan, Inf or huge value in QACC at DOF \d+\. The simulation is unstable\. Time = [\d.]+\. "
                        r"\(is a mass, an inertia or a gain out of proportion to the others\?\)\n", result.stderr)
    assert list(tmp_path.iterdir()) == [source]  # no MUJOCO_LOG.TXT


def test_a_state_no_longer_finite_stops_the_physics_for_good(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    compilation = compile_text("create2.rdis", CREATE2)
    assert compilation.model is not None
    simulation = Simulation(compilation.model)
    simulation.advance(0.01)
    simulation.data.qvel[0] = math.nan
    with pytest.raises(SimulationError, match="the simulation became unstable near t = 0.01"):
        simulation.advance(0.01)
    at = float(simulation.data.time)
    simulation.advance(1.0)  # stopped where it failed: no step, no second error
    assert float(simulation.data.time) == at
    assert simulation.now() == pytest.approx(1.02)
    assert list(tmp_path.iterdir()) == []


def test_contacts_past_mujocos_memory_are_a_message(tmp_path: Path) -> None:
    lines = ['robot star { author "tests" }', "link base { mass 1 inertia [0.1, 0.1, 0.1] collision box(1, 1, 1) }"]
    for i in range(500):
        lines.append(f"link s{i} {{ mass 1 inertia [0.1, 0.1, 0.1] collision box(1, 1, 1) }}")
        lines.append(f"joint j{i}: revolute base -> s{i} {{ axis [0, 0, 1] limit -1..1 velocity 1 effort 1 }}")
    source = tmp_path / "star.rdis"
    source.write_text("\n".join(lines), encoding="utf-8")
    result = run_rdisc("sim", source, "--duration", "0.01", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.startswith("rdisc sim: star: MuJoCo cannot simulate this body: mj_stackAlloc: out of memory")


def test_a_mesh_is_found_beside_the_description_and_a_missing_one_is_a_message(tmp_path: Path) -> None:
    folder = tmp_path / "robot"
    folder.mkdir()
    text = ('robot meshy { author "tests" }\n'
            'link base { mass 1 inertia [0.1, 0.1, 0.1] collision mesh("base.stl") }\n')
    (folder / "meshy.rdis").write_text(text, encoding="utf-8")
    (tmp_path / "base.stl").write_bytes(b"")  # in the current folder only: not the description's mesh
    result = run_rdisc("sim", folder / "meshy.rdis", "--duration", "0.01", cwd=tmp_path)
    # issue 26: the checker's diagnostic, before MuJoCo is asked
    assert result.returncode == 1
    assert result.stderr.startswith("error[E614]: mesh `base.stl` is not found: there is no file `base.stl` in the "
                                    "folder of meshy.rdis\n"), result.stderr
    # A cube of 12 triangles, binary STL, beside the description (not in the current folder).
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1), (2, 3, 7), (2, 7, 6), (0, 2, 6),
             (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    import struct

    stl = b"\0" * 80 + struct.pack("<I", len(faces))
    for face in faces:
        stl += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *corners[i]) for i in face) + b"\0\0"
    (folder / "base.stl").write_bytes(stl)
    model = compile_path(str(folder / "meshy.rdis")).model
    assert model is not None
    Simulation(model).advance(0.01)
