#!/usr/bin/env bash
# tiershade — tests/cli/test_ambient.sh
#
# `tiershade ambient PROBE [--fit lsq|mean|lsq-pixels|lsq-radiance] [--json] [--error]`
# (glue/cli/cmd_ambient.cpp, docs/irradiance_volume.md).
#   usage: tests/cli/test_ambient.sh path/to/tiershade
# Checks: bad command lines fail with status 2 and say what is wrong; a missing or truncated probe
# fails with status 1 naming the file; the text form lists the six faces in Source's order, all
# non-negative; --json holds the same six colours; a constant probe (written here: flat RGBE
# scanlines of 1.0) gives six faces of 1 (mean to the printed digits; lsq within 1e-4, its
# quadrature error at 256 x 128, tests/unit/test_ambient_fit.cpp); on grace, lsq's irradiance RMS is
# at or below the mean's on both metrics (--error).
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup ambient_cli 300 "$@"
GRACE="$HERE/../shared/data/probes/grace.hdr"

expect() {  # name, expected status, stderr pattern, args...
  local name=$1 want=$2 pat=$3
  shift 3
  run "$@"
  if cli_crashed; then fail "$name" "crashed (status $RC): $(head -c 300 "$ERR")"; return; fi
  if [ "$RC" -ne "$want" ]; then fail "$name" "status $RC, expected $want: $(head -n 2 "$ERR")"; return; fi
  if ! grep -qE -- "$pat" "$ERR"; then fail "$name" "stderr lacks /$pat/: $(head -n 2 "$ERR")"; return; fi
  pass "$name"
}

expect "no probe is a usage error" 2 "expected one probe file" ambient
expect "two probes are a usage error" 2 "expected one probe file" ambient a.hdr b.hdr
expect "unknown fit is refused" 2 "--fit: 'cubic'" ambient "$GRACE" --fit cubic
expect "missing probe names the file" 1 "nope\.hdr" ambient "$TMP/nope.hdr"
head -c 2000 "$GRACE" > "$TMP/cut.hdr"
expect "truncated probe names the file" 1 "cut\.hdr" ambient "$TMP/cut.hdr"

# The text form: a title line, then the six faces in Source's order, three non-negative numbers each.
run ambient "$GRACE"
if [ "$RC" -ne 0 ]; then
  fail "grace text form" "status $RC: $(head -n 2 "$ERR")"
else
  faces=$(awk 'NR > 1 { printf "%s ", $1 }' "$OUT")
  neg=$(awk 'NR > 1 && ($2 < 0 || $3 < 0 || $4 < 0 || NF != 4)' "$OUT")
  if [ "$faces" != "+X -X +Y -Y +Z -Z " ] || [ -n "$neg" ]; then
    fail "grace text form" "faces '$faces', bad lines '$neg'"
  else
    pass "grace text form: six non-negative faces in Source's order"
  fi
fi
cp "$OUT" "$TMP/text.txt"

# --json: the same six colours (the text prints 9 significant digits: equal within 1e-6 relative).
run ambient "$GRACE" --json
if [ "$RC" -ne 0 ]; then
  fail "grace json form" "status $RC: $(head -n 2 "$ERR")"
else
  flat=$(tr -d ' \n' < "$OUT")
  bad=""
  for face in +X -X +Y -Y +Z -Z; do
    j=$(printf '%s' "$flat" | sed -n "s/.*\"$face\":\[\([^]]*\)\].*/\1/p" | tr ',' ' ')
    t=$(awk -v f="$face" '$1 == f { print $2, $3, $4 }' "$TMP/text.txt")
    ok=$(echo "$j $t" | awk '{ for (i = 1; i <= 3; ++i) { d = $i - $(i + 3); if (d < 0) d = -d;
                                 if (NF != 6 || d > 1e-6 * ($(i + 3) + 1e-30)) { print "no"; exit } } print "yes" }')
    [ "$ok" = yes ] || bad="$bad $face(json '$j' text '$t')"
  done
  if [ -n "$bad" ] || ! printf '%s' "$flat" | grep -q '"fit":"lsq"'; then
    fail "grace json form" "differs from the text form:$bad"
  else
    pass "grace json form: the text form's six colours and the fit's name"
  fi
fi

# A constant probe of radiance 1 (RGBE 128 128 128 129 = 1.0; flat scanlines: the first bytes are not 2 2).
{ printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 128 +X 256\n'; yes $'\x80\x80\x80\x81' | tr -d '\n' | head -c $((256 * 128 * 4)); } > "$TMP/one.hdr"
for fit in mean lsq; do
  run ambient "$TMP/one.hdr" --fit "$fit"
  tol=1e-4
  [ "$fit" = mean ] && tol=1e-8
  bad=$(awk -v t="$tol" 'NR > 1 { for (i = 2; i <= 4; ++i) { d = $i - 1; if (d < 0) d = -d; if (d > t) print } }' "$OUT")
  if [ "$RC" -ne 0 ] || [ -n "$bad" ] || [ "$(wc -l < "$OUT")" -ne 7 ]; then
    fail "constant probe gives six faces of 1 ($fit)" "status $RC: $(tr '\n' '|' < "$OUT") $(head -n 1 "$ERR")"
  else
    pass "constant probe gives six faces of 1 ($fit, tolerance $tol)"
  fi
done

# --error on grace: lsq at or below the mean on both metrics.
run ambient "$GRACE" --fit mean --error
mean_line=$(grep "irradiance RMS" "$OUT")
run ambient "$GRACE" --fit lsq --error
lsq_line=$(grep "irradiance RMS" "$OUT")
ok=$(echo "$mean_line $lsq_line" | awk '{ n = 0; for (i = 1; i <= NF; ++i) if ($i ~ /^[0-9.]+$/) v[n++] = $i;
                                           print (n == 4 && v[2] <= v[0] && v[3] <= v[1]) ? "yes" : "no" }')
if [ "$ok" = yes ]; then
  pass "lsq irradiance RMS <= mean's on grace (mean: ${mean_line#*: }; lsq: ${lsq_line#*: })"
else
  fail "lsq irradiance RMS <= mean's on grace" "mean '$mean_line' lsq '$lsq_line'"
fi
cli_finish
