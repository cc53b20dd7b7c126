"""A width field `%H` and the `%` codes it sizes, outside the engine: the format stays as
written in canonical JSON and back, in `rdisc import`'s RDIS, and `rdisc dump` shows each
`%` code as `n` bytes of an unsigned integer in the format's byte order."""

from __future__ import annotations

import json
from pathlib import Path

from rdisc.compile import compile_text
from rdisc.emit.dump import dump
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import through_json
from tests.runtime.test_sized_groups import SYNC


def test_the_format_goes_through_json_and_import_as_written(tmp_path: Path) -> None:
    compilation, built = through_json(SYNC, tmp_path, "sync")
    primitive = next(p for p in json.loads(built)["primitives"] if p["name"] == "sync_write")
    assert (primitive["pack"], primitive["formatArgs"]) == ("<BH%H*(B%)", ["<131>", "<address>", "<width>", "<ids>",
                                                                          "<values>"])
    imported = run_rdisc("import", tmp_path / "sync.json")
    assert imported.returncode == 0, imported.stderr
    assert '    pack "<BH%H*(B%)" (131, address, width, ids, values)' in imported.stdout.splitlines()
    again = compile_text("again.rdis", imported.stdout)
    assert again.model is not None and again.model == compilation.model


def test_dump_shows_a_width_field_and_its_codes() -> None:
    model = compile_text("sync.rdis", SYNC).model
    assert model is not None
    assert dump(model).splitlines()[:14] == [
        ("primitive sync_write(address: int in 0..65535, width: int in 1..4, ids: int[] in 0..253, values: int[]) "
         "on bus, frame dxl(254)"),
        "  payloads stuffed: FD inserted after every FF FF FD",
        "  request: 14+n bytes",
        "  offset  size  kind                  value",
        "       0     4  header                FF FF FD 00",
        '       4     1  field id              "B" = id',
        '       5     2  length                "<H" = payload + 2',
        "       7     1  payload u8            83 (131)",
        "       8     2  payload u16 LE        address",
        "      10     2  payload u16 LE        width",
        "      12     n  payload u8 x k        ids[i]",
        "       ?     n  payload uint, width LE x k  values[i]",
        "       ?     2  checksum              crc16-buypass as <H, over header .. payload",
        "  reply: none",
    ]
