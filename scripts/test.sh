#!/usr/bin/env bash
# Set-up (scripts/setup.sh) then the test suite: the fast tests, then the validation runs.
set -euo pipefail
cd "$(dirname "$0")/.."
LRCHAIN_TEST_TOOLS=1 scripts/setup.sh build
ctest --test-dir build -L fast --output-on-failure -j "$(nproc)"
ctest --test-dir build -L validation --output-on-failure
