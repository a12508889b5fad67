// tiershade glue/browser/webgl_reflect.js: links every program of the job (job.js: var TS_JOB =
// {programs: [{webgl: 1|2, vs, fs, attributes: [names]}]}) in a WebGL 1 or WebGL 2 context, as the
// program's bundle targets (essl100 / essl300), and reports its active interface: every
// getActiveAttrib and getActiveUniform entry with its GL type enum and size. Attributes are bound to
// the manifest's list index before linking, as docs/bundles.md ("Loading a variant") says.
// Output lines in <pre id="out">:
//   I <webgl> <text>            a context (version, unmasked renderer)
//   P <program> <json>          {"attributes": [[name, type, size]...], "uniforms": [[name, type, size]...]}
//   E <program> <message>       the program failed to compile or link (message JSON-quoted)
//   X <message>                 the page itself failed (no WebGL, an exception)
//   DONE                        the last line when the page ran to its end
(function () {
  'use strict';
  const out = [];
  const contexts = {};
  function context(v) {
    if (contexts[v]) return contexts[v];
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 1;
    const gl = canvas.getContext(v === 2 ? 'webgl2' : 'webgl', {antialias: false});
    if (!gl) throw new Error('WebGL ' + v + ' is not available');
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    out.push('I ' + v + ' ' + gl.getParameter(gl.VERSION) + ' | ' +
             (dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)));
    contexts[v] = gl;
    return gl;
  }
  function compile(gl, type, src) {
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
  function reflect(p) {
    const gl = context(p.webgl);
    const vs = compile(gl, gl.VERTEX_SHADER, p.vs);
    let fs;
    try {
      fs = compile(gl, gl.FRAGMENT_SHADER, p.fs);
    } catch (e) {
      gl.deleteShader(vs);
      throw e;
    }
    const prog = gl.createProgram();
    gl.attachShader(prog, vs);
    gl.attachShader(prog, fs);
    p.attributes.forEach(function (name, i) { gl.bindAttribLocation(prog, i, name); });
    gl.linkProgram(prog);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) {
      const log = gl.getProgramInfoLog(prog);
      gl.deleteProgram(prog);
      throw new Error('link: ' + log);
    }
    const r = {attributes: [], uniforms: []};
    const na = gl.getProgramParameter(prog, gl.ACTIVE_ATTRIBUTES);
    for (let i = 0; i < na; ++i) {
      const a = gl.getActiveAttrib(prog, i);
      r.attributes.push([a.name, a.type, a.size]);
    }
    const nu = gl.getProgramParameter(prog, gl.ACTIVE_UNIFORMS);
    for (let i = 0; i < nu; ++i) {
      const u = gl.getActiveUniform(prog, i);
      r.uniforms.push([u.name, u.type, u.size]);
    }
    gl.deleteProgram(prog);
    return r;
  }
  try {
    const job = window.TS_JOB;
    if (!job) throw new Error('job.js did not define TS_JOB');
    job.programs.forEach(function (p, i) {
      try {
        out.push('P ' + i + ' ' + JSON.stringify(reflect(p)));
      } catch (e) {
        if (String(e.message || e).indexOf('is not available') >= 0) throw e;
        out.push('E ' + i + ' ' + JSON.stringify(String(e.message || e)));
      }
    });
  } catch (e) {
    out.push('X ' + JSON.stringify(String(e.message || e)));
  }
  out.push('DONE');
  document.getElementById('out').textContent = out.join('\n');
  document.title = 'done';
})();
