// compile: one SPIR-V module opened with SPIRV-Cross's C API (libspirv-cross-c-shared), for
// targets.cpp and spirv_reflect.cpp. One context per call: SPIRV-Cross contexts are not shared
// between threads, so parallel builds each open their own.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <spirv_cross_c.h>

namespace mb {

class SpvcModule {
 public:
  // Parses `spirv` and creates a compiler for `backend` (SPVC_BACKEND_NONE for reflection).
  // On failure ok() is false and error() says why (SPIRV-Cross's own message).
  SpvcModule(const std::vector<uint32_t>& spirv, spvc_backend backend);
  ~SpvcModule();
  SpvcModule(const SpvcModule&) = delete;
  SpvcModule& operator=(const SpvcModule&) = delete;

  bool ok() const { return compiler_ != nullptr; }
  spvc_compiler compiler() const { return compiler_; }
  // SPIRV-Cross's last error on this context ("" when none).
  std::string error() const;
  // Every resource of one kind (storage buffers, uniform buffers, push constants).
  std::vector<spvc_reflected_resource> resources(spvc_resource_type type) const;
  // Those the entry point uses. A backend that passes resources as function arguments (MSL)
  // declares only these: an unoptimized module (fp16, -O0) keeps a block nothing reads.
  // The active set is computed once per module, at the first call.
  std::vector<spvc_reflected_resource> activeResources(spvc_resource_type type) const;

 private:
  spvc_context context_ = nullptr;
  spvc_compiler compiler_ = nullptr;
  spvc_resources resources_ = nullptr;
  mutable spvc_resources active_ = nullptr;  // owned by the context, like resources_
  mutable bool activeTried_ = false;
};

}  // namespace mb
