"""Seeded noise on simulated replies (thesis §7.2.3): a state variable that declares noise gets
Gaussian noise of its deviation on each value the simulation reports into it, so a simulated
run scatters as a real one does; the same seed gives the same replies. Counts, not time."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

pytest.importorskip("mujoco")

from rdisc.compile import compile_path
from rdisc.semantics import model as m
from rdisc.sim import Simulation
from tests.engine.test_one_engine import implementation_of

ARM = Path(__file__).with_name("sim_arm.rdis")
DECLARED = "state present: int[2] = [512, 512]"
READS = 400  # replies of each servo: the sample deviation's own error is about 3 / sqrt(800) = 0.11


def _text(noise: str) -> str:
    text = ARM.read_text(encoding="utf-8")
    assert text.count(DECLARED) == 1
    return text.replace(DECLARED, f"{DECLARED} noise {noise}")


def _model(text: str, tmp_path: Path) -> m.Model:
    path = tmp_path / "noisy_arm.rdis"
    path.write_text(text, encoding="utf-8")
    compilation = compile_path(str(path))
    assert compilation.model is not None and not compilation.diagnostics.has_errors()
    return compilation.model


def _readings(kind: str, text: str, tmp_path: Path, seed: int | None) -> list[tuple[int, int]]:
    impl = implementation_of(kind, text, tmp_path, "noisy_arm")
    robot = impl.connect(sim=Simulation(_model(text, tmp_path), seed=seed))
    try:
        found = []
        for _ in range(READS):
            robot.call_interface("sense")
            found.append(tuple(robot.state["present"]))
        return found
    finally:
        robot.close()


def _deviation(values: list[int]) -> float:
    mean = sum(values) / len(values)
    return math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_replies_scatter_by_the_declared_deviation(kind: str, tmp_path: Path) -> None:
    readings = _readings(kind, _text("3"), tmp_path, seed=11)
    (still,) = set(_readings(kind, ARM.read_text(encoding="utf-8"), tmp_path, seed=11))  # the seed's jitter
    for servo in (0, 1):
        values = [r[servo] for r in readings]
        assert abs(sum(values) / READS - still[servo]) < 0.5  # the joint at rest, on average
        assert abs(_deviation(values) - math.sqrt(9 + 1 / 12)) < 0.45  # 3 counts, and the int's rounding


def test_a_covariance_gives_each_element_its_own_deviation(tmp_path: Path) -> None:
    readings = _readings("runtime", _text("[1, 0; 0, 36]"), tmp_path, seed=3)
    assert abs(_deviation([r[0] for r in readings]) - math.sqrt(1 + 1 / 12)) < 0.2
    assert abs(_deviation([r[1] for r in readings]) - math.sqrt(36 + 1 / 12)) < 0.9


def test_the_same_seed_gives_the_same_replies(tmp_path: Path) -> None:
    text = _text("3")
    first = _readings("runtime", text, tmp_path, seed=5)
    assert _readings("runtime", text, tmp_path, seed=5) == first
    assert _readings("runtime", text, tmp_path, seed=6) != first
    assert _readings("runtime", text, tmp_path, seed=None) == _readings("runtime", text, tmp_path, seed=None)


def test_without_noise_the_replies_do_not_scatter(tmp_path: Path) -> None:
    readings = _readings("runtime", ARM.read_text(encoding="utf-8"), tmp_path, seed=None)
    assert set(readings) == {(512, 512)}  # no seed: every joint at zero


SENSOR = '''
primitive temperature() on bus pack ">BB" (3, 0) unpack ">H"
sensor warmth: int from temperature() cache 1 ms noise 2
'''


def test_a_sensors_reads_scatter_by_its_declared_deviation(tmp_path: Path) -> None:
    text = ARM.read_text(encoding="utf-8") + SENSOR
    impl = implementation_of("runtime", text, tmp_path, "warm_arm")
    robot = impl.connect(sim=Simulation(_model(text, tmp_path), seed=2))
    try:
        values = []
        for _ in range(READS):
            robot.run_for(0.002)  # older than its cache time: each read asks the simulation
            values.append(robot.sensors.warmth)
    finally:
        robot.close()
    assert abs(_deviation(values) - math.sqrt(4 + 1 / 12)) < 0.3
