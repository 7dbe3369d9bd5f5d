#!/usr/bin/env bash
# Install dependencies, build everything (the Python module put on /usr/bin/python3's path by
# scripts/install-python.sh), run the whole test suite with ctest, then a fuzz smoke
# (scripts/fuzz.sh --smoke: builds fuzz/ with clang into build-fuzz/, ~20 s on 2 cores, and runs
# each libFuzzer target for 10 s, one per core at a time; any crash, hang or sanitizer report fails the run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash scripts/install-python.sh
(cd build && ctest --output-on-failure --parallel "${JOBS:-$(nproc)}")
bash scripts/fuzz.sh --smoke
