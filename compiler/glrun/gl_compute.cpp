#include "glrun/gl_compute.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <sstream>

namespace mb::gl {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The first line of a driver's info log.
std::string firstLine(const std::string& log) {
  const std::string line = log.substr(0, log.find('\n'));
  return line.empty() ? "no message" : line;
}

constexpr GLuint kLocalSize = 64;    // the contract's local_size_x
constexpr GLuint kTableBinding = 2;  // SPIRV-Cross keeps the storage buffer's binding
constexpr GLuint kPushBinding = 0;   // where the MbPush block is bound, whatever its layout binding

}  // namespace

// The GL entry points, from eglGetProcAddress (EGL_KHR_get_all_proc_addresses: core functions
// too), so that one loader serves the desktop and the ES context and nothing links libGL.
struct Functions {
  PFNGLGETSTRINGPROC GetString;
  PFNGLGETSTRINGIPROC GetStringi;
  PFNGLGETINTEGERVPROC GetIntegerv;
  PFNGLGETINTEGERI_VPROC GetIntegeri_v;
  PFNGLGETERRORPROC GetError;
  PFNGLCREATESHADERPROC CreateShader;
  PFNGLSHADERSOURCEPROC ShaderSource;
  PFNGLCOMPILESHADERPROC CompileShader;
  PFNGLGETSHADERIVPROC GetShaderiv;
  PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
  PFNGLDELETESHADERPROC DeleteShader;
  PFNGLCREATEPROGRAMPROC CreateProgram;
  PFNGLATTACHSHADERPROC AttachShader;
  PFNGLLINKPROGRAMPROC LinkProgram;
  PFNGLGETPROGRAMIVPROC GetProgramiv;
  PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
  PFNGLDELETEPROGRAMPROC DeleteProgram;
  PFNGLUSEPROGRAMPROC UseProgram;
  PFNGLGETUNIFORMBLOCKINDEXPROC GetUniformBlockIndex;
  PFNGLUNIFORMBLOCKBINDINGPROC UniformBlockBinding;
  PFNGLGENBUFFERSPROC GenBuffers;
  PFNGLDELETEBUFFERSPROC DeleteBuffers;
  PFNGLBINDBUFFERPROC BindBuffer;
  PFNGLBUFFERDATAPROC BufferData;
  PFNGLBINDBUFFERBASEPROC BindBufferBase;
  PFNGLMAPBUFFERRANGEPROC MapBufferRange;
  PFNGLUNMAPBUFFERPROC UnmapBuffer;
  PFNGLDISPATCHCOMPUTEPROC DispatchCompute;
  PFNGLMEMORYBARRIERPROC MemoryBarrier;
  PFNGLFINISHPROC Finish;
};

struct GlCompute::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  Functions f{};
  std::map<std::string, GLuint> programs;
  GLint maxGroupsX = 65535;
  GLint maxBlockBytes = 1 << 27;
  GLuint buffers[4] = {0, 0, 0, 0};  // in, out, push, table

  void makeCurrent() {
    if (eglGetCurrentContext() != context && !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
      throw GlError("eglMakeCurrent failed (EGL error 0x" + hex(eglGetError()) + ")");
  }
  static std::string hex(unsigned v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
  }
  void check(const char* what) {
    if (GLenum e = f.GetError(); e != GL_NO_ERROR)
      throw GlError(std::string(what) + " failed (GL error 0x" + hex(e) + ")");
  }
  GLuint program(const std::string& source, double& compileMs);
};

std::string apiName(GlApi api) { return api == GlApi::Gl45Core ? "OpenGL 4.5 core" : "OpenGL ES 3.1"; }

GlCompute::GlCompute(GlApi api) : api_(api), impl_(std::make_unique<Impl>()) {
  const std::string what = "no " + apiName(api) + " context on EGL's surfaceless platform: ";
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!clientExtensions || !std::strstr(clientExtensions, "EGL_MESA_platform_surfaceless"))
    throw GlError(what + "EGL lacks EGL_MESA_platform_surfaceless (install libegl-mesa0 and libgl1-mesa-dri)");
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  Impl& m = *impl_;
  m.display = getPlatformDisplay ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                                 : EGL_NO_DISPLAY;
  EGLint major = 0, minor = 0;
  if (m.display == EGL_NO_DISPLAY || !eglInitialize(m.display, &major, &minor))
    throw GlError(what + "eglInitialize failed (EGL error 0x" + Impl::hex(eglGetError()) + ")");
  const bool es = api == GlApi::Es31;
  if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
    eglTerminate(m.display);
    throw GlError(what + "eglBindAPI failed");
  }
  // No config and no surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): compute
  // needs neither.
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               es ? 3 : 4,
                               EGL_CONTEXT_MINOR_VERSION,
                               es ? 1 : 5,
                               es ? EGL_NONE : EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  m.context = eglCreateContext(m.display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (m.context == EGL_NO_CONTEXT) {
    const EGLint error = eglGetError();
    eglTerminate(m.display);
    throw GlError(what + "eglCreateContext failed (EGL error 0x" + Impl::hex(error) + ")");
  }
  m.makeCurrent();
  auto load = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(eglGetProcAddress(name));
    if (!fn) throw GlError(what + "no entry point " + name);
  };
  Functions& f = m.f;
  load(f.GetString, "glGetString");
  load(f.GetStringi, "glGetStringi");
  load(f.GetIntegerv, "glGetIntegerv");
  load(f.GetIntegeri_v, "glGetIntegeri_v");
  load(f.GetError, "glGetError");
  load(f.CreateShader, "glCreateShader");
  load(f.ShaderSource, "glShaderSource");
  load(f.CompileShader, "glCompileShader");
  load(f.GetShaderiv, "glGetShaderiv");
  load(f.GetShaderInfoLog, "glGetShaderInfoLog");
  load(f.DeleteShader, "glDeleteShader");
  load(f.CreateProgram, "glCreateProgram");
  load(f.AttachShader, "glAttachShader");
  load(f.LinkProgram, "glLinkProgram");
  load(f.GetProgramiv, "glGetProgramiv");
  load(f.GetProgramInfoLog, "glGetProgramInfoLog");
  load(f.DeleteProgram, "glDeleteProgram");
  load(f.UseProgram, "glUseProgram");
  load(f.GetUniformBlockIndex, "glGetUniformBlockIndex");
  load(f.UniformBlockBinding, "glUniformBlockBinding");
  load(f.GenBuffers, "glGenBuffers");
  load(f.DeleteBuffers, "glDeleteBuffers");
  load(f.BindBuffer, "glBindBuffer");
  load(f.BufferData, "glBufferData");
  load(f.BindBufferBase, "glBindBufferBase");
  load(f.MapBufferRange, "glMapBufferRange");
  load(f.UnmapBuffer, "glUnmapBuffer");
  load(f.DispatchCompute, "glDispatchCompute");
  load(f.MemoryBarrier, "glMemoryBarrier");
  load(f.Finish, "glFinish");
  f.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &m.maxGroupsX);
  f.GetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &m.maxBlockBytes);
  f.GenBuffers(4, m.buffers);
  m.check("creating the context's buffers");
}

GlCompute::~GlCompute() {
  Impl& m = *impl_;
  if (eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, m.context)) {
    for (const auto& entry : m.programs) m.f.DeleteProgram(entry.second);
    m.f.DeleteBuffers(4, m.buffers);
  }
  eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(m.display, m.context);
  eglTerminate(m.display);
}

std::string GlCompute::deviceName() const {
  impl_->makeCurrent();
  auto str = [&](GLenum name) {
    const GLubyte* s = impl_->f.GetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_RENDERER) + ", " + str(GL_VERSION);
}

bool GlCompute::hasExtension(const std::string& name) const {
  impl_->makeCurrent();
  GLint n = 0;
  impl_->f.GetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i) {
    const GLubyte* e = impl_->f.GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
    if (e && name == reinterpret_cast<const char*>(e)) return true;
  }
  return false;
}

GLuint GlCompute::Impl::program(const std::string& source, double& compileMs) {
  if (auto it = programs.find(source); it != programs.end()) return it->second;
  const auto t0 = std::chrono::steady_clock::now();
  GLuint shader = f.CreateShader(GL_COMPUTE_SHADER);
  const char* text = source.c_str();
  f.ShaderSource(shader, 1, &text, nullptr);
  f.CompileShader(shader);
  GLint ok = 0;
  f.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  auto infoLog = [&](auto getLog, GLuint object) {
    char log[4096] = {0};
    getLog(object, sizeof log, nullptr, log);
    return firstLine(log);
  };
  if (!ok) {
    const std::string why = infoLog(f.GetShaderInfoLog, shader);
    f.DeleteShader(shader);
    throw GlError("the driver's GLSL compiler rejected the kernel: " + why);
  }
  GLuint prog = f.CreateProgram();
  f.AttachShader(prog, shader);
  f.LinkProgram(prog);
  f.DeleteShader(shader);  // flagged; freed with the program
  f.GetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string why = infoLog(f.GetProgramInfoLog, prog);
    f.DeleteProgram(prog);
    throw GlError("the driver could not link the kernel: " + why);
  }
  const GLuint block = f.GetUniformBlockIndex(prog, "MbPush");
  if (block == GL_INVALID_INDEX) {
    f.DeleteProgram(prog);
    throw GlError("the kernel has no uniform block MbPush (the record count)");
  }
  f.UniformBlockBinding(prog, block, kPushBinding);
  check("linking the kernel");
  compileMs = msSince(t0);
  programs.emplace(source, prog);
  return prog;
}

GlRunResult GlCompute::run(const std::string& source, const std::vector<float>& inputs, uint32_t inStride,
                           uint32_t outStride, uint64_t count, const std::vector<float>* table) {
  Impl& m = *impl_;
  m.makeCurrent();
  GlRunResult r;
  const bool first = !m.programs.count(source);
  const GLuint prog = m.program(source, r.compileMs);
  m.f.UseProgram(prog);
  r.outputs.assign(count * outStride, 0.0f);
  const uint64_t stride = std::max(inStride, outStride) * sizeof(float);
  const uint64_t perChunk = std::max<uint64_t>(
      1, std::min<uint64_t>(static_cast<uint64_t>(m.maxGroupsX) * kLocalSize, m.maxBlockBytes / stride));
  if (table) {
    m.f.BindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[3]);
    m.f.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<size_t>(1, table->size()) * 4),
                   table->empty() ? nullptr : table->data(), GL_STATIC_DRAW);
    m.f.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kTableBinding, m.buffers[3]);
    m.check("uploading the table");
  }
  auto dispatch = [&](uint64_t begin, uint64_t n) {
    m.f.BindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[0]);
    m.f.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<uint64_t>(1, n * inStride) * 4),
                   n ? inputs.data() + begin * inStride : nullptr, GL_STATIC_DRAW);
    m.f.BindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[1]);
    m.f.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<uint64_t>(1, n * outStride) * 4), nullptr,
                   GL_STREAM_READ);
    // std140: one uint, padded to 16 bytes.
    const uint32_t push[4] = {static_cast<uint32_t>(n), 0, 0, 0};
    m.f.BindBuffer(GL_UNIFORM_BUFFER, m.buffers[2]);
    m.f.BufferData(GL_UNIFORM_BUFFER, sizeof push, push, GL_STREAM_DRAW);
    m.f.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m.buffers[0]);
    m.f.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.buffers[1]);
    m.f.BindBufferBase(GL_UNIFORM_BUFFER, kPushBinding, m.buffers[2]);
    m.f.DispatchCompute(static_cast<GLuint>(std::max<uint64_t>(1, (n + kLocalSize - 1) / kLocalSize)), 1, 1);
    m.f.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    m.check("dispatching the kernel");
    if (!n) return;
    m.f.BindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[1]);
    const void* out =
        m.f.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * outStride * 4), GL_MAP_READ_BIT);
    if (!out) throw GlError("glMapBufferRange of the output failed");
    std::memcpy(r.outputs.data() + begin * outStride, out, n * outStride * 4);
    m.f.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
    m.check("reading the output back");
  };
  if (first) {
    // llvmpipe compiles the shader to machine code at its first dispatch: a run of no records
    // takes that out of the timed interval, as the Vulkan harness's warm-up dispatch does.
    const auto t0 = std::chrono::steady_clock::now();
    dispatch(0, 0);
    m.f.Finish();
    r.firstDispatchMs = msSince(t0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  for (uint64_t begin = 0; begin < count; begin += perChunk, ++r.chunks)
    dispatch(begin, std::min(perChunk, count - begin));
  m.f.Finish();
  r.ms = msSince(t0);
  return r;
}

}  // namespace mb::gl
