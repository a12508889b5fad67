// tiershade glue/browser/webgl_conform.js: runs the conformance job (job.js: var TS_JOB) in WebGL 1 or
// 2, the way glue/gl/float_target.cpp draws on llvmpipe: one full-screen triangle (attribute a_corner)
// into a w x h RGBA32F target, the per-pixel records in the RGBA32F texture ts_record (NEAREST) on
// unit 0, the family's textures on the next units, uniforms ts_record_size and ts_grid_height; then
// readPixels(FLOAT). WebGL 1 needs OES_texture_float and WEBGL_color_buffer_float (float textures and
// a float colour target, docs/bundles.md "Extensions"), OES_texture_float_linear for LINEAR float
// textures; WebGL 2 needs EXT_color_buffer_float (and OES_texture_float_linear).
// Output lines in <pre id="out">:
//   I <text>                         the context (version, renderer)
//   E <program> <message>            the program failed to compile or link (message JSON-quoted)
//   R <program> <draw> <base64>      the draw's w*h*4 floats, little-endian, rows bottom first
//   X <message>                      the page itself failed (an extension missing, an exception)
//   V <program> <draw> <channels> <outside> <unbounded>   the page's own check (job.programs[p].bounds:
//                                    the intervals shipped with the page, `conform --page`)
//   DONE                             the last line when the page ran to its end
// With bounds, the page also shows a table (per program and draw: inside, the worst excess, the
// median width, the worst pixel's inputs): the conformance page a user opens on their own device.
(function () {
  'use strict';
  const out = [];
  function b64ToBytes(s) {
    const bin = atob(s);
    const u = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) u[i] = bin.charCodeAt(i);
    return u;
  }
  function floatsToB64(f) {
    const u = new Uint8Array(f.buffer, f.byteOffset, f.byteLength);
    let s = '';
    for (let i = 0; i < u.length; i += 8192) s += String.fromCharCode.apply(null, u.subarray(i, i + 8192));
    return btoa(s);
  }
  function floatsOf(b64) {
    const u = b64ToBytes(b64);
    return new Float32Array(u.buffer, 0, u.length / 4);
  }
  const f32 = new Float32Array(1), u32 = new Uint32Array(f32.buffer);
  function ord(x) {  // float32 order as integers (-0 and +0 both 0), as glue/conform/bounds.cpp
    f32[0] = x;
    const u = u32[0];
    return (u & 0x80000000) ? -(u & 0x7fffffff) : u;
  }
  function bytesOf(b64) { return b64ToBytes(b64); }
  // px against the intervals b (lo, hi: w*h*4 floats; nan: w*h*4 bytes, 1 = NaN admitted)
  function checkDraw(px, b) {
    const lo = floatsOf(b.lo), hi = floatsOf(b.hi), nan = bytesOf(b.nan);
    const r = {channels: px.length, outside: 0, unbounded: 0, worst: null, widths: []};
    for (let i = 0; i < px.length; ++i) {
      const v = px[i], l = lo[i], h = hi[i];
      const unb = nan[i] || !isFinite(l) || !isFinite(h);
      if (unb) ++r.unbounded;
      else if (i % 4 !== 3) r.widths.push(ord(h) - ord(l));
      const inside = isNaN(v) ? !!nan[i] : (l <= v && v <= h);
      if (!inside) {
        ++r.outside;
        const ex = isNaN(v) ? Infinity : (v < l ? ord(l) - ord(v) : ord(v) - ord(h));
        if (!r.worst || ex > r.worst.excess) r.worst = {i: i, excess: ex, v: v, lo: l, hi: h};
      }
    }
    r.widths.sort(function (a, b) { return a - b; });
    r.median = r.widths.length ? r.widths[r.widths.length >> 1] : 0;
    return r;
  }
  const report = [];
  function run() {
    const job = window.TS_JOB;
    if (!job) throw new Error('job.js did not define TS_JOB');
    const v2 = job.webgl === 2;
    const canvas = document.createElement('canvas');
    canvas.width = 1;
    canvas.height = 1;
    const gl = canvas.getContext(v2 ? 'webgl2' : 'webgl', {antialias: false, depth: false, stencil: false});
    if (!gl) throw new Error((v2 ? 'WebGL 2' : 'WebGL 1') + ' is not available');
    const need = v2 ? ['EXT_color_buffer_float'] : ['OES_texture_float', 'WEBGL_color_buffer_float'];
    for (const e of need)
      if (!gl.getExtension(e)) throw new Error('extension ' + e + ' is not available');
    const linearFloat = !!gl.getExtension('OES_texture_float_linear');
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    out.push('I ' + gl.getParameter(gl.VERSION) + ' | ' +
             (dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)));
    const internalRGBA32F = v2 ? gl.RGBA32F : gl.RGBA;
    function upload(t) {
      const target = t.kind === 'cube' ? gl.TEXTURE_CUBE_MAP : t.kind === '3d' ? gl.TEXTURE_3D : gl.TEXTURE_2D;
      if (t.kind === '3d' && !v2) throw new Error('a 3D texture (' + t.sampler + ') needs WebGL 2');
      if (t.linear && !linearFloat) throw new Error('LINEAR float texture ' + t.sampler + ' needs OES_texture_float_linear');
      const id = gl.createTexture();
      gl.bindTexture(target, id);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
      const data = floatsOf(t.data);
      if (t.kind === '2d') {
        gl.texImage2D(gl.TEXTURE_2D, 0, internalRGBA32F, t.w, t.h, 0, gl.RGBA, gl.FLOAT, data);
        // a mip chain tiershade built (glue/gl/mipmaps.h): levels 1.., each max(1, size >> l)
        (t.levels || []).forEach(function (b64, k) {
          const l = k + 1;
          gl.texImage2D(gl.TEXTURE_2D, l, internalRGBA32F, Math.max(1, t.w >> l), Math.max(1, t.h >> l), 0, gl.RGBA,
                        gl.FLOAT, floatsOf(b64));
        });
      } else if (t.kind === '3d') {
        gl.texImage3D(gl.TEXTURE_3D, 0, gl.RGBA32F, t.w, t.h, t.d, 0, gl.RGBA, gl.FLOAT, data);
      } else {
        const face = t.w * t.w * 4;
        for (let f = 0; f < 6; ++f)
          gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, internalRGBA32F, t.w, t.w, 0, gl.RGBA, gl.FLOAT,
                        data.subarray(f * face, (f + 1) * face));
      }
      const filter = t.linear ? gl.LINEAR : gl.NEAREST;
      const wrap = t.repeat && t.kind !== 'cube' ? gl.REPEAT : gl.CLAMP_TO_EDGE;
      let minFilter = filter;
      if (t.mip_filter === 'nearest') minFilter = t.linear ? gl.LINEAR_MIPMAP_NEAREST : gl.NEAREST_MIPMAP_NEAREST;
      if (t.mip_filter === 'linear') minFilter = t.linear ? gl.LINEAR_MIPMAP_LINEAR : gl.NEAREST_MIPMAP_LINEAR;
      gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, minFilter);
      gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, filter);
      gl.texParameteri(target, gl.TEXTURE_WRAP_S, wrap);
      gl.texParameteri(target, gl.TEXTURE_WRAP_T, wrap);
      if (t.kind === '3d') gl.texParameteri(target, gl.TEXTURE_WRAP_R, wrap);
      const e = gl.getError();
      if (e) throw new Error('uploading ' + t.sampler + ': GL error 0x' + e.toString(16));
      return {sampler: t.sampler, target: target, id: id};
    }
    // the grids' textures, uploaded once and shared by every program drawn over them
    const grids = job.grids.map(function (g) {
      const rec = upload({sampler: 'ts_record', kind: '2d', w: g.w, h: g.h * g.slots, linear: false, repeat: false,
                          data: g.records});
      return {w: g.w, h: g.h, slots: g.slots, textures: [rec].concat(g.textures.map(upload)),
              records: job.report ? floatsOf(g.records) : null, cases: g.cases || null, slotNames: g.slot_names || null};
    });
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    function compile(type, src) {
      const s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
        const log = gl.getShaderInfoLog(s);
        gl.deleteShader(s);
        throw new Error((type === gl.VERTEX_SHADER ? 'vertex' : 'fragment') + ' shader: ' + log);
      }
      return s;
    }
    function build(p) {
      const vs = compile(gl.VERTEX_SHADER, p.vs);
      let fs;
      try {
        fs = compile(gl.FRAGMENT_SHADER, p.fs);
      } catch (e) {
        gl.deleteShader(vs);
        throw e;
      }
      const prog = gl.createProgram();
      gl.attachShader(prog, vs);
      gl.attachShader(prog, fs);
      gl.bindAttribLocation(prog, 0, 'a_corner');
      gl.linkProgram(prog);
      gl.deleteShader(vs);
      gl.deleteShader(fs);
      if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) {
        const log = gl.getProgramInfoLog(prog);
        gl.deleteProgram(prog);
        throw new Error('link: ' + log);
      }
      return prog;
    }
    for (let pi = 0; pi < job.programs.length; ++pi) {
      const p = job.programs[pi];
      let prog;
      try {
        prog = build(p);
      } catch (e) {
        out.push('E ' + pi + ' ' + JSON.stringify(String(e.message || e)));
        continue;
      }
      gl.useProgram(prog);
      for (let di = 0; di < p.draws.length; ++di) {
        const g = grids[p.draws[di]];
        const target = gl.createTexture();
        gl.bindTexture(gl.TEXTURE_2D, target);
        gl.texImage2D(gl.TEXTURE_2D, 0, internalRGBA32F, g.w, g.h, 0, gl.RGBA, gl.FLOAT, null);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
        const fb = gl.createFramebuffer();
        gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
        if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
          throw new Error('the RGBA32F target is not complete');
        gl.viewport(0, 0, g.w, g.h);
        gl.disable(gl.BLEND);
        gl.disable(gl.DEPTH_TEST);
        const rs = gl.getUniformLocation(prog, 'ts_record_size');
        if (rs) gl.uniform2f(rs, g.w, g.h * g.slots);
        const gh = gl.getUniformLocation(prog, 'ts_grid_height');
        if (gh) gl.uniform1f(gh, g.h);
        g.textures.forEach(function (t, unit) {
          gl.activeTexture(gl.TEXTURE0 + unit);
          gl.bindTexture(t.target, t.id);
          const loc = gl.getUniformLocation(prog, t.sampler);
          if (loc) gl.uniform1i(loc, unit);
        });
        gl.activeTexture(gl.TEXTURE0);
        gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
        gl.enableVertexAttribArray(0);
        gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
        gl.clearColor(0, 0, 0, 0);
        gl.clear(gl.COLOR_BUFFER_BIT);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        const px = new Float32Array(g.w * g.h * 4);
        gl.readPixels(0, 0, g.w, g.h, gl.RGBA, gl.FLOAT, px);
        const e = gl.getError();
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
        gl.deleteFramebuffer(fb);
        gl.deleteTexture(target);
        if (e) {
          out.push('E ' + pi + ' ' + JSON.stringify('draw ' + di + ': GL error 0x' + e.toString(16)));
          break;
        }
        if (p.bounds) {
          const c = checkDraw(px, p.bounds[di]);
          out.push('V ' + pi + ' ' + di + ' ' + c.channels + ' ' + c.outside + ' ' + c.unbounded);
          report.push({p: p, g: g, c: c, set: p.sets ? p.sets[di] : String(di)});
        } else {
          out.push('R ' + pi + ' ' + di + ' ' + floatsToB64(px));
        }
      }
      gl.deleteProgram(prog);
    }
  }
  function esc(t) { return String(t).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;'); }
  function showReport() {
    const ok = report.filter(function (r) { return r.c.outside === 0; }).length;
    let h = '<h1>tiershade conformance on this device</h1><p>' + esc(out[0] ? out[0].slice(2) : '') + '</p>' +
            '<p>' + ok + ' of ' + report.length + ' runs inside their GLSL ES bounds</p>' +
            '<table border="1" cellspacing="0" cellpadding="3"><tr><th>shader</th><th>variant</th><th>set</th>' +
            '<th>inside</th><th>outside channels</th><th>worst excess (ULP)</th><th>median width (ULP)</th>' +
            '<th>unbounded</th><th>worst pixel</th></tr>';
    for (const r of report) {
      const c = r.c, g = r.g;
      let worst = '';
      if (c.worst) {
        const px = (c.worst.i >> 2), x = px % g.w, y = (px / g.w) | 0, ch = c.worst.i & 3;
        worst = '(' + x + ', ' + y + ') ch' + ch + ': ' + c.worst.v + ' not in [' + c.worst.lo + ', ' + c.worst.hi + ']';
        if (g.cases && g.cases[px]) worst += '<br>hard case: ' + esc(g.cases[px]);
        if (g.records) {
          for (let k = 0; k < g.slots; ++k) {
            const o = ((y + k * g.h) * g.w + x) * 4;
            worst += '<br>' + esc(g.slotNames ? g.slotNames[k] : 'slot ' + k) + ': ' +
                     Array.prototype.slice.call(g.records.subarray(o, o + 4)).join(' ');
          }
        }
      }
      h += '<tr><td>' + esc(r.p.shader) + '</td><td>' + esc(r.p.variant) + '</td><td>' + esc(r.set) + '</td><td>' +
           (100 * (1 - c.outside / c.channels)).toFixed(4) + ' %</td><td>' + c.outside + '</td><td>' +
           (c.worst ? c.worst.excess : 0) + '</td><td>' + c.median + '</td><td>' + c.unbounded + '</td><td>' +
           worst + '</td></tr>';
    }
    const div = document.createElement('div');
    div.innerHTML = h + '</table>';
    document.body.insertBefore(div, document.body.firstChild);
  }
  try {
    run();
  } catch (e) {
    out.push('X ' + JSON.stringify(String(e.message || e)));
  }
  if (report.length) showReport();
  out.push('DONE');
  document.getElementById('out').textContent = out.join('\n');
  document.title = 'done';
})();
