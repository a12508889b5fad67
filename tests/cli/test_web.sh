#!/usr/bin/env bash
# tiershade — tests/cli/test_web.sh
#
# The WebGL 2 demo page (tiershade web; docs/bundles.md, "The WebGL 2 demo page").
#   usage: tests/cli/test_web.sh path/to/tiershade
# Checks: bad input (no --bundle, an essl100 bundle, a dump without a camera, -o onto a foreign
# directory) gives one line on stderr and no page; for scenes/model_lighting.gltf and
# scenes/world_lighting.gltf (sm3, 160x90): the page's first frame in headless Chromium, read back
# as RGBA32F, against tiershade render's frame on llvmpipe: the camera uniforms the page recomputes
# in JavaScript equal the dump's bit for bit, and the pixels lie within the stated tolerance (the
# model scene at the default, the world scene at the wider one its lightmaps need; both justified in
# docs/bundles.md); negative controls: a dump whose ambient cube is zeroed, and one whose camera
# moved, both fail. About 25 s (five browser runs).
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup web 200 "$@"

one_line_error() {  # NAME STATUS PATTERN
  if [ "$RC" -eq "$2" ] && [ "$(grep -c '' "$ERR")" -eq 1 ] && grep -qF -- "$3" "$ERR" && ! cli_crashed; then pass "$1"
  else fail "$1" "status $RC (want $2): $(head -n 2 "$ERR" | tr '\n' ' ')"; fi
}

ML="$HERE/scenes/model_lighting.gltf"
run variants "$ML" --tier sm3 --target essl300 -o mb
[ "$RC" -eq 0 ] || fail "model bundle" "status $RC: $(head -n 1 "$ERR")"
run render "$ML" --tier sm3 --backend egl --api gles3 --size 160x90 -o mf --dump-draws md --quiet
[ "$RC" -eq 0 ] || fail "model render --dump-draws" "status $RC: $(head -n 1 "$ERR")"
if grep -q '"camera"' md/draws.json 2> /dev/null && grep -q '"projection": *"perspective"' md/draws.json; then
  pass "the draw dump records the camera"
else fail "the draw dump records the camera" "no camera in md/draws.json"; fi

# --- bad input ----------------------------------------------------------------------------
run web --dump md -o page
one_line_error "web needs --bundle" 2 "needs --bundle BUNDLE and --dump DUMP"
run variants "$ML" --tier sm3 --target essl100 -o mb1
run web --bundle mb1 --dump md -o page
one_line_error "an essl100 bundle is refused" 2 "mb1/manifest.json: target essl100: the demo page is WebGL 2"
cp -r md mdnocam && python3 - mdnocam/draws.json << 'EOF2'
import json, sys
d = json.load(open(sys.argv[1])); del d["camera"]; json.dump(d, open(sys.argv[1], "w"))
EOF2
run web --bundle mb --dump mdnocam -o page
one_line_error "a dump without a camera is refused" 2 "mdnocam/draws.json: no camera"
mkdir -p foreign && echo keep > foreign/file.txt
run web --bundle mb --dump md -o foreign
if [ "$RC" -eq 1 ] && [ "$(cat foreign/file.txt)" = keep ] && [ ! -e foreign/index.html ]; then pass "-o onto a foreign directory is refused"
else fail "-o onto a foreign directory is refused" "status $RC: $(head -n 1 "$ERR")"; fi
[ -e page ] && fail "no page after the errors" "page exists" || pass "no page after the errors"

# --- the page's first frame against tiershade render -----------------------------------------
# check NAME BUNDLE DUMP [--tolerance A,R,S]: the page's frame within the tolerance, camera exact.
check() {
  local name=$1 b=$2 d=$3
  shift 3
  rm -rf page
  run web --bundle "$b" --dump "$d" -o page --check "$@"
  if [ "$RC" -eq 0 ] && grep -q ': 0 of [1-9][0-9]* elements differ' "$OUT" && grep -q '^ok: ' "$OUT" &&
    [ -s page/index.html ] && [ -s page/webgl_scene.js ] && [ -s page/scene.js ]; then
    pass "$name: $(grep -E '^camera|^pixels' "$OUT" | sed 's/camera uniforms recomputed in JavaScript: //' | tr '\n' ';')"
  else fail "$name" "status $RC: $(grep -E '^camera|^pixels|^FAIL' "$OUT" | tr '\n' ' ') $(head -n 1 "$ERR")"; fi
}
check "model_lighting in WebGL 2 = tiershade render" mb md

# world_lighting: its lightmaps (RGBE) and albedo textures, minified without mipmaps at 160x90, are
# sampled LINEAR: each implementation's sub-texel weights (not specified by GLSL ES; dEQP's
# tcuTexLookupVerifier allows 8 weight bits) move texel-edge pixels by up to a quarter of the value
# (RGBE decodes after filtering). Measured: 87 % of pixels within 1/256, 0.78 % outside this bound.
WL="$HERE/scenes/world_lighting.gltf"
run variants "$WL" --tier sm3 --target essl300 -o wb
run render "$WL" --tier sm3 --backend egl --api gles3 --size 160x90 -o wf --dump-draws wd --quiet
if [ "$RC" -eq 0 ]; then check "world_lighting in WebGL 2 = tiershade render (A 1/16, R 1/4, 2 %)" wb wd --tolerance 0.0625,0.25,0.02
else fail "world render --dump-draws" "status $RC: $(head -n 1 "$ERR")"; fi

# --- negative controls ----------------------------------------------------------------------
doctor() {  # doctor DIR PYTHON: a copy of md with draws.json edited (d: the dump)
  rm -rf "$1" && cp -r md "$1" && python3 - "$1/draws.json" "$2" << 'EOF2'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[2])
json.dump(d, open(sys.argv[1], "w"))
EOF2
}
doctor mdamb 'for dr in d["draws"]:
    for u in dr["uniforms"]:
        if u["name"] == "u_ambient_cube": u["bits"] = [0] * len(u["bits"])'
rm -rf page
run web --bundle mb --dump mdamb -o page --check
if [ "$RC" -eq 1 ] && grep -q '^FAIL: outside the tolerance' "$OUT"; then pass "a zeroed ambient cube is caught ($(grep '^pixels' "$OUT" | cut -d';' -f3))"
else fail "a zeroed ambient cube is caught" "status $RC: $(grep -E '^pixels|^ok|^FAIL' "$OUT" | tr '\n' ' ') $(head -n 1 "$ERR")"; fi
doctor mdcam 'd["camera"]["eye"][0] += 1e-3'
rm -rf page
run web --bundle mb --dump mdcam -o page --check
if [ "$RC" -eq 1 ] && grep -q ': [1-9][0-9]* of [0-9]* elements differ' "$OUT"; then pass "a moved camera is caught ($(grep '^camera' "$OUT" | sed 's/.*: //'))"
else fail "a moved camera is caught" "status $RC: $(grep -E '^camera|^ok|^FAIL' "$OUT" | tr '\n' ' ') $(head -n 1 "$ERR")"; fi

cli_finish
