#!/usr/bin/env bash
# The one test command (README "Tests", .ci/run): the Rust tests, then the Python package's.
#
# 1. `cargo test --release`: the crate's tests (and the release binary `moving-hertz`, which
#    the Python tests compare against).
# 2. A virtual environment under the ignored target/ (target/pyenv; made once, kept), with
#    maturin, numpy, pytest, mpmath, dask[array] and distributed from PyPI.
# 3. The extension built in release mode by maturin into that environment, in the workspace's
#    target/ (GMP and MPFR, built by step 1, are not built again), then pytest python/tests.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --release
venv=target/pyenv
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    "maturin>=1.5,<2" numpy pytest mpmath "dask[array]" distributed
(cd python && VIRTUAL_ENV="$PWD/../$venv" PATH="$PWD/../$venv/bin:$PATH" \
    maturin develop --release --quiet)
"$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
