"""Frozen dataclasses whose methods were written out ahead of time.

`@dataclass(frozen=True, slots=True)` writes the source of each class's `__init__`, `__eq__`,
`__hash__` and `__repr__` and compiles it when the module is imported: for the syntax tree's
and the Model's 140 classes that was about 55 ms of a 190 ms `rdisc check`. The modules that
declare them (`rdisc/syntax/ast.py`, `rdisc/semantics/model.py`) import `dataclass` and
`field` from a module `rdisc.frozen_writer` wrote from their declarations (`*_methods.py`,
compiled once into bytecode like any module); the type checker still sees the standard ones.

Each class is still declared as a dataclass and behaves as one: frozen (assignment raises
`FrozenInstanceError`), `__slots__`, equality and hashing over the compared fields, the same
`repr`, `__match_args__` for `match`, and `__dataclass_fields__`, so `dataclasses.replace`,
`fields` and `is_dataclass` work. A class whose fields differ from what was written (the
written module is stale) is made by `dataclasses.dataclass` instead, as before; a test holds
the written modules equal to what the writer writes now.
"""

from __future__ import annotations

import sys

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    import dataclasses
    from collections.abc import Callable, Mapping
    from typing import Any, Self, TypeVar

    _Class = TypeVar("_Class", bound=type)
    _Value = TypeVar("_Value")


class _Missing:
    """No default given (`dataclasses.MISSING` where `dataclasses` is asked: it is imported only
    then, as it imports `inspect`, a tenth of a cold `rdisc check`)."""

    def __repr__(self) -> str:
        return "MISSING"


MISSING: Any = _Missing()


class _Factory:
    """The default of a parameter whose field has a `default_factory` (as `dataclasses` does)."""

    def __repr__(self) -> str:
        return "<factory>"


FACTORY: Any = _Factory()


class _Default:
    """A field whose class gives it a plain default value: the value is the class's own."""

    def __repr__(self) -> str:
        return "DEFAULT"


DEFAULT: Any = _Default()


class FieldSpec(tuple["Any", "Any", bool, bool]):
    """What `field(...)` says of a field: (default, default_factory, compare, repr); compared with
    what the writer saw. A plain tuple's class: a NamedTuple's is compiled when it is made, a
    fraction of a millisecond of a cold `rdisc check`."""

    __slots__ = ()

    def __new__(cls, default: Any = MISSING, default_factory: Any = MISSING, compare: bool = True,
                repr: bool = True) -> Self:
        return tuple.__new__(cls, (default, default_factory, compare, repr))

    @property
    def default(self) -> Any:
        return self[0]

    @property
    def default_factory(self) -> Any:
        return self[1]

    @property
    def compare(self) -> bool:
        return self[2]

    @property
    def repr(self) -> bool:
        return self[3]


def field(*, default: Any = MISSING, default_factory: Any = MISSING, compare: bool = True,
          repr: bool = True) -> Any:
    """`dataclasses.field`, for the arguments these classes use."""
    return FieldSpec(default, default_factory, compare, repr)


class Written:
    """One class as the writer saw it, and its methods."""

    __slots__ = ("declared", "methods")

    def __init__(self, declared: tuple[tuple[str, Any], ...], methods: dict[str, Callable[..., Any]]) -> None:
        self.declared = declared  # each field's name and MISSING, DEFAULT or its field(...)
        self.methods = methods


def _frozen_setattr(self: object, name: str, value: object) -> None:
    import dataclasses

    raise dataclasses.FrozenInstanceError(f"cannot assign to field {name!r}")


def _frozen_delattr(self: object, name: str) -> None:
    import dataclasses

    raise dataclasses.FrozenInstanceError(f"cannot delete field {name!r}")


def _standard_field(spec: FieldSpec) -> dataclasses.Field[Any]:
    """The `dataclasses.field(...)` that `spec` stands for."""
    import dataclasses

    def given(value: object) -> Any:
        return dataclasses.MISSING if value is MISSING else value

    made: dataclasses.Field[Any] = dataclasses.field(
        default=given(spec.default), default_factory=given(spec.default_factory), compare=spec.compare,
        repr=spec.repr)
    return made


def _getstate(self: Any) -> list[Any]:
    return [getattr(self, name) for name in self.__slots__]


def _setstate(self: Any, state: list[Any]) -> None:
    for name, value in zip(self.__slots__, state):
        object.__setattr__(self, name, value)


def _field(name: str, type_: object, given: object) -> dataclasses.Field[Any]:
    import dataclasses

    made = _standard_field(given if isinstance(given, FieldSpec) else FieldSpec(default=given))
    made.name, made.type, made.kw_only = name, type_, False
    made._field_type = dataclasses._FIELD  # type: ignore[attr-defined]  # what `fields()` and `replace()` read
    return made


class _Fields:
    """A class's `__dataclass_fields__`, made when first read (by `dataclasses.fields`, `replace`,
    `is_dataclass`): the 650 fields of the syntax tree's and the Model's classes cost a tenth of
    a cold `rdisc check`, which reads few of them."""

    def __init__(self, given: list[tuple[str, object]], annotations: dict[str, object]) -> None:
        self.given, self.annotations = given, annotations
        self.made: dict[str, dataclasses.Field[Any]] | None = None

    def __get__(self, instance: object, owner: type | None = None) -> dict[str, dataclasses.Field[Any]]:
        if self.made is None:
            self.made = {name: _field(name, self.annotations[name], value) for name, value in self.given}
        return self.made


def _default(given: object) -> object:
    """The default of a field's parameter in `__init__`."""
    if not isinstance(given, FieldSpec):
        return given
    return FACTORY if given.default_factory is not MISSING else given.default


def _standard(cls: _Class, frozen: bool, slots: bool) -> _Class:
    """The class made by `dataclasses`, its `field(...)` markers made standard fields first."""
    import dataclasses
    from typing import cast

    for name, given in list(vars(cls).items()):
        if isinstance(given, FieldSpec):
            setattr(cls, name, _standard_field(given))
    return cast("_Class", dataclasses.dataclass(frozen=frozen, slots=slots)(cls))


def _made(entry: Written, name: str, qualname: str, bases: tuple[type, ...], body: Mapping[str, Any]) -> type | None:
    """The class `body` declares, made once with the methods written for it, its slots and the
    rest of what `dataclass(frozen=True, slots=True)` gives it; None when its fields differ from
    what the writer saw (the written module is stale)."""
    annotations: dict[str, object] = body.get("__annotations__", {})
    given = [(field_name, body.get(field_name, MISSING)) for field_name in annotations]
    declared = tuple([(field_name, value if value is MISSING or isinstance(value, FieldSpec) else DEFAULT)
                      for field_name, value in given])  # (a list made first: a generator is slower)
    if entry.declared != declared:
        return None
    init = entry.methods["__init__"]
    init.__defaults__ = tuple([_default(value) for _, value in given if value is not MISSING])
    namespace = {key: value for key, value in body.items()
                 if key not in annotations and key not in ("__dict__", "__weakref__")}
    for key, method in entry.methods.items():
        method.__qualname__ = f"{qualname}.{key}"
        namespace[key] = method
    namespace.update(
        __qualname__=qualname, __slots__=tuple(annotations), __match_args__=tuple(annotations),
        __dataclass_fields__=_Fields(given, annotations),
        __setattr__=_frozen_setattr, __delattr__=_frozen_delattr,
        __getstate__=_getstate, __setstate__=_setstate,
    )
    made = type(name, bases, namespace)
    written_module, made_fields = init.__globals__, vars(made)  # its `_set_<class>_<field>`, unbound until now
    setter = "_set_" + name + "_"
    for field_name in annotations:
        written_module[setter + field_name] = made_fields[field_name].__set__
    return made


class Frozen(type):
    """The metaclass of a frozen class whose methods were written ahead of time: its class statement
    makes the finished class (`class Ident(metaclass=Frozen)`), a plain `type` with slots, where
    without it the class statement makes one class and `dataclass` makes it again with slots (two
    thirds of the cost of importing the syntax tree's classes). The methods are those written in
    the declaring module's `<module>_methods`, which it has imported for `dataclass`; a class the
    writer has not seen (or whose fields changed since) is made as any class and left to `dataclass`.
    """

    def __new__(mcs, name: str, bases: tuple[type, ...], body: dict[str, Any], /, **options: Any) -> Any:
        written: dict[str, Written] = getattr(sys.modules.get(f"{body['__module__']}_methods"), "WRITTEN", {})
        entry = written.get(body["__qualname__"])
        made = None if entry is None else _made(entry, name, body["__qualname__"], bases, body)
        return type(name, bases, body, **options) if made is None else made


def classes(written: dict[str, Written]) -> Callable[..., Callable[[_Class], _Class]]:
    """The `dataclass` decorator of one module, given the methods written for its classes: a class
    `Frozen` made is finished; any other is made again with them (or by `dataclasses`)."""

    def dataclass(*, frozen: bool = False, slots: bool = False) -> Callable[[_Class], _Class]:
        def make(cls: _Class) -> _Class:
            entry = written.get(cls.__qualname__)
            if not (frozen and slots) or entry is None:
                return _standard(cls, frozen, slots)
            if _written(cls):
                return cls
            made = _made(entry, cls.__name__, cls.__qualname__, cls.__bases__, vars(cls))
            return _standard(cls, frozen, slots) if made is None else made  # type: ignore[return-value]

        return make

    return dataclass


def _written(cls: type) -> bool:
    return isinstance(vars(cls).get("__dataclass_fields__"), _Fields)


def replace(value: _Value, /, **changes: Any) -> _Value:
    """`dataclasses.replace`: a copy of `value` with `changes`; for a written class, without
    importing `dataclasses` (all of its fields are parameters of its `__init__`)."""
    cls = type(value)
    if _written(cls):
        given = {name: getattr(value, name) for name in cls.__match_args__}  # type: ignore[attr-defined]
        given.update(changes)
        return cls(**given)
    import dataclasses

    return dataclasses.replace(value, **changes)  # type: ignore[type-var]


def field_names(value: object) -> tuple[str, ...]:
    """The fields of a dataclass's instance in order, as `dataclasses.fields` names them; () for
    any other value."""
    cls = type(value)
    if _written(cls):
        names: tuple[str, ...] = cls.__match_args__  # type: ignore[attr-defined]
        return names
    made = getattr(cls, "__dataclass_fields__", None)
    return tuple(made) if isinstance(made, dict) else ()
