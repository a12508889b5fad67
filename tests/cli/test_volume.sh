#!/usr/bin/env bash
# tiershade — tests/cli/test_volume.sh
#
# The irradiance volume in the bake directory and `tiershade light --at`'s ambient cube
# (docs/irradiance_volume.md). On a copy of scenes/large_hall_40.gltf (world faces and models)
# without its hand-typed ambient samples (so the models take the volume): `bake -o DIR` writes
# volume.bin and the manifest's "volume" entry (its size and content hash match the file); a render
# reading DIR gives the same frame bytes as the bake at load (C fallback and GL, tolerance 0: the same
# float samples through the same code); the file is what is read (a copy whose cubes are zeroed, its
# hash updated, changes the frame); `light --at` prints the cube and its samples: the weights sum to 1
# (trilinear and inverse-square; tolerance 1e-12: at most 8 weights divided by their sum in double,
# each rounding < 2^-53 relative), every contributing sample is valid in volume.bin, and at a sample's
# own position (trilinear, nearest) the one contribution is that sample with weight 1 and the cube is
# its six colours in volume.bin bit for bit (inverse-square: the sample weighs the most, 1 / the sum); a scene with hand-typed samples has no volume (text and JSON say so);
# a scene whose volume spacing or bounds differ from the bake's is refused naming that part and its
# old and new values (the manifest's /volume/inputs record), and writes no frame.
# Bad volume files are in tests/cli/test_bad_input.sh.
#   usage: tests/cli/test_volume.sh path/to/tiershade
# Prints "PASS name" / "FAIL name: detail"; exits 1 if any check failed.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup volume_cli 600 "$@"

# scene OUT.gltf BAKE_DIR_OR_EMPTY: large_hall_40 with absolute paths, no ambient samples.
scene() {
  python3 - "$HERE/scenes/large_hall_40.gltf" "$1" "$2" << 'EOF'
import json, os, sys
src, out, bake = sys.argv[1], sys.argv[2], sys.argv[3]
sd = os.path.dirname(os.path.abspath(src))
d = json.load(open(src))
for k in ('buffers', 'images'):
    for b in d.get(k, []):
        if 'uri' in b: b['uri'] = os.path.join(sd, b['uri'])
t = d['extras']['tiershade']
for p in t.get('probes', []):
    if 'image' in p: p['image'] = os.path.normpath(os.path.join(sd, p['image']))
del t['ambient']
if bake: t['lightmaps']['bake'] = os.path.abspath(bake)
json.dump(d, open(out, 'w'))
EOF
}
scene load.gltf ""
scene dir.gltf hall.bake
scene zero.gltf zero.bake

run bake load.gltf -o hall.bake
if [ "$RC" -eq 0 ] && [ -s hall.bake/volume.bin ] && grep -q '^baked: irradiance volume of [0-9]* x [0-9]* x [0-9]* samples' "$OUT" &&
  python3 - hall.bake << 'EOF'
import json, os, sys
d = sys.argv[1]
m = json.load(open(d + '/manifest.json'))['volume']
b = open(d + '/volume.bin', 'rb').read()
h = 0xcbf29ce484222325
for c in b: h = ((h ^ c) * 0x100000001b3) & 0xffffffffffffffff
n = m['samples']
ok = m['file'] == 'volume.bin' and m['bytes'] == len(b) and m['content_hash'] == '%016x' % h and \
    len(b) == 80 + 92 * n[0] * n[1] * n[2] and b[:8] == b'TSVOLUME'
sys.exit(0 if ok else 1)
EOF
then pass "bake -o DIR writes volume.bin and its manifest entry (size, content hash, grid)"
else fail "bake -o DIR writes the volume" "status $RC: $(head -n 2 "$ERR") $(ls hall.bake)"; fi

for b in cpu osmesa; do
  run render dir.gltf --size 128x72 --quiet --backend $b -o dir_$b
  r1=$RC
  run render load.gltf --size 128x72 --quiet --backend $b -o load_$b
  if [ "$r1" -eq 0 ] && [ "$RC" -eq 0 ] && cmp -s dir_$b.exr load_$b.exr && cmp -s dir_$b.png load_$b.png; then
    pass "render reading the volume from the bake directory == baking it at load ($b)"
  else fail "render from the bake directory's volume ($b)" "status $r1/$RC or the frames differ: $(head -n 2 "$ERR")"; fi
done

# The frame comes from the file: zero every cube (hash updated) and the models change.
cp -r hall.bake zero.bake
python3 - zero.bake << 'EOF'
import json, struct, sys
d = sys.argv[1]
b = bytearray(open(d + '/volume.bin', 'rb').read())
for s in range(80, len(b), 92): b[s + 20:s + 92] = bytes(72)
open(d + '/volume.bin', 'wb').write(b)
h = 0xcbf29ce484222325
for c in b: h = ((h ^ c) * 0x100000001b3) & 0xffffffffffffffff
m = json.load(open(d + '/manifest.json'))
m['volume']['content_hash'] = '%016x' % h
json.dump(m, open(d + '/manifest.json', 'w'), indent=1)
EOF
run render zero.gltf --size 128x72 --quiet --backend cpu -o zero
if [ "$RC" -eq 0 ] && ! cmp -s zero.exr dir_cpu.exr; then pass "the render samples volume.bin (zeroed cubes change the frame)"
else fail "the render samples volume.bin" "status $RC, or the frame did not change: $(head -n 2 "$ERR")"; fi

# light --at: weights, valid samples, a sample's own position.
check_light() {  # name, python check on (j = light's JSON, v = volume.bin parsed), light args...
  local name=$1 code=$2
  shift 2
  run light dir.gltf --json "$@"
  if [ "$RC" -ne 0 ]; then fail "$name" "status $RC: $(head -n 2 "$ERR")"; return; fi
  if python3 - "$OUT" hall.bake "$code" << 'EOF'
import json, struct, sys
j = json.load(open(sys.argv[1]))['volume']
d = sys.argv[2]
b = open(d + '/volume.bin', 'rb').read()
n = struct.unpack_from('<3i', b, 12)
def rec(i, jj, k):
    at = 80 + 92 * ((k * n[1] + jj) * n[0] + i)
    valid = struct.unpack_from('<I', b, at + 12)[0]
    cube = struct.unpack_from('<18f', b, at + 20)
    return valid, [list(cube[3 * f:3 * f + 3]) for f in range(6)]
faces = ['+X', '-X', '+Y', '-Y', '+Z', '-Z']
ok = True
exec(sys.argv[3])
sys.exit(0 if ok else 1)
EOF
  then pass "$name"; else fail "$name" "$(head -c 400 "$OUT")"; fi
}
SUM_OK='
w = [s["weight"] for s in j["samples"]]
ok = 1 <= len(w) <= 8 and abs(sum(w) - 1) < 1e-12 and all(0 < x <= 1 for x in w) and \
    all(rec(*s["sample"])[0] == 1 for s in j["samples"]) and abs(j["weight_sum"] - 1) < 1e-12'
check_light "light --at: trilinear weights sum to 1 over valid samples" "$SUM_OK" --at 0.3,1.9,0.7
check_light "light --at: inverse-square weights sum to 1 over valid samples" "$SUM_OK
ok = ok and j['lookup'] == 'inverse_square'" --at 0.3,1.9,0.7 --lookup inverse_square
# An interior valid sample whose position p = origin + i step maps back to i exactly in double
# ((p - origin) / step, the lookup's own arithmetic, done by Python's IEEE doubles).
AT=$(python3 - hall.bake << 'EOF'
import json, math, struct, sys
d = sys.argv[1]
m = json.load(open(d + '/manifest.json'))['volume']
b = open(d + '/volume.bin', 'rb').read()
n, o, s = m['samples'], m['origin'], m['step']
def exact(a, i): return (o[a] + i * s[a] - o[a]) / s[a] == i
for k in range(1, n[2] - 1):
    for i in range(1, n[0] - 1):
        jj = n[1] - 1
        at = 80 + 92 * ((k * n[1] + jj) * n[0] + i)
        if struct.unpack_from('<I', b, at + 12)[0] == 1 and exact(0, i) and exact(1, jj) and exact(2, k):
            print('%r,%r,%r %d %d %d' % (o[0] + i * s[0], o[1] + jj * s[1], o[2] + k * s[2], i, jj, k))
            sys.exit(0)
sys.exit(1)
EOF
)
if [ -z "$AT" ]; then fail "light --at a sample" "no interior valid sample with an exact position"; else
  set -- $AT
  for look in trilinear nearest; do
    check_light "light --at a sample's position ($look): that sample alone, weight 1, its colours bit for bit" "
s = j['samples']
valid, cube = rec($2, $3, $4)
ok = len(s) == 1 and s[0]['sample'] == [$2, $3, $4] and s[0]['weight'] == 1 and \
    all(j['cube'][faces[f]] == cube[f] for f in range(6))" --at "$1" --lookup $look
  done
  # Source's 1 / (d^2 + 1) does not interpolate: the sample itself weighs 1 before normalising, the
  # others 1 / (d^2 + 1) with d in inches (a step of 1.2 m is 48 in: about 4e-4 each).
  check_light "light --at a sample's position (inverse_square): that sample weighs the most, 1 / sum" "
s = j['samples']
me = [x for x in s if x['sample'] == [$2, $3, $4]]
raw = sum(1 / (sum(((a - b) / 0.0254) ** 2 for a, b in zip(x['position'], me[0]['position'])) + 1) for x in s) if me else 0
ok = len(me) == 1 and me[0]['weight'] == max(x['weight'] for x in s) and abs(me[0]['weight'] - 1 / raw) < 1e-12" \
    --at "$1" --lookup inverse_square
fi
run light dir.gltf --at 0.3,1.9,0.7
if [ "$RC" -eq 0 ] && grep -q '^volume: [0-9]* x [0-9]* x [0-9]* samples, trilinear lookup' "$OUT" &&
  grep -q '^  +Y [0-9.e-]* [0-9.e-]* [0-9.e-]*$' "$OUT" && grep -q 'weights sum to 1$' "$OUT"; then
  pass "light --at (text): the cube's six colours and the samples"
else fail "light --at (text)" "status $RC: $(tail -n 5 "$OUT")"; fi
run light "$HERE/scenes/large_hall_40.gltf" --at 0.3,1.9,0.7 --json
if [ "$RC" -eq 0 ] && python3 -c 'import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))["volume"] is None else 1)' "$OUT"; then
  pass "light --at on a scene with hand-typed samples: no volume (null)"
else fail "light --at without a volume" "status $RC: $(head -c 300 "$ERR")"; fi
# A stale volume says what changed: the scene's volume spacing or bounds differ from the bake's (the
# lightmaps do not depend on them, so the page is current and the volume alone is refused).
for what in spacing bounds; do
  python3 - dir.gltf stale_$what.gltf $what << 'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
d['extras']['tiershade']['volume'] = {'spacing': [2.4384, 2.4384, 2.4384]} if sys.argv[3] == 'spacing' else \
    {'bounds': [[-1, 0, -1], [1, 2, 1]]}
json.dump(d, open(sys.argv[2], 'w'))
EOF
done
run render stale_spacing.gltf --size 32x18 --quiet --backend cpu -o stale
if [ "$RC" -eq 1 ] && grep -q "hall\.bake/manifest\.json: /volume/inputs_hash: stale irradiance volume: the volume's settings (spacing \[1\.2192,2\.4384,1\.2192\] -> \[2\.4384,2\.4384,2\.4384\]) changed since it was baked; rebake" "$ERR" &&
  [ ! -e stale.exr ]; then pass "a stale volume names what changed: the settings, the spacing's old and new values"
else fail "stale volume: the settings" "status $RC: $(head -n 2 "$ERR")"; fi
run render stale_bounds.gltf --size 32x18 --quiet --backend cpu -o stale
if [ "$RC" -eq 1 ] && grep -q "stale irradiance volume: the volume's bounds (bounds \[\[.*\]\] -> \[\[-1\.0,0\.0,-1\.0\],\[1\.0,2\.0,1\.0\]\]) changed since it was baked" "$ERR" &&
  ! grep -q "settings" "$ERR" && [ ! -e stale.exr ]; then pass "a stale volume names what changed: the bounds alone, old and new"
else fail "stale volume: the bounds" "status $RC: $(head -n 2 "$ERR")"; fi

run light load.gltf --at 0,0,0 --lookup cubic
if [ "$RC" -eq 2 ] && grep -q "\-\-lookup 'cubic': expected trilinear, inverse_square or nearest" "$ERR"; then
  pass "light --lookup: a bad value is refused"
else fail "light --lookup bad value" "status $RC: $(head -n 2 "$ERR")"; fi

# Samples only where models can be: one model node names its reach (extras.tiershade.reach); the bake
# traces only the samples lookups in the reach boxes (and at the other models' centres) can read,
# says how many and the rays saved, records the boxes in the manifest; a changed reach is a stale
# volume naming the regions; a reach with its corners swapped is refused naming the node.
python3 - dir.gltf reach.gltf reach2.gltf reach_bad.gltf "$PWD/reach.bake" << 'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
t = d['extras']['tiershade']['lightmaps']
t.pop('bake', None)
m = next(i for i, n in enumerate(d['nodes']) if 'mesh' in n and d['meshes'][n['mesh']].get('name', '').startswith('hall_sphere'))
for out, box, bake in ((sys.argv[2], [[-1, 0.5, -1], [1, 1.5, 1]], None), (sys.argv[3], [[-2, 0.5, -1], [1, 1.5, 1]], sys.argv[5]),
                       (sys.argv[4], [[1, 0.5, -1], [-1, 1.5, 1]], None)):
    d['nodes'][m]['extras'] = {'tiershade': {'reach': box}}
    if bake: t['bake'] = bake
    else: t.pop('bake', None)
    json.dump(d, open(out, 'w'))
EOF
run bake reach.gltf -o reach.bake
if [ "$RC" -eq 0 ] && grep -q "^baked: volume samples only where models can be: [0-9]* of [0-9]* ([0-9]* rays saved)$" "$OUT" &&
  python3 -c 'import json,sys; v=json.load(open(sys.argv[1]))["volume"]; r=v["inputs"]["regions"]; n=v["samples"]; sys.exit(0 if [[-1,0.5,-1],[1,1.5,1]] in r and v["baked"] < n[0]*n[1]*n[2] else 1)' reach.bake/manifest.json; then
  pass "a model's reach: the bake traces only the samples models can read, says so, records the boxes ($(grep -o '[0-9]* of [0-9]* ([0-9]* rays saved)' "$OUT"))"
else fail "bake with a model's reach" "status $RC: $(grep volume "$OUT" | head -n 3) $(head -n 2 "$ERR")"; fi
run render reach2.gltf --size 32x18 --quiet --backend cpu -o stale_reach
if [ "$RC" -eq 1 ] && grep -q "stale irradiance volume: the volume's bounds (regions .* -> .*) changed since it was baked" "$ERR" &&
  [ ! -e stale_reach.exr ]; then pass "a changed reach makes the volume stale, naming the regions"
else fail "stale volume: the reach" "status $RC: $(head -n 2 "$ERR")"; fi
run bake reach_bad.gltf -o reach_bad.bake
if [ "$RC" -ne 0 ] && grep -q "nodes\[[0-9]*\].*\.extras\.tiershade\.reach: the high corner is below the low one on an axis" "$ERR" &&
  [ ! -e reach_bad.bake ]; then pass "a reach with its corners swapped is refused, naming the node"
else fail "bad reach" "status $RC: $(head -n 2 "$ERR")"; fi

cli_finish
