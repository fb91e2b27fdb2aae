// Second coordinate of the Hammersley point i of a set (Hammersley & Handscomb 1964; Karis
// 2013 "Real Shading in Unreal Engine 4", Hammersley(i, N); seeds 000, 002): the base-2
// radical inverse (Van der Corput) of i, by bit reversal:
//   phi2(i) = bitfieldReverse(uint(i)) * 2^-32
// The first coordinate is i / N. i is truncated to an integer (uint(i)). The product is exact
// up to the float conversion of the 32-bit integer (0.5 ulp).
float mb_hammersley_bitreverse(float i) {
    return float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
}
