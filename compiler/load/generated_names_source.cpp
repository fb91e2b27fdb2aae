#include "load/generated_names_source.hpp"

#include <stdexcept>

namespace mb {
namespace {

// Constant-initialized, so a source registered by another object's static initializer is
// never overwritten by this one's.
GeneratedNamesSource registeredSource = nullptr;

}  // namespace

void setGeneratedNamesSource(GeneratedNamesSource source) { registeredSource = source; }

std::map<std::string, GeneratedName> generatedNamesOf(const ShaderLibrary& lib, const MaterialDesc& material) {
  if (!registeredSource)
    throw std::logic_error(
        "no generated-names source is linked in (compile/generated_names.cpp registers it; "
        "link the program against mb_compiler)");
  return registeredSource(lib, material);
}

}  // namespace mb
