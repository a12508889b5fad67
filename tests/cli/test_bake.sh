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
# with the file named.
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
expect "no -o" 2 "-o PAGE.exr is required" "$TMP/x.exr" bake scenes/world_lighting.gltf
expect "not .exr" 2 "expected a .exr file" "$TMP/x.png" bake scenes/world_lighting.gltf -o "$TMP/x.png"
expect "no world faces" 1 "model_lighting.gltf: no LightmappedGeneric primitive" "$TMP/x.exr" \
  bake scenes/model_lighting.gltf -o "$TMP/x.exr"
expect "missing scene" 1 "nope\.gltf" "$TMP/x.exr" bake "$TMP/nope.gltf" -o "$TMP/x.exr"

# --- bake, then render from the page ---------------------------------------------------------
# A copy of world_lighting.gltf beside its buffer and textures, naming page.exr.
mkdir -p "$TMP/wl"
ln -s "$HERE/scenes/world_lighting.bin" "$TMP/wl/world_lighting.bin"
ln -s "$HERE/scenes/textures" "$TMP/wl/textures"
sed 's/"lightmaps": {/"lightmaps": {"image": "page.exr", /' "$HERE/scenes/world_lighting.gltf" > "$TMP/wl/from_page.gltf"
in_repo bake scenes/world_lighting.gltf -o "$TMP/wl/page.exr"
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
cli_finish
