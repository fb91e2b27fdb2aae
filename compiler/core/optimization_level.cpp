#include "core/optimization_level.hpp"

namespace mb {

const char* optimizationLevelName(OptimizationLevel level) {
  switch (level) {
    case OptimizationLevel::O0:
      return "O0";
    case OptimizationLevel::O1:
      return "O1";
    case OptimizationLevel::O2:
      break;
  }
  return "O2";
}

bool parseOptimizationLevel(const std::string& text, OptimizationLevel& level) {
  const std::string digit = text.size() == 2 && text[0] == 'O' ? text.substr(1) : text;
  if (digit == "0")
    level = OptimizationLevel::O0;
  else if (digit == "1")
    level = OptimizationLevel::O1;
  else if (digit == "2")
    level = OptimizationLevel::O2;
  else
    return false;
  return true;
}

}  // namespace mb
