"""`rdisc fmt` over the differential generator's random descriptions: idempotent, the same Model."""

from __future__ import annotations

from conftest import fuzz_examples
from descriptions import Description, descriptions
from hypothesis import HealthCheck, given, settings

from rdisc.compile import compile_text
from rdisc.emit.canonical import to_json
from rdisc.format import format_text


@settings(max_examples=fuzz_examples(15), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(descriptions())
def test_a_generated_description_formats_idempotently_to_the_same_model(description: Description) -> None:
    formatted = format_text(description.text, "generated.rdis")
    assert format_text(formatted) == formatted
    before, after = compile_text("generated.rdis", description.text), compile_text("generated.rdis", formatted)
    assert [d.code for d in after.diagnostics.sorted()] == [d.code for d in before.diagnostics.sorted()]
    assert (after.model is None) == (before.model is None)  # the generator's text may have errors of its own
    if before.model is not None and after.model is not None:
        assert to_json(after.model) == to_json(before.model)
