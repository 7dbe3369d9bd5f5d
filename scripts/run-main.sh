#!/usr/bin/env bash
# The main job: install dependencies, build (and put the Python module on /usr/bin/python3's path:
# scripts/install-python.sh), then explore with the defaults: every class member up
# to n = 300 built and certified, the basin-hopping search for small n (docs/search.md), billiards
# runs for the matrix stress set, compared, with the atlas (data/atlas.csv) beside them, and the
# report written to explore's default out/report (open out/report/index.html). Extra arguments go
# to `tripack explore` (e.g. --out DIR for another directory).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash scripts/install-python.sh
./build/tripack explore "$@"
