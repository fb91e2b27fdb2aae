#include "lut/dfg_lut.hpp"

namespace mb::lut {

std::vector<float> texelInputs(uint32_t size) {
  std::vector<float> in;
  in.reserve(static_cast<size_t>(size) * size * 2);
  for (uint32_t j = 0; j < size; ++j) {
    for (uint32_t i = 0; i < size; ++i) {
      in.push_back(static_cast<float>(texelCentre(i, size)));
      in.push_back(static_cast<float>(texelCentre(j, size)));
    }
  }
  return in;
}

}  // namespace mb::lut
