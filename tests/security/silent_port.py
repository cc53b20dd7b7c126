"""A port for the tests here: it keeps what is written and answers nothing."""

from __future__ import annotations


class SilentPort:
    timeout: float | None = 1.0

    def __init__(self) -> None:
        self.written = b""

    def write(self, data: bytes, /) -> int:
        self.written += data
        return len(data)

    def read(self, size: int = 1, /) -> bytes:
        return b""

    def reset_input_buffer(self) -> None:
        pass

    def close(self) -> None:
        pass
