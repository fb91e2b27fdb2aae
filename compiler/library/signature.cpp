#include "library/signature.hpp"

namespace mb {

std::string brickSignature(const Brick& brick, const Slot& slot) {
  std::string sig = toString(slot.returns) + " " + brick.function + "(";
  for (size_t i = 0; i < slot.params.size(); ++i)
    sig += (i ? ", " : "") + toString(slot.params[i].type) + " " + slot.params[i].name;
  return sig + ")";
}

}  // namespace mb
