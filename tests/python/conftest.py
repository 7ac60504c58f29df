"""Shared fixtures of the Python module's tests: the CLI binary (COLDBLAST_CLI, set by ctest) whose
JSON output the bindings must reproduce number for number."""
import json
import os
import subprocess

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def cli_binary():
    path = os.environ.get("COLDBLAST_CLI", os.path.join(REPO, "build", "bin", "coldblast"))
    if not os.path.exists(path):
        pytest.fail(f"coldblast CLI not found at {path} (set COLDBLAST_CLI)")
    return path


def run_cli(*args, expect=0, cwd=None):
    """Runs the CLI; returns (stdout, stderr); asserts the exit status."""
    done = subprocess.run([cli_binary(), *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert done.returncode == expect, f"coldblast {' '.join(map(str, args))}: exit {done.returncode}\n{done.stderr}"
    return done.stdout, done.stderr


def cli_json(*args, expect=0, cwd=None):
    return json.loads(run_cli(*args, "--format", "json", expect=expect, cwd=cwd)[0])


def cli_error(*args):
    """The message of the CLI's exit-2 error (stderr `coldblast: error: MESSAGE`)."""
    _, err = run_cli(*args, expect=2)
    line = [l for l in err.splitlines() if l.startswith("coldblast: error: ")][-1]
    return line[len("coldblast: error: "):]


@pytest.fixture
def cli():
    return run_cli
