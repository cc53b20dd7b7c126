"""`rdisc emit-python`: the generated drivers as text (goldens, lint, types, determinism)
and as running code, imported from a temporary folder and driven over real
pseudo-terminals against the emulated iRobot Create and K-Team Koala.
"""

from __future__ import annotations

import ast
import importlib.util
import itertools
import json
import re
import signal
import struct
import subprocess
import sys
import time
from pathlib import Path
from types import ModuleType

import pytest
from conftest import cli_env, run_rdisc_seeded, untimed
from devices import CreateEmulator, KoalaEmulator, pty_device
from devices.create import DRIVE, FULL, SENSORS, START, STOP, TABLE_4_3

from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from tests.support.ports import ScriptedPort

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
POLLED = REPO / "tests" / "runtime" / "data" / "polled" / "create.rdis"  # examples/create.rdis before its sensor
GOLDEN = REPO / "tests" / "golden" / "drivers"


def generate(source: Path, folder: Path, module: str) -> Path:
    compilation = compile_path(str(source))
    assert compilation.model is not None, compilation.diagnostics.items
    path = folder / f"{module}.py"
    path.write_text(to_python(compilation.model, source.name, sources=compilation.sources), encoding="utf-8")
    return path


def load(path: Path) -> ModuleType:
    """Import a generated driver from its file, as `python -c "import NAME"` would."""
    name = f"{path.stem}_{abs(hash(str(path)))}"
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def without_delays(source: Path, folder: Path) -> Path:
    """A copy of a description with every delay made 0 ms (fast tests)."""
    copy = folder / source.name
    copy.write_text(re.sub(r"delay \d+ ms", "delay 0 ms", source.read_text(encoding="utf-8")), encoding="utf-8")
    return copy


class Recorder:
    """A callback keeping what it gets; `wait` until enough arrived."""

    def __init__(self) -> None:
        self.items: list[object] = []

    def __call__(self, *args: object) -> None:
        self.items.append(args[0] if len(args) == 1 else args)

    def wait(self, predicate, timeout: float = 3.0) -> list[object]:
        deadline = time.monotonic() + timeout
        while not predicate(list(self.items)):
            if time.monotonic() > deadline:
                raise AssertionError(f"waited {timeout:g} s; got {self.items!r}")
            time.sleep(0.005)
        return list(self.items)


@pytest.fixture(scope="module")
def drivers(tmp_path_factory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("drivers")
    fast = tmp_path_factory.mktemp("fast")
    polled = tmp_path_factory.mktemp("polled")
    return {
        "create": generate(EXAMPLES / "create.rdis", folder, "irobot_create"),
        "koala": generate(EXAMPLES / "koala.rdis", folder, "koala"),
        "arm": generate(EXAMPLES / "arm.rdis", folder, "arm"),  # replies, expect, groups, a body
        "fast_create": generate(without_delays(EXAMPLES / "create.rdis", fast), fast, "fast_create"),
        # the bumpers polled, not a sensor: `--watch` prints its outputs with no sensor's age
        "fast_polled": generate(without_delays(POLLED, polled), polled, "fast_polled"),
    }


# ---- the text ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("example", ["create", "koala"])
def test_generated_source_matches_the_golden(drivers, golden, example) -> None:
    golden.check(GOLDEN / f"{example}.py", drivers[example].read_text(encoding="utf-8"))


@pytest.mark.parametrize("example", ["create", "koala", "arm"])
def test_ruff_finds_nothing(drivers, example) -> None:
    done = subprocess.run([sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache", str(drivers[example])],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout + done.stderr


def test_mypy_strict_finds_nothing(drivers, tmp_path, mypy_cache) -> None:
    paths = [str(drivers["create"]), str(drivers["koala"]), str(drivers["arm"])]
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--no-error-summary", "--cache-dir", str(mypy_cache),
         *paths],
        capture_output=True, text=True, check=False, cwd=tmp_path,
    )
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.parametrize("example", ["create", "koala"])
def test_no_eval_exec_compile_and_only_stdlib_and_pyserial(drivers, example) -> None:
    tree = ast.parse(drivers[example].read_text(encoding="utf-8"))
    calls = {node.func.id for node in ast.walk(tree) if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)}
    assert not calls & {"eval", "exec", "compile", "__import__"}
    imported = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                for alias in node.names}
    imported |= {node.module.split(".")[0] for node in ast.walk(tree)
                 if isinstance(node, ast.ImportFrom) and node.module}
    # pyserial, when a port is named; mcap-ros2-support, when a session is recorded (--record)
    assert imported <= set(sys.stdlib_module_names) | {"__future__", "serial", "mcap_ros2"}
    assert "importlib" not in imported


def test_file_line_comments_point_at_the_description(drivers) -> None:
    text = drivers["create"].read_text(encoding="utf-8")
    source = (EXAMPLES / "create.rdis").read_text(encoding="utf-8").split("\n")
    for start, comment in [("primitive drive(", "primitive drive"), ("output detect_bump", "output detect_bump")]:
        line = next(i for i, text_line in enumerate(source, 1) if text_line.startswith(start))
        assert f"# create.rdis:{line}  {comment}" in text


@pytest.fixture(scope="module")
def seeded_drivers(tmp_path_factory) -> dict[str, list[tuple[subprocess.CompletedProcess[str], Path]]]:
    """The Create's and the Koala's drivers emitted under each hash seed, one interpreter a seed
    (the seed is read when Python starts): by example, a (result, driver file) a seed."""
    folder = tmp_path_factory.mktemp("seeded")
    names = ["create", "koala"]
    drivers: dict[str, list[tuple[subprocess.CompletedProcess[str], Path]]] = {name: [] for name in names}
    for seed in ("1", "4242"):
        outs = [folder / f"{name}_{seed}" / f"driver_{seed}.py" for name in names]
        for out in outs:
            out.parent.mkdir()
        results = run_rdisc_seeded([("emit-python", EXAMPLES / f"{name}.rdis", "-o", out)
                                    for name, out in zip(names, outs)], seed)
        for name, done, out in zip(names, results, outs):
            drivers[name].append((done, out))
    return drivers


@pytest.mark.parametrize("example", ["create", "koala"])
def test_a_build_is_byte_identical_under_any_hash_seed(seeded_drivers, example) -> None:
    outputs = []
    for done, out in seeded_drivers[example]:
        assert done.returncode == 0, done.stderr
        outputs.append(out.read_bytes())
    assert outputs[0] == outputs[1]


def test_emit_python_refuses_a_description_with_errors(rdisc, tmp_path) -> None:
    bad = tmp_path / "bad.rdis"
    bad.write_text("robot r {}\nprimitive p() on nowhere pack \"B\" (1)\n", encoding="utf-8")
    out = tmp_path / "bad.py"
    result = rdisc("emit-python", bad, "-o", out)
    assert result.returncode == 1
    assert "nowhere" in result.stderr
    assert not out.exists()


# ---- the Create, over a pty --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def create(drivers):
    """(device, robot, outputs, errors) with the generated Create driver connected (startup: 2 s)."""
    driver = load(drivers["create"])
    with CreateEmulator() as dev:
        outputs, errors = Recorder(), Recorder()
        robot = driver.connect(dev.port, on_output=outputs, on_error=errors)
        try:
            yield dev, robot, outputs, errors
        finally:
            robot.close()


def test_startup_sends_start_then_full(create) -> None:
    dev = create[0]
    commands = dev.wait_for_commands(2)
    assert [c for _, c in commands[:2]] == [bytes([START]), bytes([FULL])]
    assert commands[1][0] - commands[0][0] >= 0.9  # `start() delay 1000 ms`


@pytest.mark.parametrize(("given", "expected"), TABLE_4_3, ids=[str(row[0]) for row in TABLE_4_3])
def test_set_velocity_writes_the_expected_column(create, given, expected) -> None:
    dev, robot, _, errors = create
    before = len(dev.drives())
    linear, angular = given
    robot.set_velocity(linear=linear, angular=angular)
    commands = dev.wait_for_commands(before + 1, opcode=DRIVE)
    assert commands[-1][1] == struct.pack(">Bhh", *expected)
    assert errors.items == []


def test_call_input_by_name_and_its_type_errors(create) -> None:
    dev, robot, _, _ = create
    before = len(dev.drives())
    robot.call_input("set_velocity", linear=0.1, angular=0)  # an int where a float is declared is widened
    assert dev.wait_for_commands(before + 1, opcode=DRIVE)[-1][1] == struct.pack(">Bhh", 137, 100, 32767)
    with pytest.raises(TypeError, match="takes the fields linear, angular"):
        robot.call_input("set_velocity", linear=0.1)
    with pytest.raises(TypeError, match="field linear must be float, not str"):
        robot.set_velocity(linear="fast", angular=0.0)
    with pytest.raises(KeyError):
        robot.call_input("fly", height=1.0)


def test_bumper_pressed_gives_a_zero_distance(create) -> None:
    dev, robot, outputs, _ = create
    dev.bumpers = 1
    outputs.wait(lambda items: items and items[-1] == {"name": "detect_bump", "contents": {"distance": 0.0}})
    assert robot.state["bumperStates"] == 1 and robot.state.bumperStates == 1
    dev.bumpers = 4  # a wheel drop is not an obstacle
    outputs.wait(lambda items: items[-1] == {"name": "detect_bump", "contents": {"distance": 1.0}})
    dev.bumpers = 0


def test_close_writes_the_stop_command(drivers) -> None:
    driver = load(drivers["fast_create"])
    with CreateEmulator() as dev:
        with driver.connect(dev.port, threads=False) as robot:
            robot.set_velocity(linear=0.2, angular=0.0)
        assert robot.closed
        assert dev.wait_for_commands(4)[-1][1] == STOP
        with pytest.raises(driver.RdisConnectionError, match="closed"):
            robot.set_velocity(linear=0.2, angular=0.0)


def test_ticks_without_threads_report_errors_instead_of_raising(drivers) -> None:
    driver = load(drivers["fast_create"])
    with CreateEmulator(mode="silent", bumpers=1) as dev:
        errors, outputs = Recorder(), Recorder()
        robot = driver.connect(dev.port, threads=False, timeout=0.2, on_error=errors, on_output=outputs)
        try:
            robot.tick()
            assert len(errors.items) == 1 and isinstance(errors.items[0], driver.RdisTimeout)
            assert str(errors.items[0]).startswith("bumpers: no reply within 0.2 s")
            dev.mode = "normal"
            robot.tick()
            assert outputs.items == [{"name": "detect_bump", "contents": {"distance": 0.0}}]
            assert len(errors.items) == 1
        finally:
            robot.close()


SHORT = """
robot shortie {}
state value: int = 0
connection link: serial { baud 9600 threading single at 10 Hz }
primitive read() on link pack "B" (1) unpack ">H" { value = out[0] }
interface poll() periodic { read() }
"""


def test_a_short_reply_is_a_protocol_error(tmp_path) -> None:
    source = tmp_path / "shortie.rdis"
    source.write_text(SHORT, encoding="utf-8")
    driver = load(generate(source, tmp_path, "shortie"))
    answers = iter([b"\x01", b"\x01\x02"])
    with pty_device(lambda data: next(answers)) as dev:
        errors = Recorder()
        with driver.connect(dev.port, threads=False, timeout=0.2, on_error=errors) as robot:
            robot.tick()
            (error,) = errors.items
            assert isinstance(error, driver.RdisProtocolError)
            assert str(error) == "read: expected 2 bytes, got 1"
            robot.tick()
            assert robot.state["value"] == 0x0102


def test_a_failing_output_callback_is_reported_and_delivery_goes_on(drivers) -> None:
    driver = load(drivers["fast_create"])

    def broken(output: object) -> None:
        raise RuntimeError("oops")

    with CreateEmulator(bumpers=2) as dev:
        errors, outputs = Recorder(), Recorder()
        robot = driver.connect(dev.port, threads=False, on_error=errors)
        robot.on_output(broken)
        robot.on_output(outputs)
        try:
            robot.tick()
        finally:
            robot.close()
    assert outputs.items == [{"name": "detect_bump", "contents": {"distance": 0.0}}]
    (error,) = errors.items
    assert isinstance(error, driver.RdisCallbackError) and isinstance(error.__cause__, RuntimeError)
    assert str(error).startswith("detect_bump: ")


def test_the_threads_poll_and_the_device_disappearing_is_a_connection_error(drivers) -> None:
    driver = load(drivers["fast_create"])
    with CreateEmulator() as dev:
        errors, outputs = Recorder(), Recorder()
        robot = driver.connect(dev.port, on_error=errors, on_output=outputs)
        try:
            outputs.wait(lambda items: len(items) >= 5)  # the 40 Hz thread
            dev.close_master()
            errors.wait(lambda items: any(isinstance(e, driver.RdisConnectionError) for e in items))
            with pytest.raises(driver.RdisConnectionError, match="^btserial: "):
                robot.set_velocity(linear=0.1, angular=0.0)
        finally:
            robot.close()  # the terminate hook fails too: reported, not raised


def test_io_callbacks_see_every_write_and_read(drivers) -> None:
    driver = load(drivers["fast_create"])
    with CreateEmulator(bumpers=3) as dev:
        io = Recorder()
        robot = driver.connect(dev.port, threads=False, on_io=io)
        try:
            robot.tick()
        finally:
            robot.close()
    assert io.items == [
        ("write", "btserial", bytes([START])), ("write", "btserial", bytes([FULL])),
        ("write", "btserial", bytes([SENSORS, 7])), ("read", "btserial", bytes([3])),
        ("write", "btserial", STOP),
    ]


def test_a_callback_may_call_the_robot_while_another_thread_does(drivers) -> None:
    """An output callback that reacts with an input (a reflex), I/O callbacks registered, and
    inputs from another thread at the same time: no deadlock between the port's lock and the
    callbacks' lock."""
    import threading

    driver = load(drivers["fast_create"])
    with CreateEmulator(bumpers=1) as dev:
        io, errors, reflexes = Recorder(), Recorder(), Recorder()

        def reflex(output: object) -> None:
            robot.set_velocity(linear=0.0, angular=0.0)
            reflexes(output)

        def keep_driving() -> None:  # until several reflexes crossed these calls (or 10 s, on a busy machine)
            deadline = time.monotonic() + 10
            while len(reflexes.items) < 5 and time.monotonic() < deadline:
                robot.set_velocity(linear=0.1, angular=0.0)

        robot = driver.connect(dev.port, on_io=io, on_error=errors)
        robot.on_output(reflex)
        try:
            caller = threading.Thread(target=keep_driving, daemon=True)
            caller.start()
            caller.join(timeout=20)
            assert not caller.is_alive(), "deadlocked"
            assert len(reflexes.items) >= 5
            assert errors.items == []
            dev.wait_until(lambda: STOP in [c for _, c in dev.commands], 5.0, "a reflex's drive(0, 0)")
        finally:
            robot.close()
    assert (0, 0) in dev.drives() and (100, 32767) in dev.drives()


# ---- the Koala ---------------------------------------------------------------------------------------


def test_koala_drives_reads_odometry_and_reports(drivers) -> None:
    driver = load(drivers["koala"])
    with KoalaEmulator() as dev:
        outputs = Recorder()
        robot = driver.connect({"rs232": dev.port}, threads=False, on_output=outputs)
        try:
            assert dev.lines[:2] == ["D,0,0", "G,0,0"]  # the startup hook
            robot.set_velocity(linear=0.2, angular=0.0)
            assert dev.lines[-1] == "D,44,44"  # 0.2 / 0.0045 = 44.4 speed units
            dev.counters = (2000, 2000)
            dev.proximity = [0] * 15 + [700]
            robot.tick()
            odometry, obstacle = outputs.items
            assert odometry["name"] == "odometry"
            assert odometry["contents"]["x"] == pytest.approx(0.09)  # 2000 pulses of 0.045 mm
            assert odometry["contents"]["linear"] == pytest.approx(44 * 0.0045)
            assert obstacle == {"name": "obstacle", "contents": {"distance": 0.0}}
            assert robot.state["leftCount"] == 2000 and robot.state["proximity"] == 700
        finally:
            robot.close()
    assert dev.lines[-1] == "D,0,0"  # the terminate hook


@pytest.mark.parametrize(("mode", "error", "message"), [
    ("silent", "RdisTimeout", "set_speed: no reply within 0.2 s"),
    ("garbage", "RdisProtocolError", "set_speed: reply '#?garbage!' does not match '^d\\\\s*$'"),
    ("unterminated", "RdisProtocolError", "set_speed: reply line not terminated: 'd'"),
])
def test_koala_faults_are_raised_to_the_caller_of_an_input(drivers, mode, error, message) -> None:
    driver = load(drivers["koala"])
    with KoalaEmulator() as dev:
        robot = driver.connect(dev.port, threads=False, timeout=0.2)
        try:
            dev.mode = mode
            with pytest.raises(getattr(driver, error)) as caught:
                robot.set_velocity(linear=0.1, angular=0.0)
            assert str(caught.value) == message
            dev.mode = "normal"
            robot.set_velocity(linear=0.0, angular=0.0)  # and the driver goes on
        finally:
            robot.close()


# ---- the command line ---------------------------------------------------------------------------------


def test_command_line_call_writes_the_bytes_and_stops_at_exit(drivers) -> None:
    with CreateEmulator() as dev:
        done = subprocess.run(
            [sys.executable, str(drivers["create"]), "--port", dev.port, "--trace",
             "--call", "set_velocity", "linear=0.2", "angular=0", "--duration", "0.5"],
            capture_output=True, text=True, check=False, timeout=30, env=cli_env(),
        )
        assert done.returncode == 0, done.stderr
        dev.wait_for_commands(4)
        assert dev.opcodes()[:2] == [START, FULL]
        assert dev.drives() == [(200, 32767), (0, 0)]
        assert dev.commands[-1][1] == STOP
    trace = untimed(done.stderr)
    assert trace[:2] == ["btserial > 80", "btserial > 84"]
    assert "btserial > 89 00 c8 7f ff" in trace
    assert trace[-1] == "btserial > 89 00 00 00 00"


@pytest.mark.parametrize(("signum", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_command_line_stops_the_robot_on_a_signal(drivers, signum, status) -> None:
    with CreateEmulator(bumpers=1) as dev:
        process = subprocess.Popen(
            [sys.executable, str(drivers["fast_polled"]), "--port", dev.port, "--watch"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=cli_env(PYTHONFAULTHANDLER="1"),
        )
        try:
            first = process.stdout.readline()  # the first output: the robot runs
            assert json.loads(first) == {"name": "detect_bump", "contents": {"distance": 0.0}}
            process.send_signal(signum)
            try:
                assert process.wait(timeout=30) == status
            except subprocess.TimeoutExpired:  # seen once in a full run: say where each thread stood
                process.send_signal(signal.SIGABRT)
                raise AssertionError(f"still running 30 s after the signal: {process.communicate()[1]}") from None
        finally:
            if process.poll() is None:
                process.kill()
            process.stdout.close()
            process.stderr.close()
        dev.wait_until(lambda: dev.commands and dev.commands[-1][1] == STOP, 2.0, "the stop command")


def test_command_line_usage_errors(drivers) -> None:
    for args, expected in [
        (["--call", "fly"], "has no input, interface or primitive `fly`"),
        (["--call", "set_velocity", "linear=1"], "takes linear=... angular=..."),
        ([], "give the device's port"),
    ]:
        port = ["--port", "loop://"] if args else []
        done = subprocess.run([sys.executable, str(drivers["create"]), *port, *args],
                              capture_output=True, text=True, check=False, timeout=30, env=cli_env())
        assert done.returncode == 2, done.stderr
        assert expected in done.stderr


# ---- names and literals the description chooses ------------------------------------------------------

ODD = r'''
/// A robot whose names are Python's: """quotes""" and a back\slash in its docs.
robot odd { description "names that are Python keywords and builtins" }

state lambda: int = 0
state label: string = "it's \"quoted\"\n"
state keys: float = 1.5

connection loop: serial { baud 9600 threading single at 10 Hz }

/// Echo: written, then read back (a pyserial loop:// port).
primitive echo(class: int, print: string) on loop pack ">h3s" (class, print) unpack ">h3s" {
    lambda = out[0] + 1
    label = out[1] + label
    keys = float(class) / 2
}

interface send(type: int, self: string) { echo(type, self) }

adapter Odd { class: int unit "1"  print: string }

input open: Odd -> send(class, print)
'''


def test_keywords_builtins_and_quotes_in_names_and_literals(tmp_path) -> None:
    source = tmp_path / "odd.rdis"
    source.write_text(ODD, encoding="utf-8")
    path = generate(source, tmp_path, "odd")
    text = path.read_text(encoding="utf-8")
    assert "def open_(self, class_: int, print: str)" in text
    driver = load(path)
    with driver.connect("loop://", threads=False) as robot:
        robot.open_(class_=41, print="abc")
        assert robot.state["lambda"] == 42
        assert robot.state["label"] == "abcit's \"quoted\"\n"
        assert robot.state["keys"] == 20.5
        robot.call_input("open", **{"class": 1, "print": "xy"})
        assert robot.state["lambda"] == 2
        with pytest.raises(driver.RdisValueError, match="^echo: "):
            robot.open_(class_=40000, print="abc")  # out of range for `h`
        with pytest.raises(driver.RdisValueError, match="^echo: "):
            robot.open_(class_=1, print="\u20ac")  # not latin-1
    assert '"""quotes""" and a back\\slash' in driver.Odd.__doc__
    assert dict(robot.state) == {"lambda": 2, "label": robot.state["label"], "keys": 0.5}
    done = subprocess.run([sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache", str(path)],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout


def test_values_and_errors_agree_with_the_runtime(drivers, tmp_path) -> None:
    """Edge values through set_velocity: the generated driver and the rdisc runtime write the same
    bytes or raise the same error (type and element), over pyserial loop:// ports."""
    serial = pytest.importorskip("serial")
    runtime = pytest.importorskip("rdisc.runtime")
    driver = load(drivers["fast_create"])
    description = runtime.load(without_delays(EXAMPLES / "create.rdis", tmp_path))
    values = [0.0, -0.0, 0.2, -0.4, 1e-308, -1e-308, 1e308, -1e308, 0.5000001, 3, float("inf"), float("nan")]
    ours, theirs = serial.serial_for_url("loop://"), serial.serial_for_url("loop://")
    generated = driver.connect(ours, threads=False)
    interpreted = description.connect(theirs, threads=False)
    try:
        for linear, angular in itertools.product(values, repeat=2):
            outcomes = []
            for robot, port in ((generated, ours), (interpreted, theirs)):
                port.reset_input_buffer()
                try:
                    robot.call_input("set_velocity", linear=linear, angular=angular)
                    outcomes.append(port.read(port.in_waiting))
                except Exception as err:  # noqa: BLE001 - compared by type and element
                    outcomes.append((type(err).__name__, str(err).split(":")[0]))
            assert outcomes[0] == outcomes[1], (linear, angular)
    finally:
        generated.close()
        interpreted.close()


# ---- one semantics: the generated driver and the runtime, on every expression form ---------------------

SINK = r'''
robot sink { description "every expression form, over pyserial loop:// ports" }

state count: int = 0
state total: float = 0.0
state label: string = "x"
state flag: bool = False
state big: float = 1e300
state last: int = -1
state joints: float[3] = [0, 1, 2.5]

connection wire: serial {
    baud 115200
    threading single at 50 Hz
    startup hello(2)
    terminate bye()
}

connection other: serial {
    baud 9600
    threading single at 5 Hz
    keepalive ping(count % 256) every 1 ms
}

/// Packs one value of each kind; the loop port sends the bytes back as the reply.
primitive mix(a: int, b: float, s: string, f: bool) on wire pack ">hd3s?" (a, b, s, f) unpack ">hd3s?" {
    count = out[0] + count
    total = out[1] * 2 + total
    label = out[2] + str(out[0]) + label
    flag = out[3] and not flag
}

primitive line(v: int, w: float) on wire format "V,{},{:.3f}\n" (v, w) regex r"^V,(-?\d+),(-?[\d.]+)$" {
    last = int(out[0]) % 7 - int(out[0]) // 3
    total = float(out[1]) + total
}

primitive hexed(text: string) on wire format "{}\n" (text) regex r"^(0x[0-9a-f]+|\d+)?$" {
    last = int(out[0]) if out[0] != "" else -1
}

primitive hello_p(n: int) on wire pack "B" (n)
primitive bye_p() on wire pack "BB" (0, 0)
primitive many(at: int, goal: int[3] in 0..1000) on wire pack "<B3H" (len(goal), goal) unpack "<2h" {
    joints[at] = out[0] / 100
    joints[at + 1] = [out[1], out[0]][at] * 1.5
}
primitive ping_p(n: int) on other pack "B" (n)

interface hello(n: int) { hello_p(n) }
interface bye() { bye_p() }
interface ping(n: int) { ping_p(n) }

interface work(x: float, y: float, k: int, s: string, f: bool) triggers report {
    mix(clamp(k * 3, -1000, 1000) << 2 >> 1, x ** 2 - abs(y) / 2 + sqrt(hypot(x, y)), s + "!", f or x > y)
        priority 2
    line(k ** 2 % 1000 - (k & 7 | 8 ^ 3), round(x * y, 2) if not f else -y)
    hexed(s)
}

interface only_report() triggers report { }
interface spread(k: int) { many(k % 2, [k, k * 2, round(joints[2])]) }

adapter Work { x: float y: float k: int s: string f: bool }

input go: Work -> work(x / 3, y * 1e300, -k, s, f == True)
input poke: Contact -> only_report()

output report: Range {
    distance = min(total, 1e9) + max(count, last) - (0 if flag else 1) + (big if total > 1e300 else 0)
}
'''


@pytest.fixture(scope="module")
def sink(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sink")
    source = folder / "sink.rdis"
    source.write_text(SINK, encoding="utf-8")
    return source, generate(source, folder, "sink")


def test_every_expression_form_passes_ruff_and_mypy(sink, tmp_path, mypy_cache) -> None:
    path = str(sink[1])
    done = subprocess.run([sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache", path],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-error-summary", "--cache-dir",
                           str(mypy_cache), path], capture_output=True, text=True, check=False, cwd=tmp_path)
    assert done.returncode == 0, done.stdout


@pytest.fixture(scope="module")
def sink_pair(sink):
    """The sink's generated driver, imported, and its runtime description, loaded: once for the
    module (each run below connects afresh)."""
    runtime = pytest.importorskip("rdisc.runtime")
    source, path = sink
    return load(path), runtime.load(source)


def _run_both(sink_pair, steps):
    """Drive the runtime and the generated driver through `steps` over loop:// ports; what each
    saw: I/O, outputs, errors (type and element) and the state after each step."""
    serial = pytest.importorskip("serial")
    records = []
    for implementation in sink_pair:
        connect = implementation.connect
        io, outputs, seen = Recorder(), Recorder(), []
        ports = {"wire": serial.serial_for_url("loop://"), "other": serial.serial_for_url("loop://")}
        robot = connect(ports, threads=False, on_io=io, on_output=outputs, on_error=seen.append)
        try:
            for step in steps:
                try:
                    step(robot)
                except Exception as err:  # noqa: BLE001 - compared by type and element
                    seen.append(err)
                seen.append(repr(sorted(dict(robot.state).items())))
        finally:
            robot.close()
        errors = [e if isinstance(e, str) else (type(e).__name__, str(e).split(":")[0]) for e in seen]
        records.append((io.items, repr(outputs.items), errors))
    return records


def test_the_driver_and_the_runtime_agree_on_chosen_values(sink_pair) -> None:
    steps = [
        lambda r: r.call_input("go", x=1.5, y=-2.0, k=3, s="ab", f=False),
        lambda r: r.call_input("go", x=0.0, y=0.0, k=0, s="0x1f", f=True),
        lambda r: r.call_input("go", x=1e308, y=1e-300, k=-7, s="12", f=False),
        lambda r: r.call_input("go", x=float("nan"), y=float("inf"), k=2**40, s="\u20ac", f=True),
        lambda r: r.call_input("go", x=-3.0, y=2.0, k=2**15, s="", f=False),
        lambda r: r.call_input("poke", contact=True),
        lambda r: (time.sleep(0.003), r.tick()),  # the keepalive (every 1 ms) is due
        lambda r: r.call_interface("ping", 300),
        lambda r: r.call_interface("work", 1, 2, 3, "s", True),
    ]
    ours, theirs = _run_both(sink_pair, steps)
    assert ours == theirs


hypothesis = pytest.importorskip("hypothesis")
st = hypothesis.strategies


@hypothesis.settings(max_examples=60, deadline=None,
                     suppress_health_check=[hypothesis.HealthCheck.function_scoped_fixture])
@hypothesis.given(st.lists(st.tuples(
    # Not NaNs: which NaN (sign, payload) an operation on two of them returns is the C library's
    # choice, not the description's, and the contract says nothing of it.
    st.floats(allow_nan=False), st.floats(allow_nan=False), st.integers(-(2**20), 2**20) | st.integers(),
    st.text(max_size=4) | st.sampled_from(["0x10", "0xzz", "7", " 8"]), st.booleans(),
), min_size=1, max_size=4))
def test_the_driver_and_the_runtime_agree_on_any_values(sink_pair, calls) -> None:
    steps = [
        (lambda r, c=call: r.call_input("go", x=c[0], y=c[1], k=c[2], s=c[3], f=c[4]))
        for call in calls
    ] + [lambda r: (time.sleep(0.003), r.tick())]  # the keepalive (every 1 ms) is due
    ours, theirs = _run_both(sink_pair, steps)
    assert ours == theirs


@hypothesis.settings(max_examples=300, deadline=None)
@hypothesis.given(st.text())
def test_any_doc_text_becomes_a_docstring_that_reads_back(text) -> None:
    from rdisc.emit.python_text import _docstring
    from rdisc.emit.writer import printable as _printable

    expected = "\n".join(line.rstrip() for line in text.strip("\n").split("\n"))
    expected += "\n" if "\n" in expected else ""  # a docstring of several lines ends on a line of its own
    assert ast.literal_eval(_docstring(text)) == expected
    comment = "# " + _printable(text)
    assert "\n" not in comment and "\r" not in comment
    assert ast.parse(f"x = 1  {comment}\n").body[0].lineno == 1


def test_one_thread_a_connection_and_each_stops_on_close(sink) -> None:
    driver = load(sink[1])
    io = Recorder()
    robot = driver.connect({"wire": "loop://", "other": "loop://"}, on_io=io)  # pyserial's loop:// URL
    try:
        threads = [worker._thread for worker in robot._workers]
        assert sorted(t.name for t in threads) == ["sink other", "sink wire"]
        io.wait(lambda items: ("write", "other", b"\x00") in items)  # the keepalive, every 1 ms
    finally:
        robot.close()
    assert not any(t.is_alive() for t in threads)
    assert io.items[-1] == ("write", "wire", b"\x00\x00")  # the terminate hook


def test_a_long_expect_is_broken_inside_bool_parentheses(tmp_path) -> None:
    """A condition too long for a line is broken inside `bool(...)`'s own parentheses: no second
    pair, which ruff calls extraneous (UP034). The driver still holds the reply by it."""
    source = tmp_path / "long.rdis"
    source.write_text('robot r { author "tests" }\nconnection port: serial { baud 115200 }\n'
                      'primitive q() on port pack "B" (1) unpack "BBBBBB" expect out[0] == 0x55 and out[1] == 0x66'
                      ' and out[2] == 0x77 and out[3] == 0x12 and out[4] == 0x13 and out[5] == 0x14\n',
                      encoding="utf-8")
    path = generate(source, tmp_path, "long_expect")
    assert """\
    return bool(
        reply[0] == 85
        and reply[1] == 102
        and reply[2] == 119
        and reply[3] == 18
        and reply[4] == 19
        and reply[5] == 20,
    )
""" in path.read_text(encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache", "--extend-select", "UP",
                           str(path)], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout
    driver = load(path)
    with driver.connect(ScriptedPort(bytes.fromhex("55 66 77 12 13 14 55 66 77 12 13 15")), threads=False) as robot:
        robot.primitives.q()
        with pytest.raises(driver.RdisProtocolError):
            robot.primitives.q()


MANY = """robot many { author "tests" }
connection port: serial { baud 115200 }
state first: int = 0
state kept: float = 2.5
""" + "".join(f"state v{i}: int = 0\nstate b{i}: bool\n" for i in range(9)) + "".join(
    f"state e{i}: int = {i}\n" for i in range(6)) + """
/// 19 of the 26 state variables from the reply: the whole new state (the engine renews it).
primitive all() on port pack "B" (1) unpack "B9B" {
    first = out[0] + 1
""" + "".join(f"    v{i} = out[{i + 1}]  b{i} = bool(out[{i + 1}] & 1)\n" for i in range(9)) + """}
/// 17 of the 26, merged into the state.
primitive some() on port pack "B" (2) unpack "9B" {
""" + "".join(f"    v{i} = out[{i}] * 2\n" for i in range(9)) + "".join(
    f"    b{i} = out[{i}] == 0\n" for i in range(8)) + "}\n"


def test_a_dict_of_more_than_sixteen_values_is_a_copy_filled_in(tmp_path, mypy_cache) -> None:
    """Post-actions setting more values than CPython builds a dict display of at its full size
    give a copy of their keys filled in (half the time of a display that grows); the state they
    leave is the display's, in the variables' order, and the driver passes ruff and mypy --strict."""
    source = tmp_path / "many.rdis"
    source.write_text(MANY, encoding="utf-8")
    path = generate(source, tmp_path, "many")
    text = path.read_text(encoding="utf-8")
    assert '    changes = _P_ALL_ACTIONS_KEYS.copy()\n    changes["first"] = reply[0] + 1\n    changes["v0"] = reply[1]\n' in text
    assert '    changes["b8"] = (reply[9] & 1) != 0\n    changes["kept"] = state["kept"]\n' in text  # those not set, kept
    assert '    changes = _P_SOME_ACTIONS_KEYS.copy()\n    changes["v0"] = _mul(reply[0], 2)\n' in text
    assert ('_P_SOME_ACTIONS_KEYS: dict[str, Value] = dict.fromkeys((\n'
            '    "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v8", "b0", "b1", "b2", "b3", "b4", "b5", "b6",\n'
            '    "b7",\n'
            '), 0)\n') in text
    for tool in (["ruff", "check", "--isolated", "--no-cache"],
                 ["mypy", "--strict", "--no-error-summary", "--cache-dir", str(mypy_cache)]):
        done = subprocess.run([sys.executable, "-m", *tool, str(path)], capture_output=True, text=True, check=False,
                              cwd=tmp_path)
        assert done.returncode == 0, done.stdout + done.stderr
    driver = load(path)
    reply = bytes([7, 1, 2, 3, 4, 5, 6, 7, 8, 9])
    with driver.connect(ScriptedPort(reply + bytes([0, 1, 0, 1, 0, 1, 0, 1, 5])), threads=False) as robot:
        robot.primitives.all()
        names = ["first", "kept"] + [f"{kind}{i}" for i in range(9) for kind in "vb"] + [f"e{i}" for i in range(6)]
        assert list(robot.state) == names
        assert dict(robot.state) == {"first": 8, "kept": 2.5, **{f"v{i}": i + 1 for i in range(9)},
                                     **{f"b{i}": (i + 1) % 2 == 1 for i in range(9)}, **{f"e{i}": i for i in range(6)}}
        robot.primitives.some()
        assert list(robot.state) == names
        assert dict(robot.state) == {"first": 8, "kept": 2.5, **{f"v{i}": 2 * (i % 2) for i in range(8)}, "v8": 10,
                                     **{f"b{i}": i % 2 == 0 for i in range(8)}, "b8": True, **{f"e{i}": i for i in range(6)}}
