#!/usr/bin/env bash
# tiershade — tests/cli/test_conform_bounds.sh
#
# `tiershade conform --bounds` (glue/conform/bounds, docs/conformance.md "Error bounds"):
#   usage: tests/cli/test_conform_bounds.sh path/to/tiershade
# Checks, on llvmpipe (every backend/API pair): every hdr_tonemap variant has 100 % of its pixels
# inside their GLSL ES 3.00 intervals on the random and the hard grid, and so does its C float
# twin; the random grid's median interval width is under 2^16 ULP on every variant (the bounds
# must say something: 2^16 ULP is 2^-7 relative, the sub-texel weight precision the CTS allows a
# bloom lookup, docs/conformance.md); the 0-ULP check of the same variants still passes; a selection
# without an interval instance is an error (status 1, a message naming it), not an empty success.
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup conform_bounds 600 "$@"

run conform --shader hdr_tonemap --bounds --size 24 --json
if cli_crashed || [ "$RC" -ne 0 ]; then
  fail bounds_hdr_tonemap "status $RC: $(head -c 400 "$OUT") $(head -n 2 "$ERR")"
else
  verdict=$(python3 - "$OUT" <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))
bad = [r for r in runs if not r["passed"] or r["share_inside"] != 1 or r["outside"] or r["c_outside"]]
wide = [r for r in runs if r["set"] == "random" and not r["median_width_ulp"] < 65536]
sets = {r["set"] for r in runs}
if not runs or sets != {"random", "hard"}: print("no runs or a set missing: %s" % sorted(sets))
elif bad: print("outside: %s %s %s/%s %s" % (bad[0]["shader"], bad[0]["variant"], bad[0]["backend"], bad[0]["api"], bad[0]["set"]))
elif wide: print("median width %s ULP: %s %s" % (wide[0]["median_width_ulp"], wide[0]["variant"], wide[0]["api"]))
else: print("ok %d" % len(runs))
PY
)
  case $verdict in
    ok*) pass "bounds_hdr_tonemap_all_inside (${verdict#ok } runs)" ;;
    *) fail bounds_hdr_tonemap_all_inside "$verdict" ;;
  esac
fi

run conform --shader hdr_tonemap --size 16
if [ "$RC" -eq 0 ] && grep -q ' 0 failed' "$OUT"; then pass zero_ulp_check_unchanged
else fail zero_ulp_check_unchanged "status $RC: $(tail -n 3 "$OUT")"; fi

run conform --shader bloom_blur --bounds --size 8
if [ "$RC" -eq 1 ] && grep -q 'no interval instance' "$ERR"; then pass bounds_without_instance_is_an_error
else fail bounds_without_instance_is_an_error "status $RC: $(head -n 2 "$ERR")"; fi

cli_finish
