"""The one table of what each adapter is in each framework (thesis §7.2.5): stdlib/frameworks.txt,
read into the Model as each adapter's `frameworks` (m.FrameworkMapping), which every emitter
reads: the ROS 1 and ROS 2 nodes, recordings and the live Foxglove session, `rdisc adapters`.
A framework is one more column of the table.

A standard adapter is what its rows say; an adapter a description declares with the `ros
"pkg/Msg"` shorthand is what each column's `shorthand` row makes of that type, its fields'
`ros` paths unchanged. Read with str.split, not json: `rdisc check` imports neither.
"""

from __future__ import annotations

from rdisc.semantics import model as m

HEAD = ("framework", "title", "schema", "message", "shorthand")
"""The head's rows, in order: each framework's name, title, schema and message encodings, shorthand."""


class TableError(ValueError):
    """A table that does not say what each adapter is in each framework: which line, and why."""


class Table:
    """The frameworks (the head's columns) and, by adapter, its type and its fields' paths in each."""

    def __init__(self, frameworks: tuple[tuple[str, str, str | None, str | None, str | None], ...],
                 adapters: dict[str, tuple[tuple[str | None, ...], dict[str, tuple[str | None, ...]]]]) -> None:
        self.frameworks = frameworks  # name, title, schema encoding, message encoding, shorthand
        self.adapters = adapters

    def standard(self, name: str, fields: tuple[str, ...]) -> tuple[m.FrameworkMapping, ...] | None:
        """A standard adapter's mappings, or None where the table has no row for it or for one of
        its fields (a table that does not match stdlib/adapters.rdis; a test holds them equal)."""
        row = self.adapters.get(name)
        if row is None or set(row[1]) != set(fields):
            return None
        types, paths = row
        return tuple(m.FrameworkMapping(framework, title, type_, tuple(paths[f][k] for f in fields), schema, message)
                     for k, (framework, title, schema, message, _) in enumerate(self.frameworks)
                     if (type_ := types[k]) is not None)

    def shorthand(self, ros: str | None, paths: tuple[str | None, ...]) -> tuple[m.FrameworkMapping, ...]:
        """What an adapter declared `ros "pkg/Msg"` is in each framework: none without it."""
        if ros is None:
            return ()
        package, _, message = ros.partition("/")
        return tuple(m.FrameworkMapping(framework, title, pattern.replace("{package}", package)
                                        .replace("{message}", message), paths, schema, encoding)
                     for framework, title, schema, encoding, pattern in self.frameworks if pattern is not None)

    def as_shorthand(self, name: str) -> tuple[str, dict[str, str | None]] | None:
        """A standard adapter as the `ros` shorthand writes it (a copy of it in a description): its
        type and fields' paths in the column whose shorthand is the type as written; None: none."""
        row = self.adapters.get(name)
        column = next((k for k, each in enumerate(self.frameworks) if each[4] == "{package}/{message}"), None)
        if row is None or column is None or row[0][column] is None:
            return None
        return row[0][column], {field: paths[column] for field, paths in row[1].items()}  # type: ignore[return-value]


def parse(text: str, name: str = "frameworks.txt") -> Table:
    """The table a text writes; TableError names the line it cannot read."""
    rows: list[tuple[int, bool, list[str]]] = []
    for number, line in enumerate(text.splitlines(), 1):
        if line.strip() and not line.lstrip().startswith("#"):
            rows.append((number, line[:1].isspace(), line.split()))
    if len(rows) < len(HEAD) or [words[0] for _, _, words in rows[: len(HEAD)]] != list(HEAD):
        raise TableError(f"{name}: does not start with the rows {', '.join(HEAD)}")
    head = [words[1:] for _, _, words in rows[: len(HEAD)]]
    columns = len(head[0])
    for (number, _, words), _row in zip(rows, HEAD):
        if len(words) - 1 != columns:
            raise TableError(f"{name}:{number}: {len(words) - 1} columns, the frameworks {columns}")

    def given(word: str) -> str | None:
        return None if word == "-" else word

    frameworks = tuple((head[0][k], head[1][k].replace("_", " "), given(head[2][k]), given(head[3][k]),
                        given(head[4][k])) for k in range(columns))
    adapters: dict[str, tuple[tuple[str | None, ...], dict[str, tuple[str | None, ...]]]] = {}
    current: dict[str, tuple[str | None, ...]] | None = None
    for number, indented, words in rows[len(HEAD):]:
        if len(words) - 1 != columns:
            raise TableError(f"{name}:{number}: {len(words) - 1} columns, the frameworks {columns}")
        if not indented:
            if words[0] in adapters:
                raise TableError(f"{name}:{number}: adapter {words[0]} has two rows")
            current = {}
            adapters[words[0]] = (tuple(given(w) for w in words[1:]), current)
        elif current is None:
            raise TableError(f"{name}:{number}: field {words[0]} under no adapter")
        elif words[0] in current:
            raise TableError(f"{name}:{number}: field {words[0]} has two rows")
        else:
            current[words[0]] = tuple(given(w) for w in words[1:])
    return Table(frameworks, adapters)


_standard: list[Table] = []


def standard() -> Table:
    """The table rdisc ships (stdlib/frameworks.txt), read once."""
    if not _standard:
        from rdisc.resources import frameworks_file

        with open(frameworks_file(), encoding="utf-8") as file:
            _standard.append(parse(file.read()))
    return _standard[0]


def with_frameworks(adapter: m.Adapter, table: Table | None = None) -> m.Adapter:
    """An adapter with what it is in each framework: a standard one's rows of the table (its
    `ros` and its fields' the ROS 1 column's, for what reads them), else its `ros` shorthand's."""
    table = table or standard()
    if adapter.standard:
        mappings = table.standard(adapter.name, tuple(f.name for f in adapter.fields))
        if mappings is None:
            raise TableError(f"frameworks.txt: no rows for adapter {adapter.name} and each of its fields")
        ros1 = next((each for each in mappings if each.framework == "ros1"), None)
        if ros1 is None:
            return m.Adapter(adapter.name, adapter.fields, None, True, adapter.doc, adapter.span, mappings)
        fields = tuple(m.AdapterField(f.name, f.type, f.unit, path, f.doc) for f, path in zip(adapter.fields, ros1.paths))
        return m.Adapter(adapter.name, fields, ros1.type, True, adapter.doc, adapter.span, mappings)
    mappings = table.shorthand(adapter.ros, tuple(f.ros for f in adapter.fields))
    return m.Adapter(adapter.name, adapter.fields, adapter.ros, False, adapter.doc, adapter.span, mappings)
