#!/usr/bin/env bash
# Every test of rolldyn: the Rust workspace (unit, validation against the seeds, bad input), then
# the Python package against the `rolldyn` program (python/tests: each API call, errors, Ctrl-C,
# sweeps on Dask, the tutorial) and the HTML report in headless Chromium. Screenshots of the
# report go to target/test-artefacts/.
#
# Needs cargo, Python ≥ 3.9 with pip, and Debian's chromium (apt-get install chromium); the
# Python packages (the rolldyn package itself, pytest, dask, playwright) are installed here.
set -euo pipefail
cd "$(dirname "$0")"

cargo test --workspace

# The program the Python answers are compared with, and the package (release builds share their
# compiled crates).
cargo build --release --bin rolldyn
python3 -m pip install --quiet --disable-pip-version-check "./python[test]"

ROLLDYN_BIN="$PWD/target/release/rolldyn" python3 -m pytest python/tests
