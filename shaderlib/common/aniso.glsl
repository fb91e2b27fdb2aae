// Tangent frame shared by the anisotropic bricks (specular_d_aniso, specular_v_aniso,
// bent_normal_aniso). A fragment shader receives the tangent t interpolated across a triangle:
// not unit length and not exactly orthogonal to the (also interpolated, or normal-mapped) n.
// The bricks therefore take t as it arrives and orthonormalize it against n here
// (Gram-Schmidt), with the bitangent b = n x t, as a real shader does.
//
// Degenerate tangent: when t has (almost) no component orthogonal to n (t parallel to n, or
// t = 0), the fp32 Gram-Schmidt result is rounding noise. Below |t_perp|^2 <= 1e-12 |t|^2
// (|t_perp| / |t| <= 2^-20, where the fp32 residual of ~6e-8 |t| would already be ~6% of it)
// the frame falls back to the branch-free orthonormal basis of Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited" (JCGT 6(1)), a deterministic function of n alone. The double
// reference (common/aniso_reference.hpp) applies the same test and the same fallback.
//
// Stability: one Gram-Schmidt pass leaves a residual n.t_perp of ~1e-7 |t| (the rounding of
// n.t and of the subtraction), i.e. ~1e-7 kappa relative to |t_perp| with kappa = |t| / |t_perp|.
// After normalization the tangent is tilted out of the tangent plane by ~1e-7 kappa, and near
// the specular peak (h ~ n) that tilt lands in full in t.h: at kappa = 14 and at = 0.0037 it
// gave 6.7e-4 relative error in anisotropic GGX D (lavapipe, 2 x 200,000 samples: 81 values
// outside 2e-5 relative plus the input-conditioning allowance; 1 with two passes). A second pass
// ("twice is enough", Parlett 1980 / Giraud et al. 2005) removes the residual down to ~1e-7
// relative to |t_perp|, independent of kappa. The remaining in-plane rotation of ~1e-7 kappa
// is inherent: a 1-ulp change of the fp32-normalized n rotates t_perp by as much.

// The unit tangent: t made orthogonal to the unit normal n.
vec3 mb_aniso_tangent(vec3 n, vec3 t) {
    vec3 perp = t - n * dot(n, t);
    float len2 = dot(perp, perp);
    if (len2 > 1e-12 * dot(t, t)) {
        perp -= n * dot(n, perp);
        return normalize(perp);
    }
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    return vec3(1.0 + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x);
}

// (t.l, b.l): the tangent-plane part of the light direction of the *clamped* geometry, for the
// anisotropic visibilities. makeGeometry clamps n.l at 0 but leaves l below the horizon as it
// is, and such an l does reach them: the direction to a sphere or tube light's centre (or a
// tube's equivalent point) below the horizon while the light still crosses it, where the
// horizon wrap is > 0. The geometry V is evaluated at is then l's azimuth at n.l = 0, whose
// tangent part is a unit vector: the limit the reference takes (v_aniso_reference.hpp, theta =
// acos of the clamped n.l) and what the isotropic bricks give, which see only n.l (V = 0.5 /
// (n.v alpha) at n.l = 0). l's own tangent part has length sqrt(1 - (n.l)^2) < 1 there and
// made V too large by 1 / sqrt(1 - (n.l)^2) (2.9e-3 at n.l = -0.076: brushed_metal with the
// tube light, docs/accuracy.md). No tangent part at all (l = -n): azimuth along t, as the
// reference's cos(phi) = 1. Above the horizon l is returned as it is.
vec2 mb_aniso_light_tangent(Geometry g, vec3 tangent, vec3 bitangent) {
    vec2 p = vec2(dot(tangent, g.l), dot(bitangent, g.l));
    if (dot(g.n, g.l) >= 0.0) return p;
    float len2 = dot(p, p);
    return len2 > 0.0 ? p * inversesqrt(len2) : vec2(1.0, 0.0);
}

// |v| for the anisotropic masking terms (at t.w, ab b.w, n.w). In half precision their
// squares underflow at the fp16 roughness floor (at = 0.089^2: (at 0.5)^2 = 1.6e-5, a
// denormal that may be flushed), so |v| is taken of v scaled by its largest component: the
// same number in real arithmetic. fp32 keeps length().
float mb_aniso_length(vec3 v) {
#ifdef MB_FP16
    float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
    return m > 0.0 ? m * length(v / m) : 0.0;
#else
    return length(v);
#endif
}
