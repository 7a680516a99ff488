#!/usr/bin/env bash
# The main job: build cairn, then validate the paper's cases on every available backend into
# out/validation/ (summary.csv, report.md, index.html; see docs/validation.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
"${CAIRN_BUILD_DIR:-build}/app/cairn" validate --out out/validation
