#include "glrun/gl_compute.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "glrun/gl_context.hpp"

namespace mb::gl {
namespace {

constexpr GLuint kLocalSize = 64;    // the contract's local_size_x
constexpr GLuint kTableBinding = 2;  // SPIRV-Cross keeps the storage buffer's binding
constexpr GLuint kPushBinding = 0;   // where the MbPush block is bound, whatever its layout binding

}  // namespace

// The entry points compute needs beyond GlContext's.
struct ComputeFunctions {
  PFNGLGETINTEGERI_VPROC GetIntegeri_v;
  PFNGLMAPBUFFERRANGEPROC MapBufferRange;
  PFNGLUNMAPBUFFERPROC UnmapBuffer;
  PFNGLDISPATCHCOMPUTEPROC DispatchCompute;
  PFNGLMEMORYBARRIERPROC MemoryBarrier;
};

struct GlCompute::Impl {
  explicit Impl(GlApi api) : context(api), f(context.f()) {}
  GlContext context;
  const GlFunctions& f;
  ComputeFunctions c{};
  std::map<std::string, GLuint> programs;
  GLint maxGroupsX = 65535;
  GLint maxBlockBytes = 1 << 27;
  GLuint buffers[4] = {0, 0, 0, 0};  // in, out, push, table

  void makeCurrent() { context.makeCurrent(); }
  void check(const char* what) { context.check(what); }
  GLuint program(const std::string& source, double& compileMs);
};

std::string apiName(GlApi api) { return api == GlApi::Gl45Core ? "OpenGL 4.5 core" : "OpenGL ES 3.1"; }

GlCompute::GlCompute(GlApi api) : api_(api), impl_(std::make_unique<Impl>(api)) {
  Impl& m = *impl_;
  m.context.load(m.c.GetIntegeri_v, "glGetIntegeri_v");
  m.context.load(m.c.MapBufferRange, "glMapBufferRange");
  m.context.load(m.c.UnmapBuffer, "glUnmapBuffer");
  m.context.load(m.c.DispatchCompute, "glDispatchCompute");
  m.context.load(m.c.MemoryBarrier, "glMemoryBarrier");
  m.c.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &m.maxGroupsX);
  m.f.GetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &m.maxBlockBytes);
  m.f.GenBuffers(4, m.buffers);
  m.check("creating the context's buffers");
}

GlCompute::~GlCompute() {
  Impl& m = *impl_;
  try {
    m.makeCurrent();
    for (const auto& entry : m.programs) m.f.DeleteProgram(entry.second);
    m.f.DeleteBuffers(4, m.buffers);
  } catch (const GlError&) {
    // eglMakeCurrent failed: the context goes with its objects.
  }
}  // m.context releases and destroys the context

std::string GlCompute::deviceName() const { return impl_->context.deviceName(); }

bool GlCompute::hasExtension(const std::string& name) const { return impl_->context.hasExtension(name); }

GLuint GlCompute::Impl::program(const std::string& source, double& compileMs) {
  if (auto it = programs.find(source); it != programs.end()) return it->second;
  const auto t0 = std::chrono::steady_clock::now();
  const GLuint prog = context.buildProgram({{GL_COMPUTE_SHADER, &source, "the kernel"}}, "the kernel");
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
    m.c.DispatchCompute(static_cast<GLuint>(std::max<uint64_t>(1, (n + kLocalSize - 1) / kLocalSize)), 1, 1);
    m.c.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    m.check("dispatching the kernel");
    if (!n) return;
    m.f.BindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[1]);
    const void* out =
        m.c.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * outStride * 4), GL_MAP_READ_BIT);
    if (!out) throw GlError("glMapBufferRange of the output failed");
    std::memcpy(r.outputs.data() + begin * outStride, out, n * outStride * 4);
    m.c.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
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
