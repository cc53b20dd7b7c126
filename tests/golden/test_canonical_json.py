"""Canonical JSON of the examples and `rdisc dump` of the framed ones: goldens, and
byte-identical builds whatever the hash seed."""

from __future__ import annotations

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
JSON = Path(__file__).resolve().parent / "json"
EXAMPLES = ["create", "koala", "ax12", "roboclaw", "rplidar", "firmata"]
DUMPS = Path(__file__).resolve().parent / "dumps"


@pytest.mark.parametrize("name", EXAMPLES)
def test_canonical_json_golden(name: str, rdisc, golden) -> None:
    result = rdisc("build", f"examples/{name}.rdis")
    assert (result.returncode, result.stderr) == (0, "")
    golden.check(JSON / f"{name}.json", result.stdout)


def test_the_body_golden(rdisc, golden, tmp_path: Path) -> None:
    """Links, joints and transmissions in JSON (every kind of shape, joint and binding), and the
    JSON built again gives the same text."""
    result = rdisc("build", JSON / "body.rdis")
    assert (result.returncode, result.stderr) == (0, "")
    golden.check(JSON / "body.json", result.stdout)
    (tmp_path / "body.json").write_text(result.stdout, encoding="utf-8")
    again = rdisc("build", tmp_path / "body.json")
    assert (again.returncode, again.stderr, again.stdout) == (0, "", result.stdout)


@pytest.mark.parametrize("name", EXAMPLES)
def test_build_is_byte_identical_under_different_hash_seeds(name: str, rdisc, tmp_path: Path) -> None:
    outputs = []
    for seed in ("1", "2"):
        out = tmp_path / f"{name}-{seed}.json"
        result = rdisc("build", f"examples/{name}.rdis", "-o", out, env={"PYTHONHASHSEED": seed})
        assert (result.returncode, result.stderr) == (0, "")
        outputs.append(out.read_bytes())
    assert outputs[0] == outputs[1]
    assert outputs[0].endswith(b"\n") and b"\r" not in outputs[0]


@pytest.mark.parametrize("name", ["ax12", "create2", "roboclaw", "nmea", "rplidar", "firmata"])
def test_dump_golden(name: str, rdisc, golden) -> None:
    """Each primitive's bytes, as a user holds them against the device's manual."""
    result = rdisc("dump", f"examples/{name}.rdis")
    assert (result.returncode, result.stderr) == (0, "")
    golden.check(DUMPS / f"{name}.txt", result.stdout)
