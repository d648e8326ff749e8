#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-view --offscreen on a terrain-following store: the ICON-like sample converted
# to store format 5 renders end to end, placed by its geometry field (the log says so),
# with the model's surface as the default terrain, on the plane and on the globe (--shape
# globe); a scene of cold air and cloud water.
# Through --connect (strielad-serve) it is refused for now.
# Usage: view_terrain_following_cli_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
work=$2
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
view="$(dirname "$convert")/../strielad-view/strielad-view"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
is_png() { [[ -s "$1" ]] && [[ "$(head -c 4 "$1" | od -An -c | tr -d ' ')" == "211PNG" ]]; }

"$sample" -o "$work/in" --model icon --dims 48x40x16 --steps 1 --single-file -q || exit 1
"$convert" "$work/in/icon.nc" -o "$work/store" --brick 8 -q || exit 1
cat > "$work/scene.json" <<'JSON'
{"subvolumes": [{"id": 1, "name": "cold air", "limits": [{"var": "temp", "max": 278.4}]},
                {"id": 2, "name": "cloud water", "limits": [{"var": "qc", "min": 1e-5}]}],
 "attributes": ["temp", "qc"]}
JSON
if "$view" "$work/store" --scene "$work/scene.json" --offscreen --size 480x270 --threads 2 \
    --out "$work/icon.png" --json >"$work/icon.json" 2>"$work/icon.err"; then
  is_png "$work/icon.png" || fail "icon.png is not a PNG image"
  json=$(cat "$work/icon.json")
  grep -q '"nodes_with_mesh":[1-9]' "$work/icon.json" || fail "no meshes: $json"
  grep -q '"terrain_triangles":[1-9]' "$work/icon.json" || fail "no terrain: $json"
  grep -q "vertical placement: terrain-following: vertices at geometry field 'geometry_height'" \
    "$work/icon.err" || fail "placement not logged: $(cat "$work/icon.err")"
  grep -q "terrain: .*the model's surface" "$work/icon.err" || fail "model surface not logged"
  echo "ok: offscreen view of a terrain-following store"
else
  fail "offscreen view of a terrain-following store"; cat "$work/icon.err"
fi

# On the globe the model's surface is the default terrain too.
if "$view" "$work/store" --scene "$work/scene.json" --shape globe --offscreen --size 480x270 \
    --threads 2 --out "$work/icon-globe.png" --json >"$work/icon-globe.json" 2>"$work/icon-globe.err"; then
  json=$(cat "$work/icon-globe.json")
  grep -q '"nodes_with_mesh":[1-9]' "$work/icon-globe.json" || fail "globe: no meshes: $json"
  grep -q '"terrain_triangles":[1-9]' "$work/icon-globe.json" || fail "globe: no terrain: $json"
  grep -q " info\] world frame: .*on the WGS84 globe" "$work/icon-globe.err" ||
    fail "globe not logged: $(cat "$work/icon-globe.err")"
  grep -q "terrain: .*the model's surface" "$work/icon-globe.err" || fail "globe: model surface not logged"
  echo "ok: the model's surface on the globe"
else
  fail "offscreen view of a terrain-following store on the globe"; cat "$work/icon-globe.err"
fi

# Through --connect the store is refused for now, naming the dataset (exit status 5).
serve="$(dirname "$convert")/../strielad-serve/strielad-serve"
mkdir -p "$work/root" && cp -r "$work/store" "$work/root/icon"
umask 077 && echo "s3cret" > "$work/token" && umask 022
"$serve" --root "$work/root" --listen 127.0.0.1:0 --token-file "$work/token" --threads 2 --json -q \
  >"$work/endpoint" 2>"$work/serve.err" &
serve_pid=$!
for _ in $(seq 100); do [[ -s "$work/endpoint" ]] && break; sleep 0.1; done
port=$(sed -n 's/.*"port": *\([0-9]*\).*/\1/p' "$work/endpoint")
if [[ -n "$port" ]]; then
  "$view" --connect "127.0.0.1:$port" --dataset icon --token-file "$work/token" --offscreen \
    --out "$work/remote.png" >/dev/null 2>"$work/remote.err"
  status=$?
  [[ $status -eq 5 ]] || fail "--connect: exit status $status, expected 5"
  want="icon: a terrain-following store (geometry field 'geometry_height') is viewed on its own"
  grep -q "$want" "$work/remote.err" || fail "--connect refusal: $(cat "$work/remote.err")"
  echo "ok: --connect refuses a terrain-following store"
else
  fail "strielad-serve did not start: $(cat "$work/serve.err")"
fi
kill -TERM "$serve_pid" 2>/dev/null; wait "$serve_pid" 2>/dev/null
exit $((failures > 0))
