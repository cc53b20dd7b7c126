"""A mesh's file (issue 26): found from the description, not the current folder, and through a
package's root; refused when missing (E614); and each emitted model names the same file from
where it is written (rdisc/semantics/meshes.py)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

HEAD = 'robot meshy { author "tests" }\n'


def body(path: str) -> str:
    return HEAD + f'link base {{ mass 1 inertia [0.1, 0.1, 0.1] visual mesh("{path}") collision box(1, 1, 1) }}\n'


def described(folder: Path, path: str, meshes: tuple[str, ...] = ()) -> Path:
    """A description in `folder` naming the mesh `path`, with `meshes` (paths from `folder`) made."""
    folder.mkdir(parents=True, exist_ok=True)
    for mesh in meshes:
        (folder / mesh).parent.mkdir(parents=True, exist_ok=True)
        (folder / mesh).write_text("solid m\nendsolid m\n", encoding="utf-8")
    source = folder / "meshy.rdis"
    source.write_text(body(path), encoding="utf-8")
    return source


def test_a_relative_path_starts_at_the_description_not_the_current_folder(tmp_path: Path, rdisc) -> None:
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "base.stl").write_text("solid m\nendsolid m\n", encoding="utf-8")
    source = described(tmp_path / "robot", "meshes/base.stl")  # the mesh is in the current folder only
    result = rdisc("check", "robot/meshy.rdis", cwd=tmp_path)
    assert (result.returncode, result.stderr.splitlines()[:2]) == (1, [
        ("error[E614]: mesh `meshes/base.stl` is not found: there is no file `meshes/base.stl` in the folder of "
        "meshy.rdis"), " --> robot/meshy.rdis:2:56"])
    described(source.parent, "meshes/base.stl", ("meshes/base.stl",))
    assert rdisc("check", "robot/meshy.rdis", cwd=tmp_path).returncode == 0


def test_a_package_path_goes_through_the_folder_of_that_name_holding_the_description(tmp_path: Path,
                                                                                     rdisc) -> None:
    described(tmp_path / "my_robot" / "rdis", "package://my_robot/meshes/base.stl", ("../meshes/base.stl",))
    assert rdisc("check", "my_robot/rdis/meshy.rdis", cwd=tmp_path).returncode == 0
    described(tmp_path / "my_robot" / "rdis", "package://my_robot/meshes/arm.stl")
    result = rdisc("check", "my_robot/rdis/meshy.rdis", cwd=tmp_path)
    assert result.returncode == 1 and result.stderr.startswith(
        f"error[E614]: mesh `package://my_robot/meshes/arm.stl` is not found: package `my_robot` (at "
        f"{tmp_path / 'my_robot'}) has no file `meshes/arm.stl`\n"), result.stderr


def test_a_package_elsewhere_is_found_through_ros_package_path(tmp_path: Path, rdisc, monkeypatch) -> None:
    mesh = tmp_path / "workspace" / "src" / "robot_meshes" / "base.stl"
    mesh.parent.mkdir(parents=True)
    mesh.write_text("solid m\nendsolid m\n", encoding="utf-8")
    described(tmp_path / "robot", "package://robot_meshes/base.stl")
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    result = rdisc("check", "robot/meshy.rdis", cwd=tmp_path)
    assert result.returncode == 1 and result.stderr.startswith(
        "error[E614]: mesh `package://robot_meshes/base.stl` is not found: package `robot_meshes` is not found: no "
        "folder holding the description is named `robot_meshes`, and no folder of ROS_PACKAGE_PATH holds it\n")
    monkeypatch.setenv("ROS_PACKAGE_PATH", f"{tmp_path / 'nowhere'}:{tmp_path / 'workspace' / 'src'}")
    assert rdisc("check", "robot/meshy.rdis", cwd=tmp_path).returncode == 0


def mesh_paths(xml: Path, tag: str, attribute: str | None) -> list[str]:
    root = ET.parse(xml).getroot()
    return [(e.get(attribute) if attribute else e.text) or "" for e in root.iter(tag)]


def test_each_model_written_elsewhere_names_the_same_file(tmp_path: Path, rdisc) -> None:
    """URDF and SDF keep a package's path (ROS resolves it); MuJoCo, which knows no packages, gets
    its file; a relative path is rewritten from the output's folder."""
    source = described(tmp_path / "my_robot" / "rdis", "meshes/base.stl", ("meshes/base.stl",))
    out = tmp_path / "build"
    out.mkdir()
    for verb, name, tag, attribute in (("emit-urdf", "r.urdf", "mesh", "filename"), ("emit-sdf", "r.sdf", "uri", None),
                                       ("emit-mjcf", "r.xml", "mesh", "file")):
        assert rdisc(verb, source, "-o", out / name).returncode == 0
        assert mesh_paths(out / name, tag, attribute) == ["../my_robot/rdis/meshes/base.stl"]
        assert (out / "../my_robot/rdis/meshes/base.stl").is_file()
        assert rdisc(verb, source, "-o", source.parent / name).returncode == 0  # beside it: as written
        assert mesh_paths(source.parent / name, tag, attribute) == ["meshes/base.stl"]
    described(source.parent, "package://my_robot/rdis/meshes/base.stl")
    for verb, name, tag, attribute, expected in (
            ("emit-urdf", "r.urdf", "mesh", "filename", "package://my_robot/rdis/meshes/base.stl"),
            ("emit-mjcf", "r.xml", "mesh", "file", "../my_robot/rdis/meshes/base.stl")):
        assert rdisc(verb, source, "-o", out / name).returncode == 0
        assert mesh_paths(out / name, tag, attribute) == [expected]
