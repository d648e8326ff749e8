#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-view moves clouds with the wind on the globe (docs/advection.md): a global
# store with westerlies (scripts/globe_sample_cdl.py --wind, steps 6 hours apart) drawn
# --advect-seconds after its step is not refused, moves its meshes, and its clouds seen
# over the storm track at 45 N lie further east than at time 0; at time 0 nothing moves.
# Usage: view_globe_advect_cli_test.sh STRIELAD_CONVERT WORK_DIR (skipped without ncgen).
set -uo pipefail
convert=$1
work=$2
view="$(dirname "$convert")/../strielad-view/strielad-view"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
export PYTHONPATH="$here/../support${PYTHONPATH:+:$PYTHONPATH}"
command -v ncgen >/dev/null || { echo "skip: no ncgen"; exit 77; }
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

python3 "$here/../../scripts/globe_sample_cdl.py" --wind --grid 48x25x8 >"$work/globe.cdl" &&
  ncgen -k nc4 -o "$work/globe.nc" "$work/globe.cdl" &&
  "$convert" "$work/globe.nc" -o "$work/globe" --brick 8 -q ||
  { echo "FAIL: the global store"; exit 1; }
echo '{"format_version":1,"time":0,"subvolumes":[{"id":1,"name":"cloud water","limits":[{"var":"clw","min":2e-05}]}],"attributes":[]}' >"$work/scene.json"
# Over 30 W, 45 N from 4,000 km up (200 km of height axis at 20 times), north up.
echo '{"format_version":1,"keyframes":[{"t":0,"eye":[-30,45,200000],"target":[-30,45,0],"fov_deg":45}]}' >"$work/cam.json"

draw() {  # draw NAME SECONDS
  "$view" "$work/globe" --scene "$work/scene.json" --camera "$work/cam.json" --exaggeration 20 \
    --offscreen --size 200x150 --threads 2 --advect-seconds "$2" --out "$work/$1.png" --json \
    >"$work/$1.json" 2>"$work/$1.err"
}
if draw still 0 && draw moved 21600; then
  grep -q " info\] world frame: .*on the WGS84 globe" "$work/moved.err" ||
    fail "not on the globe: $(cat "$work/moved.err")"
  python3 - "$work" <<'PY' && echo "ok: --advect-seconds on the globe" || fail "advection on the globe"
import json, sys
from png_rgba import rgba_rows
work = sys.argv[1]
still, moved = (json.loads(open(f"{work}/{n}.json").readline()) for n in ("still", "moved"))
assert moved["nodes_moved"] > 0, moved
assert moved["advect_trajectories"] > 0, moved
def clouds(name):  # mean column and count of the bright (cloud) pixels
    w, h, rows = rgba_rows(f"{work}/{name}.png")
    xs = [x for row in rows for x in range(w) if row[4 * x] + row[4 * x + 1] + row[4 * x + 2] > 300]
    return sum(xs) / max(len(xs), 1), len(xs)
(c0, n0), (c1, n1) = clouds("still"), clouds("moved")
print(f"cloud pixels {n0} at column {c0:.1f} at time 0, {n1} at column {c1:.1f} after 6 h")
assert n0 > 200, n0
# 30 m/s at 45 N for 6 h: 650 km, about 9 degrees of longitude; seen from 4,000 km up
# through 45 degrees over 200 columns, about 15 columns.
assert c1 - c0 > 5, (c0, c1)
assert abs(n1 - n0) < 0.3 * n0, (n0, n1)
PY
  cmp -s "$work/still.png" "$work/moved.png" && fail "the moved picture is the unmoved one"
else
  fail "--advect-seconds on the globe"; cat "$work/still.err" "$work/moved.err"
fi

# The window's --advect is not refused on the globe (offscreen: the same session opens it).
if "$view" "$work/globe" --scene "$work/scene.json" --advect --offscreen --size 64x48 --threads 2 \
    --out "$work/advect.png" 2>"$work/advect.err"; then
  echo "ok: --advect on the globe"
else
  fail "--advect on the globe: $(cat "$work/advect.err")"
fi

[[ $failures -eq 0 ]] || { echo "$failures failure(s)"; exit 1; }
echo "all passed"
