"""Thesis Table 4.4, for the protocol examples: lines of each RDIS description
against the code lines of the published Python driver it is checked against.

Code lines are counted the same way on both sides: no blank lines, no comment
lines, and for Python no docstrings. A description's body (links, joints,
transmissions: ch. 6) has no counterpart in the drivers and is shown apart; the
ratio is the device's part, odometry included, to the driver. Run: `python benchmarks/loc_table.py`
(the drivers must be installed: `pip install '.[test]'`).
"""

from __future__ import annotations

import importlib.util
import io
import sys
import tokenize
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET = 0.25  # every description under a quarter of the driver's code

# (description, published package, the driver's modules: what it takes to drive the device)
DEVICES = [
    ("create2.rdis", "pycreate2", ["pycreate2.create2api", "pycreate2.createSerial", "pycreate2.packets",
                                   "pycreate2.OI"]),
    ("ax12.rdis", "pyax12", ["pyax12.connection", "pyax12.packet", "pyax12.instruction_packet",
                             "pyax12.status_packet", "pyax12.utils"]),
    ("lx16a.rdis", "pylx16a", ["pylx16a.lx16a"]),
    ("roboclaw.rdis", "tcr-roboclaw", ["tcr_roboclaw.roboclaw"]),  # Basicmicro's own, the reference
    ("roboclaw.rdis", "roboclaw", ["roboclaw.roboclaw", "roboclaw.roboclaw_cmd"]),  # covers about half the commands
    ("nmea.rdis", "pynmea2", ["pynmea2.nmea", "pynmea2.nmea_utils", "pynmea2.types.talker"]),
    ("arm.rdis", "dynamixel-sdk", ["dynamixel_sdk.port_handler", "dynamixel_sdk.protocol2_packet_handler",
                                   "dynamixel_sdk.group_sync_write", "dynamixel_sdk.group_sync_read",
                                   "dynamixel_sdk.group_bulk_read", "dynamixel_sdk.robotis_def"]),
    ("firmata.rdis", "pyFirmata2", ["pyfirmata2.pyfirmata2", "pyfirmata2.util", "pyfirmata2.boards"]),
    ("tmcl.rdis", "pytrinamic", ["pytrinamic.tmcl", "pytrinamic.connections.tmcl_interface",
                                 "pytrinamic.connections.serial_tmcl_interface", "pytrinamic.helpers"]),
    ("um7.rdis", "um7py", ["um7py.um7_serial", "um7py.um7_registers", "um7py.um7_broadcast_packets",
                           "um7py.rsl_xml_svd.rsl_svd_parser"]),
    ("tfmini.rdis", "tfmini", ["tfmini.tfmini"]),
    ("sabertooth.rdis", "pysabertooth", ["pysabertooth.PySabertooth"]),
    ("slcan.rdis", "python-can", ["can.interfaces.slcan"]),
    ("sbus.rdis", "rfrx", ["rfrx.sbus"]),
    ("crsf.rdis", "rpycrsf", ["rpycrsf.protocol", "rpycrsf.drone"]),  # its channels, sticks and switches
    ("crsf.rdis", "crsf-parser", ["crsf_parser", "crsf_parser.frames", "crsf_parser.handling",
                                  "crsf_parser.payloads"]),  # its telemetry (a CRC table of 256 lines)
]


def python_code_lines(path: Path) -> int:
    """Lines holding a token other than a comment or a docstring."""
    text = path.read_text(encoding="utf-8")
    lines: set[int] = set()
    previous = tokenize.NEWLINE
    for tok in tokenize.generate_tokens(io.StringIO(text).readline):
        kind = tok.type
        if kind in (tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT,
                    tokenize.ENDMARKER):
            if kind in (tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT):
                previous = kind
            continue
        if kind == tokenize.STRING and previous in (tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT):
            previous = tokenize.STRING  # a statement that is only a string: a docstring
            continue
        previous = kind
        lines.update(range(tok.start[0], tok.end[0] + 1))
    return len(lines)


def rdis_code_lines(path: Path) -> tuple[int, int]:
    """(lines of the device's description, lines of its body): the published drivers have no
    body (links, joints, transmissions), so its lines are counted apart."""
    from rdisc.diagnostics import Diagnostics
    from rdisc.syntax import ast
    from rdisc.syntax.parse import parse

    text = path.read_text(encoding="utf-8")
    module = parse(str(path), text, Diagnostics())
    body: set[int] = set()
    for decl in module.decls:
        if isinstance(decl, ast.LinkDecl | ast.JointDecl | ast.TransmissionDecl):
            first, last = (text.count("\n", 0, at) for at in (decl.span.start, decl.span.end))
            body.update(range(first, last + 1))
    code = [i for i, line in enumerate(text.splitlines()) if line.strip() and not line.strip().startswith(("#", "///"))]
    return sum(1 for i in code if i not in body), sum(1 for i in code if i in body)


def module_path(name: str) -> Path | None:
    spec = importlib.util.find_spec(name)
    return Path(spec.origin) if spec is not None and spec.origin else None


def main() -> int:
    rows = []
    for description, package, modules in DEVICES:
        rdis = ROOT / "examples" / description
        if not rdis.exists():
            rows.append((description, package, None, None, None))
            continue
        try:
            paths = [module_path(m) for m in modules]
        except ModuleNotFoundError:
            paths = [None]
        driver = sum(python_code_lines(p) for p in paths if p) if all(paths) else None
        rows.append((description, package, *rdis_code_lines(rdis), driver))
    print(f"{'description':<16}{'lines':>7}{'+ body':>8}  {'published driver':<17}{'code lines':>11}  {'ratio':>6}  "
          f"target < {TARGET:.2f}")
    met = True
    for description, package, ours, body, theirs in rows:
        if ours is None or theirs is None:
            print(f"{description:<16}{'-':>7}{'-':>8}  {package:<17}{'-':>11}  {'-':>6}  missing")
            met = False
            continue
        ratio = ours / theirs
        ok = ratio < TARGET
        met &= ok
        print(f"{description:<16}{ours:>7}{body or '':>8}  {package:<17}{theirs:>11}  {ratio:>6.2f}  "
              f"{'PASS' if ok else 'MISS'}")
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
