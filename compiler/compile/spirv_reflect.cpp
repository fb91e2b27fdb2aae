// compile: reflectSpirv (targets.hpp): SPIRV-Cross's view of a module's interface, stored in
// the package manifest. Offsets and sizes are SPIRV-Cross's reading of the module's own
// Offset/ArrayStride decorations (std140/std430 as glslang laid them out), so a C++ mirror
// of a block can static_assert them exactly (docs/targets.md "Reflection").
#include <algorithm>
#include <stdexcept>

#include "compile/spvc_module.hpp"
#include "compile/targets.hpp"
#include "core/diagnostics.hpp"

namespace mb {
namespace {

std::string scalarName(spvc_basetype base) {
  switch (base) {
    case SPVC_BASETYPE_BOOLEAN:
      return "bool";
    case SPVC_BASETYPE_INT32:
      return "int";
    case SPVC_BASETYPE_UINT32:
      return "uint";
    case SPVC_BASETYPE_FP16:
      return "float16_t";
    case SPVC_BASETYPE_FP32:
      return "float";
    case SPVC_BASETYPE_FP64:
      return "double";
    default:
      return "";
  }
}

// GLSL's spelling of a vector prefix: vec, ivec, uvec, bvec, dvec, f16vec.
std::string vectorPrefix(spvc_basetype base) {
  switch (base) {
    case SPVC_BASETYPE_BOOLEAN:
      return "b";
    case SPVC_BASETYPE_INT32:
      return "i";
    case SPVC_BASETYPE_UINT32:
      return "u";
    case SPVC_BASETYPE_FP16:
      return "f16";
    case SPVC_BASETYPE_FP64:
      return "d";
    default:
      return "";
  }
}

// The GLSL type name of a member type: "float", "vec3", "mat4", "uint[]", "vec4[8]", or a
// struct's name.
std::string glslTypeName(spvc_compiler compiler, spvc_type_id id) {
  spvc_type type = spvc_compiler_get_type_handle(compiler, id);
  const spvc_basetype base = spvc_type_get_basetype(type);
  std::string name;
  if (base == SPVC_BASETYPE_STRUCT) {
    name = spvc_compiler_get_name(compiler, spvc_type_get_base_type_id(type));
  } else {
    const unsigned vec = spvc_type_get_vector_size(type), cols = spvc_type_get_columns(type);
    if (cols > 1)
      name = vectorPrefix(base) + "mat" + std::to_string(cols) + (vec != cols ? "x" + std::to_string(vec) : "");
    else if (vec > 1)
      name = vectorPrefix(base) + "vec" + std::to_string(vec);
    else
      name = scalarName(base);
    if (name.empty()) name = "unknown";
  }
  // SPIR-V lists array dimensions outermost last; GLSL writes them outermost first.
  const unsigned dims = spvc_type_get_num_array_dimensions(type);
  for (unsigned d = dims; d-- > 0;) {
    const SpvId size = spvc_type_get_array_dimension(type, d);
    if (!spvc_type_array_dimension_is_literal(type, d))
      name += "[spec]";  // sized by a specialization constant: not used by our emitter
    else
      name += size == 0 ? "[]" : "[" + std::to_string(size) + "]";
  }
  return name;
}

nlohmann::json blockJson(const SpvcModule& m, const spvc_reflected_resource& r, bool hasBinding) {
  spvc_compiler c = m.compiler();
  spvc_type block = spvc_compiler_get_type_handle(c, r.base_type_id);
  nlohmann::json j;
  j["name"] = spvc_compiler_get_name(c, r.base_type_id);  // the block's type name (MbIn, MbPush, ...)
  if (hasBinding) {
    j["set"] = spvc_compiler_get_decoration(c, r.id, SpvDecorationDescriptorSet);
    j["binding"] = spvc_compiler_get_decoration(c, r.id, SpvDecorationBinding);
  }
  size_t size = 0;
  spvc_compiler_get_declared_struct_size(c, block, &size);
  j["size"] = size;
  nlohmann::json members = nlohmann::json::array();
  for (unsigned i = 0; i < spvc_type_get_num_member_types(block); ++i) {
    unsigned offset = 0;
    size_t memberSize = 0;
    spvc_compiler_type_struct_member_offset(c, block, i, &offset);
    spvc_compiler_get_declared_struct_member_size(c, block, i, &memberSize);
    const char* name = spvc_compiler_get_member_name(c, r.base_type_id, i);
    members.push_back({{"name", name ? name : ""},
                       {"type", glslTypeName(c, spvc_type_get_member_type(block, i))},
                       {"offset", offset},
                       {"size", memberSize}});
  }
  j["members"] = std::move(members);
  return j;
}

// Stage inputs and outputs by location, and combined image samplers by set and binding: the
// fragment stage's interface (docs/fragment-stage.md). Sorted, so the JSON does not depend on
// the order SPIRV-Cross lists them in.
nlohmann::json locatedJson(const SpvcModule& m, spvc_resource_type kind) {
  spvc_compiler c = m.compiler();
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : m.resources(kind))
    out.push_back({{"name", r.name ? r.name : ""},
                   {"location", spvc_compiler_get_decoration(c, r.id, SpvDecorationLocation)},
                   {"type", glslTypeName(c, r.type_id)}});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a["location"] < b["location"]; });
  return out;
}

std::string samplerTypeName(spvc_compiler c, spvc_type_id id) {
  spvc_type type = spvc_compiler_get_type_handle(c, id);
  switch (spvc_type_get_image_dimension(type)) {
    case SpvDim2D:
      return "sampler2D";
    case SpvDimCube:
      return "samplerCube";
    case SpvDim3D:
      return "sampler3D";
    default:
      return "sampler";
  }
}

nlohmann::json samplersJson(const SpvcModule& m) {
  spvc_compiler c = m.compiler();
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : m.resources(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE))
    out.push_back({{"name", r.name ? r.name : ""},
                   {"set", spvc_compiler_get_decoration(c, r.id, SpvDecorationDescriptorSet)},
                   {"binding", spvc_compiler_get_decoration(c, r.id, SpvDecorationBinding)},
                   {"type", samplerTypeName(c, r.type_id)}});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return std::make_pair(a["set"], a["binding"]) < std::make_pair(b["set"], b["binding"]);
  });
  return out;
}

}  // namespace

nlohmann::json reflectSpirv(const std::vector<uint32_t>& spirv) {
  SpvcModule m(spirv, SPVC_BACKEND_NONE);
  if (!m.ok())
    throw DiagnosticError({{Severity::Error,
                            "E-TARGET-FAILED",
                            {"<spirv>", 0, 0},
                            "SPIRV-Cross cannot reflect the module: " + m.error()}});
  spvc_compiler c = m.compiler();
  nlohmann::json j;
  const spvc_entry_point* entries = nullptr;
  size_t entryCount = 0;
  spvc_compiler_get_entry_points(c, &entries, &entryCount);
  j["entry_point"] = entryCount ? entries[0].name : "";
  const bool compute = !entryCount || entries[0].execution_model == SpvExecutionModelGLCompute;
  if (compute)
    j["workgroup_size"] = {spvc_compiler_get_execution_mode_argument_by_index(c, SpvExecutionModeLocalSize, 0),
                           spvc_compiler_get_execution_mode_argument_by_index(c, SpvExecutionModeLocalSize, 1),
                           spvc_compiler_get_execution_mode_argument_by_index(c, SpvExecutionModeLocalSize, 2)};
  nlohmann::json storage = nlohmann::json::array(), uniform = nlohmann::json::array(), push = nlohmann::json::array();
  for (const auto& r : m.resources(SPVC_RESOURCE_TYPE_STORAGE_BUFFER)) {
    nlohmann::json b = blockJson(m, r, true);
    // Access qualifiers: on the variable or on every member (get_buffer_block_flags).
    const SpvDecoration* decorations = nullptr;
    size_t n = 0;
    bool readonly = false, writeonly = false;
    if (spvc_compiler_get_buffer_block_decorations(c, r.id, &decorations, &n) == SPVC_SUCCESS)
      for (size_t i = 0; i < n; ++i) {
        readonly |= decorations[i] == SpvDecorationNonWritable;
        writeonly |= decorations[i] == SpvDecorationNonReadable;
      }
    b["readonly"] = readonly;
    b["writeonly"] = writeonly;
    storage.push_back(std::move(b));
  }
  for (const auto& r : m.resources(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER)) uniform.push_back(blockJson(m, r, true));
  for (const auto& r : m.resources(SPVC_RESOURCE_TYPE_PUSH_CONSTANT)) push.push_back(blockJson(m, r, false));
  j["storage_buffers"] = std::move(storage);
  j["uniform_buffers"] = std::move(uniform);
  j["push_constants"] = std::move(push);
  // A graphics stage's interface. Compute modules (the kernels) have none of these, and their
  // reflection stays as it was before the fragment stage.
  if (!compute) {
    j["stage"] = entries[0].execution_model == SpvExecutionModelFragment ? "fragment" : "other";
    j["stage_inputs"] = locatedJson(m, SPVC_RESOURCE_TYPE_STAGE_INPUT);
    j["stage_outputs"] = locatedJson(m, SPVC_RESOURCE_TYPE_STAGE_OUTPUT);
    j["sampled_images"] = samplersJson(m);
  }
  return j;
}

}  // namespace mb
