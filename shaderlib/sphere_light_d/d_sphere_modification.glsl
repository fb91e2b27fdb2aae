// Specular D modification for sphere lights (Karis 2013, Real Shading in UE4, eq. 10, after
// Mittring & Dudash 2012, the Elemental demo): GGX D at the light centre with the widened
// alpha' = saturate(alpha + sourceRadius / (3 distance)) (seed 002's form; sin a = r / d).
// D is in the |n x h|^2 form of d_ggx (no 1 - (n.h)^2 cancellation near n.h = 1).
float mb_d_sphere_modification(Geometry g, float alpha, float sinAlpha) {
    float alphaPrime = clamp(alpha + sinAlpha * (1.0 / 3.0), 0.0, 1.0);
    vec3 nxh = cross(g.n, g.h);
    float a = g.NoH * alphaPrime;
    float k = alphaPrime / (dot(nxh, nxh) + a * a);
    return k * k * (1.0 / MB_PI);
}
