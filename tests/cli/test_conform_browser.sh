#!/usr/bin/env bash
# tiershade — tests/cli/test_conform_browser.sh
#
# `tiershade conform --backend chromium` (glue/browser, docs/conformance.md "In a browser"):
#   usage: tests/cli/test_conform_browser.sh path/to/tiershade
# Small runs of the real browser (headless Chromium, ANGLE on SwiftShader; each start ~1.5 s):
# hdr_tonemap on WebGL 1 and 2 is 100 % inside its bounds on both grids (its results come back
# through the page, so a broken page, readback or decode fails here); skybox's hard grid lands
# outside on the exact cube corner (at --size 16, the size make test runs: which pixels of the case
# land outside depends on the grid), which fails without the known-outside list and passes, noted,
# with it; a list naming a case that is inside fails as stale; the option errors name the option.
# make test runs every variant on both WebGL versions separately (tests/run_tests.sh).
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup conform_browser 300 "$@"
KNOWN=$HERE/tests/conform/chromium_known_outside.txt

run conform --backend chromium --shader hdr_tonemap --size 8 --json
if cli_crashed || [ "$RC" -ne 0 ]; then
  fail hdr_tonemap_in_browser "status $RC: $(head -c 300 "$OUT") $(head -n 3 "$ERR")"
else
  verdict=$(python3 - "$OUT" <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))
apis = {r["api"] for r in runs}
bad = [r for r in runs if not r["passed"] or r["outside"] or r["backend"] != "chromium"]
if apis != {"webgl1", "webgl2"} or {r["set"] for r in runs} != {"random", "hard"}: print("apis/sets: %s" % sorted(apis))
elif bad: print("outside: %s %s %s" % (bad[0]["variant"], bad[0]["api"], bad[0]["set"]))
else: print("ok %d" % len(runs))
PY
)
  case $verdict in
    ok*) pass "hdr_tonemap_in_browser_inside (${verdict#ok } runs)" ;;
    *) fail hdr_tonemap_in_browser_inside "$verdict" ;;
  esac
fi

run conform --backend chromium --api webgl2 --shader skybox --tier ps20 --set hard --size 16
if [ "$RC" -eq 1 ] && grep -q '^FAIL skybox' "$OUT" && grep -q 'cube corner' "$OUT"; then pass skybox_corner_outside_fails
else fail skybox_corner_outside_fails "status $RC: $(tail -n 4 "$OUT")"; fi

run conform --backend chromium --api webgl2 --shader skybox --tier ps20 --set hard --size 16 --known-outside "$KNOWN"
if [ "$RC" -eq 0 ] && grep -q 'known outside in a browser (cube corner' "$OUT"; then pass skybox_corner_known_passes
else fail skybox_corner_known_passes "status $RC: $(tail -n 4 "$OUT") $(head -n 2 "$ERR")"; fi

printf 'skybox ps20: cube corner |x| = |y| = |z|\nskybox ps20: zero direction (the zenith)\n' > stale.txt
run conform --backend chromium --api webgl2 --shader skybox --tier ps20 --set hard --size 16 --known-outside stale.txt
if [ "$RC" -eq 1 ] && grep -q "hard case 'zero direction (the zenith)' is listed as outside.*stale.txt:2.*delete the line" "$OUT"; then
  pass stale_known_outside_fails
else
  # the case name must exist in skybox.cases for this check to mean anything
  fail stale_known_outside_fails "status $RC: $(tail -n 3 "$OUT")"
fi

printf 'skybox ps20:\n' > bad_list.txt
run conform --backend chromium --api webgl2 --shader skybox --known-outside bad_list.txt
if [ "$RC" -ne 0 ] && grep -q "bad_list.txt:1: expected 'SHADER VARIANT HARD CASE NAME'" "$ERR"; then pass bad_list_line_named
else fail bad_list_line_named "status $RC: $(head -n 2 "$ERR")"; fi

run conform --backend egl --api webgl2 --shader skybox
if [ "$RC" -ne 0 ] && grep -q 'needs --backend chromium' "$ERR"; then pass webgl_api_needs_chromium
else fail webgl_api_needs_chromium "status $RC: $(head -n 2 "$ERR")"; fi

run conform --backend chromium --api gles3 --shader skybox
if [ "$RC" -ne 0 ] && grep -q "webgl1, webgl2 or all, not 'gles3'" "$ERR"; then pass chromium_needs_webgl_api
else fail chromium_needs_webgl_api "status $RC: $(head -n 2 "$ERR")"; fi

TIERSHADE_CHROMIUM=$TMP/no_such_browser run conform --backend chromium --shader skybox --size 4
if [ "$RC" -ne 0 ] && ! cli_crashed && grep -q 'TIERSHADE_CHROMIUM.*no_such_browser.*not an executable' "$ERR"; then
  pass missing_browser_named
else
  fail missing_browser_named "status $RC: $(head -n 2 "$ERR")"
fi

# The page a user opens on their own device (conform --page): written atomically, it checks itself
# in the browser; its own count of channels outside must equal what tiershade counts from the same
# browser's results (two implementations of the check, JavaScript and C++, agree).
run conform --page page --shader skybox --size 16
if [ "$RC" -eq 0 ] && [ -s page/index.html ] && [ -s page/job.js ] && [ -s page/webgl_conform.js ] && ! ls -d page.tmp.* > /dev/null 2>&1; then
  pass page_written
else
  fail page_written "status $RC: $(head -n 2 "$ERR")"
fi
BROWSER=${TIERSHADE_CHROMIUM:-$(command -v chromium || command -v chromium-browser)}
"${TIMEOUT[@]}" "$BROWSER" --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --disable-gpu-sandbox \
  --disable-background-networking --disable-component-update --disable-sync --no-first-run --user-data-dir="$TMP/profile" \
  --dump-dom "file://$TMP/page/index.html" > page_dom.txt 2> /dev/null
page_out=$(grep -o '^V [0-9]* [0-9]* [0-9]* [0-9]*' page_dom.txt | awk '{s += $5} END {print NR, s}')
run conform --backend chromium --api webgl2 --shader skybox --size 16 --json
cpp_out=$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(len(r), sum(x["outside"] for x in r))' "$OUT" 2> /dev/null)
if [ -n "$page_out" ] && [ "$page_out" = "$cpp_out" ] && [ "${page_out#* }" -gt 0 ] && grep -q 'runs inside their GLSL ES bounds' page_dom.txt; then
  pass "page_checks_itself_as_tiershade_does (runs, channels outside: $page_out)"
else
  fail page_checks_itself_as_tiershade_does "page '$page_out', tiershade '$cpp_out'"
fi
mkdir -p mine && echo keep > mine/notes.txt
run conform --page mine --shader skybox --size 4
if [ "$RC" -ne 0 ] && grep -q 'mine' "$ERR" && [ -s mine/notes.txt ]; then pass page_keeps_a_foreign_directory
else fail page_keeps_a_foreign_directory "status $RC: $(head -n 2 "$ERR")"; fi

cli_finish
