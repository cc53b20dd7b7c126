"""The engine as a package of small modules, and as a driver carries it: each module's text
after its imports, in the listed order, between markers; the standard-library imports once
above them. The package needs nothing of rdisc outside it, and the sections one after the
other are one module binding each name once (the driver tests run it)."""

from __future__ import annotations

import ast
import importlib
import sys
from pathlib import Path

import pytest

import rdisc.engine
from rdisc.emit.python import to_python
from rdisc.engine import carry
from tests.engine.test_one_engine import ROOT

FOLDER = Path(rdisc.engine.__file__).parent
MODULES = [module for module, _ in carry.MODULES]


@pytest.fixture(scope="module")
def driver() -> str:
    from rdisc.compile import compile_path

    compilation = compile_path(str(ROOT / "examples" / "create.rdis"))
    assert compilation.model is not None
    return to_python(compilation.model, "create.rdis")


def _sections(driver: str) -> dict[str, str]:
    """Each carried module's text in a driver, by the module its marker names."""
    lines = driver.split("\n")
    markers = [i for i, line in enumerate(lines) if line.startswith("# ---- rdisc engine: ")]
    plans = next(i for i, line in enumerate(lines) if i > markers[-1] and line.startswith("# ---- "))
    found = {}
    for at, end in zip(markers, [*markers[1:], plans]):
        module = lines[at].removeprefix("# ---- rdisc engine: ").split(" ")[0]
        found[module] = "\n".join(lines[at + 1 : end]).strip("\n")
    return found


def _type_checking(node: ast.stmt) -> bool:
    return isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"


def _is_type_variable(node: ast.stmt) -> bool:
    return isinstance(node, ast.Assign) and ast.unparse(node.value).startswith("TypeVar(")


def _is_head(node: ast.stmt, first: bool) -> bool:
    """A docstring, an import, `TYPE_CHECKING = False`, or `if TYPE_CHECKING:` over imports and type variables."""
    if first and isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
        return True
    if isinstance(node, (ast.Import, ast.ImportFrom)) or ast.unparse(node) == "TYPE_CHECKING = False":
        return True
    return _type_checking(node) and all(isinstance(inner, (ast.Import, ast.ImportFrom)) or _is_type_variable(inner)
                                        for inner in node.body)


def _head_imports(tree: ast.Module) -> list[ast.stmt]:
    """The imports at a module's top level and in its `if TYPE_CHECKING:`."""
    return [inner for node in tree.body for inner in (node.body if _type_checking(node) else [node])
            if isinstance(inner, (ast.Import, ast.ImportFrom))]


def test_each_section_is_its_module_but_the_head_the_carrier_drops(driver) -> None:
    sections = _sections(driver)
    assert list(sections) == MODULES  # in the listed order, each once
    for module, carried in sections.items():
        text = (FOLDER / f"{module}.py").read_text(encoding="utf-8").rstrip("\n")
        type_variables = [ast.get_source_segment(text, inner) for node in ast.parse(text).body if _type_checking(node)
                          for inner in node.body if _is_type_variable(inner)]
        for variable in type_variables:  # the head's, carried first (the driver's type checker needs them)
            assert carried.startswith(f"{variable}\n\n"), module
            carried = carried.removeprefix(f"{variable}\n\n")
        assert carried and text.endswith(carried), module
        dropped = text[: len(text) - len(carried)]
        assert dropped.endswith("\n"), module  # whole lines
        assert not [line for line in dropped.splitlines() if line.lstrip().startswith("#")], module
        statements = ast.parse(dropped).body
        assert all(_is_head(node, at == 0) for at, node in enumerate(statements)), module
        assert statements and not _is_head(ast.parse(carried).body[0], False), module  # nothing more dropped


def test_the_imports_are_gathered_once_above_the_sections(driver) -> None:
    engine = driver[driver.index("from __future__ import annotations") : driver.index("# ---- rdisc engine: ")]
    gathered = {ast.unparse(node) for node in ast.parse(engine).body}
    wanted: dict[str, set[str]] = {}
    for module in MODULES:
        for node in _head_imports(ast.parse((FOLDER / f"{module}.py").read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                wanted.setdefault("", set()).update(alias.name for alias in node.names)
            elif isinstance(node, ast.ImportFrom) and not node.module.startswith("rdisc"):
                wanted.setdefault(node.module, set()).update(a.name for a in node.names if a.name != "TYPE_CHECKING")
    expected = {f"import {name}" for name in wanted.pop("", set())}
    expected |= {f"from {module} import {', '.join(sorted(names))}" for module, names in wanted.items()}
    assert {" ".join(sorted(line.replace(",", "").split())) for line in gathered} == \
        {" ".join(sorted(line.replace(",", "").split())) for line in expected}
    assert driver.count("from __future__ import annotations") == 1
    assert "rdisc" not in "".join(line for line in driver.splitlines() if line.startswith(("import ", "from ")))


def test_every_module_of_the_package_is_carried() -> None:
    files = {path.stem for path in FOLDER.glob("*.py")} - {"__init__", "carry"}
    assert files == set(MODULES)


def test_the_engine_needs_only_the_standard_library_and_pyserial() -> None:
    """And mcap-ros2-support, imported only when a session is recorded."""
    for path in FOLDER.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            for name in names:
                assert (name.split(".")[0] in sys.stdlib_module_names | {"__future__", "serial", "mcap_ros2"}
                        or name.startswith("rdisc.engine")), f"{path.name} imports {name}"


def test_each_module_comes_after_the_modules_it_imports() -> None:
    """So the sections one after the other define each name before a module's top level uses it."""
    for at, module in enumerate(MODULES):
        for node in ast.parse((FOLDER / f"{module}.py").read_text(encoding="utf-8")).body:
            if isinstance(node, ast.ImportFrom) and node.module.startswith("rdisc.engine."):
                assert MODULES.index(node.module.split(".")[2]) < at, f"{module} imports {node.module}"


def test_no_name_is_bound_at_the_top_level_by_two_modules() -> None:
    names = carry.bound(ast.parse(carry.text()).body)
    assert sorted({name for name in names if names.count(name) > 1}) == []
    assert carry.names() == set(names)


def test_the_package_exports_every_public_name_of_its_modules() -> None:
    public = {name for section in carry.sections() for name in carry.bound(ast.parse(section.body).body)
              if not name.startswith("_")}
    assert sorted(rdisc.engine.__all__) == sorted(public)
    for section in carry.sections():
        module = importlib.import_module(f"rdisc.engine.{section.module}")  # the package imports it when asked
        for name in carry.bound(ast.parse(section.body).body):
            if not name.startswith("_"):
                assert getattr(rdisc.engine, name) is getattr(module, name)


def test_the_carrier_refuses_a_head_that_imports_rdisc_outside_the_engine() -> None:
    with pytest.raises(ValueError, match="imports nothing of rdisc but itself"):
        carry.section("bad", "", '"""Bad."""\n\nfrom rdisc.runtime import load\n\nX = 1\n')
    with pytest.raises(ValueError, match="line 5: an import after the first definition"):
        carry.section("late", "", '"""Late."""\n\nX = 1\n\nimport os\n')
    part = carry.section("good", "", '"""Good."""\n\nimport os\nfrom rdisc.engine.errors import RdisError\n\n'
                                     "# a comment is carried\nX = os.sep\n")
    assert part.body == "# a comment is carried\nX = os.sep"
