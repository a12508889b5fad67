#!/usr/bin/env bash
# tiershade — tests/cli/test_bake.sh
#
# `tiershade bake` and lightmap pages read from a file (extras.tiershade.lightmaps.image,
# docs/scenes.md "Lightmap pages").
#   usage: tests/cli/test_bake.sh path/to/tiershade
# Checks: bad command lines and a scene without world faces fail clearly and write nothing; the
# baked page of world_lighting, named in a copy of the scene, renders the same frame bit for bit
# as the bake at load (C fallback and GL, tolerance 0: the same float page through the same
# code), with GL still equal to the C twins (--check); a black page (a Radiance .hdr written
# here) changes the frame, so the file is what is sampled; a page of the wrong size is refused
# with the file named. The bake directory (-o DIR, docs/baking.md): manifest and page, a scene
# naming it renders the same frame as the bake at load, a stale one (other settings, other
# lights) is refused naming the manifest and what changed, a damaged manifest names the JSON
# place; a bake killed (SIGKILL) during its bounces resumes from DIR.partial without redoing the
# finished passes and writes the same page bytes as an uninterrupted bake; a checkpoint of another
# bake is discarded. `tiershade light` on one point light over a plane: E = I cos / d^2.
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup bake_cli 600 "$@"
# render/bake from the repository (the scenes name their files relatively).
in_repo() {
  (cd "$HERE" && "${TIMEOUT[@]}" "$TS" "$@" > "$OUT" 2> "$ERR" < /dev/null)
  RC=$?
}
expect() {  # name, expected status, stderr pattern, file that must not exist, args...
  local name=$1 want=$2 pat=$3 none=$4
  shift 4
  in_repo "$@"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  if [ "$RC" -ne "$want" ]; then fail "$name" "status $RC, expected $want: $(head -n 2 "$ERR")"; return; fi
  if ! grep -qE -- "$pat" "$ERR"; then fail "$name" "stderr lacks /$pat/: $(head -n 2 "$ERR")"; return; fi
  if [ -e "$none" ]; then fail "$name" "wrote $none"; return; fi
  pass "$name"
}

# --- bad command lines and scenes without a page --------------------------------------------
expect "no -o" 2 "-o DIR is required" "$TMP/x.exr" bake scenes/world_lighting.gltf
mkdir -p "$TMP/mine" && echo keep > "$TMP/mine/notes.txt"
expect "-o DIR that is not a bake directory" 1 "mine: exists and is not a previous bake directory" "$TMP/mine.partial" \
  bake scenes/world_lighting.gltf -o "$TMP/mine"
[ -s "$TMP/mine/notes.txt" ] || fail "-o DIR that is not a bake directory" "the directory's file is gone"
expect "no world faces" 1 "model_lighting.gltf: no LightmappedGeneric primitive" "$TMP/x.exr" \
  bake scenes/model_lighting.gltf -o "$TMP/x.exr"
expect "missing scene" 1 "nope\.gltf" "$TMP/x.exr" bake "$TMP/nope.gltf" -o "$TMP/x.exr"

# --- bake, then render from the page ---------------------------------------------------------
# A copy of world_lighting.gltf beside its buffer and textures, naming page.exr.
mkdir -p "$TMP/wl"
ln -s "$HERE/scenes/world_lighting.bin" "$TMP/wl/world_lighting.bin"
ln -s "$HERE/scenes/textures" "$TMP/wl/textures"
sed 's/"lightmaps": {/"lightmaps": {"image": "page.exr", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/from_page.gltf"
# --quality draft: what render bakes at load (docs/baking.md, "Quality"), so the frames can be equal.
in_repo bake scenes/world_lighting.gltf --quality draft -o "$TMP/wl/page.exr"
if [ "$RC" -eq 0 ] && [ -s "$TMP/wl/page.exr" ] && grep -q "512 x 256 lightmap page" "$OUT"; then
  pass "bake world_lighting: a 512 x 256 page"
else fail "bake world_lighting" "status $RC: $(head -n 2 "$ERR")"; fi
grep -q '"image": "page.exr"' "$TMP/wl/from_page.gltf" || fail "test setup" "the scene copy does not name page.exr"

same_frame() {  # name, extra args...: the baked scene and the copy reading page.exr
  local name=$1
  shift
  in_repo render scenes/world_lighting.gltf --size 96x54 --quiet "$@" -o "$TMP/baked"
  local rc1=$RC
  in_repo render "$TMP/wl/from_page.gltf" --size 96x54 --quiet "$@" -o "$TMP/read"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  if [ "$rc1" -ne 0 ] || [ "$RC" -ne 0 ]; then fail "$name" "status $rc1 / $RC: $(head -n 2 "$ERR")"; return; fi
  if ! cmp -s "$TMP/baked.exr" "$TMP/read.exr" || ! cmp -s "$TMP/baked.png" "$TMP/read.png"; then
    fail "$name" "the frames differ"
    return
  fi
  pass "$name"
}
same_frame "page from the file == page baked at load, C fallback (EXR and PNG identical)" --backend cpu
same_frame "page from the file == page baked at load, EGL GLES 3.0 ps2b" --tier ps2b
same_frame "page from the file == page baked at load, EGL GLES 2.0 ps20" --tier ps20 --api gles2

in_repo render "$TMP/wl/from_page.gltf" --size 96x54 --check --quiet -o "$TMP/chk"
line=$(grep '^check: GL frame' "$OUT")
if [ "$RC" -eq 0 ] && echo "$line" | grep -qE ': 0 of [1-9][0-9]* covered pixels differ'; then
  pass "page from the file: GL = C twin (${line#check: })"
else fail "page from the file: GL = C twin" "status $RC: ${line:-$(head -n 2 "$ERR")}"; fi

# A black page (Radiance .hdr, flat scanlines of RGBE 0): the frame must change.
{ printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 256 +X 512\n'; head -c $((512 * 256 * 4)) /dev/zero; } > "$TMP/wl/black.hdr"
sed 's/"lightmaps": {/"lightmaps": {"image": "black.hdr", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/black.gltf"
in_repo render "$TMP/wl/black.gltf" --size 96x54 --quiet --backend cpu -o "$TMP/black"
if [ "$RC" -ne 0 ]; then fail "a black page darkens the frame" "status $RC: $(head -n 2 "$ERR")"
elif cmp -s "$TMP/black.exr" "$TMP/baked.exr"; then fail "a black page darkens the frame" "the frame did not change"
else pass "a black page changes the frame (the file is what is sampled)"; fi

# A page whose size is not the scene's "page": refused, the file named, nothing written.
{ printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16 +X 32\n'; head -c $((32 * 16 * 4)) /dev/zero; } > "$TMP/wl/small.hdr"
sed 's/"lightmaps": {/"lightmaps": {"image": "small.hdr", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/small.gltf"
expect "page of the wrong size" 1 "small\.gltf: extras\.tiershade\.lightmaps\.image: .*small\.hdr: 32 x 16 texels, but \"page\" is 512 x 256" \
  "$TMP/small.exr" render "$TMP/wl/small.gltf" --size 32x18 --backend cpu -o "$TMP/small"

# --- the bake directory ------------------------------------------------------------------------
in_repo bake scenes/world_lighting.gltf --quality draft -o "$TMP/wl/world.bake"
if [ "$RC" -eq 0 ] && [ -s "$TMP/wl/world.bake/page.exr" ] && grep -q '"format": "tiershade bake"' "$TMP/wl/world.bake/manifest.json" &&
  grep -q '"all": "[0-9a-f]\{16\}"' "$TMP/wl/world.bake/manifest.json" && grep -q '"block_w"' "$TMP/wl/world.bake/manifest.json" &&
  [ ! -e "$TMP/wl/world.bake.partial" ] && grep -q '^baked: 13 faces with a normal map: 4 values' "$OUT" &&
  grep -q '^baked: sky: [1-9][0-9]* rays through the openings' "$OUT"; then
  pass "bake -o DIR: page.exr and manifest.json (hash, places), no checkpoints left, the report"
else fail "bake -o DIR" "status $RC: $(head -n 3 "$ERR") $(ls "$TMP/wl")"; fi
cmp -s "$TMP/wl/world.bake/page.exr" "$TMP/wl/page.exr" && pass "DIR/page.exr == the -o PAGE.exr page" ||
  fail "DIR/page.exr == the -o PAGE.exr page" "the pages differ"
sed 's/"lightmaps": {/"lightmaps": {"bake": "world.bake", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/from_dir.gltf"
for b in cpu osmesa; do
  in_repo render "$TMP/wl/from_dir.gltf" --size 96x54 --quiet --backend $b -o "$TMP/dir_$b"
  in_repo render scenes/world_lighting.gltf --size 96x54 --quiet --backend $b -o "$TMP/load_$b"
  if [ "$RC" -eq 0 ] && cmp -s "$TMP/dir_$b.exr" "$TMP/load_$b.exr"; then pass "render from the bake directory == bake at load ($b)"
  else fail "render from the bake directory ($b)" "status $RC or the frames differ: $(head -n 2 "$ERR")"; fi
done
# (Another quality is no staleness: the render takes the bake's, tests/cli/test_bake_quality.sh; the seed is.)
sed 's/"lightmaps": {/"lightmaps": {"bake": "world.bake", "seed": 5, /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/stale.gltf"
expect "stale bake (settings) refused" 1 "world\.bake/manifest\.json: stale bake: the bake settings \(seed 0 -> 5\)" \
  "$TMP/stale.exr" render "$TMP/wl/stale.gltf" --size 32x18 --backend cpu -o "$TMP/stale"
sed 's/"intensity": 6.0/"intensity": 6.5/; s/"lightmaps": {/"lightmaps": {"bake": "world.bake", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/stale_l.gltf"
expect "stale bake (a light) refused" 1 "manifest\.json: stale bake: the lights changed" \
  "$TMP/stale.exr" render "$TMP/wl/stale_l.gltf" --size 32x18 --backend cpu -o "$TMP/stale"
cp -r "$TMP/wl/world.bake" "$TMP/wl/bad.bake"
sed -i 's/"lights": "[0-9a-f]*"/"lights": 7/' "$TMP/wl/bad.bake/manifest.json"
sed 's/"lightmaps": {/"lightmaps": {"bake": "bad.bake", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/bad.gltf"
expect "damaged manifest: the file and the JSON place" 1 "bad\.bake/manifest\.json: /hash/lights: expected string, found number" \
  "$TMP/bad.exr" render "$TMP/wl/bad.gltf" --size 32x18 --backend cpu -o "$TMP/bad"
expect "a bake directory that is not there" 1 "nope\.bake: no bake directory there" "$TMP/bad.exr" \
  render "$(sed 's/"lightmaps": {/"lightmaps": {"bake": "nope.bake", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/nope.gltf"; echo "$TMP/wl/nope.gltf")" \
  --size 32x18 --backend cpu -o "$TMP/bad"

# --- checkpoints: a bake killed during its bounces resumes ----------------------------------------
# Many bounces with many gather rays (several seconds): the kill lands after the direct pass's
# checkpoint and at least one bounce.
sed 's/"lightmaps": {/"lightmaps": {"bounces": 12, "gather_rays": 100, /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/long.gltf"
in_repo bake "$TMP/wl/long.gltf" -o "$TMP/wl/full.bake"
[ "$RC" -eq 0 ] || fail "uninterrupted long bake" "status $RC: $(head -n 2 "$ERR")"
# The page is what the bake directory gives: another page of the same layout (the bounced one) in a
# copy of world.bake changes the frame.
cp -r "$TMP/wl/world.bake" "$TMP/wl/swapped.bake" && cp "$TMP/wl/full.bake/page.exr" "$TMP/wl/swapped.bake/page.exr"
sed 's/"lightmaps": {/"lightmaps": {"bake": "swapped.bake", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/swapped.gltf"
in_repo render "$TMP/wl/swapped.gltf" --size 96x54 --quiet --backend cpu -o "$TMP/swapped"
if [ "$RC" -eq 0 ] && ! cmp -s "$TMP/swapped.exr" "$TMP/load_cpu.exr"; then pass "the frame is rendered from DIR/page.exr"
else fail "the frame is rendered from DIR/page.exr" "status $RC, or the frame did not change: $(head -n 2 "$ERR")"; fi
(cd "$HERE" && exec "$TS" bake "$TMP/wl/long.gltf" -o "$TMP/wl/killed.bake" > "$TMP/k1.out" 2>&1 < /dev/null) &
kpid=$!
# Wait until the checkpoint holds bounce 1 or later (its pass number: the int32 at byte 20 of
# pass.bin, bake_checkpoint.cpp), then kill during the next bounce.
saved_pass() { od -An -t d4 -j 20 -N 4 "$TMP/wl/killed.bake.partial/pass.bin" 2> /dev/null | tr -d ' '; }
for _ in $(seq 1 1200); do p=$(saved_pass); [ -n "$p" ] && [ "$p" -ge 1 ] && break; sleep 0.05; done
if kill -0 $kpid 2> /dev/null; then
  kill -9 $kpid
  wait $kpid 2> /dev/null
  if [ -e "$TMP/wl/killed.bake" ]; then fail "killed bake: no DIR" "the killed bake left $TMP/wl/killed.bake"
  elif [ ! -s "$TMP/wl/killed.bake.partial/pass.bin" ]; then fail "killed bake: a checkpoint" "no DIR.partial/pass.bin"
  else pass "killed bake: no DIR, a checkpoint in DIR.partial"; fi
  cp -r "$TMP/wl/killed.bake.partial" "$TMP/wl/other.bake.partial"
  cp "$TMP/wl/killed.bake.partial/pass.bin" "$TMP/wl/saved_pass.bin"
  in_repo bake "$TMP/wl/long.gltf" -o "$TMP/wl/killed.bake"
  pass_n=$(sed -n 's/^resumed after pass \([0-9]*\).*/\1/p' "$OUT")
  if [ "$RC" -eq 0 ] && [ -n "$pass_n" ] && [ "$pass_n" -ge 1 ] && grep -q "(from the checkpoint)" "$OUT"; then
    pass "rerun resumed after pass $pass_n (the finished passes not baked again)"
  else fail "rerun resumed" "status $RC: $(head -n 3 "$OUT") $(head -n 2 "$ERR")"; fi
  if cmp -s "$TMP/wl/killed.bake/page.exr" "$TMP/wl/full.bake/page.exr" && [ ! -e "$TMP/wl/killed.bake.partial" ]; then
    pass "resumed bake == uninterrupted bake (page bytes), checkpoints removed"
  else fail "resumed bake == uninterrupted bake" "the pages differ or DIR.partial is left"; fi
  # A checkpoint of another bake (here: other settings) is discarded, never mixed in.
  sed 's/"lightmaps": {/"lightmaps": {"bounces": 1, /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/one.gltf"
  in_repo bake "$TMP/wl/one.gltf" -o "$TMP/wl/other.bake"
  if [ "$RC" -eq 0 ] && grep -q "pass.bin: from a bake of another scene, settings or seed (its hash differs); discarded" "$OUT" &&
    ! grep -q "^resumed" "$OUT"; then pass "a checkpoint of another bake is discarded"
  else fail "a checkpoint of another bake is discarded" "status $RC: $(head -n 2 "$OUT")"; fi
  # A torn checkpoint (cut short, as a full disk would leave it) is discarded too.
  mkdir -p "$TMP/wl/torn.bake.partial"
  head -c 100000 "$TMP/wl/saved_pass.bin" > "$TMP/wl/torn.bake.partial/pass.bin"
  in_repo bake "$TMP/wl/one.gltf" -o "$TMP/wl/torn.bake"
  if [ "$RC" -eq 0 ] && grep -q "pass.bin: torn or corrupt" "$OUT" && [ -s "$TMP/wl/torn.bake/page.exr" ]; then
    pass "a torn checkpoint is discarded, the bake completes"
  else fail "a torn checkpoint is discarded" "status $RC: $(head -n 2 "$OUT") $(head -n 2 "$ERR")"; fi
else
  wait $kpid
  fail "killed bake" "the bake finished before it could be killed (it is too short on this machine)"
fi

# --- tiershade light: one point light over a plane (closed form) ---------------------------------
# A 2 x 2 plane at y = 0 (normals +y), 4 luxels per unit, 1 sample per luxel (the luxel's value is
# its grid point's), a point light of intensity 2 at (0.3, 1.5, -0.2). At (0.5, 0, 0.25), a luxel:
# E = I cos / d^2 = 2 x 1.5 / d^3; to 1e-6 relative (the float32 page: ~6e-8).
mkdir -p "$TMP/plane"
cat > "$TMP/plane/plane.gltf" <<'EOG'
{"asset": {"version": "2.0"},
 "extensionsUsed": ["KHR_lights_punctual"],
 "extensions": {"KHR_lights_punctual": {"lights": [{"name": "bulb", "type": "point", "color": [1, 1, 1], "intensity": 2.0}]}},
 "buffers": [{"byteLength": 140, "uri": "data:application/octet-stream;base64,AACAvwAAAAAAAIC/AACAvwAAAAAAAIA/AACAPwAAAAAAAIA/AACAPwAAAAAAAIC/AAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAAAAAACAPwAAgD8AAIA/AACAPwAAAAAAAAEAAgAAAAIAAwA="}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                 {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
               {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
               {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
               {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
 "materials": [{"name": "plane_grey", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}, "extras": {"source": {"shader": "LightmappedGeneric"}}}],
 "meshes": [{"name": "plane", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.05, "zfar": 100}}],
 "nodes": [{"name": "plane", "mesh": 0}, {"name": "bulb", "translation": [0.3, 1.5, -0.2], "extensions": {"KHR_lights_punctual": {"light": 0}}},
           {"name": "cam", "camera": 0, "translation": [0, 3, 3], "rotation": [-0.3826834, 0, 0, 0.9238795]}],
 "scenes": [{"nodes": [0, 1, 2]}], "scene": 0,
 "extras": {"tiershade": {"lightmaps": {"luxels_per_unit": 4, "supersample": 1, "page": [64, 64]}}}}
EOG
in_repo light "$TMP/plane/plane.gltf" --at 0.5,0.1,0.25
e=$(sed -n 's/^irradiance: \([^ ]*\) .*/\1/p' "$OUT")
flat=$(sed -n 's/^  flat \([^ ]*\) .*/\1/p' "$OUT")
if [ "$RC" -eq 0 ] && grep -q '^surface: face 0 (plane_grey, meshes\[0\]\.primitives\[0\]' "$OUT" &&
  grep -q '^luxel: (6, 3) of 9 x 9' "$OUT" &&
  awk -v e="$e" -v f="$flat" 'BEGIN { d2 = 0.2^2 + 1.5^2 + 0.45^2; w = 2 * 1.5 / (d2 * sqrt(d2));
    exit !(e != "" && (e - w) / w < 1e-6 && (w - e) / w < 1e-6 && f == e) }'; then
  pass "light: E = I cos / d^2 at a luxel of a plane under a point light ($e)"
else fail "light: E = I cos / d^2" "status $RC: $(head -n 4 "$OUT") $(head -n 2 "$ERR")"; fi
in_repo light "$TMP/plane/plane.gltf" --at 0.5,0.1,0.25 --json
if [ "$RC" -eq 0 ] && grep -q '"irradiance"' "$OUT" && grep -q '"b2"' "$OUT" && grep -q '"luxel"' "$OUT"; then pass "light --json"
else fail "light --json" "status $RC: $(head -n 3 "$OUT")"; fi
expect "light --normal with no face agreeing" 1 "no world face whose front normal is within 60 degrees" "$TMP/none" \
  light "$TMP/plane/plane.gltf" --at 0,0,0 --normal 0,-1,0
expect "light --at malformed" 2 "--at '1,2': expected three numbers" "$TMP/none" light "$TMP/plane/plane.gltf" --at 1,2
cli_finish
