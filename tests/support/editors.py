"""examples/arm.rdis as the editor tests open it: with one primitive's clauses written on one line
(as a user may), so the file is not in `rdisc fmt`'s layout and Format Document has edits to make
(moving the lines after it); the example itself is in that layout."""

from __future__ import annotations

from pathlib import Path

ARM = Path(__file__).resolve().parents[2] / "examples" / "arm.rdis"
_SPREAD = 'primitive sync_goal(goal: int[6] in 0..4095 unit "count")\n    on bus\n    frame dxl(BROADCAST)\n'


def unformatted_arm() -> str:
    arm = ARM.read_text(encoding="utf-8")
    assert arm.count(_SPREAD) == 1
    return arm.replace(_SPREAD, 'primitive sync_goal(goal: int[6] in 0..4095 unit "count") on bus frame dxl(BROADCAST)\n')
