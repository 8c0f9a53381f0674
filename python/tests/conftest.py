"""Shared by the tests: the command line's binary, run as a user runs it, to compare with.

The binary is `target/release/collide` of this checkout (`cargo build --release`), or
$COLLIDE_BIN. A test that cannot run fails: nothing here is skipped (.ci/run also fails a run
with a skipped test or none).
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BIN = Path(os.environ.get("COLLIDE_BIN", ROOT / "target" / "release" / "collide"))


def run(*args, stdin=None):
    """`collide ARGS...`: (exit status, stdout, stderr)."""
    assert BIN.exists(), f"{BIN} is missing: build it with cargo build --release"
    p = subprocess.run(
        [str(BIN), *args], input=stdin, capture_output=True, text=True, timeout=120
    )
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    """The JSON the command prints (it must succeed)."""
    status, out, err = run(*args, "--format", "json")
    assert status == 0, err
    return out, json.loads(out)


def unwrapped(stderr):
    """The command's stderr with its lines rejoined (it wraps at 80 columns, continuation lines
    indented by two spaces)."""
    return stderr.replace("\n  ", " ").strip()


def cli_error(*args):
    """The message of a refusal as the module gives it: exit status 2, `error: MESSAGE` on
    stderr, with its lines rejoined; for a value a flag's parser refused, the parser's own
    message; a usage error's text without the usage line and the hint to try --help."""
    status, _, err = run(*args)
    assert status == 2, (status, err)
    message = unwrapped(err)
    assert message.startswith("error: "), message
    message = message[len("error: "):]
    message = message.split("\n\nFor more information")[0].split("\n\nUsage:")[0]
    # A value clap's parser refused: "invalid value 'X' for '--flag <V>': MESSAGE"; the message
    # is the library's.
    if message.startswith("invalid value ") and ">': " in message:
        message = message.split(">': ", 1)[1]
    return message.strip()


def pytest_sessionfinish(session, exitstatus):
    """A skipped test fails the run: every test here must run."""
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None and reporter.stats.get("skipped"):
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
