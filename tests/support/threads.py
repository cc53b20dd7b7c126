"""The threads of a process as the kernel sees them (Linux's /proc): which signals each blocks."""

from __future__ import annotations

import signal
from pathlib import Path

READABLE = Path("/proc/self/task").is_dir()
"""Whether this machine shows threads' signal masks (Linux)."""

INTERRUPTS = 1 << (signal.SIGINT - 1) | 1 << (signal.SIGTERM - 1)
"""SIGINT and SIGTERM in a mask: bit n - 1 for signal n."""


def blocked_signals(pid: int) -> dict[int, int]:
    """The signal mask of each thread of process `pid`, by thread id (the main thread's is `pid`)."""
    masks = {}
    for task in Path(f"/proc/{pid}/task").iterdir():
        status = (task / "status").read_text(encoding="utf-8")
        (mask,) = (line.split()[1] for line in status.splitlines() if line.startswith("SigBlk:"))
        masks[int(task.name)] = int(mask, 16)
    return masks


def interrupts_reach_only_the_main_thread(pid: int) -> bool:
    """Whether the main thread of `pid` takes SIGINT and SIGTERM and every other thread blocks them,
    so that the kernel gives them to the main thread, whose handlers run at once."""
    masks = blocked_signals(pid)
    return masks.pop(pid) & INTERRUPTS == 0 and all(mask & INTERRUPTS == INTERRUPTS for mask in masks.values())
