#!/usr/bin/env bash
# Every test of rolldyn: the Rust workspace (unit, validation against the seeds, bad input), then
# the Python package against the `rolldyn` program (python/tests: each API call, errors, Ctrl-C,
# sweeps on Dask, the tutorial) and the HTML report in headless Chromium. Screenshots of the
# report go to target/test-artefacts/.
#
# Needs cargo and Python ≥ 3.9 with pip. What a fresh Debian machine lacks is installed here: the
# cage-stress solid model's mesher and solver (gmsh, calculix-ccx: an end-to-end test runs them)
# and chromium (the report's browser test) from Debian's packages, then the Python packages (the
# rolldyn package itself, pytest, dask, playwright) with pip.
set -euo pipefail
cd "$(dirname "$0")"

missing=()
command -v gmsh >/dev/null 2>&1 || missing+=(gmsh)
command -v ccx >/dev/null 2>&1 || missing+=(calculix-ccx)
command -v chromium >/dev/null 2>&1 || missing+=(chromium)
if [ ${#missing[@]} -gt 0 ]; then
    if [ "$(id -u)" -ne 0 ]; then
        echo "test.sh: install ${missing[*]} first (sudo apt-get install ${missing[*]})" >&2
        exit 1
    fi
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi

# No module of a crate imports, directly or through others, a module that imports it.
python3 tools/module_cycles.py

cargo test --workspace

# The package, and the program its answers are compared with: the `rolldyn` that `cargo test` built
# (target/debug, test profile). Its arithmetic is the wheel's — the optimisation level does not
# change floating-point results (no fast-math, no contraction into FMA) — and a separate
# wheel-profile build of the program would add ≈ 3 min and test nothing more (BENCHMARKS.md,
# "CI time").
python3 -m pip install --quiet --disable-pip-version-check "./python[test]"

ROLLDYN_BIN="$PWD/target/debug/rolldyn" python3 -m pytest python/tests
