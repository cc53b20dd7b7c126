"""`format_text`: the canonical layout, every comment kept; idempotent; the same Model after."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest
from conftest import fuzz_examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_text
from rdisc.diagnostics import Diagnostics
from rdisc.emit.canonical import to_json
from rdisc.format import FormatError, format_text
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import WIDTH, print_module

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "examples").glob("*.rdis")) + [ROOT / "stdlib" / "adapters.rdis"]
# Comments as the lexer finds them: outside strings (a string has no newline and its quotes paired).
_LEXED_COMMENT = re.compile(r'r?b?"(?:[^"\\\n]|\\.)*"|(///[^\n]*|#[^\n]*)')


def comments(text: str) -> Counter[str]:
    return Counter(m.group(1).rstrip() for m in _LEXED_COMMENT.finditer(text) if m.group(1))


def same_meaning(path: Path, before: str, after: str) -> None:
    """`after` checks as `before` does: the same canonical JSON, the same diagnostic codes."""
    first, second = compile_text(str(path), before), compile_text(str(path), after)
    assert sorted(d.code for d in second.diagnostics.items) == sorted(d.code for d in first.diagnostics.items)
    assert (first.model is None) == (second.model is None)
    if first.model is not None and second.model is not None:
        assert to_json(second.model) == to_json(first.model)


MESSY = '''\
# A header comment, then two blank lines.


import   "../stdlib/adapters.rdis"
robot r { author "me"
  version "1" }
enum Op { ping = 0x01,
  read = 0x02 }   # trailing, after the enum
const T = { 1: 2,
  3: 4, }
state   count:int=0
state flag: bool = not   True



/// The link.
connection bus : serial { baud 9600
    startup   hello()  # said first
}
primitive hello() on bus pack "B" (1)
primitive read_it(id: int) on bus pack "BB" ( 2, id ) unpack "<h" { count = - out[0] }
primitive two() on bus pack "B" (3) unpack "<hh" { count = out[0]  flag = out[1] == 1 }
primitive noted() on bus  # why this bus
    pack "B" (4)
primitive a_primitive_with_a_long_name(first_parameter: int) on bus pack ">Bh" (137, first_parameter) unpack ">h"
frame f { header "\\xAA" checksum "crc16" "<H" over header .. payload  optional { literal "x"  payload } }
interface go(a: int) {
    read_it(a)  delay 10 ms

    # the second call
    read_it(a + 1,
            # one more
            2 * a)
    read_it(a_very_long_argument_name_number_one + 100000, a_very_long_argument_name_number_two * 300000)
}
# the end
'''

FORMATTED = '''\
# A header comment, then two blank lines.

import "../stdlib/adapters.rdis"
robot r {
    author "me"
    version "1"
}
enum Op {
    ping = 0x01,
    read = 0x02,
}  # trailing, after the enum
const T = {
    1: 2,
    3: 4,
}
state count: int = 0
state flag: bool = not True

/// The link.
connection bus: serial {
    baud 9600
    startup hello()  # said first
}
primitive hello() on bus pack "B" (1)
primitive read_it(id: int) on bus pack "BB" (2, id) unpack "<h" { count = -out[0] }
primitive two() on bus pack "B" (3) unpack "<hh" {
    count = out[0]
    flag = out[1] == 1
}
primitive noted()
    on bus  # why this bus
    pack "B" (4)
primitive a_primitive_with_a_long_name(first_parameter: int)
    on bus
    pack ">Bh" (137, first_parameter)
    unpack ">h"
frame f {
    header "\\xAA"
    checksum "crc16" "<H" over header .. payload
    optional { literal "x"  payload }
}
interface go(a: int) {
    read_it(a) delay 10 ms

    # the second call
    read_it(
        a + 1,
        # one more
        2 * a,
    )
    read_it(
        a_very_long_argument_name_number_one + 100000,
        a_very_long_argument_name_number_two * 300000,
    )
}
# the end
'''


def test_a_messy_description_takes_the_canonical_layout_with_its_comments_where_they_were() -> None:
    assert format_text(MESSY) == FORMATTED
    assert format_text(FORMATTED) == FORMATTED
    same_meaning(ROOT / "examples" / "t.rdis", MESSY, FORMATTED)


def test_a_long_array_is_spread_one_item_a_line_inside_its_call() -> None:
    items = ", ".join(f"position_number_{i} * 1000" for i in range(5))
    text = f"interface go() {{\n    send([{items}])\n}}\n"
    spread = "".join(f"        position_number_{i} * 1000,\n" for i in range(5))
    assert format_text(text) == f"interface go() {{\n    send([\n{spread}    ])\n}}\n"


def test_a_long_line_whose_lists_hold_little_of_it_stays_as_it_is() -> None:
    line = "    total = " + " + ".join(f"weight_{i} * int(reading_{i})" for i in range(4))
    text = f"output o: A {{\n{line}\n}}\n"
    assert len(line) > 100 and format_text(text) == text


def test_text_that_does_not_parse_raises_with_the_syntax_errors() -> None:
    with pytest.raises(FormatError) as caught:
        format_text("state x: int =\nstate y: int\n", "bad.rdis")
    assert [(d.code, d.span.start if d.span else None) for d in caught.value.diagnostics] == [("E001", 15)]
    assert str(caught.value).startswith("bad.rdis: cannot be formatted: ")


def test_empty_text_and_only_comments() -> None:
    assert format_text("") == ""
    assert format_text("\n\n# just a note  \n\n\n/// and a doc\n") == "# just a note\n\n/// and a doc\n"


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_every_example_formats_idempotently_to_the_same_model_with_every_comment(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    formatted = format_text(text, str(path))
    assert format_text(formatted, str(path)) == formatted
    assert comments(formatted) == comments(text)
    same_meaning(path, text, formatted)
    assert all(not line.endswith(" ") for line in formatted.splitlines())


def _gaps(text: str) -> list[int]:
    """Offsets where a comment may go: after each token (before the white space following it)."""
    return [m.end() for m in re.finditer(r'r?b?"(?:[^"\\\n]|\\.)*"|///[^\n]*|#[^\n]*|[^\s]+?(?=[\s]|$)', text)]


SMALL = [path for path in FILES if path.name in ("sabertooth.rdis", "sbus.rdis", "tfmini.rdis", "modbus.rdis")]


@settings(max_examples=fuzz_examples(25), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(SMALL), st.data())
def test_comments_anywhere_are_kept_and_the_result_is_stable(path: Path, data: st.DataObject) -> None:
    text = path.read_text(encoding="utf-8")
    gaps = _gaps(text)
    chosen = sorted(data.draw(st.lists(st.sampled_from(gaps), min_size=1, max_size=6, unique=True)), reverse=True)
    for i, at in enumerate(chosen):
        own_line = data.draw(st.booleans())
        note = f"# note {i}" if i % 2 else f"/// doc {i}"
        text = text[:at] + (f"\n{note}\n" if own_line else f"  {note}\n") + text[at:]
    try:
        formatted = format_text(text, str(path))
    except FormatError:  # a comment in mid-string or mid-token: it did not parse, and that was said
        return
    assert format_text(formatted, str(path)) == formatted
    assert comments(formatted) == comments(text)
    same_meaning(path, text, formatted)


def test_the_example_of_docs_format_md_is_what_fmt_gives() -> None:
    before, after = re.findall(r"```rdis\n(.*?)```", (ROOT / "docs" / "format.md").read_text(), re.DOTALL)
    assert format_text(before) == after


def test_the_printers_text_is_already_formatted_where_no_line_passes_the_width() -> None:
    """`rdisc import`'s printer and `rdisc fmt` lay out alike: the printer's text of an example is
    left as it is when all its lines fit (only a longer line is wrapped, by `rdisc fmt` alone)."""
    fitting = 0
    for path in FILES:
        printed = print_module(parse(str(path), path.read_text(encoding="utf-8"), Diagnostics()))
        if all(len(line) <= WIDTH for line in printed.splitlines()):
            fitting += 1
            assert format_text(printed) == printed, path.name
    assert fitting >= 5


@pytest.mark.parametrize(("written", "formatted"), [
    ("- ( 1 )+~ 2", "-(1) + ~2"),
    ("not  x  and y", "not x and y"),
    ("a [ 1 ] [ 2 ]", "a[1][2]"),
    ("T . m", "T.m"),
    ("f ( a , b , )", "f(a, b)"),
    ("[ 1 , 2 ] [ i ]", "[1, 2][i]"),
    ("x if c else - y ** - 2", "x if c else -y ** -2"),
    ("T . get ( k , 0 )", "T.get(k, 0)"),
])
def test_spacing_around_operators_brackets_and_commas(written: str, formatted: str) -> None:
    assert format_text(f"state s: int = {written}\n") == f"state s: int = {formatted}\n"


def test_the_rows_of_a_noise_matrix_are_written_as_the_printer_writes_them() -> None:
    assert format_text("state p: int[2] = [0, 0] noise [1 , 0.5 ;0.5, 4]\n") == (
        "state p: int[2] = [0, 0] noise [1, 0.5; 0.5, 4]\n")


def test_a_block_written_on_one_line_stays_on_one_line_when_it_fits_and_spreads_otherwise() -> None:
    one_line = 'robot r { author "me"  version "1" }\nenum Op { ping = 1, read = 2 }\nconst T = { 1: 2, 3: 4 }\n'
    assert format_text('robot r {author "me"  version "1"}\nenum Op {ping = 1, read = 2,}\nconst T = {1: 2, 3: 4}\n') == (
        one_line)
    assert format_text(one_line) == one_line
    assert format_text("enum Op { ping = 1,\n    read = 2 }\n") == "enum Op {\n    ping = 1,\n    read = 2,\n}\n"
    wide = "enum Op { " + ", ".join(f"member_{n} = {n}" for n in range(8)) + " }\n"
    assert len(wide) > 101
    assert format_text(wide) == "enum Op {\n" + "".join(f"    member_{n} = {n},\n" for n in range(8)) + "}\n"
    assert format_text("enum Op { ping = 1,  # one\n read = 2 }\n") == "enum Op {\n    ping = 1,  # one\n    read = 2,\n}\n"


def test_a_long_expression_with_no_list_to_spread_breaks_before_its_lowest_precedence_operators() -> None:
    chain = ("const A = 1 if some_long_name == 0 else 2 if another_long_name and yet_another_long_name or w\n"
             "  else 3 if zzzzz else 4\n")
    broken = ("const A = 1 if some_long_name == 0\n    else 2 if another_long_name and yet_another_long_name or w\n"
              "    else 3 if zzzzz\n    else 4\n")
    assert format_text(chain) == broken
    assert format_text(broken) == broken
    logic = "state ready: bool = " + " and ".join(f"(flag_{n} or other_{n})" for n in range(6)) + "\n"
    assert format_text(logic) == "state ready: bool = (flag_0 or other_0)\n" + "".join(
        f"    and (flag_{n} or other_{n})\n" for n in range(1, 6))
    short = "const B = 1 if a else 2 if b else 3\n"
    assert format_text(short) == short


SHIPPED = sorted({*FILES, *(ROOT / "docs").rglob("*.rdis"), *(ROOT / "stdlib").rglob("*.rdis")})


def test_every_shipped_description_is_already_in_the_layout() -> None:
    """An engineer who opens an example and formats it sees nothing move: `rdisc fmt --check`
    passes on every .rdis the project ships (examples, docs, the standard library)."""
    unformatted = [path.name for path in SHIPPED if format_text(text := path.read_text(encoding="utf-8"),
                                                                str(path)) != text]
    assert len(SHIPPED) >= 22 and unformatted == []


FRAME = 'frame f(mode: int in 0..2, code: int in 0x80..0xFF) {{\n    request {{\n        {}\n    }}\n}}\n'
EITHER = ('either when mode == 0 { field code "B" = code  payload } or when mode == 1 { header "\\xAA"'
          '  field code "B" = code & 0x7F  payload } or { header "\\xAA"  field code "B" = code & 0x7F  payload'
          '  checksum "crc" "B" width 7 poly 0x09 reflect over header .. payload }')


def test_an_either_too_long_for_its_line_starts_each_or_on_a_line_and_a_long_run_takes_one_part_a_line() -> None:
    text = FRAME.format(EITHER)
    formatted = FRAME.format(
        'either when mode == 0 { field code "B" = code  payload }\n'
        '        or when mode == 1 { header "\\xAA"  field code "B" = code & 0x7F  payload }\n'
        '        or {\n'
        '            header "\\xAA"\n'
        '            field code "B" = code & 0x7F\n'
        '            payload\n'
        '            checksum "crc" "B" width 7 poly 0x09 reflect over header .. payload\n'
        '        }')
    assert format_text(text) == formatted
    assert format_text(formatted) == formatted
    same_meaning(ROOT / "examples" / "t.rdis", text, formatted)
    fitting = FRAME.format('either when mode == 0 { payload } or { header "\\xAA"  payload }')
    assert format_text(fitting) == fitting


def test_post_actions_too_long_for_their_line_are_a_block() -> None:
    values = ", ".join(f"out[{n}]" for n in range(10))
    text = f'connection link: serial {{}}\nprimitive p() on link pack "B" (1) unpack "<10B" {{ channels = [{values}] }}\n'
    formatted = ('connection link: serial {}\nprimitive p()\n    on link\n    pack "B" (1)\n'
                 f'    unpack "<10B" {{\n        channels = [{values}]\n    }}\n')
    assert format_text(text) == formatted
    assert format_text(formatted) == formatted
    same_meaning(ROOT / "examples" / "t.rdis", text, formatted)


def test_a_long_arithmetic_expression_keeps_the_line_breaks_its_writer_chose() -> None:
    products = [f"weight_{i} * int(reading_{i})" for i in range(6)]
    written = f"output o: A {{\n    total = {products[0]} + {products[1]} + {products[2]}\n" + "".join(
        f"      + {product}\n" for product in products[3:]) + "}\n"
    kept = f"output o: A {{\n    total = {products[0]} + {products[1]} + {products[2]}\n" + "".join(
        f"        + {product}\n" for product in products[3:]) + "}\n"
    assert format_text(written) == kept
    assert format_text(kept) == kept
    one_line = f"output o: A {{\n    total = {' + '.join(products)}\n}}\n"
    assert format_text(one_line) == one_line
    short = "output o: A {\n    total = a\n        + b\n}\n"
    assert format_text(short) == "output o: A {\n    total = a + b\n}\n"
