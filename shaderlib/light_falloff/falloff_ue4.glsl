// Windowed inverse square, Karis 2013, Real Shading in UE4, eq. 9:
//   saturate(1 - (d / lightRadius)^4)^2 / (d^2 + 1)
// (d/r)^4 is taken as (d^2 / r^2)^2 so no sqrt is needed; the +1 keeps it finite at the light.
float mb_falloff_ue4(vec3 toLight, float attenuationRadius) {
    float d2 = dot(toLight, toLight);
    float x2 = d2 / (attenuationRadius * attenuationRadius);
    float window = clamp(1.0 - x2 * x2, 0.0, 1.0);
    return window * window / (d2 + 1.0);
}
