#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-view: bad flags and files give one line on stderr with the documented exit
# status; --offscreen renders a store (one camera and a camera path) to PNG files, and
# meshes moved with the wind (--advect-seconds) and flight tracks (--tracks); the
# window runs a few frames under Xvfb and saves a screenshot (skipped without xvfb-run).
# Usage: view_cli_test.sh STRIELAD_CONVERT WORK_DIR (strielad-view is found next to
# strielad-convert in the build tree).
set -uo pipefail
convert=$1
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
work=$2
view="$(dirname "$convert")/../strielad-view/strielad-view"
rm -rf "$work" && mkdir -p "$work"

# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
# png_rgba.py, for the Python blocks that look at pixels.
export PYTHONPATH="$(cd "$(dirname "$0")/../support" && pwd)${PYTHONPATH:+:$PYTHONPATH}"
# expect STATUS "SUBSTRING" -- ARGS...
expect() { expect_cli_error "$view" "$work" "$@"; }
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
is_png() { [[ -s "$1" ]] && [[ "$(head -c 4 "$1" | od -An -c | tr -d ' ')" == "211PNG" ]]; }

"$sample" -o "$work/data" --dims 40x36x12 --steps 2 --vars clw,cli,qr,ta,ua,va,wa -q
"$convert" "$work"/data/*.nc -o "$work/store" --brick 8 -q
echo '{"subvolumes": [{"id": 1, "limits": [{"var": "nope", "min": 1e-6}]}]}' > "$work/unknown-var.json"
printf 'vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n' > "$work/bad.glsl"
printf '           vec3 position, vec3 view, float time) {\n  return vec4(1.0) +;\n}\n' >> "$work/bad.glsl"
printf 'float alpha(int id, float distance) { return 0.5; }\n' >> "$work/bad.glsl"
echo '{"keyframes": [{"t": 0, "eye": [0, 0, 0], "target": [0, 0, 0]}]}' > "$work/bad-camera.json"

expect 2 "exactly one of STORE or --connect" -- --offscreen --out "$work/x.png"
expect 2 "--no-such-flag" -- "$work/store" --no-such-flag  # CLI11's errors: status 2 too
expect 2 "--offscreen needs --out" -- "$work/store" --offscreen
expect 3 "no such store directory" -- "$work/no-such-store" --offscreen --out "$work/x.png"
expect 3 "nope" -- "$work/store" --scene "$work/unknown-var.json" --offscreen --out "$work/x.png"
expect 2 "--size" -- "$work/store" --size big --offscreen --out "$work/x.png"
expect 4 "bad.glsl:3" -- "$work/store" --shader "$work/bad.glsl" --offscreen --out "$work/x.png"
expect 3 "no-shader.glsl" -- "$work/store" --shader "$work/no-shader.glsl" --offscreen --out "$work/x.png"
expect 4 "bad-camera.json" -- "$work/store" --camera "$work/bad-camera.json" --offscreen --out "$work/x.png"
expect 3 "time step 7" -- "$work/store" --time 7 --offscreen --out "$work/x.png"
expect 2 "--look scalar needs --color-by" -- "$work/store" --look scalar --offscreen --out "$work/x.png"
expect 2 "give one" -- "$work/store" --look scalar --color-by ta --shader "$work/bad.glsl" --offscreen --out "$work/x.png"
expect 2 "--color-range 5,1" -- "$work/store" --look scalar --color-by ta --color-range 5,1 --offscreen --out "$work/x.png"
expect 2 "--colormap jet" -- "$work/store" --look scalar --color-by ta --colormap jet --offscreen --out "$work/x.png"
expect 3 "--color-by ua,nope: variable 'nope'" -- "$work/store" --look scalar --color-by ua,nope --offscreen --out "$work/x.png"

# The scalar look: surfaces coloured by wind speed, and a colour bar in the lower right
# corner: viridis' yellow end and white text there, neither in the default clouds'
# picture.
for look in clouds scalar; do
  if ! "$view" "$work/store" --offscreen --size 320x180 --threads 2 --look "$look" \
      --color-by ua,va --color-range 0,30 --out "$work/look-$look.png" 2>"$work/look.err"; then
    fail "--look $look"; cat "$work/look.err"
  fi
done
python3 - "$work/look-clouds.png" "$work/look-scalar.png" <<'PY' && echo "ok: --look scalar draws a legend" || fail "--look scalar legend"
import sys
from png_rgba import rgba_rows
def corner_has(path, test):
    w, h, rows = rgba_rows(path)
    return any(test(rows[y][4 * x:4 * x + 3]) for y in range(h // 2, h) for x in range(w // 2, w))
yellow = lambda p: abs(p[0] - 253) < 12 and abs(p[1] - 231) < 12 and p[2] < 60
white = lambda p: min(p) == 255
clouds, scalar = sys.argv[1], sys.argv[2]
assert corner_has(scalar, yellow), "no viridis yellow in the scalar picture's corner"
assert corner_has(scalar, white), "no legend text"
assert not corner_has(clouds, yellow), "yellow in the clouds' corner"
PY

# One image of the home view, with statistics; without --scene the log says what the
# viewer chose: the scene (canonical JSON), the exaggeration (10 for the sample's
# domain, the paper's) and the sun.
if "$view" "$work/store" --offscreen --size 160x90 --threads 2 --out "$work/home.png" --json \
    >"$work/home.json" 2>"$work/home.err"; then
  is_png "$work/home.png" || fail "home.png is not a PNG image"
  grep -q '"nodes_with_mesh":[1-9]' "$work/home.json" || fail "no meshes: $(cat "$work/home.json")"
  grep -q '"vertical_exaggeration":10[,.]' "$work/home.json" || fail "exaggeration: $(cat "$work/home.json")"
  grep -q ' info\] default scene (no --scene): {"format_version":1,"time":0,"subvolumes":\[{"id":1,"name":"cloud water",' \
    "$work/home.err" || fail "default scene not logged: $(cat "$work/home.err")"
  grep -q ' info\] vertical exaggeration 10 for a 700 x 778 km domain' "$work/home.err" ||
    fail "exaggeration rule not logged"
  grep -q ' info\] sun: the true sun over the domain centre' "$work/home.err" || fail "sun rule not logged"
  echo "ok: offscreen home view, default choices logged"
else
  fail "offscreen home view"; cat "$work/home.err"
fi

# A global 2.5-degree-like grid (0 to 345 E, 90 N to 90 S, 1000 to 10 hPa) at 12 UTC,
# when the domain centre (172.5 E) has night: the exaggeration follows the domain (200,
# not 10) and the sun is the one over the sub-solar point, which the domain holds.
if command -v ncgen >/dev/null; then
  python3 - "$work/global.cdl" <<'PY'
import math, sys
lons = [15.0 * i for i in range(24)]
lats = [90.0 - 15.0 * j for j in range(13)]
plev = [100000, 85000, 50000, 20000, 5000, 1000]
clw = [max(0.0, 2e-4 * math.exp(-((lat - 8) / 20) ** 2) * math.cos(math.radians(3 * lon)) *
           math.exp(-((k - 1.5) / 1.5) ** 2)) for k in range(len(plev)) for lat in lats for lon in lons]
with open(sys.argv[1], "w") as f:
    f.write("netcdf global {\ndimensions:\n time = 1 ;\n plev = 6 ;\n lat = 13 ;\n lon = 24 ;\n")
    f.write("variables:\n double time(time) ;\n  time:units = \"hours since 2024-06-21 00:00:00\" ;\n")
    f.write(" double plev(plev) ;\n  plev:units = \"Pa\" ;\n  plev:standard_name = \"air_pressure\" ;\n")
    f.write(" double lat(lat) ;\n  lat:units = \"degrees_north\" ;\n")
    f.write(" double lon(lon) ;\n  lon:units = \"degrees_east\" ;\n")
    f.write(" float clw(time, plev, lat, lon) ;\n  clw:units = \"kg kg-1\" ;\ndata:\n time = 12 ;\n")
    f.write(" plev = %s ;\n lat = %s ;\n lon = %s ;\n" % (", ".join(map(str, plev)),
            ", ".join(map(str, lats)), ", ".join(map(str, lons))))
    f.write(" clw = %s ;\n}\n" % ", ".join("%.6g" % v for v in clw))
PY
  ncgen -o "$work/global.nc" "$work/global.cdl" &&
    "$convert" "$work/global.nc" -o "$work/global-store" --brick 8 -q 2>"$work/global-convert.err" ||
    fail "global store: $(cat "$work/global-convert.err")"
  # On the plane (--shape plane) as before the globe.
  if "$view" "$work/global-store" --shape plane --offscreen --size 160x90 --threads 2 \
      --out "$work/global.png" --json >"$work/global.json" 2>"$work/global.err"; then
    python3 - "$work/global.json" <<'PY' || fail "global: $(cat "$work/global.json")"
import json, sys
d = json.loads(open(sys.argv[1]).readline())
assert d["vertical_exaggeration"] == 200, d["vertical_exaggeration"]
assert d["sun_viewpoint"] == "sunniest point", d["sun_viewpoint"]
assert d["sun_elevation_deg"] > 89, d["sun_elevation_deg"]
assert abs(d["sun_seen_from"][0] - 23.44) < 0.1, d["sun_seen_from"]
PY
    grep -q " info\] sun: the sun over the domain's sunniest point (23.44 N" "$work/global.err" ||
      fail "global sun rule not logged: $(cat "$work/global.err")"
    echo "ok: a global grid gets its own exaggeration and the day side's sun"
  else
    fail "global grid"; cat "$work/global.err"
  fi
  # By default on the globe: the exaggeration capped at 20, the home view over the
  # sub-solar point (the image's centre drawn, its corners the background).
  if "$view" "$work/global-store" --offscreen --size 160x90 --threads 2 \
      --out "$work/globe.png" --json >"$work/globe.json" 2>"$work/globe.err"; then
    python3 - "$work/globe.json" <<'PY' || fail "globe: $(cat "$work/globe.json")"
import json, sys
d = json.loads(open(sys.argv[1]).readline())
assert d["vertical_exaggeration"] == 20, d["vertical_exaggeration"]
assert d["sun_elevation_deg"] > 89, d["sun_elevation_deg"]
PY
    grep -q " info\] world frame: .*on the WGS84 globe" "$work/globe.err" ||
      fail "globe not logged: $(cat "$work/globe.err")"
    grep -q " info\] vertical exaggeration 20 on the globe" "$work/globe.err" ||
      fail "globe exaggeration not logged: $(cat "$work/globe.err")"
    echo "ok: a global grid opens on the globe"
  else
    fail "globe"; cat "$work/globe.err"
  fi
  # Flight tracks on the globe: a leg from 30 W (11 UTC) to 30 E (13 UTC), both at
  # 23.4 N, its last hour drawn at 12 UTC: from 30 W along the great circle, which bows
  # north to 26.6 N at 0 E, where the aircraft is at 12 UTC. The home view looks down on
  # the sub-solar point (0.5 E, 23.4 N): the track lies left of the centre, on the rows
  # just above it. Where clouds lie in front of it, the colour is veiled.
  printf 'id,time,lon,lat,altitude\nG1,2024-06-21T11:00:00Z,-30,23.4,11000\nG1,2024-06-21T13:00:00Z,30,23.4,11000\n' \
    >"$work/globe-tracks.csv"
  if "$view" "$work/global-store" --offscreen --size 160x90 --threads 2 --tracks "$work/globe-tracks.csv" \
      --track-minutes 60 --out "$work/globe-tracks.png" --json >"$work/globe-tracks.json" \
      2>"$work/globe-tracks.err"; then
    python3 - "$work/globe-tracks.json" "$work/globe-tracks.png" "$work/globe.png" <<'PY' \
      && echo "ok: --tracks on the globe" || fail "--tracks on the globe: $(cat "$work/globe-tracks.json")"
import json, sys
from png_rgba import rgba_rows
d = json.loads(open(sys.argv[1]).readline())
assert d["tracks_shown"] == 1 and d["track_segments"] >= 50, d  # 27.5 degrees of arc
track = lambda p: p[0] > 150 and 80 < p[1] < 170 and p[2] < 60
def track_pixels(path):
    w, h, rows = rgba_rows(path)
    return w, h, [(x, y) for y in range(h) for x in range(w) if track(rows[y][4 * x:4 * x + 3])]
w, h, on = track_pixels(sys.argv[2])
assert len(on) >= 6, len(on)
assert not track_pixels(sys.argv[3])[2], "track colour without tracks"
xs, ys = [x for x, _ in on], [y for _, y in on]
assert max(xs) <= w // 2 + 2 and min(xs) < w // 2 - 10, (min(xs), max(xs))
assert all(h // 2 - 6 <= y <= h // 2 for y in ys), (min(ys), max(ys))
PY
  else
    fail "--tracks on the globe"; cat "$work/globe-tracks.err"
  fi
else
  echo "skip: global grid (no ncgen)"
fi

# A camera path: 0.2 s at 10 fps = 3 numbered frames.
cat > "$work/path.json" <<'JSON'
{"keyframes": [{"t": 0, "eye": [5.0, 54.0, 30000], "target": [5.5, 55.0, 2000]},
               {"t": 0.2, "eye": [5.2, 54.3, 20000], "target": [5.5, 55.0, 2000]}]}
JSON
if "$view" "$work/store" --offscreen --size 96x64 --threads 2 --camera "$work/path.json" --fps 10 \
    --out "$work/frames/f{:03}.png" -q 2>"$work/path.err"; then
  for f in 000 001 002; do is_png "$work/frames/f$f.png" || fail "frame $f missing"; done
  [[ ! -e "$work/frames/f003.png" ]] || fail "a frame beyond the path's end"
  echo "ok: camera path frames"
else
  fail "camera path"; cat "$work/path.err"
fi

# Wind advection: the meshes of step 0 moved 300 s (to step 1's time) differ from the
# unmoved ones; bad uses are refused with one line.
expect 2 "--advect-seconds is for --offscreen" -- "$work/store" --advect-seconds 60
expect 3 "omega" -- "$work/store" --wind ua,va,omega --advect-seconds 60 --offscreen --out "$work/x.png"
expect 2 "no next step" -- "$work/store" --time 1 --advect-seconds 60 --offscreen --out "$work/x.png"
expect 2 "U,V,W" -- "$work/store" --wind ua,va --advect-seconds 60 --offscreen --out "$work/x.png"
expect 2 "integrator" -- "$work/store" --integrator rk45 --advect-seconds 60 --offscreen --out "$work/x.png"
if "$view" "$work/store" --offscreen --size 160x90 --threads 2 --advect-seconds 300 \
    --integrator rosenbrock --advect-rtol 1e-5 --out "$work/moved.png" --json >"$work/moved.json" 2>"$work/moved.err"; then
  is_png "$work/moved.png" || fail "moved.png is not a PNG image"
  grep -q '"nodes_moved":[1-9]' "$work/moved.json" || fail "nothing moved: $(cat "$work/moved.json")"
  ! cmp -s "$work/moved.png" "$work/home.png" || fail "the moved picture is the unmoved one"
  echo "ok: --advect-seconds"
else
  fail "--advect-seconds"; cat "$work/moved.err"
fi

# Flight tracks: drawn (the last 2 minutes before the step's time), bad files refused.
cat > "$work/tracks.csv" <<'CSV'
id,time,lon,lat,altitude
A1,2013-04-26T11:58:00Z,5.0,48.0,10000
A1,2013-04-26T11:59:00Z,6.0,49.0,10500
A1,2013-04-26T12:01:00Z,8.0,51.0,11000
B2,2013-04-26T11:59:30Z,14.0,54.0,9000
B2,2013-04-26T12:00:30Z,12.0,53.0,9500
C3,2013-04-26T13:00:00Z,9.0,50.0,9000
C3,2013-04-26T13:01:00Z,9.5,50.5,9000
CSV
printf 'id,time,lon,lat\nA,2013-04-26T12:00:00Z,5,48\n' > "$work/bad-tracks.csv"
expect 4 "bad-tracks.csv:1" -- "$work/store" --tracks "$work/bad-tracks.csv" --offscreen --out "$work/x.png"
expect 3 "no-tracks.csv" -- "$work/store" --tracks "$work/no-tracks.csv" --offscreen --out "$work/x.png"
if "$view" "$work/store" --offscreen --size 160x90 --threads 2 --tracks "$work/tracks.csv" \
    --out "$work/tracks.png" --json >"$work/tracks.json" 2>"$work/tracks.err"; then
  grep -q '"tracks_shown":2' "$work/tracks.json" || fail "tracks: $(cat "$work/tracks.json")"
  ! cmp -s "$work/tracks.png" "$work/home.png" || fail "the tracks are not in the picture"
  echo "ok: --tracks"
else
  fail "--tracks"; cat "$work/tracks.err"
fi

# Through a running strielad-serve (--connect, with a token).
serve="$(dirname "$convert")/../strielad-serve/strielad-serve"
mkdir -p "$work/root" && cp -r "$work/store" "$work/root/sample"  # (symbolic links out of the root are refused)
umask 077 && echo "s3cret" > "$work/token" && umask 022
"$serve" --root "$work/root" --listen 127.0.0.1:0 --token-file "$work/token" --threads 2 --json -q \
  >"$work/endpoint" 2>"$work/serve.err" &
serve_pid=$!
for _ in $(seq 100); do [[ -s "$work/endpoint" ]] && break; sleep 0.1; done
port=$(sed -n 's/.*"port": *\([0-9]*\).*/\1/p' "$work/endpoint")
if [[ -n "$port" ]]; then
  if "$view" --connect "127.0.0.1:$port" --dataset sample --token-file "$work/token" --offscreen \
      --size 160x90 --out "$work/remote.png" --json >"$work/remote.json" 2>"$work/remote.err"; then
    is_png "$work/remote.png" || fail "remote.png is not a PNG image"
    grep -q '"nodes_with_mesh":[1-9]' "$work/remote.json" || fail "remote: no meshes"
    # The same view in-process and through the server is the same picture.
    cmp -s "$work/remote.png" "$work/home.png" || fail "remote and in-process pictures differ"
    echo "ok: --connect"
  else
    fail "--connect"; cat "$work/remote.err"
  fi
  expect 3 "no-such-dataset" -- --connect "127.0.0.1:$port" --dataset no-such-dataset \
    --token-file "$work/token" --offscreen --out "$work/x.png"
  expect 2 "--connect needs --dataset" -- --connect "127.0.0.1:$port" --offscreen --out "$work/x.png"
else
  fail "strielad-serve did not start: $(cat "$work/serve.err")"
fi
kill -TERM "$serve_pid" 2>/dev/null; wait "$serve_pid" 2>/dev/null

# A scene of format version 2 carries slices, the terrain, a fixed sun and flight tracks
# (paths relative to the scene file): one command renders all of it.
"$sample" -o "$work/geo" --dims 8x8x4 --steps 1 --vars ta --terrain 64 -q
mkdir -p "$work/scenes"
cat > "$work/scenes/figure.json" <<'JSON'
{"format_version": 2,
 "subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 1e-5}]}],
 "slices": [{"id": 1, "axis": "lat", "value": 51.0, "var": "ta", "colormap": "coolwarm"},
            {"id": 2, "axis": "height", "value": 3000.0, "var": "ua", "range": [-10.0, 10.0]}],
 "terrain": {"dem": "../geo/sample_terrain.nc"},
 "sun": {"elevation": 30.0, "azimuth": 135.0},
 "trajectories": {"file": "../tracks.csv", "minutes": 2}}
JSON
if "$view" "$work/store" --offscreen --size 160x90 --threads 2 --scene "$work/scenes/figure.json" \
    --out "$work/figure.png" --json >"$work/figure.json" 2>"$work/figure.err"; then
  python3 - "$work/figure.json" <<'PY' || fail "figure: $(cat "$work/figure.json")"
import json, sys
d = json.loads(open(sys.argv[1]).readline())
assert d["slice_triangles"] > 0, "no slice triangles"
assert [s["id"] for s in d["slices"]] == [1, 2], d["slices"]
assert d["slices"][1]["range"] == [-10.0, 10.0], d["slices"][1]
assert d["slices"][0]["range"][0] < d["slices"][0]["range"][1], d["slices"][0]
assert d["terrain_tiles"] > 0 and d["terrain_triangles"] > 0, "no terrain"
assert d["tracks_shown"] == 2, d["tracks_shown"]
assert d["sun_elevation_deg"] is None  # fixed by the scene, not the time
PY
  echo "ok: a version-2 scene with slices, terrain, sun and tracks"
else
  fail "figure scene"; cat "$work/figure.err"
fi
echo '{"format_version": 2, "subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 1e-5}]}],
       "terrain": {"dem": "missing-dem.nc"}}' > "$work/scenes/missing.json"
expect 3 "missing-dem.nc" -- "$work/store" --scene "$work/scenes/missing.json" --offscreen --out "$work/x.png"

# Placement by the grid (issue 27): a Cartesian grid (x, y in metres, no grid_mapping)
# refuses terrain and an explicit true sun with one line naming its axes, and falls back
# to the fixed light with a warning by default; a rotated-pole grid is placed through
# its grid mapping, with the terrain on the same pole.
hsurf=/usr/share/ncarg/data/nug/HSURF_regional_model_0.11deg.nc
if command -v ncgen >/dev/null; then
  python3 - "$work/cartesian.cdl" "$work/rotated.cdl" <<'PY'
import math, sys
def cdl(path, xname, yname, xunits, yvals, xvals, extra_x, extra_y, mapping):
    zs = [0, 1000, 2000, 3000]
    with open(path, "w") as o:
        o.write("netcdf g {\ndimensions:\n %s = %d ;\n %s = %d ;\n height = 4 ;\n time = 1 ;\n"
                % (xname, len(xvals), yname, len(yvals)))
        o.write("variables:\n double %s(%s) ; %s:units = \"%s\" ; %s\n" % (xname, xname, xname, xunits, extra_x))
        o.write(" double %s(%s) ; %s:units = \"%s\" ; %s\n" % (yname, yname, yname, xunits, extra_y))
        o.write(' double height(height) ; height:units = "m" ; height:positive = "up" ; height:standard_name = "height" ;\n')
        o.write(' double time(time) ; time:units = "hours since 2006-01-16 12:00:00" ;\n')
        o.write(' float ta(time, height, %s, %s) ; ta:units = "K" ;%s\n' % (yname, xname, mapping[0]))
        o.write(mapping[1] + "data:\n")
        o.write(" %s = %s ;\n %s = %s ;\n height = 0, 1000, 2000, 3000 ;\n time = 0 ;\n"
                % (xname, ", ".join(map(str, xvals)), yname, ", ".join(map(str, yvals))))
        ta = [260 + 2 * math.hypot(i - len(xvals) / 2, j - len(yvals) / 2) + 0.003 * z
              for z in zs for j in range(len(yvals)) for i in range(len(xvals))]
        o.write(" ta = " + ", ".join("%.2f" % v for v in ta) + " ;\n}\n")
cdl(sys.argv[1], "x", "y", "m", [2000.0 * j for j in range(12)], [2000.0 * i for i in range(12)],
    'x:standard_name = "projection_x_coordinate" ;', 'y:standard_name = "projection_y_coordinate" ;', ("", ""))
cdl(sys.argv[2], "rlon", "rlat", "degrees", [-6.0 + 0.25 * j for j in range(17)],
    [-8.0 + 0.25 * i for i in range(21)],
    'rlon:standard_name = "grid_longitude" ;', 'rlat:standard_name = "grid_latitude" ;',
    (' ta:grid_mapping = "rotated_pole" ;',
     ' char rotated_pole ; rotated_pole:grid_mapping_name = "rotated_latitude_longitude" ;'
     ' rotated_pole:grid_north_pole_latitude = 39.25 ; rotated_pole:grid_north_pole_longitude = -162. ;\n'))
PY
  ncgen -o "$work/cartesian.nc" "$work/cartesian.cdl" && ncgen -o "$work/rotated.nc" "$work/rotated.cdl" &&
    "$convert" "$work/cartesian.nc" -o "$work/cartesian" --brick 4 -q &&
    "$convert" "$work/rotated.nc" -o "$work/rotated" --brick 4 -q || fail "placement stores"
  if [[ -f "$hsurf" ]]; then
    expect 5 "--terrain $hsurf: terrain cannot be placed: axes 'x' (m) and 'y' (m) are Cartesian" \
      -- "$work/cartesian" --terrain "$hsurf" --offscreen --out "$work/x.png"
  fi
  expect 5 "--sun time: the true sun cannot be placed: axes 'x' (m) and 'y' (m)" \
    -- "$work/cartesian" --sun time --offscreen --out "$work/x.png"
  if "$view" "$work/cartesian" --offscreen --size 96x64 --threads 2 --out "$work/cartesian.png" \
      2>"$work/cartesian.err"; then
    grep -q ' warning\] the true sun cannot be placed (axes .x. (m) and .y. (m)' "$work/cartesian.err" ||
      fail "no warning for the default sun on a Cartesian grid: $(cat "$work/cartesian.err")"
    echo "ok: a Cartesian grid refuses terrain and the true sun"
  else
    fail "Cartesian grid"; cat "$work/cartesian.err"
  fi
  rotated_args=("$work/rotated" --offscreen --size 96x64 --threads 2 --out "$work/rotated.png" --json)
  [[ -f "$hsurf" ]] && rotated_args+=(--terrain "$hsurf")
  if "$view" "${rotated_args[@]}" >"$work/rotated.json" 2>"$work/rotated.err"; then
    is_png "$work/rotated.png" || fail "rotated.png is not a PNG image"
    grep -q "world frame: axes 'rlon' and 'rlat' placed by grid mapping 'rotated_pole'" "$work/rotated.err" ||
      fail "rotated placement not logged: $(cat "$work/rotated.err")"
    grep -q '"vertical_placement":"height axis' "$work/rotated.json" ||
      fail "vertical placement: $(cat "$work/rotated.json")"
    if [[ -f "$hsurf" ]]; then
      grep -q '"terrain_tiles":[1-9]' "$work/rotated.json" || fail "no terrain: $(cat "$work/rotated.json")"
    fi
    echo "ok: a rotated-pole grid placed by its grid mapping"
  else
    fail "rotated-pole grid"; cat "$work/rotated.err"
  fi
else
  echo "skip: placement by the grid (no ncgen)"
fi

# The window: a few frames under Xvfb, then a screenshot.
if command -v xvfb-run >/dev/null; then
  if xvfb-run -a -s "-screen 0 800x600x24" "$view" "$work/store" --size 640x400 --threads 2 \
      --frames 5 --screenshot "$work/window.png" -q 2>"$work/window.err"; then
    is_png "$work/window.png" || fail "no window screenshot"
    echo "ok: window under Xvfb"
  else
    fail "window under Xvfb"; cat "$work/window.err"
  fi
else
  echo "skip: window (no xvfb-run)"
fi

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
rm -rf "$work"
