"""Canonical JSON of the examples and `rdisc dump` of the framed ones: goldens, and
byte-identical builds whatever the hash seed."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from conftest import run_rdisc_seeded

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
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "base.stl").write_bytes(b"")  # the mesh body.rdis names, beside the copy
    (tmp_path / "body.json").write_text(result.stdout, encoding="utf-8")
    again = rdisc("build", tmp_path / "body.json")
    assert (again.returncode, again.stderr, again.stdout) == (0, "", result.stdout)


@pytest.fixture(scope="module")
def seeded_builds(tmp_path_factory: pytest.TempPathFactory) -> dict[str, list[tuple[subprocess.CompletedProcess[str], Path]]]:
    """Each example built under each hash seed: one interpreter a seed builds them all (the seed is
    read when Python starts); by name, a (result, output file) a seed."""
    folder = tmp_path_factory.mktemp("seeded")
    builds: dict[str, list[tuple[subprocess.CompletedProcess[str], Path]]] = {name: [] for name in EXAMPLES}
    for seed in ("1", "2"):
        outs = [folder / f"{name}-{seed}.json" for name in EXAMPLES]
        results = run_rdisc_seeded([("build", f"examples/{name}.rdis", "-o", out) for name, out in zip(EXAMPLES, outs)],
                                   seed)
        for name, result, out in zip(EXAMPLES, results, outs):
            builds[name].append((result, out))
    return builds


@pytest.mark.parametrize("name", EXAMPLES)
def test_build_is_byte_identical_under_different_hash_seeds(name: str, seeded_builds) -> None:
    outputs = []
    for result, out in seeded_builds[name]:
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
