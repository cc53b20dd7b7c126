"""JSON description → AST (`document.read`): the canonical JSON of `rdisc build`, and hand-written
thesis-style JSON such as thesis Appendix B.

Every JSON value keeps its place in the file (Lark, grammar/json.lark), so the
checker's diagnostics about an imported description point at the JSON line, and
an expression written `"<...>"` is parsed by the RDIS grammar with spans on the
characters inside the string. Nothing is evaluated: the thesis ran `eval` on these
strings, rdisc reads them as data.

Thesis conventions: `"<expr>"` is an expression; `""` is the default of the type
expected there (0, 0.0, False, ""); any other string is a string literal; a
post-action is `"state = expr"` with the reply called `__out__`. Missing members
default as in thesis Appendix A. Thesis JSON has no types, so parameter types
are inferred: a primitive parameter passed bare as format argument i has the
type of value i of the template (else int); an interface parameter passed bare
to a primitive parameter has that parameter's type (else float). An input or
output without an adapter gets the standard adapter with exactly its fields (for
an input, in its order: else a copy of it in that order), or an adapter of float
fields made for it.

A member of the wrong kind, a missing name or an unknown member is an E008 error
at the offending value, and the element it belongs to is left out (as the parser
leaves out a declaration with a syntax error). Size, nesting and the number of
values are bounded (E005) before Lark sees the text.
"""
