#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Frame time of strielad-view with terrain and 27,000 flight tracks (BENCHMARKS.md
# "Terrain and flight tracks together"): five configurations taking turns for 3 rounds on
# the sample store (scripts/sample.sh), one --json line each in OUT/frames.jsonl, and a
# table of medians. Needs build/ and sample-data/ (store and sample_terrain.nc).
set -euo pipefail
cd "$(dirname "$0")/.."
view=build/cmd/strielad-view/strielad-view
convert=build/cmd/strielad-convert/strielad-convert
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
cam=examples/scenes/paper-figure-camera.json
out=${OUT:-/tmp/strielad-bench-geography}
mkdir -p "$out"
tracks="$out/tracks/sample_tracks.csv"
[[ -s "$tracks" ]] || "$sample" -o "$out/tracks" --dims 8x8x4 --steps 4 --vars ta --tracks 27000 -q
: > "$out/frames.jsonl"
for round in 1 2 3; do
  for config in clouds terrain tracks terrain+tracks figure; do
    args=(sample-data/store --offscreen --camera "$cam" --time 1 --size 1280x720 --json
          --out "$out/$config.png")
    case $config in
      terrain) args+=(--terrain sample-data/sample_terrain.nc) ;;
      tracks) args+=(--tracks "$tracks") ;;
      terrain+tracks) args+=(--terrain sample-data/sample_terrain.nc --tracks "$tracks") ;;
      figure) args+=(--scene examples/scenes/paper-figure.json --tracks "$tracks") ;;
    esac
    "$view" "${args[@]}" 2>/dev/null | sed "s/^{/{\"config\":\"$config\",\"round\":$round,/" >> "$out/frames.jsonl"
  done
done
python3 - "$out/frames.jsonl" <<'PY'
import json, statistics as st, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
print("| configuration | render ms, median (min-max) | geometry ms | resolve ms | terrain tiles / triangles | tracks / segments | slice triangles | cloud triangles |")
print("|---|---|---|---|---|---|---|---|")
for c in ["clouds", "terrain", "tracks", "terrain+tracks", "figure"]:
    r = [x for x in rows if x["config"] == c]
    med = lambda k: st.median([x.get(k) or 0 for x in r])
    rm = [x["render_ms"] for x in r]
    print(f"| {c} | {st.median(rm):.0f} ({min(rm):.0f}-{max(rm):.0f}) | {med('geometry_ms'):.0f} | "
          f"{med('resolve_ms'):.0f} | {med('terrain_tiles'):.0f} / {med('terrain_triangles'):,.0f} | "
          f"{med('tracks_shown'):,.0f} / {med('track_segments'):,.0f} | {med('slice_triangles'):,.0f} | "
          f"{med('triangles'):,.0f} |")
PY
