#include "compile/reference_vertex.hpp"

#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "library/shader_library.hpp"

namespace mb {

const char* const kWebgl2VertexPath = "fragment/webgl2/engine_vertex.webgl2.vert";

std::vector<uint32_t> referenceVertexSpirv(const ShaderLibrary& lib) {
  CompileOptions options;
  options.stage = ShaderStage::Vertex;
  return compileComputeGlsl(lib.source("common/engine_vertex.vert"), "engine_vertex.vert", options).spirv;
}

std::string referenceVertexShader(const ShaderLibrary& lib, Target target) {
  return crossCompile(referenceVertexSpirv(lib), target, "engine_vertex.vert");
}

nlohmann::json webgl2VertexJson(const ShaderLibrary& lib) {
  const nlohmann::json reflection = reflectSpirv(referenceVertexSpirv(lib));
  nlohmann::json block = reflection.at("push_constants").at(0);
  block["layout"] = "std140";
  return {{"file", kWebgl2VertexPath}, {"attributes", reflection.at("stage_inputs")}, {"block", std::move(block)}};
}

}  // namespace mb
