#include "library/light_order.hpp"

#include <algorithm>

#include "library/shader_library.hpp"

namespace mb {

std::vector<std::string> canonicalLights(std::vector<std::string> lights) {
  const auto& order = allLightTypes();
  auto rank = [&](const std::string& t) { return std::find(order.begin(), order.end(), t) - order.begin(); };
  std::sort(lights.begin(), lights.end(),
            [&](const std::string& a, const std::string& b) { return rank(a) != rank(b) ? rank(a) < rank(b) : a < b; });
  lights.erase(std::unique(lights.begin(), lights.end()), lights.end());
  return lights;
}

}  // namespace mb
