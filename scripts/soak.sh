#!/usr/bin/env bash
# Soak: runs the grinder scene for one simulated hour, headless, with --events, and checks that
# - memory stays flat: the hour's peak resident set (max RSS) is within 10 % of a one-minute run's;
# - no scrape is lost: every scrape that began has ended, or is still going at the last step (the
#   grinder's wheel never stops, so its scrape is reported on every step up to the end);
# - the events file is well formed: every scrape's id begins once, nothing follows its end.
#
# Usage: bash scripts/soak.sh [--binary build/bin/contactfx] [--seconds 3600] [--short 60] [--tolerance 10]
# Needs a Release build of contactfx (bash scripts/setup.sh build --target contactfx_cli) and GNU time
# (/usr/bin/time, Debian package "time"). About 30 s on the 2-core reference machine; CI runs it after
# the Release tests (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."

binary=build/bin/contactfx
seconds=3600
short=60
tolerance=10 # percent
while [ $# -gt 0 ]; do
  case "$1" in
    --binary) binary="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --short) short="$2"; shift 2 ;;
    --tolerance) tolerance="$2"; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "soak: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ ! -x "$binary" ]; then
  echo "soak: $binary not found: build it first (bash scripts/setup.sh build --target contactfx_cli)" >&2
  exit 2
fi
if [ ! -x /usr/bin/time ]; then
  echo "soak: /usr/bin/time not found: install GNU time (apt-get install time)" >&2
  exit 2
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/contactfx-soak.XXXXXX")
trap 'rm -rf "$work"' EXIT

# run SECONDS: the grinder for SECONDS simulated seconds with --events; sets rss (KB) and wall (s).
run() {
  local s="$1"
  if ! /usr/bin/time -f '%M %e' -o "$work/time-$s" \
      "$binary" run --scene grinder --seconds "$s" --events "$work/events-$s.jsonl" \
      --stats "$work/stats-$s.json" > "$work/out-$s" 2>&1; then
    echo "soak: FAILED: contactfx run --scene grinder --seconds $s exited with an error:" >&2
    cat "$work/out-$s" >&2
    exit 1
  fi
  read -r rss wall < <(tail -n 1 "$work/time-$s")
  local bytes
  bytes=$(stat -c %s "$work/events-$s.jsonl")
  echo "soak: grinder, $s s simulated with --events: max RSS $rss KB, $wall s, $((bytes / 1000)) KB of events"
}

# scrapes FILE STEPS: checks the scrape events of a run of STEPS steps; prints a summary line.
scrapes() {
  # Lines start {"type":"...","step":N,"time":T,"id":N,... (docs/events.md): split at commas.
  awk -F, -v last_step="$(($2 - 1))" -v file="$1" '
    {
      type = $1; sub(/^\{"type":"/, "", type); sub(/"$/, "", type)
      step = $2; sub(/^"step":/, "", step)
      id = $4;   sub(/^"id":/, "", id)
      if (type == "impact") { impacts++; next }
      if (type == "particle_hits") { hits++; next }
      if (type == "scrape_began") {
        if (id in began) { printf "soak: %s:%d: scrape %s began twice\n", file, NR, id; bad++ }
        began[id] = 1; begun++
      } else if (!(id in began)) {
        printf "soak: %s:%d: %s of scrape %s, which never began\n", file, NR, type, id; bad++
      } else if (id in ended) {
        printf "soak: %s:%d: %s of scrape %s after it ended\n", file, NR, type, id; bad++
      }
      if (type == "scrape_ended") { ended[id] = 1; finished++ }
      last[id] = step
    }
    END {
      for (id in began) {
        if (id in ended) continue
        if (last[id] == last_step) { going++; continue }
        printf "soak: scrape %s began and never ended (last reported at step %s of %d)\n", id, last[id], last_step + 1
        lost++
      }
      printf "soak: scrapes: %d began, %d ended, %d still going at the last step, %d lost; %d impacts, %d particle hit groups\n",
        begun, finished, going, lost, impacts, hits
      exit (bad + lost > 0)
    }' "$1"
}

run "$short"
short_rss=$rss
scrapes "$work/events-$short.jsonl" "$(grep -o '"steps": [0-9]*' "$work/stats-$short.json" | grep -o '[0-9]*$')"
run "$seconds"
long_rss=$rss
status=0
scrapes "$work/events-$seconds.jsonl" "$(grep -o '"steps": [0-9]*' "$work/stats-$seconds.json" | grep -o '[0-9]*$')" ||
  status=1
if [ $((long_rss * 100)) -gt $((short_rss * (100 + tolerance))) ]; then
  echo "soak: FAILED: memory grows: max RSS $long_rss KB after $seconds s against $short_rss KB after $short s" \
    "(more than $tolerance % more)" >&2
  status=1
else
  echo "soak: memory flat: $long_rss KB after $seconds s, $short_rss KB after $short s" \
    "($(( (long_rss - short_rss) * 1000 / short_rss )) per mille, at most $((tolerance * 10)))"
fi
if [ "$status" -ne 0 ]; then
  echo "soak: FAILED" >&2
  exit 1
fi
echo "soak: ok"
