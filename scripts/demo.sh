#!/usr/bin/env bash
# The main job: set up, build, run the tutorial scene headless with contactfx's default effects, and
# render it to a video (sparks, smoke and dirt) plus a plot of where each effect starts and stops.
set -euo pipefail
cd "$(dirname "$0")/.."
# Only the command line program is built: the tests, benchmarks, testbed and examples wait for test.sh.
bash scripts/setup.sh build --target contactfx_cli
mkdir -p out
./build/bin/contactfx demo --seconds 20 --stats out/demo-stats.json --plot out/demo-plot.png
echo "statistics: out/demo-stats.json"
echo "tuning plot: out/demo-plot.png"
./build/bin/contactfx render --demo --seconds 20 --out out/demo.mp4
echo "video: out/demo.mp4"
