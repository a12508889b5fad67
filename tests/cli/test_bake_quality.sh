#!/usr/bin/env bash
# tiershade — tests/cli/test_bake_quality.sh
#
# `tiershade bake`'s quality options (docs/baking.md, "Quality"; glue/bake/bake_quality.h).
#   usage: tests/cli/test_bake_quality.sh path/to/tiershade
# Checks: every bad option (an unknown preset, a value out of range or not a number, an option given
# twice) and a scene's unknown "quality" fail clearly with status 2 (1 for the scene) and write
# nothing; the bake prints its quality (the preset, then the scene's keys, then the options) and
# says which scene keys override the preset; the manifest records the preset and every value; the
# same page bytes with --threads 1 and 2 (a bake with bounces, the sky and a sun's spread); a
# render of a scene naming a bake directory made at another quality and luxel density renders
# from it (the bake's layout) and says so, and one made at the scene's own quality says nothing.
# The scenes are small (world_lighting at 2 luxels per unit, a 2 x 2 plane): seconds under ASan too.
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup bake_quality 300 "$@"
in_repo() {
  (cd "$HERE" && "${TIMEOUT[@]}" "$TS" "$@" > "$OUT" 2> "$ERR" < /dev/null)
  RC=$?
}
expect() {  # name, expected status, stderr pattern, args...: and nothing written to $TMP/none*
  local name=$1 want=$2 pat=$3
  shift 3
  in_repo "$@"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  if [ "$RC" -ne "$want" ]; then fail "$name" "status $RC, expected $want: $(head -n 2 "$ERR")"; return; fi
  if ! grep -qE -- "$pat" "$ERR"; then fail "$name" "stderr lacks /$pat/: $(head -n 2 "$ERR")"; return; fi
  if compgen -G "$TMP/none*" > /dev/null; then fail "$name" "wrote $(ls -d "$TMP"/none*)"; return; fi
  pass "$name"
}
WL=scenes/world_lighting.gltf

# --- bad options: status 2, the option named, nothing written -------------------------------------
expect "--quality unknown" 2 "tiershade bake: --quality: 'best' is not a preset \(draft, default or final\)" \
  bake $WL --quality best -o "$TMP/none.bake"
expect "--bounces over 100" 2 "tiershade bake: option --bounces wants an integer in \[0, 100\], got '101'" \
  bake $WL --bounces 101 -o "$TMP/none.bake"
expect "--bounces not a number" 2 "option --bounces wants an integer in \[0, 100\], got 'many'" \
  bake $WL --bounces many -o "$TMP/none.bake"
expect "--luxel-density 0" 2 "option --luxel-density wants a number in \[0.01, 1024\], got '0'" \
  bake $WL --luxel-density 0 -o "$TMP/none.bake"
expect "--luxel-density nan" 2 "option --luxel-density wants a number in \[0.01, 1024\], got 'nan'" \
  bake $WL --luxel-density nan -o "$TMP/none.bake"
expect "--luxel-density with trailing text" 2 "option --luxel-density wants a number in \[0.01, 1024\], got '4x'" \
  bake $WL --luxel-density 4x -o "$TMP/none.bake"
expect "--supersample 9" 2 "option --supersample wants an integer in \[1, 8\], got '9'" \
  bake $WL --supersample 9 -o "$TMP/none.bake"
expect "--gather-rays 0" 2 "option --gather-rays wants an integer in \[1, 1024\], got '0'" \
  bake $WL --gather-rays 0 -o "$TMP/none.bake"
expect "--sky-samples 0" 2 "option --sky-samples wants an integer in \[1, 4096\], got '0'" \
  bake $WL --sky-samples 0 -o "$TMP/none.bake"
expect "--threshold 2" 2 "option --threshold wants a number in \[0, 1\], got '2'" \
  bake $WL --threshold 2 -o "$TMP/none.bake"
expect "--threads -1" 2 "option --threads wants an integer in \[0, 256\], got '-1'" \
  bake $WL --threads -1 -o "$TMP/none.bake"
expect "--bounces twice" 2 "option --bounces given more than once" \
  bake $WL --bounces 1 --bounces 2 -o "$TMP/none.bake"
expect "--quality without a value" 2 "option --quality needs a value" bake $WL -o "$TMP/none.bake" --quality
mkdir -p "$TMP/wl"
ln -s "$HERE/scenes/world_lighting.bin" "$TMP/wl/world_lighting.bin"
ln -s "$HERE/scenes/textures" "$TMP/wl/textures"
sed 's/"lightmaps": {/"lightmaps": {"quality": "best", /' "$HERE/$WL" > "$TMP/wl/badq.gltf"
expect "scene lightmaps.quality unknown" 1 \
  "badq\.gltf: extras\.tiershade\.lightmaps\.quality: \"best\" is not a preset \(draft, default or final\)" \
  bake "$TMP/wl/badq.gltf" -o "$TMP/none.bake"

# --- the same bytes on 1 and 2 threads; the manifest records the quality ------------------------------
# A small bake with every pass: 2 luxels per unit, the sun's spread, the sky, 3 bounces of 16 rays.
Q=(--quality final --luxel-density 2 --gather-rays 16 --bounces 3 --sky-samples 16 --supersample 2 --spread-samples 8)
# The manifest without what is a time: "ms" fields, "(N ms)" and "Mrays/s" in the report lines.
untimed() { grep -v -e '"ms"' -e ' ms)' -e 'Mrays/s' "$1"; }
in_repo bake $WL "${Q[@]}" --threads 1 -o "$TMP/wl/t1.bake"
rc1=$RC
cp "$OUT" "$TMP/t1.out"
in_repo bake $WL "${Q[@]}" --threads 2 -o "$TMP/wl/t2.bake"
if [ "$rc1" -ne 0 ] || [ "$RC" -ne 0 ]; then fail "--threads 1 and 2" "status $rc1 / $RC: $(head -n 2 "$ERR")"
elif ! grep -q '^bounce 1: [1-9][0-9]* gather rays' "$OUT" || ! grep -q '^bounce 3: [0-9]* gather rays' "$OUT" || ! grep -q '^baked: sky: [1-9][0-9]* rays' "$OUT"; then
  fail "--threads 1 and 2" "the bake lacks its bounces or sky: $(grep '^baked' "$OUT" | head -n 8)"
elif ! cmp -s "$TMP/wl/t1.bake/page.exr" "$TMP/wl/t2.bake/page.exr"; then
  fail "--threads 1 and 2: the same page bytes" "page.exr differs"
elif ! diff <(untimed "$TMP/wl/t1.bake/manifest.json") <(untimed "$TMP/wl/t2.bake/manifest.json") > /dev/null; then
  fail "--threads 1 and 2: the same manifest (times aside)" "$(diff <(untimed "$TMP/wl/t1.bake/manifest.json") <(untimed "$TMP/wl/t2.bake/manifest.json") | head -n 4)"
else pass "--threads 1 and 2: the same page bytes and manifest (bounces, sky, sun spread)"; fi
if grep -q '^quality: final with overrides (luxels_per_unit 2, supersample 2, area_samples 64, spread_samples 8, sky.samples 16, bounces 3, gather_rays 16, threshold 0.0001)$' "$TMP/t1.out" &&
  grep -q "^note: the scene's keys luxels_per_unit, sky.samples override the preset final" "$TMP/t1.out"; then
  pass "the bake prints its quality and the scene keys that override the preset"
else fail "the bake prints its quality" "$(grep -E '^(quality|note)' "$TMP/t1.out")"; fi
python3 - "$TMP/wl/t1.bake/manifest.json" << 'EOF' && pass "the manifest records the preset and every value" || fail "the manifest records the quality" "$(grep -A 14 '"settings"' "$TMP/wl/t1.bake/manifest.json")"
import json, sys
s = json.load(open(sys.argv[1]))['settings']
want = {'quality': 'final', 'luxels_per_unit': 2, 'supersample': 2, 'area_samples': 64, 'spread_samples': 8,
        'sky_samples': 16, 'bounces': 3, 'gather_rays': 16, 'threshold': 0.0001}
sys.exit(0 if all(s.get(k) == v for k, v in want.items()) else 1)
EOF

# --- a render of a bake made at another quality takes the bake's, and says so -----------------------
sed 's/"lightmaps": {/"lightmaps": {"bake": "t1.bake", /' "$HERE/$WL" > "$TMP/wl/from_t1.gltf"
in_repo render "$TMP/wl/from_t1.gltf" --size 48x27 --backend cpu -o "$TMP/from_t1"
if [ "$RC" -eq 0 ] && grep -q "^note: .*t1\.bake was baked at quality final with overrides (luxels_per_unit 2, .*; the scene's is draft with overrides (luxels_per_unit 8, .*: the frame shows the bake's" "$OUT"; then
  pass "render of a bake at another quality and density: rendered from it, the quality reported"
else fail "render of a bake at another quality" "status $RC: $(grep '^note' "$OUT") $(head -n 2 "$ERR")"; fi
in_repo render $WL --size 48x27 --backend cpu --quiet -o "$TMP/at_load"
if [ "$RC" -eq 0 ] && ! cmp -s "$TMP/at_load.exr" "$TMP/from_t1.exr"; then pass "that frame is not the bake at load's"
else fail "that frame is not the bake at load's" "status $RC, or the frames are equal"; fi
# The plane (4 luxels per unit, 1 sample): a bake at the scene's own quality is rendered without a note.
mkdir -p "$TMP/plane"
python3 - "$TMP/plane/plane.gltf" << 'EOF'
import json, struct, base64, sys
pos = [-1, 0, -1, -1, 0, 1, 1, 0, 1, 1, 0, -1]
buf = struct.pack('<12f', *pos) + struct.pack('<12f', *([0, 1, 0] * 4)) + struct.pack('<8f', 0, 0, 0, 1, 1, 1, 1, 0) + \
    struct.pack('<6H', 0, 1, 2, 0, 2, 3)
d = {"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
     "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "color": [1, 1, 1], "intensity": 2.0}]}},
     "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
     "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in ((0, 48), (48, 48), (96, 32), (128, 12))],
     "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                   {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                   {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                   {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
     "materials": [{"name": "grey", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]},
                    "extras": {"source": {"shader": "LightmappedGeneric"}}}],
     "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
     "cameras": [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.05, "zfar": 100}}],
     "nodes": [{"mesh": 0}, {"translation": [0.3, 1.5, -0.2], "extensions": {"KHR_lights_punctual": {"light": 0}}},
               {"camera": 0, "translation": [0, 3, 3], "rotation": [-0.3826834, 0, 0, 0.9238795]}],
     "scenes": [{"nodes": [0, 1, 2]}], "scene": 0,
     "extras": {"tiershade": {"lightmaps": {"luxels_per_unit": 4, "supersample": 1, "page": [64, 64]}}}}
json.dump(d, open(sys.argv[1], 'w'))
d['extras']['tiershade']['lightmaps']['bake'] = 'p.bake'
json.dump(d, open(sys.argv[1].replace('plane.gltf', 'from_p.gltf'), 'w'))
EOF
in_repo bake "$TMP/plane/plane.gltf" --quality draft -o "$TMP/plane/p.bake"
if [ "$RC" -eq 0 ] && grep -q '^quality: draft with overrides (luxels_per_unit 4, supersample 1, ' "$OUT"; then
  in_repo render "$TMP/plane/from_p.gltf" --size 32x18 --backend cpu -o "$TMP/from_p"
  if [ "$RC" -eq 0 ] && ! grep -q "was baked at quality" "$OUT"; then pass "render of a bake at the scene's own quality: no note"
  else fail "render of a bake at the scene's own quality" "status $RC: $(grep '^note' "$OUT") $(head -n 2 "$ERR")"; fi
else fail "bake the plane at draft" "status $RC: $(head -n 2 "$OUT") $(head -n 2 "$ERR")"; fi
# Without --quality: the preset default (bounces up to 100), the scene's keys applied.
in_repo bake "$TMP/plane/plane.gltf" -o "$TMP/plane/d.exr"
if [ "$RC" -eq 0 ] && grep -q '^quality: default with overrides (luxels_per_unit 4, supersample 1, .* bounces 100, ' "$OUT"; then
  pass "no --quality: the preset default with the scene's keys"
else fail "no --quality: the preset default" "status $RC: $(grep '^quality' "$OUT") $(head -n 2 "$ERR")"; fi
cli_finish
