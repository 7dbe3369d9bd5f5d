#!/usr/bin/env bash
# The main job: install dependencies, build, then explore with the defaults: every class member up
# to n = 300 built and certified, billiards runs for small n and the matrix stress set, compared,
# and the report written to ./report (open report/index.html).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/tripack explore "$@"
