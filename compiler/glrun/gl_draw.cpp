#include "glrun/gl_draw.hpp"

#include <algorithm>
#include <chrono>
#include <set>

#include "glrun/gl_context.hpp"

namespace mb::gl {
namespace {

// The entry points drawing needs beyond GlContext's.
struct DrawFunctions {
  PFNGLENABLEPROC Enable;
  PFNGLDISABLEPROC Disable;
  PFNGLCULLFACEPROC CullFace;
  PFNGLFRONTFACEPROC FrontFace;
  PFNGLDEPTHFUNCPROC DepthFunc;
  PFNGLDEPTHMASKPROC DepthMask;
  PFNGLCLIPCONTROLPROC ClipControl;  // glClipControl, or ES's glClipControlEXT; null without it
  PFNGLVIEWPORTPROC Viewport;
  PFNGLSCISSORPROC Scissor;
  PFNGLPIXELSTOREIPROC PixelStorei;
  PFNGLGENVERTEXARRAYSPROC GenVertexArrays;
  PFNGLBINDVERTEXARRAYPROC BindVertexArray;
  PFNGLVERTEXATTRIBPOINTERPROC VertexAttribPointer;
  PFNGLENABLEVERTEXATTRIBARRAYPROC EnableVertexAttribArray;
  PFNGLDRAWELEMENTSPROC DrawElements;
  PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
  PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
  PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer;
  PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
  PFNGLGENRENDERBUFFERSPROC GenRenderbuffers;
  PFNGLBINDRENDERBUFFERPROC BindRenderbuffer;
  PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage;
  PFNGLDRAWBUFFERSPROC DrawBuffers;
  PFNGLREADBUFFERPROC ReadBuffer;
  PFNGLREADPIXELSPROC ReadPixels;
  PFNGLCLEARBUFFERFVPROC ClearBufferfv;
  PFNGLGENTEXTURESPROC GenTextures;
  PFNGLBINDTEXTUREPROC BindTexture;
  PFNGLACTIVETEXTUREPROC ActiveTexture;
  PFNGLTEXSTORAGE2DPROC TexStorage2D;
  PFNGLTEXSUBIMAGE2DPROC TexSubImage2D;
  PFNGLTEXPARAMETERIPROC TexParameteri;
  PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
  PFNGLUNIFORM1IPROC Uniform1i;
  PFNGLGETACTIVEUNIFORMBLOCKIVPROC GetActiveUniformBlockiv;
  PFNGLGETACTIVEUNIFORMBLOCKNAMEPROC GetActiveUniformBlockName;
};

void loadDrawFunctions(const GlContext& c, DrawFunctions& d) {
  c.load(d.Enable, "glEnable");
  c.load(d.Disable, "glDisable");
  c.load(d.CullFace, "glCullFace");
  c.load(d.FrontFace, "glFrontFace");
  c.load(d.DepthFunc, "glDepthFunc");
  c.load(d.DepthMask, "glDepthMask");
  if (c.api() == GlApi::Gl45Core)
    c.load(d.ClipControl, "glClipControl");
  else if (c.hasExtension("GL_EXT_clip_control"))
    c.loadOptional(d.ClipControl, "glClipControlEXT");
  c.load(d.Viewport, "glViewport");
  c.load(d.Scissor, "glScissor");
  c.load(d.PixelStorei, "glPixelStorei");
  c.load(d.GenVertexArrays, "glGenVertexArrays");
  c.load(d.BindVertexArray, "glBindVertexArray");
  c.load(d.VertexAttribPointer, "glVertexAttribPointer");
  c.load(d.EnableVertexAttribArray, "glEnableVertexAttribArray");
  c.load(d.DrawElements, "glDrawElements");
  c.load(d.GenFramebuffers, "glGenFramebuffers");
  c.load(d.BindFramebuffer, "glBindFramebuffer");
  c.load(d.FramebufferRenderbuffer, "glFramebufferRenderbuffer");
  c.load(d.CheckFramebufferStatus, "glCheckFramebufferStatus");
  c.load(d.GenRenderbuffers, "glGenRenderbuffers");
  c.load(d.BindRenderbuffer, "glBindRenderbuffer");
  c.load(d.RenderbufferStorage, "glRenderbufferStorage");
  c.load(d.DrawBuffers, "glDrawBuffers");
  c.load(d.ReadBuffer, "glReadBuffer");
  c.load(d.ReadPixels, "glReadPixels");
  c.load(d.ClearBufferfv, "glClearBufferfv");
  c.load(d.GenTextures, "glGenTextures");
  c.load(d.BindTexture, "glBindTexture");
  c.load(d.ActiveTexture, "glActiveTexture");
  c.load(d.TexStorage2D, "glTexStorage2D");
  c.load(d.TexSubImage2D, "glTexSubImage2D");
  c.load(d.TexParameteri, "glTexParameteri");
  c.load(d.GetUniformLocation, "glGetUniformLocation");
  c.load(d.Uniform1i, "glUniform1i");
  c.load(d.GetActiveUniformBlockiv, "glGetActiveUniformBlockiv");
  c.load(d.GetActiveUniformBlockName, "glGetActiveUniformBlockName");
}

// A job GL would draw wrongly without an error (an incomplete texture samples black, an index
// past the vertices reads outside the buffer) is refused before any GL call.
void checkJob(const DrawJob& job) {
  auto bad = [](const std::string& why) { throw GlError("malformed draw job: " + why); };
  if (job.width == 0 || job.height == 0) bad("an empty target");
  const DrawMesh& mesh = job.mesh;
  if (!mesh.indices.empty()) {
    if (mesh.floatsPerVertex == 0 || mesh.vertices.size() % mesh.floatsPerVertex)
      bad("the vertices are not whole vertices of floatsPerVertex floats");
    if (mesh.indices.size() % 3) bad("the indices are not whole triangles");
    const size_t vertexCount = mesh.vertices.size() / mesh.floatsPerVertex;
    for (uint32_t index : mesh.indices)
      if (index >= vertexCount) bad("index " + std::to_string(index) + " past the last vertex");
  }
  for (const DrawVertexAttribute& a : mesh.attributes)
    if (a.components < 1 || a.components > 4 || a.offset + a.components > mesh.floatsPerVertex)
      bad("attribute location " + std::to_string(a.location) + " does not fit in a vertex");
  for (size_t t = 0; t < job.textures.size(); ++t) {
    const DrawTexture& tex = job.textures[t];
    const std::string name = "texture " + std::to_string(t);
    if (tex.levels.empty()) bad(name + " has no level");
    const uint32_t w0 = tex.levels[0].width, h0 = tex.levels[0].height;
    if (w0 == 0 || h0 == 0) bad(name + " is empty");
    if (tex.cube && w0 != h0) bad(name + " is a cube with faces that are not square");
    uint32_t full = 1;  // the levels of a full chain
    while ((std::max(w0, h0) >> full) > 0) ++full;
    if (tex.levels.size() > full) bad(name + " has more levels than its chain");
    for (size_t l = 0; l < tex.levels.size(); ++l) {
      const DrawTextureLevel& level = tex.levels[l];
      if (level.width != std::max(1u, w0 >> l) || level.height != std::max(1u, h0 >> l))
        bad(name + " level " + std::to_string(l) + " is not half of the level above it");
      if (level.rgba.size() != size_t{level.width} * level.height * 4 * (tex.cube ? 6 : 1))
        bad(name + " level " + std::to_string(l) + " does not hold its texels");
    }
  }
  for (size_t d = 0; d < job.draws.size(); ++d)
    for (const auto& [name, index] : job.draws[d].samplers)
      if (index >= job.textures.size())
        bad("draw " + std::to_string(d) + " samples texture " + std::to_string(index) + " of " +
            std::to_string(job.textures.size()));
}

// The program's active uniform blocks, by name.
std::set<std::string> activeBlocks(const GlFunctions& f, const DrawFunctions& d, GLuint program) {
  GLint count = 0, longest = 0;
  f.GetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &count);
  f.GetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCK_MAX_NAME_LENGTH, &longest);
  std::set<std::string> names;
  std::vector<char> name(static_cast<size_t>(std::max(longest, 1)));
  for (GLint i = 0; i < count; ++i) {
    GLsizei length = 0;
    d.GetActiveUniformBlockName(program, static_cast<GLuint>(i), static_cast<GLsizei>(name.size()), &length,
                                name.data());
    names.emplace(name.data(), static_cast<size_t>(length));
  }
  return names;
}

}  // namespace

DrawResult drawOnGl(GlApi api, const DrawJob& job) {
  checkJob(job);
  // A context of its own per job: every object below goes with it (no share group), and no
  // state is left from an earlier job.
  GlContext context(api);
  const GlFunctions& f = context.f();
  DrawFunctions d{};
  loadDrawFunctions(context, d);
  DrawResult result;
  result.device = context.deviceName();
  if (api == GlApi::Es31) {
    auto require = [&](const char* extension, const char* forWhat) {
      if (!context.hasExtension(extension))
        throw GlError(apiName(api) + " on " + result.device + " lacks " + extension + " (" + forWhat + ")");
    };
    require("GL_EXT_color_buffer_float", "RGBA32F colour targets");
    if (!job.textures.empty()) require("GL_OES_texture_float_linear", "linear filtering of RGBA32F textures");
  }
  GLint maxDrawBuffers = 0, maxAttachments = 0, maxUnits = 0, maxBindings = 0, maxAttributes = 0;
  f.GetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  f.GetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &maxAttachments);
  f.GetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &maxUnits);
  f.GetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &maxBindings);
  f.GetIntegerv(GL_MAX_VERTEX_ATTRIBS, &maxAttributes);
  auto limit = [&](size_t asked, GLint most, const char* what) {
    if (asked > static_cast<size_t>(most))
      throw GlError(std::to_string(asked) + " " + what + " asked, " + result.device + " has " + std::to_string(most));
  };
  limit(job.colorTargets, std::min(maxDrawBuffers, maxAttachments), "colour targets");
  for (const DrawCall& call : job.draws) {
    limit(call.samplers.size(), maxUnits, "texture units");
    limit(call.uniformBlocks.size(), maxBindings, "uniform buffer bindings");
  }
  for (const DrawVertexAttribute& a : job.mesh.attributes) limit(a.location + size_t{1}, maxAttributes, "attributes");

  const auto t0 = std::chrono::steady_clock::now();
  const GLuint program = context.buildProgram({{GL_VERTEX_SHADER, &job.vertexSource, "the vertex shader"},
                                               {GL_FRAGMENT_SHADER, &job.fragmentSource, "the fragment shader"}},
                                              "the program");
  result.compileMs = msSince(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const std::set<std::string> blocks = activeBlocks(f, d, program);

  // The targets: RGBA32F colour and DEPTH_COMPONENT32F depth renderbuffers.
  const auto width = static_cast<GLsizei>(job.width), height = static_cast<GLsizei>(job.height);
  GLuint framebuffer = 0;
  d.GenFramebuffers(1, &framebuffer);
  d.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  std::vector<GLuint> renderbuffers(job.colorTargets + 1);
  d.GenRenderbuffers(static_cast<GLsizei>(renderbuffers.size()), renderbuffers.data());
  std::vector<GLenum> attachments;
  for (uint32_t i = 0; i <= job.colorTargets; ++i) {
    const bool depth = i == job.colorTargets;
    const GLenum attachment = depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0 + i;
    d.BindRenderbuffer(GL_RENDERBUFFER, renderbuffers[i]);
    d.RenderbufferStorage(GL_RENDERBUFFER, depth ? GL_DEPTH_COMPONENT32F : GL_RGBA32F, width, height);
    d.FramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffers[i]);
    if (!depth) attachments.push_back(attachment);
  }
  context.check("making the targets");
  if (GLenum status = d.CheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("the framebuffer of " + std::to_string(job.colorTargets) + " RGBA32F targets of " +
                  std::to_string(job.width) + "x" + std::to_string(job.height) + " is incomplete (status 0x" +
                  hex(status) + ")");
  d.DrawBuffers(static_cast<GLsizei>(attachments.size()), attachments.data());

  // The mesh.
  GLuint vertexArray = 0, meshBuffers[2] = {0, 0};
  d.GenVertexArrays(1, &vertexArray);
  d.BindVertexArray(vertexArray);
  f.GenBuffers(2, meshBuffers);
  f.BindBuffer(GL_ARRAY_BUFFER, meshBuffers[0]);
  f.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(job.mesh.vertices.size() * sizeof(float)),
               job.mesh.vertices.data(), GL_STATIC_DRAW);
  f.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshBuffers[1]);  // recorded in the vertex array
  f.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(job.mesh.indices.size() * sizeof(uint32_t)),
               job.mesh.indices.data(), GL_STATIC_DRAW);
  const auto stride = static_cast<GLsizei>(job.mesh.floatsPerVertex * sizeof(float));
  for (const DrawVertexAttribute& a : job.mesh.attributes) {
    d.VertexAttribPointer(a.location, static_cast<GLint>(a.components), GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(uintptr_t{a.offset} * sizeof(float)));
    d.EnableVertexAttribArray(a.location);
  }
  context.check("uploading the mesh");

  // The textures: immutable RGBA32F storage of the job's levels, the Vulkan path's sampler.
  std::vector<GLuint> textures(job.textures.size());
  if (!textures.empty()) d.GenTextures(static_cast<GLsizei>(textures.size()), textures.data());
  d.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  d.PixelStorei(GL_PACK_ALIGNMENT, 4);
  for (size_t t = 0; t < textures.size(); ++t) {
    const DrawTexture& tex = job.textures[t];
    const GLenum target = tex.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    d.BindTexture(target, textures[t]);
    const auto levels = static_cast<GLsizei>(tex.levels.size());
    d.TexStorage2D(target, levels, GL_RGBA32F, static_cast<GLsizei>(tex.levels[0].width),
                   static_cast<GLsizei>(tex.levels[0].height));
    for (GLsizei l = 0; l < levels; ++l) {
      const DrawTextureLevel& level = tex.levels[static_cast<size_t>(l)];
      const size_t faceFloats = size_t{level.width} * level.height * 4;
      for (int face = 0; face < (tex.cube ? 6 : 1); ++face)
        d.TexSubImage2D(tex.cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + face : GL_TEXTURE_2D, l, 0, 0,
                        static_cast<GLsizei>(level.width), static_cast<GLsizei>(level.height), GL_RGBA, GL_FLOAT,
                        level.rgba.data() + faceFloats * face);
    }
    d.TexParameteri(target, GL_TEXTURE_BASE_LEVEL, 0);
    d.TexParameteri(target, GL_TEXTURE_MAX_LEVEL, levels - 1);
    d.TexParameteri(target, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    d.TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    d.TexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    d.TexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    d.TexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  }
  context.check("uploading the textures");

  // Fixed state, the Vulkan path's. Its CCW front is counter-clockwise by Vulkan's rule, whose
  // area has the opposite sign of GL's for the same framebuffer coordinates: the vertex shader
  // writes Vulkan's clip space unchanged, so a triangle lands on the same (x, row) in both, and
  // GL calls it clockwise. GL_CW front therefore culls exactly the triangles Vulkan culls.
  d.Enable(GL_CULL_FACE);
  d.CullFace(GL_BACK);
  d.FrontFace(GL_CW);
  d.Enable(GL_DEPTH_TEST);
  d.DepthFunc(GL_LESS);
  d.DepthMask(GL_TRUE);
  d.Disable(GL_BLEND);
  d.Disable(GL_DITHER);
  // Vulkan's clip depth is 0..1: clip and map it so (glClipControl, core in 4.5; ES's
  // GL_EXT_clip_control), with GL's lower-left origin kept (the rows above). Without it GL maps
  // -1..1 to 0..1: the same depth order, with only geometry nearer than z = 0 drawn that
  // Vulkan clips.
  if (d.ClipControl) d.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  if (api == GlApi::Gl45Core) d.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // always so on ES 3.x
  context.check("setting the fixed state");

  d.Disable(GL_SCISSOR_TEST);
  for (uint32_t i = 0; i < job.colorTargets; ++i) {
    const std::array<float, 4> clear = i < job.clearColors.size() ? job.clearColors[i] : std::array<float, 4>{};
    d.ClearBufferfv(GL_COLOR, static_cast<GLint>(i), clear.data());
  }
  const float depthOne = 1.0f;
  d.ClearBufferfv(GL_DEPTH, 0, &depthOne);
  context.check("clearing the targets");

  // The draws. The scissor is the viewport, as on the Vulkan path.
  d.Enable(GL_SCISSOR_TEST);
  f.UseProgram(program);
  for (size_t n = 0; n < job.draws.size(); ++n) {
    const DrawCall& call = job.draws[n];
    const std::string drawName = "draw " + std::to_string(n);
    const auto& v = call.viewport;
    if (v[2])
      d.Viewport(static_cast<GLint>(v[0]), static_cast<GLint>(v[1]), static_cast<GLsizei>(v[2]),
                 static_cast<GLsizei>(v[3]));
    else
      d.Viewport(0, 0, width, height);
    if (v[2])
      d.Scissor(static_cast<GLint>(v[0]), static_cast<GLint>(v[1]), static_cast<GLsizei>(v[2]),
                static_cast<GLsizei>(v[3]));
    else
      d.Scissor(0, 0, width, height);
    for (const std::string& block : blocks)
      if (!call.uniformBlocks.count(block))
        throw GlError(drawName + ": the program's uniform block " + block + " has no contents");
    GLuint binding = 0;
    for (const auto& [name, bytes] : call.uniformBlocks) {
      const GLuint index = f.GetUniformBlockIndex(program, name.c_str());
      if (index == GL_INVALID_INDEX) continue;  // not in the program (an optimized stage dropped it)
      GLint size = 0;
      d.GetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
      if (bytes.size() < static_cast<size_t>(size))
        throw GlError(drawName + ": uniform block " + name + " has " + std::to_string(bytes.size()) +
                      " bytes, the program's has " + std::to_string(size));
      GLuint buffer = 0;  // one per block and draw
      f.GenBuffers(1, &buffer);
      f.BindBuffer(GL_UNIFORM_BUFFER, buffer);
      f.BufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(bytes.size()), bytes.data(), GL_STATIC_DRAW);
      f.UniformBlockBinding(program, index, binding);
      f.BindBufferBase(GL_UNIFORM_BUFFER, binding, buffer);
      ++binding;
    }
    GLint unit = 0;
    for (const auto& [name, index] : call.samplers) {
      const GLint location = d.GetUniformLocation(program, name.c_str());
      if (location < 0) continue;  // not in the program
      const DrawTexture& tex = job.textures[index];
      d.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
      d.BindTexture(tex.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D, textures[index]);
      d.Uniform1i(location, unit);
      ++unit;
    }
    context.check((drawName + ": binding its blocks and textures").c_str());
    if (!job.mesh.indices.empty())
      d.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(job.mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
    context.check(drawName.c_str());
  }

  // Read-back: GL's rows bottom-up are the Vulkan path's rows top-down (draw_job.hpp), so
  // glReadPixels' order is the result's.
  result.targets.resize(job.colorTargets);
  for (uint32_t i = 0; i < job.colorTargets; ++i) {
    result.targets[i].resize(size_t{job.width} * job.height * 4);
    d.ReadBuffer(GL_COLOR_ATTACHMENT0 + i);
    d.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, result.targets[i].data());
  }
  context.check("reading the targets back");
  result.renderMs = msSince(t1);
  return result;
}

}  // namespace mb::gl
