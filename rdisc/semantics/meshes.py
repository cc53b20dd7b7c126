"""Where a mesh's file is, one rule for the checker, the emitters and the simulation (issue 26).

A mesh's path is read as the tools reading the output read it, but from the description:
- a relative path (`meshes/base.stl`) starts at the folder of the file that declares the link,
  never at the current folder;
- `package://NAME/PATH` is PATH in the package NAME, whose root is the nearest folder named
  NAME that holds the description (a description kept inside its ROS package), else NAME in a
  folder of ROS_PACKAGE_PATH (or that folder itself, when it is named NAME), as ROS finds it;
- `file:///abs/path` and an absolute path are that file.
An emitted model written to a file names the same file: a relative path is rewritten to start
at the output's folder; a MuJoCo model, which knows no packages, gets the package's file.
"""

from __future__ import annotations

import os
import posixpath

from rdisc.semantics import model as m

PACKAGE = "package://"
FILE = "file://"


def located(path: str, described: str) -> tuple[str | None, str]:
    """The file (absolute) a mesh's path in the description `described` names, or None and why."""
    if path.startswith(PACKAGE):
        name, _, rest = path[len(PACKAGE):].partition("/")
        root = package_root(name, described)
        if root is None:
            return None, (f"package `{name}` is not found: no folder holding the description is named `{name}`, "
                          f"and no folder of ROS_PACKAGE_PATH holds it")
        return os.path.join(root, rest), f"package `{name}` (at {root}) has no file `{rest}`"
    if path.startswith(FILE):
        return path[len(FILE):], f"there is no file `{path[len(FILE):]}`"
    if os.path.isabs(path):
        return path, f"there is no file `{path}`"
    return (os.path.join(os.path.dirname(os.path.abspath(described)), path),
            f"there is no file `{path}` in the folder of {os.path.basename(described)}")


def package_root(name: str, described: str) -> str | None:
    """The root of package `name`: a folder of that name holding the description, else in
    ROS_PACKAGE_PATH."""
    folder = os.path.dirname(os.path.abspath(described))
    while True:
        if os.path.basename(folder) == name:
            return folder
        parent = os.path.dirname(folder)
        if parent == folder:
            break
        folder = parent
    for entry in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep):
        if not entry:
            continue
        if os.path.basename(os.path.normpath(entry)) == name and os.path.isdir(entry):
            return os.path.abspath(entry)
        if os.path.isdir(os.path.join(entry, name)):
            return os.path.abspath(os.path.join(entry, name))
    return None


def written(path: str, described: str | None, output: str | None, files: bool) -> str:
    """A mesh's path as an output written to `output` (None: to stdout) carries it: a relative
    path from the output's folder; with `files` (MuJoCo), a package's path as its file, and
    on stdout every path as its absolute file (a link of an imported file has its own folder)."""
    if described is None or not os.path.isfile(described):
        return path
    relative = not path.startswith((PACKAGE, FILE)) and not os.path.isabs(path)
    if not relative and not (files and path.startswith((PACKAGE, FILE))):
        return path
    if relative and output is None and not files:
        return path  # on stdout: as written, from the description's folder
    found, _ = located(path, described)
    if found is None:
        return path
    if output is None:
        return found
    return posixpath.join(*os.path.relpath(found, os.path.dirname(os.path.abspath(output))).split(os.sep))


def rebased(model: m.Model, output: str | None, *, files: bool = False) -> m.Model:
    """The model with each mesh's path as written to `output` (the model itself when none moves)."""
    import dataclasses

    links = {}
    for name, link in model.links.items():
        def moved(shape: m.Shape) -> m.Shape:
            if shape.path is None:
                return shape
            path = written(shape.path, shape.span.path if shape.span is not None else None, output, files)
            return shape if path == shape.path else dataclasses.replace(shape, path=path)

        visuals, collisions = tuple(map(moved, link.visuals)), tuple(map(moved, link.collisions))
        same = visuals == link.visuals and collisions == link.collisions
        links[name] = link if same else dataclasses.replace(link, visuals=visuals, collisions=collisions)
    if all(links[n] is model.links[n] for n in links):
        return model
    return dataclasses.replace(model, links=links)
