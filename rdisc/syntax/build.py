"""Lark parse tree → AST nodes. Construction only: no checking beyond literals.

The Builder (rdisc.syntax.builder) holds a chunk's positions, spans and the expression rules'
bookkeeping; `Rules` is its method for each rule of the grammar, written by kind of declaration
(rules_declarations, rules_frames, rules_body, rules_expressions); Lark's Transformer walks a tree
with them, and the fast loop (rdisc.syntax.reduce) calls them as it reduces.
"""

from __future__ import annotations

from functools import lru_cache

from rdisc import TYPE_CHECKING
from rdisc.syntax import ast
from rdisc.syntax.builder import MAX_EXPR_DEPTH, MAX_INT_DIGITS, Builder, TooDeep, decode_bytes, decode_string
from rdisc.syntax.rules_body import BodyRules
from rdisc.syntax.rules_declarations import DeclarationRules
from rdisc.syntax.rules_expressions import ExpressionRules
from rdisc.syntax.rules_frames import FrameRules

if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

    from lark import Token, Transformer, Tree


__all__ = ["MAX_EXPR_DEPTH", "MAX_INT_DIGITS", "Builder", "Rules", "TooDeep", "build_expression", "build_tree",
           "decode_bytes", "decode_string", "rule_methods", "transformer_class"]


class Rules(DeclarationRules, FrameRules, BodyRules, ExpressionRules):
    """The Builder's method for each rule of the grammar (`v_args(meta=True)`: the rule's positions
    and its children): Lark's Transformer walks a tree with them (`transformer_class`), and the
    fast loop (rdisc.syntax.reduce) calls them as it reduces, without Lark."""

    # The methods that read only the text of their one child where it is a token (`str(c[0])`), never
    # its positions: the fast loop gives them the text, without making a Token.
    TEXT_ONLY = frozenset({"name", "int_lit", "float_lit", "bool_lit", "robot_key", "hook_event", "encoding_kind",
                           "decoding_kind", "kind_word", "time_unit", "check_word", "hex_word", "actuator_key"})

    def __init__(self, builder: Builder) -> None:
        self.b = builder



def rule_methods() -> dict[str, Callable[..., Any]]:
    """The Builder's method for each rule name that has one, from every part of `Rules`."""
    return {name: value for part in reversed(Rules.__mro__[:-1]) for name, value in vars(part).items()
            if not name.startswith("__") and callable(value)}


# What an `expr_start` tree builds: one expression.
_EXPRESSIONS = (ast.IntLit, ast.FloatLit, ast.StrLit, ast.BytesLit, ast.BoolLit, ast.Ref, ast.Index, ast.ArrayLit,
                ast.Unary, ast.BinOp, ast.Conditional, ast.CallExpr, ast.Member, ast.MethodCall)


def build_tree(builder: Builder, tree: Tree[Token], base: int) -> list[ast.Decl]:
    """The declarations of one chunk (a `start` tree, at `base` in its file) that Lark parsed;
    raises TooDeep for an expression past the limit."""
    builder.base = base
    builder.prefixed.clear()
    builder.depth.clear()
    try:
        return transformer_class()(builder).transform(tree)
    finally:
        builder.prefixed.clear()
        builder.depth.clear()


def build_expression(builder: Builder, tree: Tree[Token], base: int) -> ast.Expr:
    """The expression of an `expr_start` tree (one expression on its own, as a JSON string holds
    it); raises TooDeep as `build_tree` does."""
    built: object = build_tree(builder, tree, base)  # the transformer builds the tree's root: here, an expression
    assert isinstance(built, _EXPRESSIONS), f"an expression tree built {built!r}"
    return built


@lru_cache(maxsize=1)
def transformer_class() -> Callable[[Builder], Transformer[Token, list[ast.Decl]]]:
    """Lark's Transformer of the Rules, defined when first needed: Lark is imported lazily (start-up time)."""
    import lark
    from lark import v_args

    def __init__(self: Any, builder: Builder) -> None:
        lark.Transformer.__init__(self, visit_tokens=False)
        self.b = builder

    namespace: dict[str, Any] = {**rule_methods(), "__init__": __init__}
    made: Callable[[Builder], Transformer[Token, list[ast.Decl]]] = v_args(meta=True)(
        type("Transformer", (lark.Transformer,), namespace))
    return made
