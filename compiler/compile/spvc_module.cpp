#include "compile/spvc_module.hpp"

namespace mb {

SpvcModule::SpvcModule(const std::vector<uint32_t>& spirv, spvc_backend backend) {
  if (spvc_context_create(&context_) != SPVC_SUCCESS) {
    context_ = nullptr;
    return;
  }
  spvc_parsed_ir ir = nullptr;
  if (spvc_context_parse_spirv(context_, spirv.data(), spirv.size(), &ir) != SPVC_SUCCESS) return;
  spvc_compiler compiler = nullptr;
  if (spvc_context_create_compiler(context_, backend, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) != SPVC_SUCCESS)
    return;
  if (spvc_compiler_create_shader_resources(compiler, &resources_) != SPVC_SUCCESS) return;
  compiler_ = compiler;
}

SpvcModule::~SpvcModule() {
  // Destroying the context frees everything allocated through it (spirv_cross_c.h).
  if (context_) spvc_context_destroy(context_);
}

std::string SpvcModule::error() const {
  if (!context_) return "spvc_context_create failed";
  const char* e = spvc_context_get_last_error_string(context_);
  return e ? e : "";
}

namespace {

std::vector<spvc_reflected_resource> listOf(spvc_resources resources, spvc_resource_type type) {
  const spvc_reflected_resource* list = nullptr;
  size_t count = 0;
  if (!resources || spvc_resources_get_resource_list_for_type(resources, type, &list, &count) != SPVC_SUCCESS)
    return {};
  return {list, list + count};
}

}  // namespace

std::vector<spvc_reflected_resource> SpvcModule::resources(spvc_resource_type type) const {
  return listOf(resources_, type);
}

std::vector<spvc_reflected_resource> SpvcModule::activeResources(spvc_resource_type type) const {
  if (!activeTried_ && compiler_) {
    activeTried_ = true;
    spvc_set active = nullptr;
    if (spvc_compiler_get_active_interface_variables(compiler_, &active) != SPVC_SUCCESS ||
        spvc_compiler_create_shader_resources_for_active_variables(compiler_, &active_, active) != SPVC_SUCCESS)
      active_ = nullptr;
  }
  return listOf(active_, type);
}

}  // namespace mb
