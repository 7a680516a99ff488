#!/usr/bin/env bash
# Build cairn in Release (installing missing Debian packages) and run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir "${CAIRN_BUILD_DIR:-build}" --output-on-failure -j2
