"""Shared test machinery: golden files and running the `rdisc` command.

Goldens are files under tests/golden/ holding an exact expected output. A test
compares what it produced with its golden; `pytest --update-goldens` rewrites
the goldens instead (and still fails nothing), so a changed rendering is
reviewed in the diff rather than accepted silently. Nothing else writes them.

`run_rdisc` runs a verb that only reads and writes files (check, build, dump, ...) in this
process, through the command's entry function, as a subprocess would see it (a pipe, no
colour, 200 columns): about 5 ms where starting Python costs a second. `run`, `sim` and `replay`
too: their ports (loop://, a pseudo-terminal, a socket) and simulations are closed and their signal
handlers put back as a run ends; a test that signals a run starts its own process. The console
(it serves until stopped) and runs that set interpreter
variables (PYTHONHASHSEED) start a real process; `run_rdisc_process` always does.
"""

from __future__ import annotations

import contextlib
import difflib
import io
import json
import os
import re
import subprocess
import sys
import threading
import traceback
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from unittest import mock

import pytest
from hypothesis import HealthCheck, settings

REPO = Path(__file__).resolve().parent.parent


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--update-goldens",
        action="store_true",
        default=False,
        help="rewrite the golden files under tests/golden/ with the current output (review the diff)",
    )


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "long: a file that takes long; the workers start it before the others")


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The files marked `long` first, each kept whole and in order: a worker that takes one at the
    end would run it alone while the other waits (pytest-xdist hands out files in this order)."""
    items.sort(key=lambda item: item.get_closest_marker("long") is None)


@dataclass(frozen=True)
class Golden:
    """Compares output with a golden file, or rewrites the file under --update-goldens."""

    update: bool

    def check(self, path: Path, actual: str) -> None:
        path = Path(path)
        if self.update:
            if not path.is_file() or path.read_bytes() != actual.encode("utf-8"):
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_bytes(actual.encode("utf-8"))
            return
        shown = _shown(path)
        if not path.is_file():
            pytest.fail(
                f"golden {shown} does not exist: run `pytest --update-goldens` and review the new file",
                pytrace=False,
            )
        expected = path.read_bytes().decode("utf-8")
        if expected != actual:
            diff = "".join(
                difflib.unified_diff(
                    expected.splitlines(keepends=True),
                    actual.splitlines(keepends=True),
                    fromfile=f"{shown} (golden)",
                    tofile=f"{shown} (actual)",
                )
            )
            pytest.fail(
                f"output differs from golden {shown}; if the change is intended, rerun with "
                f"--update-goldens and review the diff\n{diff}",
                pytrace=False,
            )


def _shown(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(REPO))
    except ValueError:
        return str(path)


@pytest.fixture(scope="session")
def golden(request: pytest.FixtureRequest) -> Golden:
    return Golden(bool(request.config.getoption("--update-goldens")))


@pytest.fixture(scope="session")
def mypy_cache(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One mypy cache for a worker's runs of `mypy --strict` over generated code, in pytest's cache
    (kept between runs, one a worker): the standard library's stubs are read once, not once a test
    or a run (each run still checks its own files)."""
    if request.config.cache is None:
        return tmp_path_factory.mktemp("mypy-cache")
    return request.config.cache.mkdir(f"mypy-generated-{os.environ.get('PYTEST_XDIST_WORKER', 'main')}")


#: RDISC_FUZZ_SCALE=N: the property tests try N times their default number of examples (a deeper
#: search, after a change to what they test); the defaults keep the suite within minutes on 2 cores
FUZZ_SCALE = float(os.environ.get("RDISC_FUZZ_SCALE", "1"))


# Hypothesis's "too slow" health check times the generation of inputs by the wall clock, so on busy
# cores (seven others' tests besides the suite's) it failed tests whose inputs are right: the suite's
# property tests are bounded by their counts of examples, never by time (no deadlines either).
settings.register_profile("rdisc", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("rdisc")


def _constants_read_from_the_checkout_only() -> None:
    """Hypothesis (6.131 on) draws some inputs from the constants in the source of each module
    imported, read anew whenever sys.modules grows: every generated driver or node a worker
    imported from a temporary folder (200 KB each) was parsed by the next example drawn, 30 s in
    one draw on a fresh checkout. Only modules under the checkout are read (the drivers carry the
    engine's modules, whose constants are read there). Private to Hypothesis: left as it is if gone."""
    from hypothesis.internal.conjecture import providers

    local = getattr(providers, "is_local_module_file", None)
    if callable(local):
        checkout = str(REPO) + os.sep
        providers.is_local_module_file = lambda path: path.startswith(checkout) and local(path)


_constants_read_from_the_checkout_only()


def _utf8_known_without_a_scan() -> None:
    """`st.text()` draws the characters UTF-8 encodes (codec "utf-8"), which Hypothesis finds by
    encoding and decoding each of the 1,114,112 code points, 2.6 s of CPU a worker on a fresh
    machine (kept in .hypothesis/ after). For UTF-8 the answer is known: every code point but the
    surrogates, each read back as written (tests/properties/test_utf8_intervals.py holds it to the codec).
    Private to Hypothesis: left as it is if gone."""
    from hypothesis.internal import charmap
    from hypothesis.internal.intervalsets import IntervalSet

    scan = getattr(charmap, "intervals_from_codec", None)
    if not callable(scan):
        return
    known = (IntervalSet([(0, 0xD7FF), (0xE000, 0x10FFFF)]), IntervalSet([]))

    def intervals_from_codec(codec_name: str) -> tuple[IntervalSet, IntervalSet]:
        return known if codec_name == "utf-8" else scan(codec_name)

    intervals_from_codec.scan = scan  # type: ignore[attr-defined]  # the original, for the test holding them equal
    charmap.intervals_from_codec = intervals_from_codec


_utf8_known_without_a_scan()


def fuzz_examples(n: int) -> int:
    """A property test's number of examples: `n`, times RDISC_FUZZ_SCALE."""
    return max(1, round(n * FUZZ_SCALE))


def cli_env(**extra: str) -> dict[str, str]:
    """The environment of an `rdisc` subprocess: no colour, UTF-8, nothing forced, its stacks on SIGABRT."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("FORCE_COLOR", "CLICOLOR_FORCE", "TTY_COMPATIBLE", "TTY_INTERACTIVE", "PYTHONHASHSEED")}
    # PYTHONFAULTHANDLER: a process that hangs writes every thread's stack on SIGABRT (`stacks_of`)
    env.update({"NO_COLOR": "1", "TERM": "dumb", "PYTHONIOENCODING": "utf-8", "COLUMNS": "200",
                "PYTHONFAULTHANDLER": "1"})
    env.update(extra)
    return env


def untimed(stderr: str) -> list[str]:
    """The lines of a `--trace` without their times (`0.1234 CONN > 89 00` -> `CONN > 89 00`),
    each checked to start with the seconds since the run started, four decimals, never going back."""
    lines, last = [], 0.0
    for line in stderr.splitlines():
        match = re.fullmatch(r"(\d+\.\d{4}) (.*)", line)
        assert match is not None, f"not a timed trace line: {line!r}"
        assert float(match[1]) >= last, f"the trace goes back in time: {line!r}"
        last = float(match[1])
        lines.append(match[2])
    return lines


#: verbs run in this process by `run_rdisc` (each ends closing what it opened; the console serves on)
IN_PROCESS_VERBS = frozenset({"check", "build", "import", "explain", "adapters", "dump", "decode", "graph", "replay", "sim",
                              "run", "emit-python", "emit-ros", "emit-urdf", "emit-sdf", "emit-mjcf", "fmt"})


def run_rdisc(
    *args: str | os.PathLike[str],
    cwd: Path = REPO,
    env: dict[str, str] | None = None,
    timeout: float = 60,
) -> subprocess.CompletedProcess[str]:
    """`rdisc ARGS...`, text captured; `env` adds variables. In this process when the verb only
    reads and writes files (or is no verb: a usage error), else `python -m rdisc` in a subprocess."""
    argv = [str(a) for a in args]
    verb = next((a for a in argv if not a.startswith("-")), None)
    from rdisc.cli.main import VERBS

    at_start = any(name.startswith("PYTHON") for name in env or {})  # read only when Python starts
    if (verb in IN_PROCESS_VERBS or verb not in VERBS) and not at_start:
        return run_rdisc_here(*argv, cwd=cwd, env=env)
    return run_rdisc_process(*argv, cwd=cwd, env=env, timeout=timeout)


def run_rdisc_process(
    *args: str | os.PathLike[str],
    cwd: Path = REPO,
    env: dict[str, str] | None = None,
    timeout: float = 60,
) -> subprocess.CompletedProcess[str]:
    """`python -m rdisc ARGS...` in a real subprocess, text captured; `env` adds variables."""
    return subprocess.run(
        [sys.executable, "-m", "rdisc", *map(str, args)],
        cwd=cwd,
        env=cli_env(**(env or {})),
        capture_output=True,
        check=False,  # the exit code is what the tests look at
        text=True,
        encoding="utf-8",
        errors="replace",
        timeout=timeout,
    )


_SEEDED = """
import json, sys
sys.path.insert(0, sys.argv[1])
from conftest import run_rdisc_here
print(json.dumps([(r.returncode, r.stdout, r.stderr) for r in (run_rdisc_here(*argv) for argv in json.loads(sys.argv[2]))]))
"""


def run_rdisc_seeded(
    runs: Sequence[Sequence[str | os.PathLike[str]]], seed: str, cwd: Path = REPO,
) -> list[subprocess.CompletedProcess[str]]:
    """`rdisc ARGS...` for each of `runs`, one after the other (as `run_rdisc_here` runs them) in one
    new interpreter whose hash seed is `seed`: what a process each would give, for one start-up."""
    argvs = [[str(a) for a in argv] for argv in runs]
    done = subprocess.run([sys.executable, "-c", _SEEDED, str(Path(__file__).parent), json.dumps(argvs)], cwd=cwd,
                          env=cli_env(PYTHONHASHSEED=seed), capture_output=True, text=True, encoding="utf-8",
                          check=False, timeout=300)
    assert done.returncode == 0, done.stderr
    return [subprocess.CompletedProcess([sys.executable, "-m", "rdisc", *argv], status, out, err)
            for argv, (status, out, err) in zip(argvs, json.loads(done.stdout), strict=True)]


class _Pipe(io.TextIOWrapper):
    """A standard stream as a subprocess's is when captured: UTF-8 over bytes, not a terminal."""

    def __init__(self, data: bytes = b"") -> None:
        self.data = io.BytesIO(data)
        super().__init__(self.data, encoding="utf-8", write_through=True)

    def captured(self) -> str:
        """What was written, read back as `subprocess.run(text=True)` reads a pipe (universal newlines)."""
        self.flush()
        return self.data.getvalue().decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n")


_ONE_AT_A_TIME = threading.Lock()  # the streams, folder and environment are the process's: one run holds them


@contextlib.contextmanager
def _as_a_subprocess(cwd: Path, env: dict[str, str]) -> Iterator[tuple[_Pipe, _Pipe]]:
    """For one run: the subprocess's environment (rich reads NO_COLOR, TERM and COLUMNS from it when
    it makes a console), working folder and standard streams; all restored after."""
    stdout, stderr = _Pipe(), _Pipe()
    with mock.patch.dict(os.environ, env, clear=True), contextlib.chdir(cwd), \
            mock.patch.object(sys, "stdin", _Pipe()), \
            contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
        yield stdout, stderr


def run_rdisc_here(
    *args: str | os.PathLike[str],
    cwd: Path = REPO,
    env: dict[str, str] | None = None,
) -> subprocess.CompletedProcess[str]:
    """`rdisc ARGS...` through the command's entry function, in this process: the exit status,
    stdout and stderr that `python -m rdisc` would give (what escapes `main` is a traceback and
    status 1, as the interpreter makes it)."""
    from rdisc.cli.main import main

    return _entry_here(main, [sys.executable, "-m", "rdisc"], [str(a) for a in args], cwd, env)


def run_driver_here(
    driver: Path, *args: str | os.PathLike[str], cwd: Path = REPO, env: dict[str, str] | None = None,
) -> subprocess.CompletedProcess[str]:
    """`python DRIVER ARGS...` through the generated driver's `main`, in this process (imported once
    a file and version): its exit status, stdout and stderr, as `run_rdisc_here` gives rdisc's."""
    stat = driver.stat()
    module = _drivers.get((str(driver), stat.st_mtime_ns, stat.st_size))
    if module is None:
        import importlib.util

        name = f"_command_line_{len(_drivers)}_{driver.stem}"
        spec = importlib.util.spec_from_file_location(name, driver)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module  # dataclasses look their module up by name
        spec.loader.exec_module(module)
        _drivers[(str(driver), stat.st_mtime_ns, stat.st_size)] = module
    with mock.patch.object(sys, "argv", [str(driver)]):  # argparse's prog: the driver's file name
        return _entry_here(module.main, [sys.executable, str(driver)], [str(a) for a in args], cwd, env)


_drivers: dict[tuple[str, int, int], Any] = {}


def run_command_here(
    command: Sequence[str | os.PathLike[str]], cwd: Path = REPO, env: dict[str, str] | None = None,
) -> subprocess.CompletedProcess[str]:
    """A command line of rdisc (`python -m rdisc ARGS`) or of a generated driver (`python DRIVER ARGS`)
    run in this process, by `run_rdisc_here` or `run_driver_here`."""
    argv = [str(word) for word in command]
    assert argv[0] == sys.executable, argv
    if argv[1:3] == ["-m", "rdisc"]:
        return run_rdisc_here(*argv[3:], cwd=cwd, env=env)
    return run_driver_here(Path(argv[1]), *argv[2:], cwd=cwd, env=env)


def _entry_here(main: Callable[[list[str]], int], command: list[str], argv: list[str], cwd: Path,
                env: dict[str, str] | None) -> subprocess.CompletedProcess[str]:
    with _ONE_AT_A_TIME, _as_a_subprocess(cwd, cli_env(**(env or {}))) as (stdout, stderr):
        try:
            status = main(argv)
        except SystemExit as exit_:  # argparse's usage errors, --help, --version
            if exit_.code is None or isinstance(exit_.code, int):
                status = exit_.code or 0
            else:
                print(exit_.code, file=sys.stderr)
                status = 1
        except Exception:  # noqa: BLE001 - the interpreter would print it and exit 1
            traceback.print_exc(file=sys.stderr)
            status = 1
    return subprocess.CompletedProcess([*command, *argv], status, stdout.captured(), stderr.captured())


def start_console(*args: str | os.PathLike[str]) -> tuple[subprocess.Popen[str], str, str]:
    """`rdisc console ARGS --http 127.0.0.1:0`: the process, the line it prints once it listens
    (after the startup hooks) and the address in it, with its token (`http://127.0.0.1:P/?token=T`)."""
    process = subprocess.Popen([sys.executable, "-m", "rdisc", "console", *map(str, args), "--http", "127.0.0.1:0"],
                               cwd=REPO, env=cli_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert process.stdout is not None
    line = process.stdout.readline()
    found = re.search(r"http://127\.0\.0\.1:\d+/\?token=[A-Za-z0-9_-]+", line)
    if found is None:
        process.kill()
        raise AssertionError(f"no address printed: {line!r} {process.communicate()}")
    return process, line, found.group(0)


def console_ws(url: str) -> str:
    """The WebSocket address of the console at `url` (as `start_console` gives it), with its token."""
    base, _, query = url.partition("?")
    return base.replace("http", "ws", 1) + "ws" + (f"?{query}" if query else "")


def console_origin(url: str) -> str:
    """The origin (http://host:port) of the console at `url`."""
    return url.partition("?")[0].rstrip("/")


def stop_process(process: subprocess.Popen[str], signum: int) -> tuple[int, str]:
    """Signal a process; its exit status and what it printed on stderr (killed if not ended in 60 s)."""
    process.send_signal(signum)
    try:
        _, stderr = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.communicate()
    return process.returncode, stderr


def check_text(folder: Path, text: str, name: str = "d.rdis") -> tuple[Path, subprocess.CompletedProcess[str]]:
    """Write `text` as a description in `folder` and run `rdisc check` on it."""
    source = folder / name
    source.write_text(text, encoding="utf-8")
    return source, run_rdisc("check", source)


@pytest.fixture(scope="session")
def rdisc() -> Callable[..., subprocess.CompletedProcess[str]]:
    """Run the rdisc command: `rdisc("check", path)` -> CompletedProcess (in process where it can)."""
    return run_rdisc


@pytest.fixture(scope="session")
def rdisc_process() -> Callable[..., subprocess.CompletedProcess[str]]:
    """Run the rdisc command as a user does, `python -m rdisc` in a subprocess."""
    return run_rdisc_process
