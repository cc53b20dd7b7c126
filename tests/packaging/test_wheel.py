"""The wheel works on its own: built, installed into a fresh virtual environment,
and run from a directory outside the checkout, it checks and builds descriptions
with the grammar and the standard library it carries.

Building needs hatchling and installing needs lark, rich and pyserial, both from
the package index. Without one (offline) the tests are skipped with the reason,
except under CI=true, where that is a failure: CI must prove the wheel works.
"""

from __future__ import annotations

import os
import subprocess
import sys
import urllib.request
import zipfile
from dataclasses import dataclass
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import pytest
from conftest import cli_env

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

ROOT = Path(__file__).resolve().parents[2]
CREATE = ROOT / "examples" / "create.rdis"
POLLED = ROOT / "tests" / "runtime" / "data" / "polled" / "create.rdis"  # its bumpers a call, not a sensor
ON_CI = os.environ.get("CI", "").lower() in ("1", "true", "yes")
INDEX = "https://pypi.org/simple/"


@dataclass(frozen=True)
class Installed:
    wheel: Path
    bin: Path  # the venv's scripts folder
    outside: Path  # a working directory outside the checkout
    env: dict[str, str]

    def run(self, *args: str | os.PathLike[str], program: str = "rdisc") -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [str(self.bin / program), *map(str, args)],
            check=False, cwd=self.outside, env=self.env, stdin=subprocess.DEVNULL,
            capture_output=True, text=True, encoding="utf-8", errors="replace", timeout=120,
        )


def _index_unreachable() -> str | None:
    """Why the package index cannot be reached, or None when it can."""
    try:
        with urllib.request.urlopen(INDEX, timeout=10):
            return None
    except OSError as err:
        return f"{INDEX} is unreachable ({err})"


def _step(what: str, cmd: list[str], **kwargs) -> None:
    """Run a set-up step; when it fails, fail (CI, or online) or skip (offline)."""
    done = subprocess.run(cmd, check=False, capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=600, **kwargs)
    if done.returncode == 0:
        return
    output = f"$ {' '.join(cmd)}\n{done.stdout}\n{done.stderr}"
    offline = None if ON_CI else _index_unreachable()
    if offline:
        pytest.skip(f"cannot {what} offline: {offline}")
    pytest.fail(f"could not {what} (exit {done.returncode}):\n{output}", pytrace=False)


def _pip_installs_elsewhere() -> bool:
    """Whether this environment's pip installs into another Python's (`pip --python`, pip 22.3)."""
    try:
        release = tuple(int(part) for part in version("pip").split(".")[:2])
    except (PackageNotFoundError, ValueError):
        return False
    return release >= (22, 3)


def _clean_env(**extra: str) -> dict[str, str]:
    """The tests' `rdisc` environment, minus anything that could leak the checkout in."""
    return {k: v for k, v in cli_env(**extra).items() if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Installed:
    base = tmp_path_factory.mktemp("wheel")
    dist, venv, outside = base / "dist", base / "venv", base / "elsewhere"
    outside.mkdir()
    env = _clean_env()
    _step("build the wheel", [sys.executable, "-m", "build", "--wheel", "--outdir", str(dist), str(ROOT)],
          cwd=ROOT, env=env)
    (wheel,) = dist.glob("rdisc-*.whl")
    bin_dir = venv / ("Scripts" if os.name == "nt" else "bin")
    python = bin_dir / ("python.exe" if os.name == "nt" else "python")
    if _pip_installs_elsewhere():  # the venv without a pip of its own (seconds saved): ours installs into it
        _step("create a virtual environment", [sys.executable, "-m", "venv", "--without-pip", str(venv)], env=env)
        install = [sys.executable, "-m", "pip", "--python", str(python)]
    else:
        _step("create a virtual environment", [sys.executable, "-m", "venv", str(venv)], env=env)
        install = [str(python), "-m", "pip"]
    _step("install the wheel and its dependencies",
          [*install, "install", "--disable-pip-version-check", "-q", str(wheel)], cwd=outside, env=env)
    env = _clean_env(PATH=f"{bin_dir}{os.pathsep}{env.get('PATH', '')}")
    return Installed(wheel, bin_dir, outside, env)


def test_wheel_carries_the_grammar_and_the_stdlib(installed: Installed) -> None:
    names = set(zipfile.ZipFile(installed.wheel).namelist())
    assert {"rdisc/grammar/rdis.lark", "rdisc/stdlib/adapters.rdis", "rdisc/cli/main.py"} <= names
    assert not any(n.startswith(("tests/", "examples/", "benchmarks/")) for n in names)


def test_wheel_carries_the_console_page_and_its_server_imports(installed: Installed) -> None:
    names = set(zipfile.ZipFile(installed.wheel).namelist())
    assert {"rdisc/console/assets/console.js", "rdisc/console/assets/console.css", "rdisc/console/server.py"} <= names
    done = installed.run("-c", "import rdisc.console.server as s, importlib.resources as r; "
                               "print(all(r.files('rdisc.console').joinpath('assets', p[1:]).read_text() "
                               "for p in s.ASSETS))", program="python")
    assert (done.returncode, done.stdout) == (0, "True\n"), done.stderr


def test_installed_package_reads_its_own_files(installed: Installed) -> None:
    assert not installed.outside.resolve().is_relative_to(ROOT)
    done = installed.run("-c", "import rdisc, rdisc.resources as r; "
                               "print(rdisc.__file__); print(r.grammar_path()); print(r.stdlib_path())",
                         program="python")
    assert done.returncode == 0, done.stderr
    venv = installed.bin.parent.resolve()
    for line in done.stdout.splitlines():
        assert Path(line).resolve().is_relative_to(venv), f"{line} is not inside the virtual environment"


def test_check_example_is_clean(installed: Installed) -> None:
    done = installed.run("check", CREATE)
    assert (done.returncode, done.stderr) == (0, "")


def test_check_broken_copy_reports_a_diagnostic(installed: Installed) -> None:
    broken = installed.outside / "broken.rdis"
    text = POLLED.read_text(encoding="utf-8")
    assert text.count("    bumpers() delay") == 1
    broken.write_text(text.replace("    bumpers() delay", "    bumpres() delay"), encoding="utf-8")
    done = installed.run("check", broken)
    assert done.returncode == 1, done.stderr
    assert "error[E102]: unknown primitive or interface `bumpres`" in done.stderr
    assert "broken.rdis:" in done.stderr and "did you mean `bumpers`?" in done.stderr
    assert "Traceback" not in done.stderr


def test_explain_works_installed(installed: Installed) -> None:
    done = installed.run("explain", "E102")
    assert done.returncode == 0 and "unknown-element" in done.stdout


def test_build_matches_the_checkout(installed: Installed) -> None:
    if not (ROOT / "rdisc" / "emit" / "canonical.py").is_file():
        pytest.skip("rdisc build needs rdisc/emit/canonical.py, which the checkout does not have yet")
    here = installed.outside / "from-checkout.json"
    wheel = installed.outside / "from-wheel.json"
    done = subprocess.run([sys.executable, "-m", "rdisc", "build", str(CREATE), "-o", str(here)], check=False,
                          cwd=ROOT, env=_clean_env(), capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    done = installed.run("build", CREATE, "-o", wheel)
    assert (done.returncode, done.stderr) == (0, "")
    assert wheel.read_bytes() == here.read_bytes()


def test_pygmentize_knows_rdis_installed(installed: Installed) -> None:
    """The entry point `pygments.lexers: rdis`: Pygments finds the lexer by its name, with no path."""
    done = installed.run("-l", "rdis", "-f", "raw", CREATE, program="pygmentize")
    assert (done.returncode, done.stderr) == (0, "")
    assert "Token.Keyword.Declaration\t'robot'\nToken.Text.Whitespace\t' '\nToken.Name.Class\t'irobot_create'\n" in done.stdout
    assert "Token.Error" not in done.stdout
