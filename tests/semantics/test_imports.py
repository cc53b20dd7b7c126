"""Imports: transitive, each file once (cycles included), paths relative to the importer."""

from __future__ import annotations

from pathlib import Path

from rdisc.compile import compile_path

HERE = Path(__file__).parent / "imports"


def test_imported_declarations_join_the_model() -> None:
    c = compile_path(str(HERE / "main.rdis"))
    assert [(d.code, d.message) for d in c.diagnostics.items] == [
        ("E007", "imported file `missing.rdis` does not exist")
    ]
    assert c.model is None  # an error is an error, wherever it is

    fine = (HERE / "main.rdis").read_text().replace('import "missing.rdis"\n', "")
    path = HERE / "parts" / ".." / "main_ok.rdis"
    path.write_text(fine)
    try:
        c = compile_path(str(path))
    finally:
        path.unlink()
    assert c.diagnostics.items == []
    model = c.model
    assert model is not None
    assert list(model.primitives) == ["set_speed", "read_heading"]
    assert model.primitives["set_speed"].doc == "Speed in cm/s."
    assert model.outputs["compass"].adapter == "Odometry"
    assert sorted(p.rsplit("/", 1)[-1] for p in c.sources) == ["adapters.rdis", "main_ok.rdis", "motors.rdis", "sensors.rdis"]


def test_a_robot_belongs_in_the_main_file(tmp_path: Path) -> None:
    (tmp_path / "lib.rdis").write_text('robot other { author "x" }\n')
    (tmp_path / "main.rdis").write_text('import "lib.rdis"\nrobot main { author "y" }\n')
    c = compile_path(str(tmp_path / "main.rdis"))
    assert [(d.code, d.message) for d in c.diagnostics.items] == [
        ("E107", "a `robot` declaration belongs in the main description, not an imported file")
    ]


def test_imports_stay_inside_the_description_folder(tmp_path: Path) -> None:
    """A description may come from a device or a network: it reads no other files."""
    (tmp_path / "inner").mkdir()
    (tmp_path / "secret.rdis").write_text("state s: int = 0\n")
    main = tmp_path / "inner" / "main.rdis"
    main.write_text('import "/etc/passwd"\nimport "../secret.rdis"\nimport "notes.txt"\nrobot r { author "x" }\n')
    c = compile_path(str(main))
    assert [(d.code, d.message, d.label) for d in c.diagnostics.items] == [
        ("E007", f"cannot import `{path}`", "not a relative path to an .rdis file in the description's folder")
        for path in ("/etc/passwd", "../secret.rdis", "notes.txt")
    ]
    assert sorted(c.sources) == sorted([str(main), *(p for p in c.sources if p.endswith("adapters.rdis"))])
