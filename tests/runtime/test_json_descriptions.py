"""The runtime runs JSON descriptions: `rdisc build` output and hand-written
thesis Appendix B style; a hostile one is refused when loading, never evaluated."""

from __future__ import annotations

import struct

import pytest
from devices import CreateEmulator
from devices.create import DRIVE, STOP
from runtime_support import CREATE, DATA, Recorder, typed_thesis_create

from rdisc.runtime import RdisLoadError, load


def test_canonical_json_runs_like_its_source(rdisc, tmp_path) -> None:
    built = tmp_path / "create.json"
    result = rdisc("build", CREATE, "-o", built)
    assert result.returncode == 0, result.stderr
    with CreateEmulator(bumpers=2) as dev:
        outputs = Recorder()
        with load(built).connect(dev.port, threads=False, on_output=outputs) as robot:
            robot.call_input("set_velocity", linear=-0.2, angular=-0.4)
            robot.tick()
        assert dev.wait_for_commands(2, opcode=DRIVE)[0][1] == struct.pack(">Bhh", 137, -200, 500)
    assert outputs.snapshot() == [{"name": "detect_bump", "contents": {"distance": 0.0}}]


def test_hand_written_appendix_b_json_runs() -> None:
    with CreateEmulator(bumpers=1) as dev:
        outputs = Recorder()
        with load(DATA / "appendix_b.json").connect(dev.port, on_output=outputs) as robot:
            robot.call_input("set_velocity", linear=0.2, angular=0.4)
            outputs.wait_count(2)
        assert dev.wait_for_commands(2, opcode=DRIVE)[-1][1] == STOP
        assert dev.drives()[0] == (200, 500)
    assert outputs.snapshot()[0] == {"name": "detect_bump", "contents": {"distance": 0.0}}


def test_a_hostile_expression_is_refused_and_never_evaluated(tmp_path, monkeypatch, rdisc) -> None:
    marker = tmp_path / "pwned"
    hostile = tmp_path / "hostile.json"
    hostile.write_text((DATA / "hostile.json").read_text().replace("HOSTILE_MARKER", str(marker)))
    monkeypatch.chdir(tmp_path)
    with pytest.raises(RdisLoadError) as caught:
        load(hostile)
    message = str(caught.value)
    assert "error[E002]: names cannot start with `_`" in message
    assert "__import__('os').system(" in message  # the source line, shown
    assert [d.code for d in caught.value.diagnostics] == ["E002"]
    result = rdisc("run", hostile, "--port", "loop://", "--call", "set_velocity", "linear=0", "angular=0")
    assert result.returncode == 1
    assert "error[E002]" in result.stderr
    assert not marker.exists()


def test_a_description_with_errors_is_a_load_error(tmp_path) -> None:
    with pytest.raises(RdisLoadError) as caught:
        load(typed_thesis_create(tmp_path))
    assert str(caught.value).count("error[E402]") == 2
    assert str(caught.value).endswith("2 errors emitted")


def test_a_missing_file_is_a_load_error(tmp_path) -> None:
    with pytest.raises(RdisLoadError, match="cannot read"):
        load(tmp_path / "nothing.rdis")
