#!/usr/bin/env bash
# tiershade — tests/cli/test_render.sh
#
# `tiershade render` from the command line (docs/scenes.md).
#   usage: tests/cli/test_render.sh path/to/tiershade
# Checks: bad command lines and bad scene files give one clear line on stderr naming the
# problem (and the file), a non-zero status and no output files; every shipped scene in every
# tier, on EGL GLES 3.0 (and OSMesa GL 3.3, EGL GLES 2.0 for some), renders with --check: the
# GL forward frame equals, bit for bit, the C twin shading GL's own G-buffer, and the HDR path
# and colour correction on GL equal their C twins run on GL's lit frame (tolerance 0: the same
# inputs through the same arithmetic); the C fallback writes both files; ps20 never builds a
# Phong variant; a constant envmap mask skips its fetch.
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup render_cli 600 "$@"
# render ARGS... from the repository (the scenes name their files relatively).
run() {
  (cd "$HERE" && "${TIMEOUT[@]}" "$TS" render "$@" > "$OUT" 2> "$ERR" < /dev/null)
  RC=$?
}

# --- bad input -----------------------------------------------------------------------------
bad() {  # name, expected status, stderr pattern, args...
  local name=$1 want=$2 pat=$3
  shift 3
  rm -f "$TMP"/o.png "$TMP"/o.exr
  run "$@"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  if [ "$RC" -ne "$want" ]; then fail "$name" "status $RC, expected $want: $(head -n 2 "$ERR")"; return; fi
  if ! grep -qE -- "$pat" "$ERR"; then fail "$name" "stderr lacks /$pat/: $(head -n 2 "$ERR")"; return; fi
  if [ -e "$TMP/o.png" ] || [ -e "$TMP/o.exr" ]; then fail "$name" "left an output file"; return; fi
  pass "$name"
}
bad "no scene" 2 "expected one scene file" -o "$TMP/o"
bad "no -o" 2 "-o OUT is required" scenes/model_lighting.gltf
bad "bad tier" 2 "unknown tier 'ps30'" scenes/model_lighting.gltf --tier ps30 -o "$TMP/o"
bad "bad size" 2 "bad --size '0x10'" scenes/model_lighting.gltf --size 0x10 -o "$TMP/o"
bad "bad backend" 2 "unknown backend 'vulkan'" scenes/model_lighting.gltf --backend vulkan -o "$TMP/o"
bad "bad hdr path" 2 "unknown HDR path 'log'" scenes/model_lighting.gltf --hdr log -o "$TMP/o"
bad "check needs GL" 2 "--check compares GL with C" scenes/model_lighting.gltf --backend cpu --check -o "$TMP/o"
bad "missing scene file" 1 "nope\.gltf" "$TMP/nope.gltf" -o "$TMP/o"
bad "bad --probe-cubes" 2 "--probe-cubes vulkan: expected c or gl" scenes/world_lighting.gltf --probe-cubes vulkan -o "$TMP/o"
bad "probe cubes on GL need GL" 2 "--probe-cubes gl renders the cubes on GL" scenes/world_lighting.gltf --backend cpu --probe-cubes gl -o "$TMP/o"
sed 's/"name": "room_centre",/"name": "room_centre", "source": "photons",/' "$HERE/scenes/world_lighting.gltf" > "$HERE/scenes/.probe_source_test_$$.gltf"
bad "bad probe source" 1 'probes\[0\]\.source: expected "render" or "rays", got "photons"' scenes/.probe_source_test_$$.gltf -o "$TMP/o"
rm -f "$HERE/scenes/.probe_source_test_$$.gltf"
printf '{"asset": {"version": "2.0"}, "scenes": [' > "$TMP/broken.gltf"
bad "broken scene file" 1 "broken\.gltf" "$TMP/broken.gltf" -o "$TMP/o"
bad "float path on ES 2" 1 "float HDR path needs fp16" scenes/hdr_atrium.gltf --api gles2 --size 32x18 -o "$TMP/o"
bad "empty -o" 2 "expected a file name" scenes/model_lighting.gltf --backend cpu --size 32x18 -o ""
bad "-o names a directory" 2 "expected a file name" scenes/model_lighting.gltf --backend cpu --size 32x18 -o "$TMP/"
bad "output directory missing" 1 "no_such_dir" scenes/model_lighting.gltf --size 32x18 --backend cpu -o "$TMP/no_such_dir/o"
# The EXR and the PNG are written in parallel: when one cannot be written (here o.png is a
# directory, so its rename fails), the other must not be left behind.
mkdir -p "$TMP/o.png"
run scenes/model_lighting.gltf --size 32x18 --backend cpu -o "$TMP/o"
if cli_crashed; then fail "one output fails" "crashed (status $RC): $(head -c 300 "$ERR")"
elif [ "$RC" -ne 1 ]; then fail "one output fails" "status $RC, expected 1: $(head -n 2 "$ERR")"
elif ! grep -q "o\.png" "$ERR"; then fail "one output fails" "stderr does not name o.png: $(head -n 2 "$ERR")"
elif [ -e "$TMP/o.exr" ]; then fail "one output fails" "left o.exr behind"
else pass "one output fails"; fi
rmdir "$TMP/o.png"

# --- GL frame = C twin on GL's G-buffer, every scene and tier -------------------------------
check() {  # name, args...
  local name=$1
  shift
  run "$@" --size 96x54 --check --quiet -o "$TMP/c"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  local line post
  line=$(grep '^check: GL frame' "$OUT")
  post=$(grep '^check: HDR path' "$OUT")
  if [ "$RC" -ne 0 ] || ! echo "$line" | grep -qE ': 0 of [1-9][0-9]* covered pixels differ' ||
     ! echo "$post" | grep -qE ': 0 of [1-9][0-9]* channels differ'; then
    fail "$name" "status $RC: ${line:-$(head -n 2 "$ERR")} ${post}"
    return
  fi
  pass "$name: ${line#check: }; post: ${post##*: }"
}
for s in model_lighting world_lighting hdr_atrium lightmap_charts lightmap_charts_pages; do
  for t in ps20 ps2b sm3; do check "$s $t egl gles3" "scenes/$s.gltf" --tier $t; done
done
check "model_lighting sm3 osmesa gl33" scenes/model_lighting.gltf --tier sm3 --backend osmesa
check "world_lighting ps2b egl gl33" scenes/world_lighting.gltf --tier ps2b --api gl33
check "model_lighting ps20 egl gles2" scenes/model_lighting.gltf --tier ps20 --api gles2
check "hdr_atrium sm3 egl gles2, integer path" scenes/hdr_atrium.gltf --tier sm3 --api gles2 --hdr integer
# The float path without bloom (model_lighting's bloom is 0): the bloom passes are skipped on GL
# and in C alike.
check "model_lighting sm3, float path, bloom 0" scenes/model_lighting.gltf --tier sm3 --hdr float
run scenes/model_lighting.gltf --tier ps20 --hdr float --size 32x18 -o "$TMP/nb"
if [ "$RC" -eq 0 ] && grep -q 'bloom 0: the bloom passes are skipped' "$OUT"; then pass "float path, bloom 0: says the bloom passes are skipped"
else fail "float path, bloom 0: says the bloom passes are skipped" "status $RC: $(grep -m1 note "$OUT")"; fi
# The shader warm-up thread (glue/scene/frame.cpp) off, and on with an empty shader cache.
TIERSHADE_NO_WARMUP=1 check "model_lighting ps2b, no warm-up" scenes/model_lighting.gltf --tier ps2b
MESA_SHADER_CACHE_DIR="$TMP/cache" check "model_lighting sm3, warm-up, empty cache" scenes/model_lighting.gltf --tier sm3

# --- the C fallback and the selection -------------------------------------------------------
run scenes/world_lighting.gltf --backend cpu --size 64x36 -o "$TMP/cpu"
if [ "$RC" -eq 0 ] && [ -s "$TMP/cpu.png" ] && [ -s "$TMP/cpu.exr" ]; then pass "C fallback writes PNG and EXR"
else fail "C fallback writes PNG and EXR" "status $RC: $(head -n 2 "$ERR")"; fi
run scenes/model_lighting.gltf --backend cpu --tier ps20 --size 32x18 -o "$TMP/p"
if [ "$RC" -eq 0 ] && grep -q 'sm\|ps20:' "$OUT" && ! grep -q 'PHONG=1' "$OUT" && grep -q '\$phong dropped' "$OUT"; then
  pass "ps20 builds no Phong variant and says why"
else fail "ps20 builds no Phong variant and says why" "status $RC: $(grep -m1 PHONG "$OUT")"; fi
run scenes/world_lighting.gltf --backend cpu --size 32x18 -o "$TMP/w"
if [ "$RC" -eq 0 ] && grep -q 'is constant' "$OUT" && grep -q 'BUMPMAP=0: no \$bumpmap' "$OUT"; then
  pass "world: a constant envmap mask skips the fetch, a face without a normal map skips RNM"
else fail "world: constant mask and flat faces" "status $RC: $(grep -m1 ENVMAPMASK "$OUT")"; fi
# The sky (docs/baking.md, "The sky as the skybox"): the room's sky selects the skybox variant and
# --check counts every pixel (the sky covers what no geometry does); a scene without a sky has none.
run scenes/world_lighting.gltf --size 32x18 --check -o "$TMP/sky"
if [ "$RC" -eq 0 ] && grep -q '^  skybox sm3:' "$OUT" && grep -q 'extras.tiershade.sky' "$OUT" &&
   grep -qE ': 0 of 576 covered pixels differ' "$OUT"; then pass "a scene with a sky draws the skybox (GL = C twin on all 576 pixels)"
else fail "a scene with a sky draws the skybox" "status $RC: $(grep -m1 -E 'skybox|check: GL' "$OUT")"; fi
run scenes/model_lighting.gltf --size 32x18 -o "$TMP/nosky"
if [ "$RC" -eq 0 ] && ! grep -q 'skybox' "$OUT"; then pass "a scene without a sky selects no skybox"
else fail "a scene without a sky selects no skybox" "status $RC: $(grep -m1 skybox "$OUT")"; fi
# --- --frames N: the first frame is the one written, then N warm frames and their median ----
bad "frames with check" 2 "--frames times warm frames" scenes/model_lighting.gltf --frames 2 --check -o "$TMP/o"
bad "negative frames" 2 "--frames" scenes/model_lighting.gltf --frames -1 -o "$TMP/o"
for b in egl cpu; do
  run scenes/model_lighting.gltf --backend $b --size 48x27 --quiet -o "$TMP/f0"
  run scenes/model_lighting.gltf --backend $b --size 48x27 --quiet --frames 3 -o "$TMP/f3"
  if [ "$RC" -ne 0 ]; then fail "--frames 3 ($b)" "status $RC: $(head -n 2 "$ERR")"
  elif ! grep -qE '^median frame [0-9.]+ ms \(lit pass [0-9.]+ ms, post [0-9.]+ ms; median of 3 warm frames' "$OUT"; then
    fail "--frames 3 ($b)" "no median frame line: $(head -n 2 "$OUT")"
  elif ! cmp -s "$TMP/f0.png" "$TMP/f3.png" || ! cmp -s "$TMP/f0.exr" "$TMP/f3.exr"; then
    fail "--frames 3 ($b)" "the written frame differs from a render without --frames"
  else pass "--frames 3 ($b): median line, the written frame unchanged"; fi
done
# The world probes' cubes rendered on GL (docs/world_lighting.md): each face equals the C twin on
# GL's own G-buffer bit for bit, and the render's notes say where each cube came from.
run scenes/world_lighting.gltf --size 64x36 --check --probe-cubes gl -o "$TMP/pc"
if cli_crashed; then fail "probe cubes on GL, --check" "crashed (status $RC): $(head -c 300 "$ERR")"
elif [ "$RC" -ne 0 ] || ! grep -qE '^check: probe cube maps on GL .*: 0 of [1-9][0-9]* texels differ' "$OUT"; then
  fail "probe cubes on GL, --check" "status $RC: $(grep -E '^check: probe' "$OUT" | head -n 1) $(head -n 2 "$ERR")"
elif ! grep -q 'note: probe room_centre: its 64 x 64 cube map rendered in-engine by the GL egl/gles3' "$OUT"; then
  fail "probe cubes on GL, --check" "no note of the cube's source: $(grep '^note' "$OUT" | head -n 3)"
else pass "probe cubes on GL, --check: 0 texels differ from the C twin on GL's G-buffer"; fi
run scenes/world_lighting.gltf --size 32x18 --backend cpu -o "$TMP/pc"
if [ "$RC" -eq 0 ] && grep -q 'note: probe by_the_crate: its 32 x 32 cube map rendered in-engine by the C fallback' "$OUT"; then
  pass "probe cubes by the C fallback: the note names the source"
else fail "probe cubes by the C fallback: the note names the source" "status $RC: $(grep '^note' "$OUT" | head -n 3)"; fi
# --- mipmaps (docs/rendering.md "Mipmaps"): the C fallback's frame equals GL 3.3's byte for byte
# with each mipmap mode of the glTF sampler (the shipped scenes ask 9987 LINEAR_MIPMAP_LINEAR),
# and differs from the frame of the same scene without mipmaps (9729), so the chain is used.
# magFilter 9728 (NEAREST) also takes the image filter of the minified levels.
mip_case() {  # name, scene, sed expression
  local name=$1 scene=$2 expr=$3 f="$HERE/scenes/.mip_test_$$.gltf" g="$HERE/scenes/.mip_none_$$.gltf"
  sed "$expr" "$HERE/scenes/$scene" > "$f"
  sed "$expr; s/\"minFilter\": 998[4-7]/\"minFilter\": 9729/" "$HERE/scenes/$scene" > "$g"
  run "${f#$HERE/}" --size 160x90 --backend cpu --quiet -o "$TMP/mc"
  local rc1=$RC
  run "${f#$HERE/}" --size 160x90 --backend osmesa --api gl33 --quiet -o "$TMP/mg"
  local rc2=$RC
  run "${g#$HERE/}" --size 160x90 --backend cpu --quiet -o "$TMP/mn"
  rm -f "$f" "$g"
  if [ "$rc1" -ne 0 ] || [ "$rc2" -ne 0 ] || [ "$RC" -ne 0 ]; then fail "$name" "status $rc1/$rc2/$RC: $(head -n 2 "$ERR")"
  elif ! cmp -s "$TMP/mc.exr" "$TMP/mg.exr"; then fail "$name" "the C fallback's frame differs from GL 3.3's"
  elif cmp -s "$TMP/mc.exr" "$TMP/mn.exr"; then fail "$name" "the frame equals the frame without mipmaps"
  else pass "$name: C frame = GL 3.3 frame byte for byte, and not the unmipmapped frame"; fi
}
for mf in 9984 9985 9986 9987; do
  mip_case "mipmaps $mf (world)" world_lighting.gltf "s/\"minFilter\": 9987/\"minFilter\": $mf/"
done
mip_case "mipmaps 9987, magFilter NEAREST (model)" model_lighting.gltf \
  "s/\"minFilter\": 9987/\"minFilter\": 9987/; s/\"magFilter\": 9729/\"magFilter\": 9728/"
cli_finish
