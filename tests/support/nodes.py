"""A generated ROS 1 or ROS 2 node loaded as a module, and the message stand-ins its fill
functions write into, for tests that read what a node puts in a message without a ROS."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType, SimpleNamespace

from rdisc.compile import compile_path
from rdisc.emit.ros import to_ros
from rdisc.emit.ros2 import to_ros2


def node_of(text: str, kind: str, folder: Path, name: str) -> ModuleType:
    """The `kind` ("ros1" or "ros2") node of the description `text`, written to `folder` as NAME.py
    and imported."""
    source = folder / f"{name}.rdis"
    source.write_text(text, encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None and not compilation.diagnostics.has_errors(), compilation.diagnostics.items
    node = to_ros if kind == "ros1" else to_ros2
    path = folder / f"{name}_{kind}.py"
    path.write_text(node(compilation.model, source.name), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"{name}_{kind}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def vector() -> SimpleNamespace:
    """A geometry_msgs Vector3 at zero."""
    return SimpleNamespace(x=0.0, y=0.0, z=0.0)


def quaternion() -> SimpleNamespace:
    """A geometry_msgs Quaternion, no rotation."""
    return SimpleNamespace(x=0.0, y=0.0, z=0.0, w=1.0)


def odometry() -> SimpleNamespace:
    """An empty nav_msgs/Odometry: pose and twist at zero, each covariance 36 zeros."""
    return SimpleNamespace(
        pose=SimpleNamespace(pose=SimpleNamespace(position=vector(), orientation=quaternion()), covariance=[0.0] * 36),
        twist=SimpleNamespace(twist=SimpleNamespace(linear=vector(), angular=vector()), covariance=[0.0] * 36))
