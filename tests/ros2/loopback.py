"""Cyclone DDS on loopback only, as CYCLONEDDS_URI: the ROS 2 tests' and benchmark's participants
find each other there by unicast (loopback has no multicast)."""

from __future__ import annotations

import json
import os
import queue
import signal
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent

LOOPBACK = ('<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces>'
            "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
            '<Peers><Peer address="127.0.0.1"/></Peers></Discovery></Domain></CycloneDDS>')


def first_messages(node_file: Path, parameters: list[str], topics: dict[str, str], seed: int) -> dict[str, str]:
    """The first message (CDR, hex) on each of `topics` (name: ROS 2 type) the node at `node_file`
    publishes, run with `-p` `parameters` in a domain of this process's own (from its pid and
    `seed`), read by reader.py in another process; the node then ends on SIGINT with 130."""
    env = dict(os.environ, ROS_DOMAIN_ID=str(10 + (os.getpid() + seed) % 200), CYCLONEDDS_URI=LOOPBACK)
    reader = subprocess.Popen([sys.executable, str(HERE / "reader.py"), "jazzy",
                               *(f"{topic}={kind}" for topic, kind in topics.items())], env=env,
                              stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    lines: queue.Queue[dict[str, Any]] = queue.Queue()
    threading.Thread(target=_read, args=(reader, lines), daemon=True).start()
    node = None
    got: dict[str, str] = {}
    try:
        assert lines.get(timeout=30) == {"ready": True}
        node = subprocess.Popen([sys.executable, str(node_file), "--ros-args",
                                 *(word for parameter in parameters for word in ("-p", parameter))],
                                env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        while len(got) < len(topics):
            event = lines.get(timeout=30)
            got.setdefault(event["topic"], event["cdr"])
    finally:
        if node is not None:
            node.send_signal(signal.SIGINT)
            _, stderr = node.communicate(timeout=15)
            assert node.returncode == 130, stderr
        assert reader.stdin is not None
        reader.stdin.close()
        reader.wait(timeout=15)
    return got


def _read(process: subprocess.Popen[str], lines: queue.Queue[dict[str, Any]]) -> None:
    assert process.stdout is not None
    for line in process.stdout:
        lines.put(json.loads(line))
