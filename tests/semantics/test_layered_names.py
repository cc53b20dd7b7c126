"""The checker's two-layer view of the names an expression may read (rdisc.semantics.types.Layered)
holds what ChainMap(top, base) holds, in its order: a suggestion for a misspelt name reads them
in that order."""

from collections import ChainMap

from rdisc.semantics.model import Scope, Type
from rdisc.semantics.types import Layered


def test_a_layered_view_reads_as_the_chain_map_of_its_layers() -> None:
    base = {"a": (Scope.STATE, Type.INT), "b": (Scope.STATE, Type.FLOAT), "c": (Scope.STATE, Type.BOOL)}
    top = {"c": (Scope.PARAM, Type.INT), "d": (Scope.PARAM, Type.STRING)}
    layered, chained = Layered(top, base), ChainMap(top, base)
    assert list(layered) == list(chained) == ["a", "b", "c", "d"]
    assert {**layered} == {**chained} and dict(layered) == dict(chained)
    assert len(layered) == len(chained) == 4
    for name in ("a", "b", "c", "d", "e"):
        assert (name in layered) == (name in chained)
        assert layered.get(name) == chained.get(name)
        assert layered.get(name, (None, None)) == chained.get(name, (None, None))
    assert layered["c"] == (Scope.PARAM, Type.INT) and layered["a"] == (Scope.STATE, Type.INT)
    assert Layered({}, {}).get("x") is None and list(Layered({}, {})) == []
