// Base-2 radical inverse by a digit loop, for targets without bitfieldReverse (GLSL ES 2 /
// WebGL 1 style; the Van der Corput construction used by Hammersley & Handscomb 1964 and
// Karis 2013). Each set bit k of uint(i) adds 2^-(k+1); the sum of distinct powers of two is
// exact in fp32 while it spans <= 24 bits (i < 2^24), so the result equals the correctly
// rounded radical inverse up to 1 ulp.
float mb_hammersley_loop(float i) {
    uint bits = uint(i);
    float result = 0.0;
    float weight = 0.5;
    for (int k = 0; k < 32; ++k) {
        if (bits == 0u) {
            break;
        }
        if ((bits & 1u) != 0u) {
            result += weight;
        }
        weight *= 0.5;
        bits >>= 1u;
    }
    return result;
}
