// tiershade glue/browser/webgl_scene.js: replays a scene's draw dump (scene.js: var TS_SCENE) in WebGL 2
// with its essl300 bundle's programs, as tests/bundle/bare_gl_render.cpp replays it on llvmpipe
// (docs/bundles.md, "Loading a variant", "The state the shaders expect"): attributes bound to the
// manifest's list index, every dumped uniform set from its float32 bits, samplers on the manifest's
// units, RGBA32F textures, an RGBA32F colour target with a DEPTH_COMPONENT24 buffer cleared to 1,
// depth test LESS, no blending, no culling. Then a display pass copies the target to the canvas
// (clamped; sRGB-encoded where the draw wrote linear values, found by a second pass of the same vertex
// stages writing a flag): no HDR post passes (bloom, tone map, auto exposure), no colour correction.
// The camera: u_view_proj, u_eye and u_eye_position are recomputed here from TS_SCENE.camera in double
// as glue/scene/prepare.cpp (camera_matrix) and camera_ortho.cpp compute them with GLM (lookAtRH,
// perspectiveRH_NO, infinitePerspectiveRH, orthoRH_NO, the same operations in the same order), then
// rounded to float; an orbit camera turns the dump's eye about a pivot on its view axis.
// index.html?orbit=YAW,PITCH,SCALE starts from an orbited view. index.html?check: one frame at the
// dump's camera (or the orbit given), then in <pre id="out">:
//   I <text>                   the context (version, unmasked renderer)
//   VP <differ> <compared>     camera uniform elements whose JS value differs from the dump's bits
//   F <base64>                 the RGBA32F frame, w*h*4 floats, rows bottom first (as frame.f32)
//   X <message>                the page failed (WebGL 2 or an extension missing, a program, GL error)
//   DONE
(function () {
  'use strict';
  const S = window.TS_SCENE;
  const check = /[?&]check\b/.test(location.search);
  const out = [];
  function bytes(b64) {
    const bin = atob(b64);
    const u = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) u[i] = bin.charCodeAt(i);
    return u;
  }
  function floats(b64) { const u = bytes(b64); return new Float32Array(u.buffer, 0, u.length >> 2); }
  function u32s(b64) { const u = bytes(b64); return new Uint32Array(u.buffer, 0, u.length >> 2); }
  function toB64(f) {
    const u = new Uint8Array(f.buffer, f.byteOffset, f.byteLength);
    let s = '';
    for (let i = 0; i < u.length; i += 8192) s += String.fromCharCode.apply(null, u.subarray(i, i + 8192));
    return btoa(s);
  }

  // --- GLM's double arithmetic, operation for operation (column-major 4x4 as 16 numbers) ---
  const dot3 = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];  // glm compute_dot: (x + y) + z
  const cross3 = (x, y) => [x[1] * y[2] - y[1] * x[2], x[2] * y[0] - y[2] * x[0], x[0] * y[1] - y[0] * x[1]];
  function normalize3(v) { const k = 1 / Math.sqrt(dot3(v, v)); return [v[0] * k, v[1] * k, v[2] * k]; }
  function identity() { return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]; }
  function mul(A, B) {  // glm mat4 * mat4: Result[i] = ((A0 B[i][0] + A1 B[i][1]) + A2 B[i][2]) + A3 B[i][3]
    const R = new Array(16);
    for (let i = 0; i < 4; ++i)
      for (let k = 0; k < 4; ++k)
        R[i * 4 + k] = A[k] * B[i * 4] + A[4 + k] * B[i * 4 + 1] + A[8 + k] * B[i * 4 + 2] + A[12 + k] * B[i * 4 + 3];
    return R;
  }
  function translate(m, v) {  // glm::translate: Result[3] = m[0] v0 + m[1] v1 + m[2] v2 + m[3]
    const R = m.slice();
    for (let k = 0; k < 4; ++k) R[12 + k] = m[k] * v[0] + m[4 + k] * v[1] + m[8 + k] * v[2] + m[12 + k];
    return R;
  }
  function lookAtRH(eye, center, up) {
    const f = normalize3([center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]]);
    const s = normalize3(cross3(f, up));
    const u = cross3(s, f);
    const R = identity();
    R[0] = s[0]; R[4] = s[1]; R[8] = s[2];
    R[1] = u[0]; R[5] = u[1]; R[9] = u[2];
    R[2] = -f[0]; R[6] = -f[1]; R[10] = -f[2];
    R[12] = -dot3(s, eye); R[13] = -dot3(u, eye); R[14] = dot3(f, eye);
    return R;
  }
  function viewProj(cam, eye, forward, aspect) {
    if (cam.projection === 'orthographic') {  // camera_ortho.cpp: glm::ortho * glm::lookAt(eye, eye + fwd, up)
      const sx = Math.max(cam.xmag, cam.ymag * aspect), sy = sx / aspect;
      const P = identity();
      const l = -sx, r = sx, b = -sy, t = sy, n = cam.znear, f = cam.zfar;
      P[0] = 2 / (r - l); P[5] = 2 / (t - b); P[10] = -2 / (f - n);
      P[12] = -(r + l) / (r - l); P[13] = -(t + b) / (t - b); P[14] = -(f + n) / (f - n);
      const c = [eye[0] + forward[0], eye[1] + forward[1], eye[2] + forward[2]];
      return mul(P, lookAtRH(eye, c, cam.up));
    }
    // prepare.cpp camera_matrix: lookAtRH(0, forward, up) * translate(I, -eye), then the projection
    const view = mul(lookAtRH([0, 0, 0], forward, cam.up), translate(identity(), [-eye[0], -eye[1], -eye[2]]));
    const P = new Array(16).fill(0);
    if (cam.zfar > 0) {  // perspectiveRH_NO
      const th = Math.tan(cam.yfov / 2);
      P[0] = 1 / (aspect * th); P[5] = 1 / th;
      P[10] = -(cam.zfar + cam.znear) / (cam.zfar - cam.znear); P[11] = -1;
      P[14] = -(2 * cam.zfar * cam.znear) / (cam.zfar - cam.znear);
    } else {  // infinitePerspectiveRH
      const range = Math.tan(cam.yfov / 2) * cam.znear;
      const l = -range * aspect, r = range * aspect, b = -range, t = range;
      P[0] = (2 * cam.znear) / (r - l); P[5] = (2 * cam.znear) / (t - b);
      P[10] = -1; P[11] = -1; P[14] = -2 * cam.znear;
    }
    return mul(P, view);
  }

  // --- the orbit camera: the dump's eye and forward turned about a pivot on the view axis ---
  const cam = S ? S.camera : null;
  const orbit = {yaw: 0, pitch: 0, scale: 1, pivotDist: 1};
  {  // index.html?orbit=YAW,PITCH,SCALE (radians, radians, distance factor): a view to link to
    const m = /[?&]orbit=([-0-9.e]+),([-0-9.e]+),([0-9.e]+)/.exec(location.search);
    if (m) { orbit.yaw = +m[1]; orbit.pitch = Math.max(-1.5, Math.min(1.5, +m[2])); orbit.scale = +m[3] || 1; }
  }
  function rotate(v, axis, a) {  // Rodrigues, axis unit
    const c = Math.cos(a), s = Math.sin(a), d = dot3(axis, v), x = cross3(axis, v);
    return [v[0] * c + x[0] * s + axis[0] * d * (1 - c), v[1] * c + x[1] * s + axis[1] * d * (1 - c),
            v[2] * c + x[2] * s + axis[2] * d * (1 - c)];
  }
  function cameraNow() {
    if (orbit.yaw === 0 && orbit.pitch === 0 && orbit.scale === 1) return {eye: cam.eye, forward: cam.forward};
    const pivot = cam.eye.map((e, k) => e + cam.forward[k] * orbit.pivotDist);
    const right = normalize3(cross3(cam.forward, cam.up));
    let f = rotate(cam.forward, right, orbit.pitch);
    f = normalize3(rotate(f, normalize3(cam.up), orbit.yaw));
    const d = orbit.pivotDist * orbit.scale;
    return {eye: pivot.map((p, k) => p - f[k] * d), forward: f};
  }

  const canvas = document.getElementById('view');
  let gl = null;

  function compile(type, src, what) {
    const s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(what + ': ' + gl.getShaderInfoLog(s));
    return s;
  }
  function link(vs, fs, attributes, what) {
    const p = gl.createProgram();
    gl.attachShader(p, compile(gl.VERTEX_SHADER, vs, what + ' vertex shader'));
    gl.attachShader(p, compile(gl.FRAGMENT_SHADER, fs, what + ' fragment shader'));
    attributes.forEach((n, i) => gl.bindAttribLocation(p, i, n));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(what + ' link: ' + gl.getProgramInfoLog(p));
    return p;
  }

  let vpDiffer = 0, vpCompared = 0;
  function run() {
    if (!S) throw new Error('scene.js did not define TS_SCENE');
    canvas.width = S.width;
    canvas.height = S.height;
    gl = canvas.getContext('webgl2', {antialias: false, depth: false, preserveDrawingBuffer: true});
    if (!gl) throw new Error('WebGL 2 is not available');
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    out.push('I ' + gl.getParameter(gl.VERSION) + ' | ' +
             (dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)));
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('extension EXT_color_buffer_float is not available');
    const linearFloat = !!gl.getExtension('OES_texture_float_linear');
    const programs = S.programs.map(function (p) {
      const prog = link(p.vs, p.fs, p.attributes, p.shader + ' ' + p.variant);
      // the same vertex stage with a fragment stage that writes whether the draw's values are
      // linear: the display pass encodes those pixels only (as glue/scene/frame.cpp does per pixel)
      const flag = link(p.vs, '#version 300 es\nprecision highp float; uniform float ts_flag; out vec4 ts_o;\n' +
                        'void main() { ts_o = vec4(ts_flag); }\n', p.attributes, p.shader + ' ' + p.variant + ' (display flag)');
      return {prog: prog, flag: flag, linear: !!p.linear_output, attributes: p.attributes, samplers: p.samplers};
    });
    // one GL texture per (data, filter, wrap) the draws use
    const texCache = {};
    function texture(t) {
      const key = t.texture + (t.linear ? 'L' : 'N') + (t.repeat ? 'R' : 'C') + (t.mip_filter || 'none');
      if (texCache[key]) return texCache[key];
      const d = S.textures[t.texture], data = floats(d.data);
      if (t.linear && !linearFloat) throw new Error('LINEAR float texture ' + t.sampler + ' needs OES_texture_float_linear');
      const target = d.kind === 'cube' ? gl.TEXTURE_CUBE_MAP : gl.TEXTURE_2D;
      const id = gl.createTexture();
      gl.bindTexture(target, id);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
      if (d.kind === 'cube') {
        const face = d.w * d.w * 4;
        for (let f = 0; f < 6; ++f)
          gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, gl.RGBA32F, d.w, d.w, 0, gl.RGBA, gl.FLOAT,
                        data.subarray(f * face, (f + 1) * face));
      } else {
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, d.w, d.h, 0, gl.RGBA, gl.FLOAT, data);
        // the mip chain tiershade built (levels 1..n, max(1, size >> k) a side)
        (d.levels || []).forEach(function (b64, k) {
          const l = k + 1;
          gl.texImage2D(gl.TEXTURE_2D, l, gl.RGBA32F, Math.max(1, d.w >> l), Math.max(1, d.h >> l), 0, gl.RGBA,
                        gl.FLOAT, floats(b64));
        });
      }
      const filter = t.linear ? gl.LINEAR : gl.NEAREST, wrap = t.repeat && d.kind !== 'cube' ? gl.REPEAT : gl.CLAMP_TO_EDGE;
      let minFilter = filter;
      if (t.mip_filter === 'nearest') minFilter = t.linear ? gl.LINEAR_MIPMAP_NEAREST : gl.NEAREST_MIPMAP_NEAREST;
      if (t.mip_filter === 'linear') minFilter = t.linear ? gl.LINEAR_MIPMAP_LINEAR : gl.NEAREST_MIPMAP_LINEAR;
      gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, minFilter);
      gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, filter);
      gl.texParameteri(target, gl.TEXTURE_WRAP_S, wrap);
      gl.texParameteri(target, gl.TEXTURE_WRAP_T, wrap);
      return (texCache[key] = {target: target, id: id});
    }
    const draws = S.draws.map(function (d) {
      const p = programs[d.program];
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      p.attributes.forEach(function (name, i) {
        const a = d.arrays[name];
        const b = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, b);
        gl.bufferData(gl.ARRAY_BUFFER, floats(a.data), gl.STATIC_DRAW);
        gl.enableVertexAttribArray(i);
        gl.vertexAttribPointer(i, a.size, gl.FLOAT, false, 0, 0);
      });
      const ib = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ib);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, u32s(d.index), gl.STATIC_DRAW);
      gl.bindVertexArray(null);
      const uniforms = d.uniforms.map(function (u) {
        const bits = u32s(u.data);
        return {name: u.name, type: u.type, bits: bits, values: new Float32Array(bits.buffer, bits.byteOffset, bits.length),
                loc: gl.getUniformLocation(p.prog, u.name), flagLoc: gl.getUniformLocation(p.flag, u.name)};
      });
      // each sampler the manifest lists on its unit, with the dump's texture of that name (the
      // renderer may bind a texture the variant does not sample: not listed, not bound, as bare_gl_render)
      const textures = p.samplers.map(function (name, unit) {
        const t = d.textures.find(x => x.sampler === name);
        if (!t) throw new Error('the dump has no texture for the sampler ' + name);
        return {unit: unit, tex: texture(t), loc: gl.getUniformLocation(p.prog, name)};
      });
      return {p: p, vao: vao, count: d.count, uniforms: uniforms, textures: textures};
    });
    // the RGBA32F target and its depth buffer
    const color = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, color);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, S.width, S.height, 0, gl.RGBA, gl.FLOAT, null);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    const depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, S.width, S.height);
    const fb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, color, 0);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
    if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error('the RGBA32F target is not complete');
    // the display flags: RGBA8, with a depth buffer of their own (the same vertex stages: the same coverage)
    const flagTex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, flagTex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, S.width, S.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    const flagDepth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, flagDepth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, S.width, S.height);
    const flagFb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, flagFb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, flagTex, 0);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, flagDepth);
    // the display pass: the target to the canvas
    const display = link('#version 300 es\nin vec2 a_corner; void main() { gl_Position = vec4(a_corner, 0.0, 1.0); }\n',
                         '#version 300 es\nprecision highp float; uniform sampler2D u_frame, u_flags; out vec4 o;\n' +
                         'void main() { vec3 c = clamp(texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb, 0.0, 1.0);\n' +
                         '  if (texelFetch(u_flags, ivec2(gl_FragCoord.xy), 0).r > 0.5) c = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));\n' +
                         '  o = vec4(c, 1.0); }\n', ['a_corner'], 'display pass');
    const corner = gl.createVertexArray();
    gl.bindVertexArray(corner);
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
    // the orbit's pivot: the view axis's point nearest the centre of the scene's bounds (world space)
    {
      const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
      S.draws.forEach(function (d, i) {
        const pos = floats(d.arrays.a_position ? d.arrays.a_position.data : '');
        const um = draws[i].uniforms.find(u => u.name === 'u_model');
        const m = um ? um.values : new Float32Array(identity());
        for (let v = 0; v + 2 < pos.length; v += 3)
          for (let k = 0; k < 3; ++k) {
            const w = m[k] * pos[v] + m[4 + k] * pos[v + 1] + m[8 + k] * pos[v + 2] + m[12 + k];
            lo[k] = Math.min(lo[k], w);
            hi[k] = Math.max(hi[k], w);
          }
      });
      const c = lo.map((l, k) => (l + hi[k]) / 2);
      const along = dot3([c[0] - cam.eye[0], c[1] - cam.eye[1], c[2] - cam.eye[2]], cam.forward);
      orbit.pivotDist = isFinite(along) && along > 1e-3 ? along : 1;
    }
    function setUniform(loc, type, v, name) {
      if (!loc) return;
      switch (type) {
        case 'float': gl.uniform1fv(loc, v); break;
        case 'vec2': gl.uniform2fv(loc, v); break;
        case 'vec3': gl.uniform3fv(loc, v); break;
        case 'vec4': gl.uniform4fv(loc, v); break;
        case 'mat3': gl.uniformMatrix3fv(loc, false, v); break;
        case 'mat4': gl.uniformMatrix4fv(loc, false, v); break;
        case 'int': case 'bool': gl.uniform1iv(loc, Int32Array.from(v)); break;
        default: throw new Error('uniform ' + name + ': type ' + type + ' is not replayed');
      }
    }
    function frame(first) {
      const now = cameraNow();
      const vp = viewProj(cam, now.eye, now.forward, S.width / S.height).map(Math.fround);
      const eye4 = [Math.fround(now.eye[0]), Math.fround(now.eye[1]), Math.fround(now.eye[2]), 1];
      gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
      gl.viewport(0, 0, S.width, S.height);
      gl.disable(gl.BLEND);
      gl.disable(gl.CULL_FACE);
      gl.enable(gl.DEPTH_TEST);
      gl.depthFunc(gl.LESS);
      gl.depthMask(true);
      gl.clearColor(S.clear[0], S.clear[1], S.clear[2], S.clear[3]);
      gl.clearDepth(1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      const f32 = new Float32Array(1), b32 = new Uint32Array(f32.buffer);
      for (const d of draws) {
        gl.useProgram(d.p.prog);
        for (const u of d.uniforms) {
          let v = u.values;
          // the camera's uniforms, recomputed; at the dump's camera they must equal the dump's bits
          const cameraValue = u.name === 'u_view_proj' ? vp : (u.name === 'u_eye' || u.name === 'u_eye_position') ? eye4 : null;
          if (cameraValue) {
            if (first)
              for (let k = 0; k < cameraValue.length; ++k) {
                f32[0] = cameraValue[k];
                ++vpCompared;
                if (b32[0] !== u.bits[k]) ++vpDiffer;
              }
            v = new Float32Array(cameraValue);
          }
          u.now = v;
          setUniform(u.loc, u.type, v, u.name);
        }
        for (const t of d.textures) {
          gl.activeTexture(gl.TEXTURE0 + t.unit);
          gl.bindTexture(t.tex.target, t.tex.id);
          if (t.loc) gl.uniform1i(t.loc, t.unit);
        }
        gl.activeTexture(gl.TEXTURE0);
        gl.bindVertexArray(d.vao);
        gl.drawElements(gl.TRIANGLES, d.count, gl.UNSIGNED_INT, 0);
      }
      gl.bindVertexArray(null);
      const e = gl.getError();
      if (e) throw new Error('GL error 0x' + e.toString(16) + ' while drawing');
      if (check && first) {
        const px = new Float32Array(S.width * S.height * 4);
        gl.readPixels(0, 0, S.width, S.height, gl.RGBA, gl.FLOAT, px);
        out.push('VP ' + vpDiffer + ' ' + vpCompared);
        out.push('F ' + toB64(px));
        return;  // the check reads the lit target only
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, flagFb);
      gl.clearColor(0, 0, 0, 0);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      for (const d of draws) {
        gl.useProgram(d.p.flag);
        for (const u of d.uniforms) setUniform(u.flagLoc, u.type, u.now, u.name);
        gl.uniform1f(gl.getUniformLocation(d.p.flag, 'ts_flag'), d.p.linear ? 1 : 0);
        gl.bindVertexArray(d.vao);
        gl.drawElements(gl.TRIANGLES, d.count, gl.UNSIGNED_INT, 0);
      }
      gl.bindVertexArray(null);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.viewport(0, 0, S.width, S.height);
      gl.disable(gl.DEPTH_TEST);
      gl.useProgram(display);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, color);
      gl.uniform1i(gl.getUniformLocation(display, 'u_frame'), 0);
      gl.activeTexture(gl.TEXTURE1);
      gl.bindTexture(gl.TEXTURE_2D, flagTex);
      gl.activeTexture(gl.TEXTURE0);
      gl.uniform1i(gl.getUniformLocation(display, 'u_flags'), 1);
      gl.bindVertexArray(corner);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.bindVertexArray(null);
    }
    frame(true);
    if (check) return;
    let pending = false, drag = null;
    function redraw() {
      if (pending) return;
      pending = true;
      requestAnimationFrame(function () { pending = false; frame(false); });
    }
    canvas.addEventListener('mousedown', function (e) { drag = {x: e.clientX, y: e.clientY}; canvas.style.cursor = 'grabbing'; });
    window.addEventListener('mouseup', function () { drag = null; canvas.style.cursor = 'grab'; });
    window.addEventListener('mousemove', function (e) {
      if (!drag) return;
      orbit.yaw -= (e.clientX - drag.x) * 0.01;
      orbit.pitch = Math.max(-1.5, Math.min(1.5, orbit.pitch - (e.clientY - drag.y) * 0.01));
      drag = {x: e.clientX, y: e.clientY};
      redraw();
    });
    canvas.addEventListener('wheel', function (e) {
      e.preventDefault();
      orbit.scale = Math.max(0.05, Math.min(20, orbit.scale * Math.exp(e.deltaY * 0.001)));
      redraw();
    }, {passive: false});
    canvas.addEventListener('dblclick', function () { orbit.yaw = orbit.pitch = 0; orbit.scale = 1; redraw(); });
  }
  try {
    run();
  } catch (e) {
    out.push('X ' + JSON.stringify(String(e.message || e)));
    document.getElementById('info').textContent = 'error: ' + (e.message || e);
  }
  out.push('DONE');
  document.getElementById('out').textContent = out.join('\n');
  document.title = 'done';
})();
