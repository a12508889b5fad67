#!/usr/bin/env bash
# tiershade — tests/bundle/test_webgl_bundle.sh
#
# Bundles and tiers a browser accepts (issue 14; docs/bundles.md "Extensions" and "The declared
# interface", docs/budget_model.md "Constant registers").
#   usage: tests/bundle/test_webgl_bundle.sh path/to/tiershade
# Checks: essl100 offers every variant but the 9 colour-correction 3D-LUT ones and texture_grad's
# (its variants' `targets` leave essl100 out: explicit derivatives need EXT_shader_texture_lod,
# which llvmpipe's ES contexts lack; docs/conformance.md) (a named one is refused, status 2); a float-HDR scene is refused for essl100 with a message naming the path,
# and bundles with --hdr integer; a ps20 manifest lists u_lights (vertex) at its declared 20 with
# Mesa's 10 under may_trim and u_light_pack (fragment) at 8 with Mesa's 7, and the extensions the
# variant uses; Chromium's reflection of it agrees with the manifest, and doctored manifests (Mesa's
# u_lights[10], a_uv left out, an unused uniform) are caught by check-bundle; the budget passes the
# largest ps2b Phong 4-light variant on constant registers (31 <= 32, packed lights) and ps20 on
# WebGL 1's 16 fragment uniform vectors, and fails a listed variant that fits. About 30 s (the
# three budget runs compile ~30 variants).
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/../cli/lib.sh"
cli_setup webgl_bundle 300 "$@"

# --- which variants essl100 offers ---------------------------------------------------------
run variants --count; all=$(cat "$OUT")
run variants --count --target essl100; es2=$(cat "$OUT")
run variants --count --target essl300; es3=$(cat "$OUT")
run variants --count --shader texture_grad; grad=$(cat "$OUT")
if [ -n "$all" ] && [ -n "$grad" ] && [ "$grad" -gt 0 ] && [ "$es2" = $((all - 9 - grad)) ] && [ "$es3" = "$all" ]; then
  pass "essl100 offers all but the 9 3D-LUT and the $grad texture_grad variants ($es2 of $all), essl300 all"
else fail "essl100 offers all but the 9 3D-LUT and the texture_grad variants" "all '$all' essl100 '$es2' essl300 '$es3' texture_grad '$grad'"; fi
run variants --list --target essl100 --shader color_correction
if [ "$RC" -eq 0 ] && ! grep -q 'LUT_ATLAS=0' "$OUT" && [ "$(grep -c 'LUT_ATLAS=1' "$OUT")" -eq 16 ]; then
  pass "essl100 lists the 16 atlas colour-correction variants and no 3D one"
else fail "essl100 lists the atlas colour-correction variants" "status $RC: $(tr '\n' ' ' < "$OUT" | head -c 300)"; fi

V3D='ps2b:LUT_ATLAS=0,SHADER_TRILINEAR=0,NUM_LOOKUPS=2'
run variants --shader color_correction --variant "$V3D" --target essl100 -o b3d
if [ "$RC" -eq 2 ] && grep -q 'not offered on essl100' "$ERR" && grep -q 'OES_texture_3D' "$ERR" && [ ! -e b3d ]; then
  pass "a named 3D-LUT variant is refused for essl100"
else fail "a named 3D-LUT variant is refused for essl100" "status $RC: $(head -n 1 "$ERR")"; fi
run variants --shader color_correction --variant "$V3D" --target essl300 -o b3d
if [ "$RC" -eq 0 ] && grep -q '"type": "sampler3D"' b3d/manifest.json; then pass "the same variant bundles for essl300"
else fail "the same variant bundles for essl300" "status $RC: $(head -n 1 "$ERR")"; fi
run variants --shader color_correction --tier ps2b --target essl100 -o bcc
if [ "$RC" -eq 0 ] && grep -q '9 variants left out' "$OUT" && ! grep -q 'LUT_ATLAS=0' bcc/manifest.json; then
  pass "a whole-tier essl100 bundle leaves the 3D variants out, and says so"
else fail "a whole-tier essl100 bundle leaves the 3D variants out" "status $RC: $(tail -n 1 "$OUT") $(head -n 1 "$ERR")"; fi

# --- the float HDR path and WebGL 1 ---------------------------------------------------------
SC="$HERE/scenes/hdr_atrium.gltf"
run variants "$SC" --tier sm3 --target essl100 -o bhdr
if [ "$RC" -eq 2 ] && grep -q 'float HDR path' "$ERR" && grep -q 'fp16 render targets' "$ERR" && grep -q 'hdr_atrium.gltf' "$ERR" &&
  [ "$(grep -c '' "$ERR")" -eq 1 ] && [ ! -e bhdr ]; then
  pass "a float-HDR scene is refused for essl100 with one line naming it"
else fail "a float-HDR scene is refused for essl100" "status $RC: $(head -n 2 "$ERR" | tr '\n' ' ')"; fi
run variants "$SC" --tier sm3 --target essl100 --hdr integer -o bhdr
if [ "$RC" -eq 0 ] && [ -s bhdr/manifest.json ]; then pass "the same scene bundles for essl100 with --hdr integer"
else fail "the same scene bundles for essl100 with --hdr integer" "status $RC: $(head -n 1 "$ERR")"; fi
run variants "$SC" --tier sm3 --target essl300 -o bhdr3
if [ "$RC" -eq 0 ]; then pass "the float-HDR scene bundles for essl300"
else fail "the float-HDR scene bundles for essl300" "status $RC: $(head -n 1 "$ERR")"; fi

# --- the declared interface against Mesa's, and the extensions -----------------------------
V20='ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2'
run variants --shader model_lighting --variant "$V20" --target essl100 -o b20
if [ "$RC" -ne 0 ]; then fail "ps20 essl100 bundle" "status $RC: $(head -n 1 "$ERR")"
else
  got=$(python3 - b20/manifest.json << 'EOF'
import json, sys
m = json.load(open(sys.argv[1]))
v = m["variants"][0]
u = {x["name"]: x for x in v["uniforms"]}
t = {x["name"]: x["array_size"] for x in v["may_trim"]["uniforms"]}
e = [x["name"] for x in v["extensions"]]
print("declared", u["u_lights"]["array_size"], "stages", "+".join(u["u_lights"]["stages"]),
      "mesa", t.get("u_lights"), "pack", u["u_light_pack"]["array_size"], "+".join(u["u_light_pack"]["stages"]),
      "mesa", t.get("u_light_pack"), "ext", ",".join(e), "top", ",".join(m["extensions"]),
      "dx9", v["constant_registers"], "webgl", v["uniform_vectors"]["fragment"], "units", v["texture_units"]["fragment"])
EOF
  )
  case "$got" in
    # u_lights feeds ps20's per-vertex attenuation only; the fragment stage reads the packed lights
    # (shaders/common_lights.glsl ts_light_unpack): declared 4 x 2, Mesa keeps 7 (light 1's p3 unread).
    "declared 20 stages vertex mesa 10 pack 8 fragment mesa 7 "*)
      pass "u_lights: declared 20 (vertex), Mesa's 10; u_light_pack: declared 8 (fragment), Mesa's 7 ($got)" ;;
    *) fail "u_lights: declared 20 (vertex), Mesa's 10; u_light_pack: declared 8 (fragment), Mesa's 7" "$got" ;;
  esac
  missing=""
  for x in OES_texture_float OES_texture_float_linear WEBGL_color_buffer_float OES_element_index_uint; do
    echo "$got" | grep -q "ext [^ ]*$x" || missing+=" $x"
  done
  if [ -z "$missing" ] && ! echo "$got" | grep -q OES_texture_3D; then pass "ps20 extensions for WebGL 1"
  else fail "ps20 extensions for WebGL 1" "missing$missing: $got"; fi
  # ps20 model_lighting, 2 lights, albedo texture (u_albedo_color unused): DX9 registers
  # u_ambient_cube 6 + u_light_pack 7 (light 1's position is element 6) + u_params = 14; WebGL's
  # measure takes u_light_pack at its declared 8: 6 + 8 + 1 = 15 <= WebGL 1's 16 (docs/tiers.md).
  case "$got" in *"dx9 14 webgl 15 units 1"*) pass "ps20 counts: 14 DX9 constants, 15 uniform vectors, 1 unit" ;;
    *) fail "ps20 counts: 14 DX9 constants, 15 uniform vectors, 1 unit" "$got" ;; esac
fi

# --- the manifest against Chromium's reflection (tiershade check-bundle) -----------------------
# b20 as written passes; the manifest Mesa's reflection alone gave (u_lights at its 10 elements),
# one without a_uv, and one declaring a uniform no stage uses each fail, naming the entry.
if [ -s b20/manifest.json ]; then
  run check-bundle b20
  if [ "$RC" -eq 0 ] && grep -q '^ok: every manifest agrees' "$OUT"; then pass "check-bundle: the ps20 bundle agrees with Chromium"
  else fail "check-bundle: the ps20 bundle agrees with Chromium" "status $RC: $(grep -m 2 -E '^FAIL|^declared' "$OUT" | tr '\n' ' ') $(head -n 1 "$ERR")"; fi
  doctor() {  # doctor NAME PYTHON: a copy of b20 whose variant v is edited by PYTHON
    rm -rf "$1" && cp -r b20 "$1" && python3 - "$1/manifest.json" "$2" << 'EOF2'
import json, sys
m = json.load(open(sys.argv[1])); v = m["variants"][0]
exec(sys.argv[2])
json.dump(m, open(sys.argv[1], "w"), indent=2)
EOF2
  }
  doctor bmesa 'v["uniforms"] = [dict(u, array_size=10) if u["name"] == "u_lights" else u for u in v["uniforms"]]; v["may_trim"]["uniforms"] = []'
  doctor bnouv 'v["attributes"] = [a for a in v["attributes"] if a["name"] != "a_uv"]'
  doctor bextra 'v["uniforms"].append({"name": "u_unused", "type": "vec4", "array_size": 0, "stages": ["fragment"]})'
  run check-bundle bmesa
  if [ "$RC" -eq 1 ] && grep -q "^FAIL .*active uniform 'u_lights' (vec4, size 20) against the declared vec4\[10\]" "$OUT"; then
    pass "check-bundle: Mesa's u_lights[10] is caught"
  else fail "check-bundle: Mesa's u_lights[10] is caught" "status $RC: $(grep -m 2 '^FAIL' "$OUT")"; fi
  run check-bundle bnouv
  if [ "$RC" -eq 1 ] && grep -q "^FAIL .*active attribute 'a_uv' (vec2, size 1) is not in the declared interface" "$OUT"; then
    pass "check-bundle: an active attribute the manifest omits is caught"
  else fail "check-bundle: an active attribute the manifest omits is caught" "status $RC: $(grep -m 2 '^FAIL' "$OUT")"; fi
  run check-bundle bextra
  if [ "$RC" -eq 1 ] && grep -q "^FAIL .*declared uniform 'u_unused' (vec4) is not under may_trim but the browser reports it inactive" "$OUT"; then
    pass "check-bundle: a declared entry Chromium does not report active is caught"
  else fail "check-bundle: a declared entry Chromium does not report active is caught" "status $RC: $(grep -m 2 '^FAIL' "$OUT")"; fi
  run check-bundle nope
  if [ "$RC" -eq 2 ] && grep -q 'nope/manifest.json: cannot open' "$ERR"; then pass "check-bundle: a missing bundle names its manifest"
  else fail "check-bundle: a missing bundle names its manifest" "status $RC: $(head -n 1 "$ERR")"; fi
fi

# --- the budget's constant registers --------------------------------------------------------
P4='ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,PHONG=1,PHONG_EXPONENT_MAP=1,RIM_LIGHT=1,ENVMAP=1,LIGHT_WARP=1,NUM_LIGHTS=4'
KNOWN="$HERE/tests/bundle/budget_known_over.txt"
# ps2b Phong with 4 lights, every feature: 6 + u_light_pack 16 (4 lights x 4 vec4) + u_params + the
# 8 Phong vec4s = 31 <= ps_2_b's 32 (35 with 5 vec4 per light, before issue 14's packing).
run budget --shader model_lighting --variant "$P4" --known-over "$KNOWN"
if [ "$RC" -eq 0 ] && grep -q '^ok .*const  31 .*const 32' "$OUT" && ! grep -q 'known over' "$OUT"; then
  pass "budget: ps2b Phong with 4 lights fits, 31 constants <= 32, not on the known-over list"
else fail "budget: ps2b Phong with 4 lights fits, 31 constants <= 32" "status $RC: $(head -n 1 "$OUT")"; fi
# ps20: WebGL 1's fragment uniform vectors are counted and limited (16).
run budget --shader model_lighting --variant "$V20"
if [ "$RC" -eq 0 ] && grep -q '^ok .*const  14 vec  15 .*vec 16)' "$OUT"; then pass "budget: ps20 uses 15 of WebGL 1's 16 fragment uniform vectors"
else fail "budget: ps20 uses 15 of WebGL 1's 16 fragment uniform vectors" "status $RC: $(head -n 1 "$OUT")"; fi
echo "model_lighting $V20" > fits.txt
run budget --shader model_lighting --variant "$V20" --known-over fits.txt
if [ "$RC" -eq 1 ] && grep -q 'but fits' "$OUT"; then pass "a listed variant that fits fails"
else fail "a listed variant that fits fails" "status $RC: $(head -n 2 "$OUT" | tr '\n' ' ')"; fi

cli_finish
