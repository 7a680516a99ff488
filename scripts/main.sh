#!/usr/bin/env bash
# The main job: build cairn, then run every shipped scene on every available backend into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
"${CAIRN_BUILD_DIR:-build}/app/cairn" run-all --out out/
