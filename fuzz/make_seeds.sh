#!/usr/bin/env bash
# Seed corpus of the scene-loader fuzzer: every scene of scenarios/ as part 1, a few overrides as
# part 2 and the head of the El Centro record as part 3 (the earthquake scene points at it).
# Comment lines and blank lines are left out: short seeds keep the fuzzer fast.
# usage: fuzz/make_seeds.sh OUT_DIR
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?usage: make_seeds.sh OUT_DIR}"
mkdir -p "$out"
csv="$(grep -v '^#' "$here/scenarios/data/elcentro_1940_ns.csv" | head -n 12)"
n=0
while IFS= read -r -d '' scene; do
  n=$((n + 1))
  name="$(basename "${scene%.toml}")"
  body="$(grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' "$scene" |
          sed 's|^file = ".*elcentro_1940_ns.csv"|file = "g.csv"|')"
  printf '%s\n' "$body" > "$out/$name"
  printf '%s\n%%%%\nrun.duration=0.1\ncontact.friction=0.5\n%%%%\n%s\n' "$body" "$csv" > "$out/${name}_set"
done < <(find "$here/scenarios" -name '*.toml' -print0 | sort -z)
echo "make_seeds: $((2 * n)) seeds in $out"
