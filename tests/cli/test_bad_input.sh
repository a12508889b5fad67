#!/usr/bin/env bash
# tiershade — tests/cli/test_bad_input.sh
#
# The reproductions of issue 15 (hostile input, bounded resources), each built in a temp dir:
# a FIFO and a /dev/zero symlink as the scene and as LUTs, a 53-byte Radiance header claiming
# 11585 x 11585 pixels (as a probe and as a lightmap page), extras nested 20,000 deep, an
# accessor count of 67,108,864 over a 19,600-byte view, a broken and a zip-bomb PNG texture, an EXR probe,
# a lightmap page too small for the faces, damaged irradiance-volume files in a bake directory, --size overflow and malformed sizes, `lut convert`
# onto itself, the limits (--size 8192x8192, 64 probes of 512, an 8192 x 8192 page) and demo's
# output directory. Each checks the exit status, the message (it names the file and the limit),
# that nothing is left at the output path, and the peak memory (/usr/bin/time -f %M): an input
# that makes the process allocate its claimed gigabytes fails here, not as a slow run.
#   usage: tests/cli/test_bad_input.sh path/to/tiershade
set -u

. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup bad_input 120 "$@"

# Peak RSS bound for a refused input (MiB): the program's own ~20 MiB (ASan's shadow and
# Mesa's libraries ~100 MiB more) with a wide margin; each bug allocated 1.2-2.7 GiB.
PEAK_MIB=400
HAVE_TIME=0
[ -x /usr/bin/time ] && HAVE_TIME=1

# bad NAME STATUS REGEX OUTBASE -- ARGS...: tiershade ARGS... exits STATUS (1 or 2) within the
# timeout, stderr matches REGEX, nothing named OUTBASE* exists afterwards, peak RSS < PEAK_MIB.
bad() {
  local name=$1 want=$2 re=$3 outbase=$4
  shift 5
  if [ $HAVE_TIME = 1 ]; then
    "${TIMEOUT[@]}" /usr/bin/time -o "$TMP/rss" -f %M "$TS" "$@" > "$OUT" 2> "$ERR" < /dev/null
  else
    "${TIMEOUT[@]}" "$TS" "$@" > "$OUT" 2> "$ERR" < /dev/null
  fi
  RC=$?
  if cli_crashed; then
    fail "$name" "crashed or timed out (status $RC): $(head -n 2 "$ERR")"
    return
  fi
  if [ "$RC" -ne "$want" ]; then
    fail "$name" "status $RC, expected $want: $(head -n 2 "$ERR")"
    return
  fi
  if ! grep -qE -- "$re" "$ERR"; then
    fail "$name" "message does not match /$re/: $(head -n 2 "$ERR")"
    return
  fi
  if [ -n "$outbase" ] && ls -d "$outbase"* > /dev/null 2>&1; then
    fail "$name" "left output behind: $(ls -d "$outbase"* | head -n 3 | tr '\n' ' ')"
    return
  fi
  if [ $HAVE_TIME = 1 ]; then
    local kib
    kib=$(tail -n 1 "$TMP/rss")
    if [ "$kib" -gt $((PEAK_MIB * 1024)) ]; then
      fail "$name" "peak memory $((kib / 1024)) MiB, over $PEAK_MIB MiB for a refused input"
      return
    fi
  fi
  pass "$name"
}

SC=$HERE/scenes
# scene COPY_OF NEW.gltf PYTHON: a shipped scene with absolute paths, edited by PYTHON (d = the JSON).
scene() {
  python3 - "$SC/$1" "$2" "$3" << 'EOF'
import json, os, sys
src, out, edit = sys.argv[1], sys.argv[2], sys.argv[3]
sd = os.path.dirname(os.path.abspath(src))
d = json.load(open(src))
for k in ('buffers', 'images'):
    for b in d.get(k, []):
        if 'uri' in b: b['uri'] = os.path.join(sd, b['uri'])
for p in d.get('extras', {}).get('tiershade', {}).get('probes', []):
    if 'image' in p: p['image'] = os.path.normpath(os.path.join(sd, p['image']))
sky = d.get('extras', {}).get('tiershade', {}).get('sky')
if sky and 'image' in sky: sky['image'] = os.path.normpath(os.path.join(sd, sky['image']))
exec(edit)
text = json.dumps(d)
text = text.replace('"@@DEEP@@"', '[' * 20000 + ']' * 20000)
open(out, 'w').write(text)
EOF
}
if ! command -v python3 > /dev/null; then
  skip bad_input "python3 is needed to build the hostile scenes"
  cli_finish
fi

# --- 4. special files: a FIFO and /dev/zero as the scene and as LUTs -----------------------
mkfifo fifo.gltf fifo.cube fifo.raw
ln -s /dev/zero z.gltf
ln -s /dev/zero z.cube
ln -s /dev/zero z.raw
bad fifo_scene 1 "fifo.gltf: not a regular file \(a FIFO\)" r_fifo -- render fifo.gltf --backend cpu -o r_fifo
bad zero_scene 1 "z.gltf: not a regular file" r_zero -- render z.gltf --backend cpu -o r_zero
bad fifo_cube_inspect 2 "fifo.cube: not a regular file \(a FIFO\)" "" -- lut inspect fifo.cube
bad fifo_raw_inspect 2 "fifo.raw: not a regular file \(a FIFO\)" "" -- lut inspect fifo.raw
bad zero_cube_inspect 2 "z.cube: not a regular file" "" -- lut inspect z.cube
bad zero_raw_convert 2 "z.raw: not a regular file" out_z -- lut convert z.raw out_z.cube
bad fifo_cube_convert 2 "fifo.cube: not a regular file" out_f -- lut convert fifo.cube out_f.raw

# --- 1. deep nesting in a node's extras -----------------------------------------------------
scene phong_sphere.gltf deep.gltf "d['nodes'][0]['extras'] = '@@DEEP@@'"
bad deep_extras 1 "deep.gltf: line 1, column [0-9]+: arrays and objects nested more than 128 deep" r_deep \
  -- render deep.gltf --backend cpu -o r_deep

# --- 3. an accessor count far beyond its view -------------------------------------------------
scene phong_sphere.gltf acc_count.gltf "d['accessors'][4]['count'] = 67108864"
bad accessor_count_limit 1 "acc_count.gltf: accessors\[4\]: count 67108864 is more than the limit of 16777216" r_acc \
  -- render acc_count.gltf --backend cpu -o r_acc
scene phong_sphere.gltf acc_view.gltf "d['accessors'][1]['count'] = 16777216"
bad accessor_over_view 1 "acc_view.gltf: accessors\[1\]: .*16777216 x 12 bytes needs 201326592 bytes, bufferViews\[1\] has 14700" r_acc \
  -- render acc_view.gltf --backend cpu -o r_acc

# --- 2. a Radiance header claiming 11585 x 11585 (and 1 x 2^27) with no pixels -----------------
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 11585 +X 11585\n' > big.hdr
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 134217728\n' > wide.hdr
scene phong_sphere.gltf probe_big.gltf "
for p in d['extras']['tiershade']['probes']: p['image'] = os.path.abspath('big.hdr')"
bad hdr_probe_header 1 "probe_big.gltf: extras.tiershade.probes\[0\].image: read_hdr: '.*big.hdr': unexpected end of file in pixel data" r_hdr \
  -- render probe_big.gltf --backend cpu -o r_hdr
scene phong_sphere.gltf probe_wide.gltf "
for p in d['extras']['tiershade']['probes']: p['image'] = os.path.abspath('wide.hdr')"
bad hdr_probe_wide 1 "read_hdr: '.*wide.hdr': unexpected end of file in pixel data" r_hdr \
  -- render probe_wide.gltf --backend cpu -o r_hdr
scene world_lighting.gltf page_big.gltf "d['extras']['tiershade']['lightmaps']['image'] = os.path.abspath('big.hdr'); del d['extras']['tiershade']['lightmaps']['page']"
bad hdr_page_header 1 "page_big.gltf: extras.tiershade.lightmaps.image: read_hdr: '.*big.hdr': unexpected end of file in pixel data" r_page \
  -- render page_big.gltf --backend cpu -o r_page

# --- 5. an EXR probe renders; errors name the scene once ---------------------------------------
run render "$SC/phong_sphere.gltf" --backend cpu --size 64x32 -o probe_src --quiet
scene phong_sphere.gltf probe_exr.gltf "
for p in d['extras']['tiershade']['probes']: p['image'] = os.path.abspath('probe_src.exr')"
run render probe_exr.gltf --backend cpu --size 48x32 -o r_exr --quiet
if [ "$RC" -eq 0 ] && [ -s r_exr.png ] && [ -s r_exr.exr ]; then pass exr_probe_renders; else
  fail exr_probe_renders "status $RC: $(head -n 2 "$ERR")"; fi

# --- TEXCOORD_1 lightmap charts (glue/bake/charts.h): bad charts name the primitive ------------
# The dome's lightmap UVs replaced by its TEXCOORD_0 (0..2.4: outside the unit square); its
# triangles replaced by the cove's indices (over the dome's fan: two triangles share a wedge).
CH="m = {x['name']: x for x in d['meshes']}; dome = m['dome']['primitives'][0]; cove = m['cove']['primitives'][0]"
scene lightmap_charts.gltf chart_range.gltf "$CH; dome['attributes']['TEXCOORD_1'] = dome['attributes']['TEXCOORD_0']"
bad chart_out_of_range 1 "chart_range.gltf: meshes\[4\].primitives\[0\] \(node \"dome\"\): TEXCOORD_1 of vertex 0 is \(1.200000, 1.200000\), outside \[0, 1\]" r_chr \
  -- render chart_range.gltf --backend cpu -o r_chr
scene lightmap_charts.gltf chart_overlap.gltf "$CH; dome['indices'] = cove['indices']"
bad chart_overlap 1 "chart_overlap.gltf: meshes\[4\].primitives\[0\] \(node \"dome\"\): TEXCOORD_1 triangles [0-9]+ and [0-9]+ overlap at" r_cho \
  -- render chart_overlap.gltf --backend cpu -o r_cho
# A page the planar faces fit on (several pages if need be) but not the cove's 48 x 48 chart (50 rows).
scene lightmap_charts.gltf chart_page.gltf "d['extras']['tiershade']['lightmaps']['page'] = [256, 40]"
bad chart_page_full 1 "chart_page.gltf: lightmap bake: brick \(meshes\[5\].primitives\[0\] \(node \"cove\"\)\): lm_page_pack: face 5 \(48x48 luxels, 4 lightmaps\) does not fit in the 256x40 page" r_chp \
  -- render chart_page.gltf --backend cpu -o r_chp

# --- 8. unnamed errors: a broken PNG texture, a page too small for the faces -------------------
head -c 100 "$SC/textures/brick.png" > broken.png
scene phong_sphere.gltf bad_png.gltf "d['images'][2]['uri'] = os.path.abspath('broken.png')"
bad broken_png_named 1 "bad_png.gltf: images\[2\] \(.*broken.png\): cannot decode the image" r_png \
  -- render bad_png.gltf --backend cpu -o r_png
# A zip-bomb PNG texture (fuzz_png's finding: a 4x4 header, an IDAT that inflates without end):
# stb_image grew its inflate buffer past 1 GiB; libpng stops at the rows the header declares.
cp "$HERE/tests/fuzz/regressions/png/png_zip_bomb-2c5666476c9d" zip_bomb.png
scene phong_sphere.gltf bomb_png.gltf "d['images'][2]['uri'] = os.path.abspath('zip_bomb.png')"
bad zip_bomb_png_named 1 "bomb_png.gltf: images\[2\] \(.*zip_bomb.png\): cannot decode the image \(libpng: " r_bomb \
  -- render bomb_png.gltf --backend cpu -o r_bomb
scene world_lighting.gltf page_small.gltf "d['extras']['tiershade']['lightmaps']['image'] = os.path.abspath('probe_src.exr'); del d['extras']['tiershade']['lightmaps']['page']"
bad small_page_named 1 "^tiershade render: page_small.gltf: extras.tiershade.lightmaps.image .*probe_src.exr: the page cannot hold" r_small \
  -- render page_small.gltf --backend cpu -o r_small
if grep -q "page_small.gltf: .*page_small.gltf" "$ERR"; then fail small_page_scene_once "$(head -n 1 "$ERR")"; else pass small_page_scene_once; fi

# --- 7. --size: digits only, no overflow, a stated maximum -------------------------------------
for s in 64x4294967360 "64x 36" " 64x36" "+64x+36" "64x36 " 0x36 8193x16 64 x36 "64x-36" 64x36x2; do
  bad "size_refused_'$s'" 2 "bad --size '.*' \(WxH: two integers, 1..8192 each" r_size \
    -- render "$SC/phong_sphere.gltf" --backend cpu --size "$s" -o r_size
done

# --- 9. lut convert to the same format or onto itself ------------------------------------------
cp "$SC/luts/desaturate.cube" lut.cube
cp lut.cube lut_before.cube
bad lut_convert_self 2 "lut.cube and lut.cube are both .cube \(and the same file\)" "" -- lut convert lut.cube lut.cube
if cmp -s lut.cube lut_before.cube; then pass lut_convert_self_untouched; else fail lut_convert_self_untouched "input rewritten"; fi
bad lut_convert_same_format 2 "are both .cube" other -- lut convert lut.cube other.cube
ln -s lut.cube link.raw 2> /dev/null
bad lut_convert_same_file 2 "are the same file" "" -- lut convert lut.cube link.raw

# --- 10. limits: --size 8192x8192, 64 probes of 512, an 8192 x 8192 page ------------------------
bad limit_size 1 "the render or bake \(mostly the frame of 8192 x 8192\) needs [0-9]+ MiB, over the memory limit of 1024 MiB \(raise it with --max-memory MIB\)" r_lim \
  -- render "$SC/phong_sphere.gltf" --backend cpu --size 8192x8192 -o r_lim
scene phong_sphere.gltf probes64.gltf "
p = d['extras']['tiershade']['probes'][0]
p['size'] = 512
p['image'] = os.path.abspath('probe_src.exr')
d['extras']['tiershade']['probes'] = [dict(p) for i in range(64)]"
bad limit_probes 1 "the render or bake \(mostly 64 probe cubes\) needs [0-9]+ MiB, over the memory limit of 1024 MiB" r_lim \
  -- render probes64.gltf --backend cpu -o r_lim
scene world_lighting.gltf page8k.gltf "d['extras']['tiershade']['lightmaps']['page'] = [8192, 8192]"
bad limit_page 1 "the lightmap page of 8192 x 8192 \(baked at load\)\) needs [0-9]+ MiB, over the memory limit of 1024 MiB" r_lim \
  -- render page8k.gltf --backend cpu -o r_lim
bad limit_page_bake 1 "tiershade bake: page8k.gltf: the render or bake \(mostly the lightmap page of 8192 x 8192 \(baked at load\)\) needs" page8k.exr \
  -- bake page8k.gltf -o page8k.exr
bad max_memory_range 2 "option --max-memory wants an integer in \[64, 1048576\]" r_lim \
  -- render "$SC/phong_sphere.gltf" --backend cpu --max-memory 10 -o r_lim
# A limit below what an image needs refuses it; the default renders every shipped scene size.
bad max_memory_small 1 "needs [0-9]+ MiB, over the memory limit of 64 MiB" r_lim \
  -- render probe_exr.gltf --backend cpu --size 2048x2048 --max-memory 64 -o r_lim

# --- 11. the bake directory's irradiance volume (docs/irradiance_volume.md) -------------------------
# large_hall_40 without its hand-typed samples: its models take the volume, written by bake -o DIR.
scene large_hall_40.gltf hv.gltf "del d['extras']['tiershade']['ambient']; d['extras']['tiershade']['lightmaps']['bake'] = os.path.abspath('hv_bad.bake')"
"${TIMEOUT[@]}" "$TS" bake hv.gltf -o hv.bake > "$OUT" 2> "$ERR" < /dev/null || fail volume_setup "bake: $(head -n 2 "$ERR")"
# vol_case NAME REGEX PYTHON: a copy of hv.bake as hv_bad.bake edited by PYTHON (b: volume.bin's
# bytes, m: the manifest), then a render of hv.gltf must fail naming the file and the place.
vol_case() {
  rm -rf hv_bad.bake && cp -r hv.bake hv_bad.bake
  python3 - hv_bad.bake "$3" << 'EOF2'
import json, os, sys
d, edit = sys.argv[1], sys.argv[2]
b = bytearray(open(d + '/volume.bin', 'rb').read())
m = json.load(open(d + '/manifest.json'))
def rehash():
    h = 0xcbf29ce484222325
    for c in b: h = ((h ^ c) * 0x100000001b3) & 0xffffffffffffffff
    m['volume']['content_hash'] = '%016x' % h
exec(edit)
if b is not None: open(d + '/volume.bin', 'wb').write(b)
else: os.remove(d + '/volume.bin')
json.dump(m, open(d + '/manifest.json', 'w'))
EOF2
  bad "$1" 1 "$2" r_vol -- render hv.gltf --backend cpu --size 32x18 -o r_vol
}
vol_case volume_flipped_byte "hv_bad\.bake/volume\.bin: content hash [0-9a-f]{16} is not the manifest's /volume/content_hash" "b[5000] ^= 1"
vol_case volume_truncated "hv_bad\.bake/volume\.bin: 1000 bytes, the manifest's /volume/bytes says [0-9]+" "b = b[:1000]"
vol_case volume_missing_file "hv_bad\.bake/volume\.bin: cannot read" "b = None"
vol_case volume_missing_entry "hv_bad\.bake/manifest\.json: /volume: missing: the bake has no irradiance volume" "del m['volume']"
vol_case volume_entry_type "hv_bad\.bake/manifest\.json: /volume/bytes: expected a non-negative integer, found string" "m['volume']['bytes'] = 'x'"
vol_case volume_stale "hv_bad\.bake/manifest\.json: /volume/inputs_hash: stale irradiance volume" "m['volume']['inputs_hash'] = '0' * 16"
# File and manifest edited together (hash updated): the fields' own checks name the sample and byte.
vol_case volume_negative_colour "hv_bad\.bake/volume\.bin: sample \(1, 0, 0\) at byte 172: colour 0\.0 is negative or not finite" \
  "import struct; struct.pack_into('<f', b, 80 + 92 + 20, -1.0); rehash(); m['volume']['bytes'] = len(b)"
vol_case volume_bad_validity "hv_bad\.bake/volume\.bin: sample \(0, 0, 0\) at byte 80: validity 7" \
  "b[80 + 12] = 7; rehash()"
vol_case volume_bad_magic "hv_bad\.bake/volume\.bin: byte 0: not a tiershade volume file" "b[0:8] = b'XXXXXXXX'; rehash()"
vol_case volume_bad_grid "hv_bad\.bake/volume\.bin: [0-9]+ bytes, a 34 x 2 x 33 volume takes" \
  "import struct; struct.pack_into('<i', b, 12, struct.unpack_from('<i', b, 12)[0] + 1); rehash()"

# --- 6. demo: refuses another directory, a failure leaves nothing, scenes found from anywhere --
mkdir mine && echo keep > mine/notes.txt
bad demo_refuses_other_dir 2 "mine: exists and is not a previous demo output" "" -- demo -o mine --size 96x48
if [ "$(cat mine/notes.txt)" = keep ] && [ "$(ls mine)" = notes.txt ]; then pass demo_other_dir_untouched; else
  fail demo_other_dir_untouched "$(ls mine)"; fi
# A disk that fills at the first picture (RLIMIT_FSIZE 4 KiB): the demo has found its scenes from
# this temporary directory, fails with the write error and leaves no directory, temporary or final.
( ulimit -f 8; "${TIMEOUT[@]}" "$TS" demo -o demo_out --size 96x48 > "$OUT" 2> "$ERR" < /dev/null )
RC=$?
if [ "$RC" -eq 1 ] && grep -q "write failed\|File too large" "$ERR" && ! ls -d demo_out* > /dev/null 2>&1; then
  pass demo_failure_leaves_nothing
else
  fail demo_failure_leaves_nothing "status $RC, $(head -n 2 "$ERR"), left: $(ls -d demo_out* 2> /dev/null | tr '\n' ' ')"
fi

cli_finish
