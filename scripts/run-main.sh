#!/usr/bin/env bash
# The main job: install dependencies, build, then build, polish and tabulate the first terms of
# every class of the catalogue.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/tripack table
