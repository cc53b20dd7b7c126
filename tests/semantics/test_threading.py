"""Threading models through the toolchain: the checker's rules (E209, E204, W230), the printer,
JSON both ways, the one lowering and the link budget's per-thread figures (`check --verbose`)."""

from __future__ import annotations

import json
from pathlib import Path

from rdisc.compile import compile_path
from rdisc.emit.canonical import to_json
from rdisc.lower import lower

SOURCE = """\
robot threads25 {{ author "tests" }}

connection link: serial {{ baud 9600 threading {model} at 20 Hz }}

primitive ask_f() on link format "F\\n" ()
primitive ask_s() on link format "S\\n" ()

interface fast() periodic {{ ask_f() }}

interface slow() periodic {rate} Hz {{ ask_s() delay {delay} ms }}
"""


def checked(tmp_path: Path, model: str = "multiple", rate: str = "5", delay: int = 0) -> tuple:
    path = tmp_path / "threads.rdis"
    path.write_text(SOURCE.format(model=model, rate=rate, delay=delay), encoding="utf-8")
    compilation = compile_path(str(path))
    return compilation, [(d.code, d.message) for d in compilation.diagnostics.items]


def test_a_rate_is_positive_bounded_and_used_under_multiple_only(tmp_path) -> None:
    assert checked(tmp_path)[1] == []
    assert checked(tmp_path, rate="0")[1] == [("E204", "the rate must be positive, not 0 Hz")]
    assert checked(tmp_path, rate="20000")[1] == [("E204", "the rate must be at most 10000 Hz")]
    for model in ("single", "dual"):
        assert checked(tmp_path, model)[1] == [
            ("W230", (f"`slow` states its own rate, but `link` is `threading {model}`: it runs at the "
                      "connection's frequency")),
        ]
    assert checked(tmp_path, "triple")[1] == [("E209", "unknown threading model `triple`")]


def test_the_model_the_plans_and_the_printer_carry_the_model_and_rates(rdisc, tmp_path) -> None:
    compilation, _ = checked(tmp_path)
    model = compilation.model
    assert model is not None
    assert model.connections["link"].threading == "multiple"
    assert (model.interfaces["fast"].rate_hz, model.interfaces["slow"].rate_hz) == (None, 5.0)
    link = lower(model).device.connections["link"]
    assert (link.threading, link.frequency, link.rates) == ("multiple", 20.0, (0.0, 5.0))
    single, _ = checked(tmp_path, "single")
    assert single.model is not None
    assert lower(single.model).device.connections["link"].rates == ()  # a rate is used under `multiple` only


def test_json_both_ways(rdisc, tmp_path) -> None:
    compilation, _ = checked(tmp_path)
    assert compilation.model is not None
    document = json.loads(to_json(compilation.model))
    [connection] = document["connections"]["spp"]
    assert connection["multipleThreading"] == {"freqHz": 20}
    assert "singleThreading" not in connection
    assert [(i["name"], i.get("rateHz")) for i in document["interfaces"]] == [("fast", None), ("slow", 5)]
    path = tmp_path / "threads.json"
    path.write_text(to_json(compilation.model), encoding="utf-8")
    done = rdisc("import", path)
    assert done.returncode == 0, done.stderr
    assert "    threading multiple at 20 Hz\n" in done.stdout
    assert "interface fast() periodic {\n" in done.stdout
    assert "interface slow() periodic 5 Hz {\n" in done.stdout


def test_json_refuses_two_models_and_a_rate_on_an_adhoc_interface(rdisc, tmp_path) -> None:
    compilation, _ = checked(tmp_path)
    assert compilation.model is not None
    document = json.loads(to_json(compilation.model))
    document["connections"]["spp"][0]["dualThreading"] = {"freqHz": 5}
    document["interfaces"][0]["rateHz"] = 3
    document["interfaces"][0]["type"] = "adhoc"
    path = tmp_path / "threads.json"
    path.write_text(json.dumps(document), encoding="utf-8")
    done = rdisc("check", path)
    assert done.returncode == 1
    assert "error[E008]: a connection has one threading model: `dualThreading` or `multipleThreading`" \
        in done.stderr
    assert "error[E008]: `rateHz` is a periodic interface's own rate: its `type` is `periodic`" in done.stderr


def test_the_budget_holds_each_thread_to_its_own_period(rdisc, tmp_path) -> None:
    path = tmp_path / "threads.rdis"
    path.write_text(SOURCE.format(model="multiple", rate="100", delay=15), encoding="utf-8")
    done = rdisc("check", "--verbose", path)
    assert done.stdout.splitlines()[1:] == [
        "  thread `fast` (20 Hz, 50.0 ms):",
        "    fast: 2 bytes, 2.08 ms on the wire + 0 ms of delays = 2.08 ms",
        "    2.08 ms of 50.0 ms per run",
        "  thread `slow` (100 Hz, 10.0 ms):",
        "    slow: 2 bytes, 2.08 ms on the wire + 15 ms of delays = 17.08 ms",
        "    17.08 ms of 10.0 ms per run",
        "  scheduled: 240.0 bytes/s, 25.0% of the link",
    ]
    assert ("warning[W402]: the periodic work of `slow` (its own thread on `link`) takes 17.08 ms per run, "
            "longer than its 10.0 ms period (100 Hz)") in done.stderr
    # the same work on one thread (dual): a tick of both, 19.16 ms of 50 ms, and no W402
    path.write_text(SOURCE.format(model="dual", rate="100", delay=15), encoding="utf-8")
    done = rdisc("check", "--verbose", path)
    assert done.stdout.splitlines()[1:] == [
        "  every tick (20 Hz, 50.0 ms) on the periodic thread (a command waits for one exchange at most):",
        "    fast: 2 bytes, 2.08 ms on the wire + 0 ms of delays = 2.08 ms",
        "    slow: 2 bytes, 2.08 ms on the wire + 15 ms of delays = 17.08 ms",
        "    19.17 ms of 50.0 ms per tick",
        "  scheduled: 80.0 bytes/s, 8.3% of the link",
    ]
    assert "W402" not in done.stderr


def test_the_graph_labels_each_periodic_interface_with_its_rate(rdisc, tmp_path) -> None:
    path = tmp_path / "threads.rdis"
    for model, slow in (("multiple", "5 Hz"), ("single", "20 Hz")):
        path.write_text(SOURCE.format(model=model, rate="5", delay=0), encoding="utf-8")
        dot = rdisc("graph", path).stdout
        assert '"connection:link" -> "interface:fast" [label="every tick (20 Hz)"];' in dot
        assert f'"connection:link" -> "interface:slow" [label="every tick ({slow})"];' in dot
