#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-view --offscreen on a curvilinear store: the curvilinear sample (a rotated pole
# given only as 2-D lat/lon) renders end to end, its world frame placed by the store's
# GEOMETRY coordinates (the log says so) and a default camera path over it; advection on
# it and viewing it through --connect are refused with the reason (exit status 5).
# Usage: view_curvilinear_cli_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
work=$2
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
view="$(dirname "$convert")/../strielad-view/strielad-view"
serve="$(dirname "$convert")/../strielad-serve/strielad-serve"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
is_png() { [[ -s "$1" ]] && [[ "$(head -c 4 "$1" | od -An -c | tr -d ' ')" == "211PNG" ]]; }

"$sample" -o "$work/in" --model curvilinear --dims 48x40x12 --steps 2 -q || exit 1
"$convert" "$work/in"/*.nc -o "$work/store" --brick 8 -q || exit 1
cat > "$work/scene.json" <<'JSON'
{"subvolumes": [{"id": 1, "name": "cloud water", "limits": [{"var": "qc", "min": 1e-5}]},
                {"id": 2, "name": "warm air", "limits": [{"var": "temp", "min": 285}]}],
 "attributes": ["temp"]}
JSON
if "$view" "$work/store" --scene "$work/scene.json" --offscreen --size 480x270 --threads 2 \
    --out "$work/curvilinear.png" --json >"$work/view.json" 2>"$work/view.err"; then
  is_png "$work/curvilinear.png" || fail "curvilinear.png is not a PNG image"
  grep -q '"nodes_with_mesh":[1-9]' "$work/view.json" || fail "no meshes: $(cat "$work/view.json")"
  grep -q "world frame: index axes 'x' and 'y' of a curvilinear grid ('lon' / 'lat') placed by its 2-D longitudes and latitudes" \
    "$work/view.err" || fail "frame not logged: $(cat "$work/view.err")"
  echo "ok: offscreen view of a curvilinear store"
else
  fail "offscreen view of a curvilinear store"; cat "$work/view.err"
fi

# A camera path in the store's index axes (eye beyond the grid's south-west corner).
cat > "$work/camera.json" <<'JSON'
{"format_version": 1, "keyframes": [
  {"t": 0, "eye": [-30, -40, 300000], "target": [24, 20, 0], "fov_deg": 45},
  {"t": 1, "eye": [80, -20, 200000], "target": [24, 20, 0], "fov_deg": 45}]}
JSON
mkdir -p "$work/frames"
if "$view" "$work/store" --scene "$work/scene.json" --offscreen --size 160x90 --threads 2 \
    --camera "$work/camera.json" --fps 2 --out "$work/frames/f{:02}.png" >/dev/null 2>"$work/path.err"; then
  [[ $(ls "$work/frames" | wc -l) -eq 3 ]] || fail "the camera path rendered $(ls "$work/frames" | wc -l) frames, expected 3"
else
  fail "camera path over a curvilinear store"; cat "$work/path.err"
fi

"$view" "$work/store" --scene "$work/scene.json" --offscreen --size 160x90 --threads 2 \
  --advect --wind u,v,w --out "$work/advect.png" >/dev/null 2>"$work/advect.err"
status=$?
[[ $status -eq 5 ]] || fail "--advect: exit status $status, expected 5"
grep -q "advection on a curvilinear grid ('lon' / 'lat') is not supported" "$work/advect.err" ||
  fail "--advect refusal: $(tail -1 "$work/advect.err")"

# Through --connect the store is refused, naming the dataset.
mkdir -p "$work/root" && cp -r "$work/store" "$work/root/curvi"
umask 077 && echo "s3cret" > "$work/token" && umask 022
"$serve" --root "$work/root" --listen 127.0.0.1:0 --token-file "$work/token" --threads 2 --json -q \
  >"$work/endpoint" 2>"$work/serve.err" &
serve_pid=$!
for _ in $(seq 100); do [[ -s "$work/endpoint" ]] && break; sleep 0.1; done
port=$(sed -n 's/.*"port": *\([0-9]*\).*/\1/p' "$work/endpoint")
if [[ -n "$port" ]]; then
  "$view" --connect "127.0.0.1:$port" --dataset curvi --token-file "$work/token" --offscreen \
    --out "$work/remote.png" >/dev/null 2>"$work/remote.err"
  status=$?
  [[ $status -eq 5 ]] || fail "--connect: exit status $status, expected 5"
  grep -q "curvi: a curvilinear store ('lon' / 'lat') is viewed on its own machine" \
    "$work/remote.err" || fail "--connect refusal: $(cat "$work/remote.err")"
else
  fail "strielad-serve did not start: $(cat "$work/serve.err")"
fi
kill -TERM "$serve_pid" 2>/dev/null; wait "$serve_pid" 2>/dev/null
[[ $failures -eq 0 ]] && rm -rf "$work"
exit $((failures > 0))
