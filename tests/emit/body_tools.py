"""The independent tools that judge rdisc's URDF and SDF, and a body that uses every part of
the language (the examples' bodies are all revolute joints without rotations).

A tool that is not installed skips its tests, except under CI=true, where it fails them:
`.ci/run` installs them all (Debian's liburdfdom-tools, ignition-tools and libsdformat-dev;
urchin from PyPI).
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

import pytest

from rdisc.compile import compile_path
from rdisc.semantics import model as m

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = sorted(p for p in (REPO / "examples").glob("*.rdis") if re.search(r"^link \w", p.read_text(), re.MULTILINE))


def require(name: str) -> str:
    """The path of a command-line tool; skipped when absent, unless CI=true."""
    path = shutil.which(name)
    if path is None:
        missing(f"`{name}` is not installed (.ci/run installs it)")
    return path  # type: ignore[return-value]


def require_module(name: str) -> ModuleType:
    try:
        return __import__(name)
    except ImportError:
        missing(f"the Python package `{name}` is not installed (it is in the `test` extra)")
        raise


def missing(reason: str) -> None:
    if os.environ.get("CI") == "true":
        pytest.fail(f"required under CI: {reason}", pytrace=False)
    pytest.skip(reason)


def run(*args: str | Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, check=False, timeout=120)


@dataclass(frozen=True)
class Tree:
    """What `check_urdf` printed: the robot's name, its root and each link's parent, as a list
    of (parent, child) in the order printed (a link shown twice is there twice)."""

    name: str
    root: str
    edges: list[tuple[str, str]]


def check_urdf(path: Path) -> Tree | str:
    """urdfdom's reading of a URDF: its tree, or its error message."""
    result = run(require("check_urdf"), path)
    if result.returncode != 0:
        return " ".join(line.strip() for line in result.stderr.splitlines() if line.startswith("Error:"))
    lines = result.stdout.splitlines()
    name = re.fullmatch(r"robot name is: (\S+)", lines[0])
    root = re.fullmatch(r"root Link: (\S+) has \d+ child\(ren\)", lines[2])
    assert name is not None and root is not None and lines[1].startswith("-----"), result.stdout
    stack, edges = [root[1]], []
    for line in lines[3:]:
        found = re.fullmatch(r"( +)child\(\d+\):  (\S+)", line)
        assert found is not None, line
        depth = len(found[1]) // 4
        del stack[depth:]
        edges.append((stack[-1], found[2]))
        stack.append(found[2])
    return Tree(name[1], root[1], edges)


def ign_sdf_check(path: Path) -> tuple[int, str]:
    """libsdformat's check (`ign sdf -k`): exit code and what it said (its output, then its
    errors), without colours or ign's own noise about a backtrace library it lacks."""
    result = run(require("ign"), "sdf", "-k", path)
    text = re.sub(r"\x1b\[[0-9;]*m", "", result.stdout + "\n" + result.stderr)
    said = [line for line in text.splitlines() if line and "libignition-tools-backward" not in line]
    return result.returncode, "\n".join(said)


def model_of(path: Path) -> m.Model:
    compilation = compile_path(str(path))
    assert compilation.model is not None and not compilation.diagnostics.has_errors(), compilation.diagnostics.items
    return compilation.model


# -- the description's poses as matrices (written here, apart from the emitters) ----------


def rotation(rpy: m.Vector) -> list[list[float]]:
    """Roll about x, then pitch about y, then yaw about z, all fixed axes: Rz Ry Rx."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def matrix(pose: m.Pose) -> list[list[float]]:
    """The 4x4 homogeneous transform of a pose."""
    rot = rotation(pose.rpy)
    return [[*rot[0], pose.xyz[0]], [*rot[1], pose.xyz[1]], [*rot[2], pose.xyz[2]], [0.0, 0.0, 0.0, 1.0]]


def unit(v: m.Vector) -> list[float]:
    norm = math.sqrt(sum(x * x for x in v))
    return [x / norm for x in v]


# A body with every joint kind, every shape, rotated frames, a non-unit axis, a full inertia
# tensor, damping and friction, and docs with `--` (which an XML comment cannot hold).
TWISTY = """\
robot twisty { description "A test body -- every kind of joint, shape and pose" }
connection c: serial { baud 115200 }
state enc: int
primitive go(v: int in -500..500) on c pack ">Bh" (1, v)
primitive servo(goal: int in 0..1023) on c pack ">BH" (2, goal)
/// The base -- a plate.
link base {
    visual cylinder(0.17, 0.09) at [0, 0, 0.045]
    visual box(0.05, 0.05, 0.02) at [0.1, 0, 0.1] rpy [0, 0, 0.7]
    collision box(0.3, 0.3, 0.09) at [0, 0, 0.045] rpy [0.1, 0.2, 0.3]
    mass 3.6  centre [0, 0, 0.03]  inertia [0.02, 0.02, 0.035, 0.001, -0.002, 0.0005]
}
link wheel { visual sphere(0.036)  collision mesh("meshes/wheel.stl", 0.001)  mass 0.1  inertia [0.001, 0.001, 0.001] }
link arm { visual mesh("meshes/arm.dae", [1, 2, 3]) at [0.05, 0, 0]  mass 0.2  inertia [0.001, 0.001, 0.001] }
link slider { mass 0.05  centre [0.01, 0.02, 0.03]  inertia [0.0001, 0.0001, 0.0001] }
link camera { }
/// Turns the wheel -- forever.
joint spin: continuous base -> wheel {
    at [0, 0.1, 0.03]  rpy [1.5707963267948966, 0, 0]  axis [0, 0, 2]  velocity 13  effort 1  damping 0.1
}
joint lift: revolute base -> arm {
    at [0.05, 0, 0.1]  rpy [0.3, -0.4, 1.2]  axis [1, 1, 0]  limit -1.5..1.5  velocity 2  effort 1  friction 0.2
}
joint slide: prismatic arm -> slider { at [0.1, 0, 0]  axis [1, 0, 0]  limit 0..0.2  velocity 0.5  effort 20 }
joint mount: fixed arm -> camera { at [0, 0, 0.05]  rpy [0, 0.5, 0] }
transmission drive: spin {
    command velocity to go.v { raw = round(velocity * 36)  velocity = raw / 36 }
    measure position from enc { raw = round(position * 100) % 65536  position = raw / 100 }
}
transmission lifter: lift {
    command position to servo.goal { raw = round(position * 195.3) + 512  position = (raw - 512) / 195.3 }
}
"""


def write_twisty(source: Path, text: str = TWISTY) -> None:
    """TWISTY at `source`, with the mesh files it names beside it (the checker finds them there)."""
    source.write_text(text, encoding="utf-8")
    (source.parent / "meshes").mkdir(exist_ok=True)
    for name in ("wheel.stl", "arm.dae"):
        (source.parent / "meshes" / name).write_bytes(b"")
