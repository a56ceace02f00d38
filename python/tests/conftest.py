"""Shared fixtures: the repository root, the command-line tool, the reference data."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"


def _target_dir():
    env = os.environ.get("CARGO_TARGET_DIR")
    return pathlib.Path(env) if env else ROOT / "target"


@pytest.fixture(scope="session")
def cli_path():
    """The release binary `moving-hertz`: $MOVING_HERTZ_BIN, else the workspace's
    target/release/moving-hertz, built by cargo if missing."""
    env = os.environ.get("MOVING_HERTZ_BIN")
    path = pathlib.Path(env) if env else _target_dir() / "release" / "moving-hertz"
    if not path.exists():
        subprocess.run(["cargo", "build", "--release", "--bin", "moving-hertz"], cwd=ROOT,
                       check=True)
    assert path.exists(), f"no command-line tool at {path}"
    return path


@pytest.fixture(scope="session")
def cli(cli_path):
    """Runs `moving-hertz ARGS --json` and returns the parsed JSON object."""

    def run(*args):
        out = subprocess.run([str(cli_path), *map(str, args), "--json"], capture_output=True,
                             text=True, check=True)
        return json.loads(out.stdout)

    return run


def read_csv(name):
    """The rows of a reference file of tests/data (comment lines skipped), as lists of text."""
    rows = []
    for line in (DATA / name).read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            rows.append(line.split(","))
    return rows
