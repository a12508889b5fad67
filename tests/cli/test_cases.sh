#!/usr/bin/env bash
# tiershade — tests/cli/test_cases.sh
#
# The conformance hard cases as data (tests/conform/<family>.cases, docs/conformance.md).
#   usage: tests/cli/test_cases.sh path/to/tiershade
# Checks: every family has a case file and every case file a family; the binary's (embedded)
# cases are the repository's, name for name, and their count per family is the file's; the
# first and last case of every family reach the hard grid (probe --case) and agree GL = C; a
# user's --cases file replaces a family's cases in conform and probe; a malformed case file
# (unknown slot, function, section or combo, bad or out-of-range number, wrong width, duplicate
# or empty case, unset slot without 'random', a repeat-reading value without [repeat]) and an
# unknown case name are errors naming file:line (status 2, one line, nothing on stdout).
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup cases 300 "$@"
CASES="$HERE/tests/conform"

# --- the files and the binary agree --------------------------------------------------------
run conform --list-cases
if cli_crashed || [ "$RC" -ne 0 ]; then
  fail list_cases "status $RC: $(head -n 1 "$ERR")"
else
  pass list_cases
  listed=$(grep -v '^ ' "$OUT" | cut -d: -f1 | sort | tr '\n' ' ')
  files=$(for f in "$CASES"/*.cases; do basename "$f" .cases; done | sort | tr '\n' ' ')
  if [ -n "$files" ] && [ "$listed" = "$files" ]; then pass one_case_file_per_family
  else fail one_case_file_per_family "families: $listed; case files: $files"; fi
fi

total=0
for f in "$CASES"/*.cases; do
  fam=$(basename "$f" .cases)
  n=$(grep -c '^\[case ' "$f")
  total=$((total + n))
  run conform --list-cases --shader "$fam"
  if [ "$RC" -eq 0 ] && head -n 1 "$OUT" | grep -qF "$fam: $n hard cases (tests/conform/$fam.cases)"; then
    pass "count_$fam"
  else fail "count_$fam" "the file has $n cases; conform says: $(head -n 1 "$OUT") $(head -n 1 "$ERR")"; fi
  sed -n 's/^\[case \(.*\)\]$/\1/p' "$f" > "$TMP/want"
  sed -n 's/^  //p' "$OUT" > "$TMP/got"
  if cmp -s "$TMP/want" "$TMP/got"; then pass "names_$fam"
  else fail "names_$fam" "embedded names differ from $f: $(diff "$TMP/want" "$TMP/got" | head -n 3)"; fi
  for name in "$(head -n 1 "$TMP/want")" "$(tail -n 1 "$TMP/want")"; do
    run probe --shader "$fam" --variant 0 --case "$name" --size 16
    if [ "$RC" -eq 0 ] && grep -qF "hard case: $name" "$OUT" && grep -q "agree bit for bit" "$OUT"; then
      pass "probe_case_${fam}_$name"
    else fail "probe_case_${fam}_$name" "status $RC; $(tail -n 1 "$OUT") $(head -n 1 "$ERR")"; fi
  done
done
echo "# $total hard cases in $CASES"

# The repeat: one hard grid for every INPUT_ENCODING, each case once per encoding.
run probe --shader luminance_compare --variant 1 --case "lum exactly at the bucket min (edge of the sRGB variant)"
if [ "$RC" -eq 0 ] && grep -qF "hard case: lum exactly at the bucket min (edge of the sRGB variant)" "$OUT"; then
  pass probe_case_repeat_value
else fail probe_case_repeat_value "status $RC; $(head -n 2 "$OUT") $(head -n 1 "$ERR")"; fi

# --- a user's case file ---------------------------------------------------------------------
mkdir -p "$TMP/mine"
MINE="$TMP/mine/model_lighting.cases"
printf '# mine\n[case my zero normal]\nrandom\nnormal 0 0 0 0\n\n[case my NaN eye]\nllvmpipe_only\nrandom\neye.xz nan 0x1p-3\n' > "$MINE"
run conform --list-cases --shader model_lighting --cases "$MINE"
if [ "$RC" -eq 0 ] && head -n 1 "$OUT" | grep -qF "model_lighting: 2 hard cases ($MINE)"; then pass user_file_listed
else fail user_file_listed "status $RC; $(head -n 1 "$OUT") $(head -n 1 "$ERR")"; fi
run conform --shader model_lighting --tier ps20 --backend osmesa --set hard --size 3 --verbose --cases "$MINE"
if [ "$RC" -eq 0 ] && grep -q '^conform: 12 runs, 12 passed, 0 failed' "$OUT"; then pass user_file_conform
else fail user_file_conform "status $RC; $(tail -n 1 "$OUT") $(head -n 1 "$ERR")"; fi
run probe --shader model_lighting --variant 0 --cases "$MINE" --case "my NaN eye"
if [ "$RC" -eq 0 ] && grep -qF "hard case: my NaN eye" "$OUT" && grep -qE '^ +eye +nan [^ ]+ 0.125 ' "$OUT"; then
  pass user_file_probe
else fail user_file_probe "status $RC; $(grep -E 'hard case|eye' "$OUT" | tr '\n' ' ') $(head -n 1 "$ERR")"; fi

# --- errors ---------------------------------------------------------------------------------
# bad NAME 'pattern|pattern' FILE-TEXT [FAMILY]: conform --list-cases with that file must fail
# with status 2 and one line naming every pattern.
bad() {
  local name=$1 patterns=$2 text=$3 fam=${4:-model_lighting}
  mkdir -p "$TMP/$name"
  printf '%b' "$text" > "$TMP/$name/$fam.cases"
  run conform --list-cases --shader "$fam" --cases "$TMP/$name/$fam.cases"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  local problems="" p IFS='|'
  [ "$RC" -eq 2 ] || problems+="status $RC, want 2; "
  [ "$(grep -c '' "$ERR")" -eq 1 ] || problems+="$(grep -c '' "$ERR") lines on stderr; "
  [ -s "$OUT" ] && problems+="stdout not empty; "
  for p in $patterns; do grep -qF -- "$p" "$ERR" || problems+="message lacks '$p'; "; done
  if [ -z "$problems" ]; then pass "$name"; else fail "$name" "${problems}stderr: $(head -n 1 "$ERR")"; fi
}
bad error_nonfinite_untagged "model_lighting.cases:3:|'a' writes NaN or Inf|llvmpipe_only" '[case a]\nrandom\nnormal.x inf\n'
bad error_llvmpipe_only_twice "model_lighting.cases:3:|'llvmpipe_only' twice" '[case a]\nllvmpipe_only\nllvmpipe_only\nrandom\nnormal.x inf\n'
bad error_unknown_slot "model_lighting.cases:3:|'bogus'" '[case a]\nrandom\nbogus 1 2 3 4\n'
bad error_unknown_swizzle "model_lighting.cases:3:|'normal.q'" '[case a]\nrandom\nnormal.q 1\n'
bad error_bad_number "model_lighting.cases:4:|'1x'" '[case a]\nrandom\n\nnormal 0 0 1x 0\n'
bad error_number_out_of_range "model_lighting.cases:3:|'1e-50'|outside the float range" '[case a]\nrandom\nnormal 1e-50 0 0 0\n'
bad error_too_few_values "model_lighting.cases:3:|wants 4 values, got 3" '[case a]\nrandom\nnormal 0 0 1\n'
bad error_too_many_values "model_lighting.cases:3:|'params.x' wants 1 values, got 2" '[case a]\nrandom\nparams.x 1 2\n'
bad error_duplicate_case "model_lighting.cases:4:|duplicate case 'a'|line 1" '[case a]\nrandom\nuv 0 0 0 0\n[case a]\nrandom\nuv 1 1 0 0\n'
bad error_empty_case "model_lighting.cases:2:|case 'b' sets no slot" '# an empty case\n[case b]\nrandom\n'
bad error_unset_without_random "model_lighting.cases:1:|leaves|unset|random" '[case c]\nnormal 0 0 1 0\n'
bad error_unknown_function "model_lighting.cases:3:|unknown function 'foo'" '[case a]\nrandom\nnormal foo(1) 0 0 0\n'
bad error_function_width "model_lighting.cases:3:|normalize()" '[case a]\nrandom\nnormal normalize(uv) 0\n'
bad error_unclosed_call "model_lighting.cases:3:|mul()" '[case a]\nrandom\nnormal mul(normal.xyz, 2 0\n'
bad error_outside_section "model_lighting.cases:1:|outside a section" 'normal 0 0 1 0\n'
bad error_unknown_section "model_lighting.cases:1:|unknown section" '[test]\n'
bad error_no_cases "model_lighting.cases:1:|no [case NAME]" '# nothing\n'
bad error_repeat_unknown_combo "model_lighting.cases:1:|no combo 'NOPE'" '[repeat NOPE]\n0 zero\n[case a]\nrandom\nuv 0 0 0 0\n'
bad error_repeat_value_range "luminance_compare.cases:2:|INPUT_ENCODING|not 7" '[repeat INPUT_ENCODING]\n7 seven\n[case a]\nrandom\nrange 0 1 1 0\n' luminance_compare
bad error_repeat_needed "luminance_compare.cases:3:|[repeat INPUT_ENCODING]" '[case a]\nrandom\nrange.x lum(color, range.z)\n' luminance_compare
mkdir -p "$TMP/nofam"
printf '[case a]\nrandom\nuv 0 0 0 0\n' > "$TMP/nofam/nope.cases"
run conform --list-cases --cases "$TMP/nofam/nope.cases"
if [ "$RC" -eq 2 ] && grep -qF "'nope' is not a shader family" "$ERR"; then pass error_file_of_no_family
else fail error_file_of_no_family "status $RC: $(head -n 1 "$ERR")"; fi
run conform --list-cases --cases "$TMP/no_such_dir/model_lighting.cases"
if [ "$RC" -eq 2 ] && grep -qF "$TMP/no_such_dir/model_lighting.cases: cannot read" "$ERR"; then pass error_missing_file
else fail error_missing_file "status $RC: $(head -n 1 "$ERR")"; fi
run probe --shader model_lighting --variant 0 --case "no such case"
if [ "$RC" -eq 2 ] && grep -qF "unknown hard case 'no such case'" "$ERR" && grep -qF "tests/conform/model_lighting.cases" "$ERR"; then
  pass error_unknown_case_name
else fail error_unknown_case_name "status $RC: $(head -n 1 "$ERR")"; fi

cli_finish
