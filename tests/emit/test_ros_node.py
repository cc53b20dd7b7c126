"""The node `rdisc emit-ros` writes, without ROS: it is the generated driver with the
bridge in place of its command line, its tables hold the adapters' ROS messages and
field paths, and it is clean for ruff and `mypy --strict`. (tests/ros runs it
against a real roscore.)"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from rdisc.emit.ros import to_ros

REPO = Path(__file__).resolve().parents[2]


def _node(example: str) -> tuple[str, str]:
    compilation = compile_path(str(REPO / "examples" / f"{example}.rdis"))
    assert compilation.model is not None
    name = f"{example}.rdis"
    return (to_ros(compilation.model, name, sources=compilation.sources),
            to_python(compilation.model, name, sources=compilation.sources))


def test_the_node_is_the_driver_with_a_ros_main() -> None:
    node, driver = _node("create")
    body = driver.removesuffix('if __name__ == "__main__":\n    sys.exit(main())\n')
    assert node.startswith(body)
    assert node.endswith('if __name__ == "__main__":\n    sys.exit(ros_main())\n')
    assert ('    "set_velocity": ("geometry_msgs/Twist", (("linear", "linear.x"), ("angular", "angular.z"),)),'
            in node)
    assert '    "detect_bump": ("sensor_msgs/Range", (("distance", "range"),)),' in node


def test_ruff_and_mypy_strict_find_nothing(tmp_path: Path) -> None:
    path = tmp_path / "irobot_create_node.py"
    path.write_text(_node("create")[0], encoding="utf-8")
    for command in (["ruff", "check", "--isolated", "--no-cache"],
                    ["mypy", "--strict", "--no-error-summary", "--cache-dir", str(tmp_path / "cache")]):
        done = subprocess.run([sys.executable, "-m", *command, str(path)], capture_output=True, text=True,
                              check=False, cwd=tmp_path)
        assert done.returncode == 0, done.stdout + done.stderr
