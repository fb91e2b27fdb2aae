#include "core/vocabulary.hpp"

namespace mb {

const std::vector<std::string>& allQualityLevels() {
  static const std::vector<std::string> v{"low", "medium", "high"};
  return v;
}

}  // namespace mb
