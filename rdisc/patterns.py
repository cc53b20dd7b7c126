"""Regular expressions compiled when first used, and kept: a cold `rdisc check` compiles only those
the description in hand needs (each is a tenth to half a millisecond to compile, at import time a
millisecond or two of a check of create.rdis). `re`'s own cache keeps patterns too, but only the
last 512, and a large description's own regexes push them out."""

from __future__ import annotations

import re
from functools import cache


@cache
def pattern(text: str, flags: int = 0) -> re.Pattern[str]:
    """`re.compile(text, flags)`, compiled once."""
    return re.compile(text, flags)
