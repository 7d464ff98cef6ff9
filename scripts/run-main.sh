#!/usr/bin/env bash
# Newcomer command 1: install dependencies, build, and run the main job on built-in data.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh -DBEZOUTIAN_BUILD_TESTS=OFF
bash examples/main_job.sh build/examples/bezoutian
