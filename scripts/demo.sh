#!/usr/bin/env bash
# The main job: set up, build, and run the tutorial scene headless with contactfx's default effects.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build
mkdir -p out
./build/bin/contactfx demo --seconds 20 --stats out/demo-stats.json
echo "statistics: out/demo-stats.json"
