// Reference for hammersley_bitreverse: the base-2 radical inverse phi2(i) = sum_k d_k 2^-(k+1)
// for i = sum_k d_k 2^k (Van der Corput 1935), computed digit by digit in double.
#include "common/reference.hpp"

namespace mb::ref {

static double radicalInverse2(double i) {
  unsigned long long n = static_cast<unsigned long long>(std::floor(i));
  double result = 0.0, digitWeight = 0.5;
  while (n > 0) {
    if (n & 1ull) result += digitWeight;
    digitWeight *= 0.5;
    n >>= 1;
  }
  return result;
}

MB_REFERENCE("hammersley_bitreverse", radicalInverse2);

}  // namespace mb::ref
