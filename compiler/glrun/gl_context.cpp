#include "glrun/gl_context.hpp"

#include <cstring>
#include <mutex>
#include <sstream>
#include <vector>

namespace mb::gl {
namespace {

// EGL hands out one display per platform and native display, and eglTerminate ends it for every
// context made on it: each GlContext takes a reference, and the last one terminates it, so that
// destroying one context (a drawOnGl call's) leaves the others (a GlCompute's) usable.
std::mutex displayMutex;
int displayUsers = 0;

void releaseDisplay(EGLDisplay display) {
  std::lock_guard<std::mutex> lock(displayMutex);
  if (--displayUsers == 0) eglTerminate(display);
}

}  // namespace

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string hex(unsigned v) {
  std::ostringstream s;
  s << std::hex << v;
  return s.str();
}

std::string firstLine(const std::string& log) {
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) return line;
  return "no message";
}

std::string GlContext::noContext() const { return "no " + apiName(api_) + " context on EGL's surfaceless platform: "; }

GlContext::GlContext(GlApi api) : api_(api) {
  const std::string what = noContext();
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!clientExtensions || !std::strstr(clientExtensions, "EGL_MESA_platform_surfaceless"))
    throw GlError(what + "EGL lacks EGL_MESA_platform_surfaceless (install libegl-mesa0 and libgl1-mesa-dri)");
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  display_ = getPlatformDisplay ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                                : EGL_NO_DISPLAY;
  {
    std::lock_guard<std::mutex> lock(displayMutex);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
      throw GlError(what + "eglInitialize failed (EGL error 0x" + hex(eglGetError()) + ")");
    ++displayUsers;
  }
  const bool es = api == GlApi::Es31;
  if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
    releaseDisplay(display_);
    throw GlError(what + "eglBindAPI failed");
  }
  // No config and no surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): compute
  // needs neither, and drawing goes to framebuffer objects.
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               es ? 3 : 4,
                               EGL_CONTEXT_MINOR_VERSION,
                               es ? 1 : 5,
                               es ? EGL_NONE : EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context_ == EGL_NO_CONTEXT) {
    const EGLint error = eglGetError();
    releaseDisplay(display_);
    throw GlError(what + "eglCreateContext failed (EGL error 0x" + hex(error) + ")");
  }
  try {
    makeCurrent();
    load(f_.GetString, "glGetString");
    load(f_.GetStringi, "glGetStringi");
    load(f_.GetIntegerv, "glGetIntegerv");
    load(f_.GetError, "glGetError");
    load(f_.CreateShader, "glCreateShader");
    load(f_.ShaderSource, "glShaderSource");
    load(f_.CompileShader, "glCompileShader");
    load(f_.GetShaderiv, "glGetShaderiv");
    load(f_.GetShaderInfoLog, "glGetShaderInfoLog");
    load(f_.DeleteShader, "glDeleteShader");
    load(f_.CreateProgram, "glCreateProgram");
    load(f_.AttachShader, "glAttachShader");
    load(f_.LinkProgram, "glLinkProgram");
    load(f_.GetProgramiv, "glGetProgramiv");
    load(f_.GetProgramInfoLog, "glGetProgramInfoLog");
    load(f_.DeleteProgram, "glDeleteProgram");
    load(f_.UseProgram, "glUseProgram");
    load(f_.GetUniformBlockIndex, "glGetUniformBlockIndex");
    load(f_.UniformBlockBinding, "glUniformBlockBinding");
    load(f_.GenBuffers, "glGenBuffers");
    load(f_.DeleteBuffers, "glDeleteBuffers");
    load(f_.BindBuffer, "glBindBuffer");
    load(f_.BufferData, "glBufferData");
    load(f_.BindBufferBase, "glBindBufferBase");
    load(f_.Finish, "glFinish");
  } catch (...) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    releaseDisplay(display_);
    throw;
  }
}

GlContext::~GlContext() {
  if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  releaseDisplay(display_);
}

void GlContext::makeCurrent() const {
  if (eglGetCurrentContext() != context_ && !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    throw GlError("eglMakeCurrent failed (EGL error 0x" + hex(eglGetError()) + ")");
}

void (*GlContext::entryPoint(const char* name, bool required) const)() {
  auto fn = eglGetProcAddress(name);
  if (!fn && required) throw GlError(noContext() + "no entry point " + name);
  return fn;
}

std::string GlContext::deviceName() const {
  makeCurrent();
  auto str = [&](GLenum name) {
    const GLubyte* s = f_.GetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_RENDERER) + ", " + str(GL_VERSION);
}

bool GlContext::hasExtension(const std::string& name) const {
  makeCurrent();
  GLint n = 0;
  f_.GetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i) {
    const GLubyte* e = f_.GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
    if (e && name == reinterpret_cast<const char*>(e)) return true;
  }
  return false;
}

void GlContext::check(const char* what) const {
  if (GLenum e = f_.GetError(); e != GL_NO_ERROR)
    throw GlError(std::string(what) + " failed (GL error 0x" + hex(e) + ")");
}

GLuint GlContext::buildProgram(std::initializer_list<GlShaderSource> shaders, const char* programWhat) const {
  auto infoLog = [&](auto getLog, GLuint object) {
    char log[4096] = {0};
    getLog(object, sizeof log, nullptr, log);
    return firstLine(log);
  };
  std::vector<GLuint> compiled;
  auto deleteShaders = [&] {
    for (GLuint shader : compiled) f_.DeleteShader(shader);  // once attached: flagged, freed with the program
  };
  for (const GlShaderSource& s : shaders) {
    GLuint shader = f_.CreateShader(s.stage);
    compiled.push_back(shader);
    const char* text = s.source->c_str();
    f_.ShaderSource(shader, 1, &text, nullptr);
    f_.CompileShader(shader);
    GLint ok = 0;
    f_.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string why = infoLog(f_.GetShaderInfoLog, shader);
      deleteShaders();
      throw GlError(std::string("the driver's GLSL compiler rejected ") + s.what + ": " + why);
    }
  }
  GLuint program = f_.CreateProgram();
  for (GLuint shader : compiled) f_.AttachShader(program, shader);
  f_.LinkProgram(program);
  deleteShaders();
  GLint ok = 0;
  f_.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string why = infoLog(f_.GetProgramInfoLog, program);
    f_.DeleteProgram(program);
    throw GlError(std::string("the driver could not link ") + programWhat + ": " + why);
  }
  return program;
}

}  // namespace mb::gl
