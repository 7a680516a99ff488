#!/usr/bin/env bash
# The main job: build cairn, then into out/validation/: the mesh-inertia study (study/), the
# speed-accuracy and stability benches (bench/), and the validation of the paper's cases on every
# available backend, whose report includes the other two (summary.csv, report.md, index.html;
# see docs/validation.md, docs/inertia.md, docs/bench.md). A few minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cairn="${CAIRN_BUILD_DIR:-build}/app/cairn"
"$cairn" study inertia --out out/validation/study --quiet
"$cairn" study contact --out out/validation/contact --quiet
"$cairn" bench all --out out/validation/bench --quiet
"$cairn" validate --out out/validation
