#!/usr/bin/env bash
# tiershade — tests/cli/test_bundle.sh
#
# Shader bundles for engines (docs/bundles.md), from the command line.
#   usage: tests/cli/test_bundle.sh path/to/tiershade
# The bare GL program is $(dirname tiershade)/tests/bare_gl_render (the Makefile builds it).
# Checks: bad input (unknown target, missing -o, bad scene, -o onto a non-bundle) gives one
# line on stderr, status 2 (usage/input) or 1, no stdout and no directory left behind; an
# explicit bundle holds exactly `tiershade assemble`'s text; a bundle replaces a bundle; and,
# when `tiershade render` exists, for every scenes/*.gltf x tier x target the bare program
# replays the --dump-draws capture bit for bit, and a corrupted dump is caught; the essl100 and
# essl300 bundles' programs, linked in headless Chromium, report active only what their manifests
# declare, and everything the manifests do not list under may_trim (tiershade check-bundle).
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup bundle_cli 300 "$@"
BARE=$(dirname "$TS")/tests/bare_gl_render
crashed() {
  if [ "$RC" -ge 124 ] && [ "$RC" -ne 125 ] || grep -qE 'AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:|terminate called|Segmentation fault' "$ERR"; then
    fail "$1" "crashed or timed out (status $RC): $(head -n 1 "$ERR")"
    return 0
  fi
  return 1
}
no_temporaries() { ! ls -a "$TMP" 2> /dev/null | grep -qE '\.(tmp|old)\.'; }

# expect_fail NAME STATUS 'pattern|...' OUTPUT -- ARGS...: one stderr line with every pattern,
# no stdout, OUTPUT (if given) not created or changed, no temporaries.
expect_fail() {
  local name=$1 status=$2 patterns=$3 output=$4
  shift 5
  local before=""
  [ -n "$output" ] && [ -e "$output" ] && before=$(ls -lR "$output" 2> /dev/null)
  run "$@"
  crashed "$name" && return
  local problems="" p
  [ "$RC" -eq "$status" ] || problems+="status $RC, want $status; "
  [ "$(grep -c '' "$ERR")" -eq 1 ] || problems+="stderr has $(grep -c '' "$ERR") lines; "
  [ -s "$OUT" ] && problems+="stdout not empty; "
  local IFS='|'
  for p in $patterns; do grep -qF -- "$p" "$ERR" || problems+="message lacks '$p'; "; done
  unset IFS
  if [ -n "$output" ]; then
    if [ -z "$before" ] && [ -e "$output" ]; then problems+="created $output; "; fi
    if [ -n "$before" ] && [ "$before" != "$(ls -lR "$output" 2> /dev/null)" ]; then problems+="changed $output; "; fi
  fi
  no_temporaries || problems+="left a temporary; "
  if [ -z "$problems" ]; then pass "$name"; else fail "$name" "${problems}stderr: $(head -n 1 "$ERR")"; fi
}

ML=model_lighting
V1='sm3:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,PHONG=1,PHONG_EXPONENT_MAP=0,RIM_LIGHT=0,ENVMAP=1,LIGHT_WARP=0'
V2='ps20:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=0,NUM_LIGHTS=2'

# --- bad input ----------------------------------------------------------------------------
expect_fail "unknown target" 2 "unknown target 'essl200'" b -- variants --shader $ML --variant "$V1" --target essl200 -o b
expect_fail "missing -o" 2 "needs -o DIR" "" -- variants --shader $ML --variant "$V1" --target essl300
expect_fail "scene needs one tier" 2 "exactly one --tier" b -- variants "$TMP/nope.gltf" -o b
expect_fail "bad scene path" 2 "nope.gltf" b -- variants "$TMP/nope.gltf" --tier sm3 -o b
mkdir -p notbundle && echo keep > notbundle/file.txt
expect_fail "-o onto a non-bundle directory" 1 "notbundle|not a previous bundle" notbundle -- variants --shader $ML --variant "$V1" -o notbundle
echo x > plainfile
expect_fail "-o onto a file" 1 "plainfile|not a directory" plainfile -- variants --shader $ML --variant "$V1" -o plainfile
expect_fail "-o in a missing directory" 1 "missing/b" "" -- variants --shader $ML --variant "$V1" -o missing/b
expect_fail "unknown variant" 2 "$ML" b -- variants --shader $ML --variant 'sm3:NOPE=1' -o b

# --- an explicit bundle: files = tiershade assemble's text, manifest fields -----------------
run variants --shader $ML --variant "$V1" --variant "$V2" --target essl300 -o b
if crashed "explicit bundle"; then :
elif [ "$RC" -ne 0 ] || [ ! -s b/manifest.json ]; then fail "explicit bundle" "status $RC: $(head -n 1 "$ERR")"
else
  pass "explicit bundle"
  same=1
  for v in "$V1" "$V2"; do
    frag=$(grep -A4 "\"name\": \"$v\"" b/manifest.json | sed -n 's/.*"fragment": "\(.*\)".*/\1/p')
    vert=$(grep -A4 "\"name\": \"$v\"" b/manifest.json | sed -n 's/.*"vertex": "\(.*\)".*/\1/p')
    "$TS" assemble --shader $ML --variant "$v" --target essl300 > a.frag 2> /dev/null || same=0
    "$TS" assemble --shader $ML --variant "$v" --target essl300 --vertex > a.vert 2> /dev/null || same=0
    { [ -n "$frag" ] && cmp -s a.frag "b/$frag" && cmp -s a.vert "b/$vert"; } || same=0
  done
  if [ $same -eq 1 ]; then pass "bundle files are tiershade assemble's text"; else fail "bundle files are tiershade assemble's text" "differ"; fi
  missing=""
  for k in '"tiershade_bundle": 1' '"target": "essl300"' '"glsl_version": "300 es"' '"name": "a_tangent"' \
           '"name": "u_envmap"' '"type": "samplerCube"' '"unit": 0' '"array_size": 20' '"alu":' '"tex":' \
           '"TS_TIER_SM3": 1' '"name": "ts_FragColor"'; do
    grep -qF -- "$k" b/manifest.json || missing+=" $k"
  done
  if [ -z "$missing" ]; then pass "manifest fields"; else fail "manifest fields" "missing$missing"; fi
  if [ "$(find b -name '*.frag' | wc -l)" -eq 2 ] && [ "$(find b -name '*.vert' | wc -l)" -eq 2 ]; then
    pass "one .vert and one .frag per variant"; else fail "one .vert and one .frag per variant" "$(find b | tr '\n' ' ')"; fi
  run variants --shader $ML --variant "$V2" --target glsl330 -o b
  if [ "$RC" -eq 0 ] && grep -q '"target": "glsl330"' b/manifest.json && [ "$(find b -name '*.frag' | wc -l)" -eq 1 ] && no_temporaries; then
    pass "a bundle replaces a bundle"; else fail "a bundle replaces a bundle" "status $RC: $(head -n 1 "$ERR")"; fi
fi

# --- scenes: tiershade render --dump-draws replayed by the bare program --------------------
# Every check below runs for every shipped scene; a missing piece is a failure, not a skip.
scenes=("$HERE"/scenes/*.gltf)
# Under the sanitizers (run_tests.sh sets TIERSHADE_TEST_SANITIZED) the two biggest instanced halls
# are left out: they draw the same materials as large_hall_40 (tools/make_scenes.py large_hall),
# which stays, so every code path of the dump and the replay still runs under ASan/UBSan; only
# the draw count differs (446 and 160 draws against 40). The unsanitized run covers every scene.
if [ -n "${TIERSHADE_TEST_SANITIZED:-}" ]; then
  kept=()
  for sc in "${scenes[@]}"; do
    case "$(basename "$sc")" in large_hall.gltf | large_hall_160.gltf) ;; *) kept+=("$sc") ;; esac
  done
  scenes=("${kept[@]}")
fi
if [ ! -x "$BARE" ]; then
  fail "bare program" "$BARE is missing (make builds it)"
elif ! "$TS" render --help 2>&1 | grep -q -- '--dump-draws'; then
  fail "scene bundles" "tiershade render has no --dump-draws"
elif [ ! -e "${scenes[0]}" ]; then
  fail "scene bundles" "no scenes/*.gltf"
else
  # corrupt DIR: sets the first element of every u_view_proj to 0.5 (2.0 if it was 0.5).
  corrupt() {
    awk '/"name": "u_view_proj"/ { f = 1 } f == 1 && /"bits"/ { f = 2; print; next }
         f == 2 && /[0-9]/ { sub(/[0-9]+/, ($0 ~ /1056964608/) ? "1073741824" : "1056964608"); f = 0 } { print }' \
      "$1/draws.json" > "$1/draws.json.new" && mv "$1/draws.json.new" "$1/draws.json"
  }
  for scene in "${scenes[@]}"; do
    s=$(basename "$scene" .gltf)
    for tier in sm3 ps20; do
      for pair in essl300:gles3 glsl330:gl33 essl100:gles2; do
        target=${pair%%:*} api=${pair##*:} name="$s $tier $target"
        # ES 2.0 has no fp16 render targets: scenes on the float HDR path run the integer path there.
        hdr=(); [ "$api" = gles2 ] && hdr=(--hdr integer)
        rm -rf bb dd frame.exr frame.png
        run variants "$scene" --tier $tier --target $target "${hdr[@]}" -o bb
        if crashed "$name bundle"; then continue; fi
        if [ "$RC" -ne 0 ]; then fail "$name bundle" "status $RC: $(head -n 1 "$ERR")"; continue; fi
        # the browser targets' bundles, for the check against Chromium's reflection below
        [ "$target" = glsl330 ] || { mkdir -p web && cp -r bb "web/${s}_${tier}_$target"; }
        run render "$scene" --tier $tier --backend egl --api $api "${hdr[@]}" --size 160x90 -o frame --dump-draws dd
        if crashed "$name render"; then continue; fi
        if [ "$RC" -ne 0 ] || [ ! -s dd/draws.json ]; then fail "$name render --dump-draws" "status $RC: $(head -n 1 "$ERR")"; continue; fi
        got=$("${TIMEOUT[@]}" "$BARE" --bundle bb --dump dd --api $api 2>&1); st=$?
        if [ $st -eq 0 ] && echo "$got" | grep -q ', 0 channels differ'; then pass "$name: bare GL = tiershade render ($got)"
        else fail "$name: bare GL = tiershade render" "status $st: $got"; fi
        corrupt dd
        got=$("${TIMEOUT[@]}" "$BARE" --bundle bb --dump dd --api $api 2>&1); st=$?
        if [ $st -eq 1 ]; then pass "$name: a corrupted u_view_proj is caught"
        else fail "$name: a corrupted u_view_proj is caught" "status $st: $got"; fi
      done
    done
  done
  # Every program of the WebGL bundles above, on one page in headless Chromium: what
  # getActiveAttrib/getActiveUniform report lies in the declared interface, and every entry
  # may_trim does not list is active at its declared size (docs/bundles.md, "Checked in a browser").
  run check-bundle web/*
  if crashed "scene bundles in Chromium"; then :
  elif [ "$RC" -eq 0 ] && grep -q '0 active entries outside it, 0 required entries inactive' "$OUT" &&
    grep -q '^ok: every manifest agrees' "$OUT"; then
    pass "scene bundles in Chromium: $(sed -n 's/^\([0-9]* bundles.*\)/\1/p' "$OUT"); $(grep '^Mesa' "$OUT")"
  else fail "scene bundles in Chromium" "status $RC: $(grep -m 3 -E '^FAIL|^declared' "$OUT" | tr '\n' ' ') $(head -n 1 "$ERR")"; fi
fi

cli_finish
