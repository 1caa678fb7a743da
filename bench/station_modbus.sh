#!/usr/bin/env bash
# The station's Modbus round trip next to its TCP MARK round trip, in one run (issue 22's
# figures): `marker serve --virtual-time --modbus` on the 20-character serial job of
# bench/prog_station_tcp.cpp ("SN " + 17 digits) with a fresh SQLite store, driven by pymodbus
# (tests/marker/station/modbus_client.py: write the start coil, poll busy until it clears, read
# the registers) for MARKS parts; then build/bench/station_tcp --parts PARTS.
# POLL_MS: the client's pause between polls of busy (a PLC's scan cycle; 0: back to back).
#   bench/station_modbus.sh [MARKS] [PARTS] [POLL_MS]   (defaults 60, 100, 0; needs build/marker/marker, build/bench/station_tcp)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
marks=${1:-60}
parts=${2:-100}
poll_ms=${3:-0}
dir=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; rm -rf "$dir"' EXIT
cat >"$dir/job.json" <<'JOB'
{
  "format": "marker-job/1", "head": "SL10", "time_zone": "UTC",
  "counters": {"serial": {"start": 1, "width": 17}},
  "pens": {"fine": {"speed_mm_s": 2000, "power_pct": 100, "frequency_khz": 40}},
  "objects": [{"name": "serial", "pen": "fine", "template": "SN {serial}", "height_mm": 2, "x_mm": -30, "y_mm": 0}]
}
JOB
STATE_DIRECTORY=$dir "$root/build/marker/marker" serve --job "$dir/job.json" --store "$dir/s.sqlite" --create-counters \
  --virtual-time --listen 127.0.0.1:0 --modbus 127.0.0.1:0 2>"$dir/serve.log" &
pid=$!
for _ in $(seq 100); do
  port=$(sed -n 's/.* modbus on 127\.0\.0\.1:\([0-9]*\)$/\1/p' "$dir/serve.log")
  [[ -n $port ]] && break
  sleep 0.05
done
[[ -n ${port:-} ]] || { cat "$dir/serve.log" >&2; exit 1; }
/usr/bin/python3 "$root/tests/marker/station/modbus_client.py" "$port" "$marks" 127.0.0.1 "$poll_ms" | /usr/bin/python3 -c '
import json, sys
r = json.load(sys.stdin)
serials = [p["serial"] for p in r["parts"]]
assert serials == list(range(1, len(serials) + 1)), serials
print("modbus start coil -> busy clear (pymodbus, %d marks, poll every '"$poll_ms"' ms): median %.3f ms, p99 %.3f ms"
      % (len(serials), r["round_trip_median_s"] * 1e3, r["round_trip_p99_s"] * 1e3))'
kill -TERM "$pid"
wait "$pid"
"$root/build/bench/station_tcp" --parts "$parts"
