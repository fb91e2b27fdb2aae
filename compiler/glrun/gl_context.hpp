// The EGL context that GlCompute (gl_compute.hpp) and drawOnGl (gl_draw.hpp) run in: OpenGL 4.5
// core or OpenGL ES 3.1 on EGL's surfaceless platform (EGL_MESA_platform_surfaceless), no config
// and no surface, every GL entry point from eglGetProcAddress (EGL_KHR_get_all_proc_addresses:
// core functions too), so that one loader serves the desktop and the ES context and nothing
// links libGL or libGLESv2. Internal to compiler/glrun/: it includes the EGL and GL headers,
// which the public headers keep out of their users.
#pragma once
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <chrono>
#include <initializer_list>
#include <string>

#include "glrun/gl_compute.hpp"

namespace mb::gl {

double msSince(std::chrono::steady_clock::time_point t0);
std::string hex(unsigned v);
// The first non-empty line of a driver's info log, or "no message".
std::string firstLine(const std::string& log);

// The entry points every user of a context needs: queries, errors, shaders and programs,
// buffers and uniform blocks.
struct GlFunctions {
  PFNGLGETSTRINGPROC GetString;
  PFNGLGETSTRINGIPROC GetStringi;
  PFNGLGETINTEGERVPROC GetIntegerv;
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
  PFNGLFINISHPROC Finish;
};

// One shader of a program: its stage, its source and how messages name it ("the kernel",
// "the vertex shader").
struct GlShaderSource {
  GLenum stage;
  const std::string* source;
  const char* what;
};

class GlContext {
 public:
  // Creates the context, makes it current on this thread and loads GlFunctions. Throws
  // GlError("no <apiName> context on EGL's surfaceless platform: why"). The EGL display is
  // shared by every context of the process and terminated with the last one.
  explicit GlContext(GlApi api);
  ~GlContext();  // releases the context from this thread and destroys it
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  GlApi api() const { return api_; }
  const GlFunctions& f() const { return f_; }

  // Makes the context current on the calling thread, when it is not. Throws GlError.
  void makeCurrent() const;
  // Loads an entry point beyond GlFunctions; throws GlError("no <api> context ...: no entry
  // point <name>"), as the constructor does.
  template <class Fn>
  void load(Fn& fn, const char* name) const {
    fn = reinterpret_cast<Fn>(entryPoint(name, true));
  }
  // The same, leaving fn null when the driver lacks it (an extension's function).
  template <class Fn>
  void loadOptional(Fn& fn, const char* name) const {
    fn = reinterpret_cast<Fn>(entryPoint(name, false));
  }

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string deviceName() const;
  bool hasExtension(const std::string& name) const;
  // Throws GlError("<what> failed (GL error 0x...)") when glGetError reports one.
  void check(const char* what) const;

  // Compiles `shaders` and links them into a program. Throws GlError("the driver's GLSL compiler
  // rejected <shader.what>: <first message line>") or ("the driver could not link
  // <programWhat>: <first message line>"), deleting what it made.
  GLuint buildProgram(std::initializer_list<GlShaderSource> shaders, const char* programWhat) const;

 private:
  void (*entryPoint(const char* name, bool required) const)();
  std::string noContext() const;  // "no <api> context on EGL's surfaceless platform: "

  GlApi api_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  GlFunctions f_{};
};

}  // namespace mb::gl
