// Reference compositions of shading models: plain C++ in double that combines the
// references of whichever bricks a material bound to the model's slots.
#pragma once
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "common/reference.hpp"

namespace mb::ref {

struct ModelEvalInput {
  Vec3 n, v, l;
  Vec3 illuminance{1, 1, 1};
  std::map<std::string, std::vector<double>> inputs;  // model input name -> value
  std::map<std::string, std::string> bricks;          // slot -> brick id
  // Call each bound brick's ground truth where one is registered (else its reference): the
  // exact material a permutation approximates, which bench measures error against.
  bool groundTruths = false;

  double floatInput(const std::string& name) const;
  Vec3 vec3Input(const std::string& name) const;
  // Calls the reference of the brick bound to `slot`. When `withGeometry` is set, the
  // packed n, v, l come first (the slot's Geometry parameter), then `args`.
  double callScalar(const std::string& slot, std::initializer_list<double> args,
                    bool withGeometry = false, std::initializer_list<double> tail = {}) const;
  Vec3 callVec3(const std::string& slot, std::initializer_list<double> args,
                bool withGeometry = false, std::initializer_list<double> tail = {}) const;
};

using ModelReferenceFn = Vec3 (*)(const ModelEvalInput&);

class ModelRegistry {
 public:
  static ModelRegistry& instance();
  bool add(const std::string& model, ModelReferenceFn fn);
  ModelReferenceFn find(const std::string& model) const;

 private:
  std::map<std::string, ModelReferenceFn> entries_;
};

}  // namespace mb::ref

#define MB_MODEL_REFERENCE(NAME, FN)                                         \
  [[maybe_unused]] static const bool MB_CONCAT(mb_model_reference_, __LINE__) = \
      ::mb::ref::ModelRegistry::instance().add(NAME, FN)
