// Reference for hammersley_loop: the base-2 radical inverse, evaluated as the bit-reversed
// integer divided by 2^32 in double (an independent route from the digit loop).
#include <cstdint>

#include "common/reference.hpp"

namespace mb::ref {

static double radicalInverseByReversal(double i) {
  uint32_t n = static_cast<uint32_t>(std::floor(i));
  uint32_t reversed = 0;
  for (int k = 0; k < 32; ++k) reversed |= ((n >> k) & 1u) << (31 - k);
  return std::ldexp(static_cast<double>(reversed), -32);
}

MB_REFERENCE("hammersley_loop", radicalInverseByReversal);

}  // namespace mb::ref
