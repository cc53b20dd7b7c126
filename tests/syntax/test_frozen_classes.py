"""The frozen classes written ahead of time (rdisc/frozen.py): the written modules are what
the writer writes now, and every class behaves as `dataclasses` would have made it."""

from __future__ import annotations

import dataclasses
import importlib
import importlib.util
import pickle
import sys
import types
from pathlib import Path
from typing import Any

import pytest

from rdisc import frozen, frozen_writer
from rdisc.semantics import model, model_body, model_elements, model_expressions, model_frames, model_layouts
from rdisc.syntax import ast, ast_body, ast_expressions, ast_frames, ast_primitives

PACKAGE = Path(frozen_writer.__file__).resolve().parent


@pytest.mark.parametrize("source", sorted(frozen_writer.MODULES))
def test_written_modules_are_what_the_writer_writes(golden, source: str) -> None:
    golden.check(PACKAGE / frozen_writer.MODULES[source], frozen_writer.write(PACKAGE / source))


def standard(module: types.ModuleType, folder: Path, monkeypatch: pytest.MonkeyPatch) -> types.ModuleType:
    """The same module with its classes made by `dataclasses` (as before the written methods)."""
    text = Path(module.__file__ or "").read_text(encoding="utf-8")
    written = f"from {module.__name__}_methods import dataclass, field"
    assert written in text
    name = f"standard_{module.__name__.replace('.', '_')}"
    path = folder / f"{name}.py"
    path.write_text(text.replace(written, "from dataclasses import dataclass, field"), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    made = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, name, made)  # where dataclasses looks for the module
    spec.loader.exec_module(made)
    return made


def frozen_classes(*modules: types.ModuleType) -> list[str]:
    return [name for module in modules for name, value in vars(module).items()
            if isinstance(value, type) and value.__module__ == module.__name__ and dataclasses.is_dataclass(value)]


def declared(modules: list[types.ModuleType]) -> dict[str, Any]:
    """Each frozen class of the modules, by name, from the module that declares it."""
    return {name: getattr(module, name) for module in modules for name in frozen_classes(module)}


# The syntax tree's and the Model's classes are declared by concern in the modules their namespaces
# re-export (rdisc/syntax/ast.py, rdisc/semantics/model.py).
AST = (ast_expressions, ast_primitives, ast_frames, ast_body, ast)
MODEL = (model_expressions, model_layouts, model_frames, model_elements, model_body, model)


def described(fields: tuple[dataclasses.Field[Any], ...]) -> list[tuple[Any, ...]]:
    return [(f.name, f.type, repr(f.default), f.default_factory, f.init, f.repr, f.compare, f.hash, f.kw_only)
            for f in fields]


def outcome(function: Any, *args: Any) -> Any:
    try:
        return function(*args)
    except Exception as err:  # noqa: BLE001  (the same exception is the same behaviour)
        return type(err), str(err)


@pytest.mark.parametrize("modules", [AST, MODEL], ids=["ast", "model"])
def test_classes_behave_as_dataclasses_made_them(modules: tuple[types.ModuleType, ...], tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    before = [standard(module, tmp_path, monkeypatch) for module in modules]
    names = frozen_classes(*modules)
    assert names == frozen_classes(*before) and len(names) > 40
    made, standard_made = declared(list(modules)), declared(before)
    for name in names:
        mine, theirs = made[name], standard_made[name]
        assert "__init__" in mine.__dict__ and mine.__init__.__module__.endswith("_methods"), name  # written
        assert mine.__slots__ == theirs.__slots__ and mine.__match_args__ == theirs.__match_args__, name
        assert described(dataclasses.fields(mine)) == described(dataclasses.fields(theirs)), name
        assert ([k for k in vars(mine) if not k.startswith("__")] == [k for k in vars(theirs) if not k.startswith("__")])
        required = [f.name for f in dataclasses.fields(mine) if f.default is f.default_factory is dataclasses.MISSING]
        values = {field: index for index, field in enumerate(required)}
        a, b = mine(**values), theirs(**values)
        assert repr(a) == repr(b), name
        assert outcome(hash, a) == outcome(hash, b), name
        other = mine(**{**values, **({"span": object()} if "span" in mine.__slots__ else {})})
        assert a == other and a == dataclasses.replace(a) and a != (required and mine(**{**values, required[0]: -1}))
        assert a.__eq__(b) is NotImplemented  # another class
        for field in mine.__slots__:
            assert outcome(setattr, a, field, 1) == outcome(setattr, b, field, 1), name
            assert outcome(delattr, a, field) == outcome(delattr, b, field), name
        assert outcome(setattr, a, "other", 1)[0] is dataclasses.FrozenInstanceError
        assert pickle.loads(pickle.dumps(a)) == a


def test_patterns_replace_and_defaults() -> None:
    ident = ast.Ident("drive", ast.Ident("span").span)
    match ast.Call(ident, ()):
        case ast.Call(ast.Ident(text), args):
            assert (text, args) == ("drive", ())
    assert dataclasses.replace(ident, text="stop") == ast.Ident("stop")
    joint = model.Joint("j", model.JointKind.FIXED, "a", "b")
    assert joint.origin is model.Joint("k", model.JointKind.FIXED, "a", "b").origin  # the class's own default
    first, second = model.Model(*[None] * 8), model.Model(*[None] * 8)
    assert first.frames == {} and first.frames is not second.frames  # a default factory's


def test_a_class_the_written_module_does_not_know_is_made_by_dataclasses() -> None:
    dataclass = frozen.classes({})

    @dataclass(frozen=True, slots=True)
    class Point:
        x: int
        y: int = frozen.field(default=0, compare=False)

    assert Point.__init__.__module__ != frozen.__name__ and dataclasses.fields(Point)[1].compare is False
    assert Point(1, 2) == Point(1, 3) and repr(Point(1)).endswith(".Point(x=1, y=0)")


def test_a_class_whose_fields_changed_since_it_was_written_is_made_by_dataclasses() -> None:
    from rdisc.syntax import ast_methods

    dataclass = frozen.classes(ast_methods.WRITTEN)

    @dataclass(frozen=True, slots=True)
    class Ident:  # as written, with a field added since
        text: str
        span: object = frozen.field(compare=False, repr=False, default=None)
        quoted: bool = False

    assert Ident.__init__.__module__ != ast_methods.__name__
    assert Ident("x", 1) == Ident("x", 2, False) and repr(Ident("x")).endswith("Ident(text='x', quoted=False)")


def test_the_class_statement_makes_the_finished_class_which_dataclass_keeps(monkeypatch: pytest.MonkeyPatch) -> None:
    """`metaclass=Frozen`: the class statement makes the class with its slots and written methods,
    a plain `type`, and the decorator gives that class back rather than making it a second time."""
    from rdisc.syntax import ast_expressions_methods as ast_methods

    for name in ("_set_Ident_text", "_set_Ident_span"):  # bound to this class's slots below: put back after
        monkeypatch.setitem(vars(ast_methods), name, vars(ast_methods)[name])
    given: list[type] = []

    def dataclass(**options: bool) -> Any:
        def make(cls: type) -> type:
            given.append(cls)
            return ast_methods.dataclass(**options)(cls)

        return make

    @dataclass(frozen=True, slots=True)
    class Ident(metaclass=frozen.Frozen):
        __module__ = "rdisc.syntax.ast_expressions"  # where the metaclass finds the methods written for it
        __qualname__ = "Ident"
        text: str
        span: object = frozen.field(compare=False, repr=False, default=None)

    assert given == [Ident] and type(Ident) is type and Ident.__slots__ == ("text", "span")
    assert Ident.__init__ is ast_methods._init_Ident and not hasattr(Ident("x"), "__dict__")
    assert Ident("x", 1) == Ident("x", 2) and repr(Ident("x")) == "Ident(text='x')"
    with pytest.raises(dataclasses.FrozenInstanceError):
        Ident("x").text = "y"  # type: ignore[misc]


def test_the_writer_refuses_a_frozen_class_made_twice(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A frozen class declared without the metaclass would be made by its class statement and
    again by `dataclass`: the writer says so instead of writing its methods."""
    monkeypatch.setattr(frozen_writer, "PACKAGE", tmp_path / "rdisc")  # what the writer names paths from
    declared = tmp_path / "rdisc" / "declared.py"
    declared.parent.mkdir()
    declared.write_text("@dataclass(frozen=True, slots=True)\nclass Point:\n    x: int\n", encoding="utf-8")
    with pytest.raises(frozen_writer.WriterError,
                       match=r"^rdisc/declared.py:2: Point: declare it `class Point\(metaclass=Frozen\)`"):
        frozen_writer.write(declared)
    declared.write_text(declared.read_text(encoding="utf-8").replace("Point:", "Point(metaclass=Frozen):"))
    assert "def _init_Point(self: Any, x: Any) -> None:" in frozen_writer.write(declared)


@pytest.mark.parametrize("source", sorted(frozen_writer.MODULES))
def test_each_written_init_sets_its_fields_through_their_slots(source: str) -> None:
    """A written `__init__` calls each field's slot's own setter (a third faster than
    `object.__setattr__`), bound when the class is made; the class stays frozen."""
    name = "rdisc." + frozen_writer.MODULES[source].removesuffix(".py").replace("/", ".")
    methods = importlib.import_module(name)
    declaring = importlib.import_module(name.removesuffix("_methods"))
    classes = 0
    for cls_name in methods.WRITTEN:
        cls = getattr(declaring, cls_name)
        for field_name in cls.__slots__:
            setter = getattr(methods, f"_set_{cls_name}_{field_name}")
            assert setter == vars(cls)[field_name].__set__, (cls_name, field_name)
        classes += 1
    assert classes == len(methods.WRITTEN) > 0
    with pytest.raises(dataclasses.FrozenInstanceError):
        ast.Ident("x").text = "y"  # type: ignore[misc]
