"""What each adapter is in each framework (thesis §7.2.5), read into the Model as each adapter's
`frameworks` (m.FrameworkMapping), which every emitter reads: the ROS 1 and ROS 2 nodes,
recordings and the live Foxglove session, `rdisc adapters`. The frameworks are the columns of
stdlib/frameworks.txt: a framework is one more column.

Every adapter, standard or a description's own, is what each column's `shorthand` row makes of
its `ros "pkg/Msg"` annotation, its fields' `ros` paths unchanged: the annotations are the one
writing of an adapter's types and paths (what the editor shows, what a copy of one writes). The
table has a row for a standard adapter only where a framework names it otherwise; such a row
agrees with the annotations in the column that is the annotation as written (ROS 1's) and may
not repeat what the shorthand says. Read with str.split, not json: `rdisc check` imports neither.
"""

from __future__ import annotations

from rdisc.semantics import model as m

HEAD = ("framework", "title", "schema", "message", "shorthand")
"""The head's rows, in order: each framework's name, title, schema and message encodings, shorthand."""
SAME = "{package}/{message}"
"""The shorthand of a framework whose type is the `ros` annotation as written (ROS 1's)."""


class TableError(ValueError):
    """A table that does not say what each adapter is in each framework: which line, and why."""


class Table:
    """The frameworks (the head's columns) and, by adapter, its type and its fields' paths in each."""

    def __init__(self, frameworks: tuple[tuple[str, str, str | None, str | None, str | None], ...],
                 adapters: dict[str, tuple[tuple[str | None, ...], dict[str, tuple[str | None, ...]]]]) -> None:
        self.frameworks = frameworks  # name, title, schema encoding, message encoding, shorthand
        self.adapters = adapters

    def standard(self, name: str, fields: tuple[str, ...]) -> tuple[m.FrameworkMapping, ...] | None:
        """A standard adapter's mappings where the table has a row for it, else None (its shorthand
        says it); TableError where the row's fields are not the adapter's."""
        row = self.adapters.get(name)
        if row is None:
            return None
        if set(row[1]) != set(fields):
            raise TableError(f"frameworks.txt: the rows of adapter {name} are not one for each of its fields")
        types, paths = row
        return tuple(m.FrameworkMapping(framework, title, type_, tuple(paths[f][k] for f in fields), schema, message)
                     for k, (framework, title, schema, message, _) in enumerate(self.frameworks)
                     if (type_ := types[k]) is not None)

    def column(self, framework: str) -> tuple[str, str, str | None, str | None, str | None]:
        """A framework's head: its name, title, encodings and shorthand."""
        return next(each for each in self.frameworks if each[0] == framework)

    def shorthand(self, ros: str | None, paths: tuple[str | None, ...]) -> tuple[m.FrameworkMapping, ...]:
        """What an adapter declared `ros "pkg/Msg"` is in each framework: none without it."""
        if ros is None:
            return ()
        package, _, message = ros.partition("/")
        return tuple(m.FrameworkMapping(framework, title, pattern.replace("{package}", package)
                                        .replace("{message}", message), paths, schema, encoding)
                     for framework, title, schema, encoding, pattern in self.frameworks if pattern is not None)


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
    """An adapter with what it is in each framework: its `ros` shorthand's, or a standard one's
    rows of the table where it has some. TableError where those rows disagree with the adapter's
    own `ros` annotations (stdlib/adapters.rdis) or only repeat what the shorthand says."""
    table = table or standard()
    paths = tuple(f.ros for f in adapter.fields)
    mappings = table.shorthand(adapter.ros, paths)
    rows = table.standard(adapter.name, tuple(f.name for f in adapter.fields)) if adapter.standard else None
    if rows is not None:
        written = {(each.framework, each.type, each.paths) for each in mappings}
        if any((row.framework, row.type, row.paths) not in written for row in rows
               if table.column(row.framework)[4] == SAME):
            raise TableError(f"frameworks.txt: adapter {adapter.name} is not what its `ros` annotations in "
                             "adapters.rdis say")
        if rows == mappings:
            raise TableError(f"frameworks.txt: the rows of adapter {adapter.name} say what its `ros` shorthand "
                             "does: only a framework that names it otherwise needs a row")
        mappings = rows
    return m.Adapter(adapter.name, adapter.fields, adapter.ros, adapter.standard, adapter.doc, adapter.span,
                     mappings)
