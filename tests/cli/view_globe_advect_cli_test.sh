#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-view moves clouds with the wind on the globe (docs/advection.md): a global
# store with westerlies (scripts/globe_sample_cdl.py --wind, steps 6 hours apart) drawn
# --advect-seconds after its step is not refused, moves its meshes, and the cloud seen
# over 30 W, 45 N (in the westerlies) lies further east, by the wind's distance, than at
# time 0; --advect is not refused either.
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
# An opaque flat Earth (a 2-degree DEM at sea level) hides the far side's clouds, which
# move west on the screen as the near side's move east.
python3 - "$work/dem.cdl" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("netcdf dem {\ndimensions:\n lat = 91 ;\n lon = 181 ;\nvariables:\n")
    f.write(" double lat(lat) ;\n  lat:units = \"degrees_north\" ;\n double lon(lon) ;\n  lon:units = \"degrees_east\" ;\n")
    f.write(" float elevation(lat, lon) ;\n  elevation:units = \"m\" ;\ndata:\n")
    f.write(" lat = %s ;\n lon = %s ;\n" % (", ".join(str(-90 + 2 * j) for j in range(91)),
                                          ", ".join(str(-180 + 2 * i) for i in range(181))))
    f.write(" elevation = %s ;\n}\n" % ", ".join(["0"] * (91 * 181)))
PY
ncgen -o "$work/dem.nc" "$work/dem.cdl" || { echo "FAIL: the DEM"; exit 1; }
echo '{"format_version":1,"time":0,"subvolumes":[{"id":1,"name":"cloud water","limits":[{"var":"clw","min":2e-05}]}],"attributes":[]}' >"$work/scene.json"
echo '{"format_version":1,"time":0,"subvolumes":[{"id":1,"name":"none","limits":[{"var":"clw","min":1}]}],"attributes":[]}' >"$work/bare-scene.json"
# Over 30 W, 45 N from 12,000 km up (600 km of height axis at 20 times), north up: the
# whole disc shows, so no cloud leaves the picture.
echo '{"format_version":1,"keyframes":[{"t":0,"eye":[-30,45,600000],"target":[-30,45,0],"fov_deg":45}]}' >"$work/cam.json"

draw() {  # draw NAME SECONDS [SCENE]
  "$view" "$work/globe" --scene "$work/${3:-scene}.json" --camera "$work/cam.json" --exaggeration 20 \
    --terrain "$work/dem.nc" --offscreen --size 200x150 --threads 2 --advect-seconds "$2" --out "$work/$1.png" --json \
    >"$work/$1.json" 2>"$work/$1.err"
}
# The sun moves with the time shown: each picture's clouds are what differs from the ground
# alone at its time.
if draw still 0 && draw moved 21600 && draw bare 0 bare-scene && draw bare-moved 21600 bare-scene; then
  grep -q " info\] world frame: .*on the WGS84 globe" "$work/moved.err" ||
    fail "not on the globe: $(cat "$work/moved.err")"
  python3 - "$work" <<'PY' && echo "ok: --advect-seconds on the globe" || fail "advection on the globe"
import json, sys
from png_rgba import rgba_rows
work = sys.argv[1]
still, moved = (json.loads(open(f"{work}/{n}.json").readline()) for n in ("still", "moved"))
assert moved["nodes_moved"] > 0, moved
assert moved["advect_trajectories"] > 0, moved
def clouds(name, bare_name):  # the cloud the view centres on: its mean column, size
    _, _, rows = rgba_rows(f"{work}/{name}.png")
    _, _, bare = rgba_rows(f"{work}/{bare_name}.png")
    xs = [x for row, b in zip(rows[30:100], bare[30:100]) for x in range(70, 140)
          if sum(abs(row[4 * x + c] - b[4 * x + c]) for c in range(3)) > 24]
    return sum(xs) / max(len(xs), 1), len(xs)
(c0, n0), (c1, n1) = clouds("still", "bare"), clouds("moved", "bare-moved")
print(f"the central cloud: {n0} pixels at column {c0:.1f} at time 0, {n1} at {c1:.1f} after 6 h")
assert n0 > 200, n0
# About 14 m/s at 47 N, 5 km up, for 6 h: 300 km, 4 degrees of longitude east; seen from
# 12,000 km up through 45 degrees over 200 columns, 3.8 columns right.
assert 2.5 < c1 - c0 < 5.5, (c0, c1)
assert abs(n1 - n0) < 0.1 * n0, (n0, n1)
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
