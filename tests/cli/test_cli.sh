#!/usr/bin/env bash
# tiershade — tests/cli/test_cli.sh
#
# Command-line checks of the tiershade program.
#   usage: tests/cli/test_cli.sh path/to/tiershade
# Prints "PASS name" / "FAIL name: detail" per check (and "SKIP name: why" for
# subcommands that are still being written), exits 1 if any check failed.
#
# Bad input must give exit status 2 for usage errors (glue/cli/args.h: every bad
# argument or input file gives "tiershade <cmd>: <what is wrong>" and status 2)
# or 1 for runtime failures, a one-line message on stderr naming the problem
# (and file:line for input files), nothing on stdout, and never a crash: a
# status >= 128 or a sanitizer report on stderr is a FAIL. Good input must give
# status 0 and well-formed output. Needs only bash, coreutils, grep and awk.
set -u

. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup cli 120 "$@"
# shows the first line of stderr (for details)
err1() { head -n 1 "$ERR"; }
nlines() { grep -c '' "$1"; }

# crashed NAME: FAIL and return 0 when the last run crashed, timed out or had a sanitizer report.
crashed() {
  local name=$1
  if [ "$RC" -ge 124 ] && [ "$RC" -ne 125 ] || grep -qE 'AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:|terminate called|Segmentation fault' "$ERR"; then
    fail "$name" "crashed or timed out (status $RC): $(grep -m1 -E 'Sanitizer|runtime error|terminate|Segmentation' "$ERR" || err1)"
    return 0
  fi
  return 1
}

# expect_fail NAME STATUS 'pattern|pattern...' -- ARGS...
#   The message must be a single line on stderr containing every pattern (fixed strings,
#   separated by '|'), stdout must be empty, and the status must be STATUS.
expect_fail() {
  local name=$1 status=$2 patterns=$3
  shift 4
  run "$@"
  crashed "$name" && return
  local problems=""
  [ "$RC" -eq "$status" ] || problems+="status $RC, want $status; "
  [ -s "$ERR" ] || problems+="no message on stderr; "
  [ "$(nlines "$ERR")" -le 1 ] || problems+="message has $(nlines "$ERR") lines; "
  [ -s "$OUT" ] && problems+="stdout not empty ($(head -c 80 "$OUT")); "
  local p IFS='|'
  for p in $patterns; do
    grep -qF -- "$p" "$ERR" || problems+="message lacks '$p'; "
  done
  if [ -z "$problems" ]; then pass "$name"; else fail "$name" "${problems}stderr: $(err1)"; fi
}

# json_ok FILE: structural JSON check without python. Strings become S, numbers and
# literals V; then innermost arrays/objects are reduced to V until one value is left.
json_ok() {
  awk '
    { text = text $0 "\n" }
    END {
      n = length(text); sk = ""; i = 1
      while (i <= n) {
        c = substr(text, i, 1)
        if (c == " " || c == "\t" || c == "\n" || c == "\r") { i++; continue }
        if (c == "\"") {
          i++; closed = 0
          while (i <= n) {
            d = substr(text, i, 1)
            if (d == "\\") { i += 2; continue }
            if (d == "\n") break
            if (d == "\"") { closed = 1; i++; break }
            i++
          }
          if (!closed) { print "unterminated string"; exit 1 }
          sk = sk "S"; continue
        }
        if (index("[]{},:", c)) { sk = sk c; i++; continue }
        rest = substr(text, i)
        if (match(rest, /^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) { sk = sk "V"; i += RLENGTH; continue }
        if (match(rest, /^(true|false|null)/)) { sk = sk "V"; i += RLENGTH; continue }
        print "unexpected character " c " at offset " i; exit 1
      }
      for (;;) {
        before = sk
        gsub(/\[\]/, "V", sk); gsub(/\{\}/, "V", sk)
        gsub(/\[[SV](,[SV])*\]/, "V", sk)
        gsub(/\{S:[SV](,S:[SV])*\}/, "V", sk)
        if (sk == before) break
      }
      if (sk != "V" && sk != "S") { print "not one JSON value (skeleton " substr(sk, 1, 60) ")"; exit 1 }
    }' "$1"
}

# json_keys NAME FILE KEY...: every object line of FILE has every "KEY":
json_keys() {
  local name=$1 file=$2
  shift 2
  local objs missing="" k
  objs=$(grep -c '^ *{' "$file")
  if [ "$objs" -eq 0 ]; then fail "$name" "no objects"; return; fi
  for k in "$@"; do
    [ "$(grep '^ *{' "$file" | grep -c "\"$k\":")" -eq "$objs" ] || missing+=" $k"
  done
  if [ -z "$missing" ]; then pass "$name"; else fail "$name" "objects without key(s):$missing"; fi
}

# json_checks WHAT STATUSES KEY...: after `run <WHAT> --json ...`: the status is one of STATUSES,
# stdout (kept as $TMP/WHAT.json) is one JSON value, every object has every KEY.
json_checks() {
  local what=$1 statuses=$2
  shift 2
  cp "$OUT" "$TMP/$what.json"
  case " $statuses " in
    *" $RC "*) pass "${what}_json_status" ;;
    *) fail "${what}_json_status" "status $RC, want one of $statuses: $(err1)" ;;
  esac
  if msg=$(json_ok "$TMP/$what.json"); then pass "${what}_json_valid"; else fail "${what}_json_valid" "$msg"; fi
  json_keys "${what}_json_keys" "$TMP/$what.json" "$@"
}

# json_objects NAME FILE TEXT WHY: every object line of FILE contains TEXT.
json_objects() {
  if ! grep '^ *{' "$2" | grep -qvF -- "$3"; then pass "$1"; else fail "$1" "$4"; fi
}

ML=model_lighting

# ---------------------------------------------------------------- bad input
run
if ! crashed no_command; then
  if [ "$RC" -eq 2 ] && grep -q usage "$ERR" && [ ! -s "$OUT" ]; then pass no_command
  else fail no_command "status $RC, want 2 and usage on stderr: $(err1)"; fi
fi
run frobnicate
if ! crashed unknown_command; then
  if [ "$RC" -eq 2 ] && head -n 1 "$ERR" | grep -qF "unknown command 'frobnicate'" && [ ! -s "$OUT" ]; then
    pass unknown_command
  else fail unknown_command "status $RC, want 2; first line: $(err1)"; fi
fi

expect_fail unknown_option          2 "unknown option '--bogus'"              -- variants --bogus
expect_fail unknown_option_eq       2 "unknown option '--bogus'"              -- conform --bogus=1
expect_fail option_missing_value    2 "--shader|needs a value"                -- variants --shader
expect_fail option_missing_value_last 2 "--size|needs a value"                -- conform --tier ps20 --size
expect_fail flag_given_a_value      2 "--count|takes no value"                -- variants --count=3
expect_fail option_given_twice      2 "--shader|more than once"               -- probe --shader $ML --shader $ML --variant 0
expect_fail unexpected_argument     2 "unexpected argument 'extra'"           -- variants extra
expect_fail size_zero               2 "--size|'0'"                            -- conform --size 0 --tier ps20 --backend osmesa
expect_fail size_negative           2 "--size|'-5'"                           -- conform --size -5 --tier ps20 --backend osmesa
expect_fail size_not_a_number       2 "--size|'abc'"                          -- conform --size abc --tier ps20 --backend osmesa
expect_fail size_too_large          2 "--size|'99999'"                        -- conform --size 99999 --tier ps20 --backend osmesa
expect_fail size_empty              2 "--size"                                -- conform --size= --tier ps20 --backend osmesa
expect_fail size_overflow           2 "--size"                                -- conform --size 99999999999999999999999 --tier ps20
expect_fail probe_size_zero         2 "--size|'0'"                            -- probe --shader $ML --variant 0 --size 0
expect_fail seed_negative           2 "--seed|'-1'"                           -- conform --seed -1 --tier ps20 --backend osmesa
expect_fail unknown_tier            2 "unknown tier 'ps30'"                   -- variants --tier ps30
expect_fail unknown_tier_budget     2 "unknown tier 'sm4'"                    -- budget --tier sm4
expect_fail unknown_tier_conform    2 "unknown tier 'ps1'"                    -- conform --tier ps1 --backend osmesa
expect_fail unknown_shader          2 "no_such_shader"                        -- variants --shader no_such_shader
expect_fail unknown_shader_conform  2 "no_such_shader"                        -- conform --shader no_such_shader --backend osmesa
expect_fail unknown_shader_probe    2 "no_such_shader"                        -- probe --shader no_such_shader --variant 0
expect_fail unknown_variant_index   2 "'9999'|$ML"                            -- probe --shader $ML --variant 9999
expect_fail unknown_variant_name    2 "'ps20:BOGUS=1'"                        -- assemble --shader $ML --variant ps20:BOGUS=1
expect_fail unknown_variant_conform 2 "'ps20:ALBEDO_TEXTURE=7'"               -- conform --shader $ML --variant ps20:ALBEDO_TEXTURE=7 --backend osmesa
expect_fail variant_without_shader  2 "--variant|--shader"                    -- variants --variant 0
expect_fail variant_without_shader_budget 2 "--variant|--shader"              -- budget --variant 0
expect_fail backend_cpu_conform     2 "--backend"                             -- conform --backend cpu --tier ps20 --size 4
expect_fail backend_unknown_conform 2 "unknown backend 'vulkan'"              -- conform --backend vulkan --tier ps20 --size 4
expect_fail api_unknown_conform     2 "unknown api 'gles4'"                   -- conform --api gles4 --tier ps20 --size 4
expect_fail osmesa_gles2_conform    2 "osmesa|gles2"                          -- conform --backend osmesa --api gles2 --tier ps20 --size 4
expect_fail osmesa_gles3_probe      2 "osmesa|gles3"                          -- probe --shader $ML --variant 0 --backend osmesa --api gles3
expect_fail backend_cpu_probe       2 "cpu"                                   -- probe --shader $ML --variant 0 --backend cpu
expect_fail api_unknown_probe       2 "gles9"                                 -- probe --shader $ML --variant 0 --api gles9
expect_fail input_set_unknown       2 "'bogus'"                               -- conform --set bogus --tier ps20 --backend osmesa
expect_fail probe_needs_shader      2 "--shader"                              -- probe --variant 0
expect_fail probe_grid_bad          2 "--grid|'hard:1'"                       -- probe --shader $ML --variant 0 --grid hard:1
expect_fail probe_grid_outside      2 "--grid"                                -- probe --shader $ML --variant 0 --grid hard:9,9 --size 4
expect_fail probe_grid_unknown_set  2 "'sparse:0,0'"                          -- probe --shader $ML --variant 0 --grid sparse:0,0

MISSING="$TMP/no_such_dir/pixel.txt"
expect_fail probe_missing_input     2 "$MISSING"                              -- probe --shader $ML --variant 0 --input "$MISSING"
# A directory is not an input file.
mkdir -p "$TMP/a_directory"
expect_fail probe_input_is_directory 2 "$TMP/a_directory"                     -- probe --shader $ML --variant 0 --input "$TMP/a_directory"

# bad_input NAME TEXT PATTERNS: probe --input refuses a file holding TEXT (printf format) with
# a message naming the file and the place; @ in PATTERNS stands for the file's path.
bad_input() {
  local f="$TMP/$1.txt"
  printf "$2" > "$f"
  expect_fail "probe_input_$1" 2 "${3//@/$f}" -- probe --shader $ML --variant 0 --input "$f"
}
bad_input unknown_slot       '# pixel input\nnormal 0 0 1\nbogus_slot 1 2 3\n' "@:3:|'bogus_slot'"
bad_input malformed_number   'normal 0 0 1\n\nposition 1.0 2.x 3\n'           "@:3:|position|2.x"
bad_input too_many_numbers   'normal 1 2 3 4 5\n'                              "@:1:|normal"
bad_input no_numbers         'uv   # nothing\n'                                "@:1:|uv"
expect_fail probe_set_without_eq    2 "--set|'normal'"                        -- probe --shader $ML --variant 0 --set normal
expect_fail probe_set_unknown_slot  2 "--set|'nrm'"                           -- probe --shader $ML --variant 0 --set nrm=0,0,1
expect_fail probe_set_malformed     2 "--set|normal|1,,x"                     -- probe --shader $ML --variant 0 --set normal=1,,x
expect_fail assemble_unknown_target 2 "unknown target 'hlsl'"                 -- assemble --shader $ML --variant 0 --target hlsl
expect_fail assemble_needs_variant  2 "--variant"                             -- assemble --shader $ML

# ---------------------------------------------------------------- good input
run --help
if ! crashed help; then
  if [ "$RC" -eq 0 ] && grep -q usage "$OUT"; then pass help; else fail help "status $RC: $(err1)"; fi
fi
run help
if ! crashed help_word; then
  if [ "$RC" -eq 0 ] && grep -q usage "$OUT"; then pass help_word; else fail help_word "status $RC: $(err1)"; fi
fi
for c in variants assemble budget conform probe; do
  run $c --help
  crashed "help_$c" && continue
  if [ "$RC" -eq 0 ] && grep -q "usage: tiershade $c" "$OUT" && [ ! -s "$ERR" ]; then pass "help_$c"
  else fail "help_$c" "status $RC; stdout: $(head -n 1 "$OUT"); stderr: $(err1)"; fi
done
for c in demo bench fold; do
  run $c --help
  crashed "help_$c" && continue
  if [ "$RC" -eq 0 ] && grep -q "usage: tiershade $c" "$OUT" && [ ! -s "$ERR" ]; then pass "help_$c"
  else fail "help_$c" "status $RC; stdout: $(head -n 1 "$OUT"); stderr: $(err1)"; fi
done

# lights files (fold, demo): bad files name the file and line; the shipped scene file works.
printf 'point 1 1 1  0 0 0  0 0 0\n' > "$TMP/zero_atten.lights"
printf '# two lines\nspot 1 1\n' > "$TMP/short.lights"
printf 'sun 1 1 1 0 0 -1\n' > "$TMP/unknown.lights"
printf 'directional 1 1 1  0 0 x\n' > "$TMP/nan.lights"
printf '# nothing\n' > "$TMP/empty.lights"
expect_fail fold_lights_zero_atten 2 "zero_atten.lights:1:|c + l + q" -- fold --lights "$TMP/zero_atten.lights"
expect_fail fold_lights_short      2 "short.lights:2:|wants 15 numbers" -- fold --lights "$TMP/short.lights"
expect_fail fold_lights_unknown    2 "unknown.lights:1:|unknown light type 'sun'" -- fold --lights "$TMP/unknown.lights"
expect_fail fold_lights_not_number 2 "nan.lights:1:|'x' is not a number" -- fold --lights "$TMP/nan.lights"
expect_fail fold_lights_empty      2 "empty.lights|no lights" -- fold --lights "$TMP/empty.lights"
expect_fail fold_lights_missing    2 "cannot read lights file" -- fold --lights "$TMP/nope.lights"
expect_fail fold_lights_directory  2 "cannot read lights file" -- fold --lights "$TMP"
expect_fail fold_bad_center        2 "--center" -- fold --center 1,2
expect_fail demo_lights_short      2 "short.lights:2:" -- demo --lights "$TMP/short.lights" -o "$TMP/demo_bad"
if [ -e "$TMP/demo_bad" ] && [ -n "$(ls -A "$TMP/demo_bad")" ]; then fail demo_bad_no_output "files written"; else pass demo_bad_no_output; fi
expect_fail demo_bad_size          2 "--size" -- demo --size 10 -o "$TMP/demo_bad"
run fold --lights "$HERE/scenes/sphere_grid.lights" --tier ps20
if ! crashed fold_scene_file; then
  if [ "$RC" -eq 0 ] && grep -q "keeps 2 of 6" "$OUT"; then pass fold_scene_file
  else fail fold_scene_file "status $RC; stdout: $(head -n 1 "$OUT"); stderr: $(err1)"; fi
fi

run variants --count
if ! crashed variants_count; then
  if [ "$RC" -eq 0 ] && grep -qxE '[1-9][0-9]*' "$OUT" && [ "$(nlines "$OUT")" -eq 1 ]; then pass variants_count
  else fail variants_count "status $RC; stdout: $(head -c 80 "$OUT")"; fi
fi
TOTAL=$(head -n 1 "$OUT")
# Per tier, --count must agree with the names --list prints (the counts themselves are derived
# from shaders/model_lighting.variants by test_glue), and the tiers add up to the shader's total.
ml_sum=0
for t in ps20 ps2b sm3; do
  run variants --list --shader $ML --tier $t
  crashed "variants_list_$t" && continue
  listed=$(grep -c "^  $t:" "$OUT")
  if [ "$RC" -eq 0 ] && [ "$listed" -gt 0 ] && [ "$(tail -n 1 "$OUT")" = "$listed variants" ]; then pass "variants_list_$t"
  else fail "variants_list_$t" "status $RC; $listed names; last line: $(tail -n 1 "$OUT")"; fi
  run variants --count --shader $ML --tier $t
  crashed "variants_count_$t" && continue
  if [ "$RC" -eq 0 ] && [ "$(cat "$OUT")" = "$listed" ]; then pass "variants_count_$t"
  else fail "variants_count_$t" "status $RC; got '$(head -c 40 "$OUT")', want $listed (from --list)"; fi
  ml_sum=$((ml_sum + listed))
done
run variants --count --shader $ML
if ! crashed variants_count_all_tiers; then
  if [ "$RC" -eq 0 ] && [ "$(cat "$OUT")" = "$ml_sum" ]; then pass variants_count_all_tiers
  else fail variants_count_all_tiers "status $RC; got '$(head -c 40 "$OUT")', want $ml_sum"; fi
fi

run variants --json
if ! crashed variants_json; then
  json_checks variants 0 shader variant tier defines
  objs=$(grep -c '^ *{' "$TMP/variants.json")
  if [ "$objs" = "$TOTAL" ]; then pass variants_json_count_matches_count
  else fail variants_json_count_matches_count "$objs objects, --count says $TOTAL"; fi
fi

run assemble --shader $ML --variant 0 --target essl100
if ! crashed assemble_essl100; then
  if [ "$RC" -eq 0 ] && [ "$(head -n 1 "$OUT")" = "#version 100" ] && grep -q '^#line ' "$OUT" && ! grep -q '#include' "$OUT"
  then pass assemble_essl100; else fail assemble_essl100 "status $RC; first line $(head -n 1 "$OUT"); $(err1)"; fi
fi
run assemble --shader $ML --variant "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,NUM_LIGHTS=4" --target essl300
if ! crashed assemble_by_name_essl300; then
  if [ "$RC" -eq 0 ] && [ "$(head -n 1 "$OUT")" = "#version 300 es" ] && grep -q '^#define NUM_LIGHTS 4' "$OUT"
  then pass assemble_by_name_essl300; else fail assemble_by_name_essl300 "status $RC; $(err1)"; fi
fi

run budget --json --tier ps20 --shader $ML
if ! crashed budget_json; then
  # documented: status 1 when a variant is over budget, 0 otherwise
  json_checks budget "0 1" shader variant tier alu tex total limit_alu limit_tex limit_total
  objs=$(grep -c '^ *{' "$TMP/budget.json")
  if [ "$objs" -eq 12 ]; then pass budget_json_one_object_per_variant; else fail budget_json_one_object_per_variant "$objs objects, want 12"; fi
  json_objects budget_json_tier_filter "$TMP/budget.json" '"tier":"ps20"' "objects of another tier"
  json_objects budget_json_ps20_limits "$TMP/budget.json" '"limit_alu":64,"limit_tex":32,"limit_total":96' \
    "ps20 limits are not 64/32/96"
fi

run conform --json --size 4 --tier ps20 --backend osmesa --shader $ML
if ! crashed conform_json; then
  json_checks conform 0 shader variant tier backend api pixels mismatches max_ulp max_abs
  objs=$(grep -c '^ *{' "$TMP/conform.json")
  # one object per variant (12 in ps20) and input set (random, hard)
  if [ "$objs" -eq 24 ]; then pass conform_json_object_count; else fail conform_json_object_count "$objs objects, want 24"; fi
  json_objects conform_json_backend_filter "$TMP/conform.json" '"backend":"osmesa","api":"gl33"' \
    "objects of another backend/api"
  json_objects conform_json_pixels "$TMP/conform.json" '"pixels":16,' "pixels is not 16 for --size 4"
fi

# probe_ok NAME ARGS...: status 0 and "agree bit for bit"
probe_ok() {
  local name=$1
  shift
  run probe "$@"
  crashed "$name" && return
  if [ "$RC" -eq 0 ] && grep -q "agree bit for bit" "$OUT"; then pass "$name"
  else fail "$name" "status $RC; last line: $(tail -n 1 "$OUT"); stderr: $(err1)"; fi
}
probe_ok probe_valid_pixel --shader $ML --variant 0
probe_ok probe_zero_normal --shader $ML --variant 0 --set normal=0,0,0
probe_ok probe_zero_normal_ps2b_lit --shader $ML --variant "ps2b:ALBEDO_TEXTURE=1,HALF_LAMBERT=1,OUTPUT_MODE=2,NUM_LIGHTS=4" --set normal=0,0,0
probe_ok probe_hard_grid --shader $ML --variant 5 --grid hard:3,2 --size 4
probe_ok probe_egl_gles2 --shader $ML --variant 0 --backend egl --api gles2
GOOD="$TMP/good.txt"
printf '# a pixel, with comments and hex floats\n\nnormal 0 0 1   # up\nalbedo 0x1p-1, 0.5, 0.25 1\nuv 0.25\n' > "$GOOD"
probe_ok probe_input_file --shader $ML --variant 1 --input "$GOOD"

echo "test_cli: $PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
