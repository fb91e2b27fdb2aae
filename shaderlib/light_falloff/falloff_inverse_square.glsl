// Inverse-square law of a punctual light, 1 / d^2 (Karis 2013, Real Shading in UE4, p. 11).
// d^2 straight from the vector: no sqrt, and no +1 bias, so it is singular at the light.
float mb_falloff_inverse_square(vec3 toLight, float attenuationRadius) {
    return 1.0 / dot(toLight, toLight);
}
