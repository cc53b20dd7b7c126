"""HOST:PORT as the servers of rdisc take it (`rdisc console --http`, `--foxglove`), and which
hosts are this machine's loopback only: a server beyond it needs `--allow-remote`."""

from __future__ import annotations

import ipaddress


def parse_address(text: str, option: str) -> tuple[str, int]:
    """HOST:PORT (an IPv6 host in brackets; no host: 127.0.0.1) as (host, port); ValueError,
    naming `option`, for anything else."""
    host, sep, port = text.rpartition(":")
    if not sep or not port.isdigit() or int(port) > 65535:
        raise ValueError(f"{option} `{text}` is not HOST:PORT")
    return host.strip("[]") or "127.0.0.1", int(port)


def is_loopback(host: str) -> bool:
    """Whether HOST is this machine's loopback only (127.0.0.0/8, ::1, localhost)."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:  # a name: it may lead anywhere
        return False


def shown(host: str, port: int) -> str:
    """HOST:PORT as a URL writes it (an IPv6 host in brackets)."""
    return f"[{host}]:{port}" if ":" in host else f"{host}:{port}"
