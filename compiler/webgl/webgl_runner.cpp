#include "webgl/webgl_runner.hpp"

namespace mb::webgl {

// WebGL 2.0 (Khronos WebGL 2.0 spec; OpenGL ES 3.0 semantics): the same fixed state as
// glrun/gl_draw.cpp and the Vulkan path. Row 0 of readPixels is the framebuffer's bottom row,
// which with the vertex shader's Vulkan clip space is the Vulkan path's top row (glrun/draw_job.hpp).
const std::string& webglRunnerScript() {
  static const std::string script = R"JS(
'use strict';
globalThis.mbDraw = function (job) {
  const bytes = (b64) => {
    const s = atob(b64);
    const out = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
    return out;
  };
  const floats = (b64) => new Float32Array(bytes(b64).buffer);
  const toBase64 = (u8) => {
    let s = '';
    for (let i = 0; i < u8.length; i += 0x8000) s += String.fromCharCode.apply(null, u8.subarray(i, i + 0x8000));
    return btoa(s);
  };
  const canvas = document.createElement('canvas');
  canvas.width = 1;
  canvas.height = 1;
  const gl = canvas.getContext('webgl2', {antialias: false, depth: false, stencil: false, alpha: true});
  if (!gl) throw new Error('no WebGL 2.0 context');
  for (const e of ['EXT_color_buffer_float', 'OES_texture_float_linear'])
    if (!gl.getExtension(e)) throw new Error('WebGL 2.0 lacks ' + e);
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const device = (info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)) + ', ' +
      gl.getParameter(gl.VERSION);
  const firstLine = (log) => (log || 'no message').split('\n').filter((l) => l.trim())[0] || 'no message';
  const t0 = performance.now();
  const shader = (type, source, stage) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS))
      throw new Error('WebGL 2.0 ' + stage + ' shader: ' + firstLine(gl.getShaderInfoLog(s)));
    return s;
  };
  const program = gl.createProgram();
  gl.attachShader(program, shader(gl.VERTEX_SHADER, job.vertexSource, 'vertex'));
  gl.attachShader(program, shader(gl.FRAGMENT_SHADER, job.fragmentSource, 'fragment'));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS))
    throw new Error('WebGL 2.0 link: ' + firstLine(gl.getProgramInfoLog(program)));
  const compileMs = performance.now() - t0;

  const t1 = performance.now();
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  const attachments = [];
  for (let i = 0; i < job.colorTargets; ++i) {
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, job.width, job.height);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, t, 0);
    attachments.push(gl.COLOR_ATTACHMENT0 + i);
  }
  const depth = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT32F, job.width, job.height);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  gl.drawBuffers(attachments);
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (status !== gl.FRAMEBUFFER_COMPLETE) throw new Error('WebGL 2.0 framebuffer incomplete (0x' + status.toString(16) + ')');

  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ARRAY_BUFFER, floats(job.mesh.vertices), gl.STATIC_DRAW);
  for (const a of job.mesh.attributes) {
    gl.enableVertexAttribArray(a.location);
    gl.vertexAttribPointer(a.location, a.components, gl.FLOAT, false, job.mesh.floatsPerVertex * 4, a.offset * 4);
  }
  const indices = new Uint32Array(bytes(job.mesh.indices).buffer);
  gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);

  const textures = job.textures.map((t) => {
    const target = t.cube ? gl.TEXTURE_CUBE_MAP : gl.TEXTURE_2D;
    const tex = gl.createTexture();
    gl.bindTexture(target, tex);
    gl.texStorage2D(target, t.levels.length, gl.RGBA32F, t.levels[0].width, t.levels[0].height);
    t.levels.forEach((l, level) => {
      const data = floats(l.rgba);
      const face = l.width * l.height * 4;
      if (t.cube)
        for (let f = 0; f < 6; ++f)
          gl.texSubImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + f, level, 0, 0, l.width, l.height, gl.RGBA, gl.FLOAT,
                           data.subarray(f * face, (f + 1) * face));
      else
        gl.texSubImage2D(gl.TEXTURE_2D, level, 0, 0, l.width, l.height, gl.RGBA, gl.FLOAT, data);
    });
    gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, t.levels.length > 1 ? gl.LINEAR_MIPMAP_LINEAR : gl.LINEAR);
    gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(target, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(target, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    if (t.cube) gl.texParameteri(target, gl.TEXTURE_WRAP_R, gl.CLAMP_TO_EDGE);
    return {target, tex};
  });

  gl.useProgram(program);
  gl.enable(gl.CULL_FACE);
  gl.cullFace(gl.BACK);
  gl.frontFace(gl.CW);  // Vulkan's counter-clockwise front (glrun/draw_job.hpp)
  gl.enable(gl.DEPTH_TEST);
  gl.depthFunc(gl.LESS);
  gl.depthMask(true);
  gl.disable(gl.BLEND);
  for (let i = 0; i < job.colorTargets; ++i)
    gl.clearBufferfv(gl.COLOR, i, (job.clearColors && job.clearColors[i]) || [0, 0, 0, 0]);
  gl.clearBufferfv(gl.DEPTH, 0, [1]);

  const ubos = [];
  for (const d of job.draws) {
    let binding = 0;
    for (const [name, b64] of Object.entries(d.uniformBlocks)) {
      const index = gl.getUniformBlockIndex(program, name);
      if (index === gl.INVALID_INDEX) continue;
      const data = bytes(b64);
      const size = gl.getActiveUniformBlockParameter(program, index, gl.UNIFORM_BLOCK_DATA_SIZE);
      if (data.length < size) throw new Error('block ' + name + ': ' + data.length + ' bytes for ' + size);
      gl.uniformBlockBinding(program, index, binding);
      const ubo = gl.createBuffer();
      ubos.push(ubo);
      gl.bindBuffer(gl.UNIFORM_BUFFER, ubo);
      gl.bufferData(gl.UNIFORM_BUFFER, data, gl.STATIC_DRAW);
      gl.bindBufferBase(gl.UNIFORM_BUFFER, binding, ubo);
      ++binding;
    }
    let unit = 0;
    for (const [name, index] of Object.entries(d.samplers)) {
      const location = gl.getUniformLocation(program, name);
      if (location === null) continue;
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(textures[index].target, textures[index].tex);
      gl.uniform1i(location, unit);
      ++unit;
    }
    const [x, y, w, h] = d.viewport;
    if (w === 0) gl.viewport(0, 0, job.width, job.height);
    else gl.viewport(x, y, w, h);
    gl.drawElements(gl.TRIANGLES, indices.length, gl.UNSIGNED_INT, 0);
  }
  const targets = [];
  for (let i = 0; i < job.colorTargets; ++i) {
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + i);
    const pixels = new Float32Array(job.width * job.height * 4);
    gl.readPixels(0, 0, job.width, job.height, gl.RGBA, gl.FLOAT, pixels);
    targets.push(toBase64(new Uint8Array(pixels.buffer)));
  }
  const error = gl.getError();
  if (error !== gl.NO_ERROR) throw new Error('WebGL 2.0 error 0x' + error.toString(16));
  const renderMs = performance.now() - t1;
  ubos.forEach((b) => gl.deleteBuffer(b));
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();
  return {device, compileMs, renderMs, targets};
};
)JS";
  return script;
}

}  // namespace mb::webgl
