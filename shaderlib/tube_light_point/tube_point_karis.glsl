// Direction to Karis's representative point of a tube light (Karis 2013, Real Shading in UE4,
// eqs. 15-16, then the sphere step of eqs. 11-12 with the tube's radius). L0 and L1 are the
// segment's endpoints relative to the shading point, r = reflect(-v, n):
//   t = ((r.L0)(r.Ld) - L0.Ld) / (|Ld|^2 - (r.Ld)^2),  p = L0 + saturate(t) Ld   (Ld = L1 - L0),
// the point of the segment closest to the line of r; then, treating p as a sphere's centre,
//   centerToRay = (p.r) r - p,  closest = p + centerToRay saturate(sourceRadius / |centerToRay|).
// Returns normalize(closest), the light direction l of eq. 16.
// Stability: for unit r, (r.L0)(r.Ld) - L0.Ld = -(r x L0).(r x Ld) and |Ld|^2 - (r.Ld)^2 =
// |r x Ld|^2 (Lagrange's identity). The source's differences cancel when Ld is nearly parallel
// to r (|Ld|^2 (1 - cos^2), with |r| = 1 +- ulps in fp32: relative error ~1e-7 / sin^2); the
// cross-product form has no cancellation and is homogeneous in r, so |r| drops out of t.
// t = 0/0 only for r parallel to Ld (or Ld = 0), where every point is equally close to the
// line of r: the saturate's limit at the numerator 0 is taken, t = 0.
vec3 mb_tube_point_karis(Geometry g, vec3 L0, vec3 L1, float sourceRadius) {
    vec3 r = reflect(-g.v, g.n);
    vec3 Ld = L1 - L0;
    vec3 rxLd = cross(r, Ld);
    float den = dot(rxLd, rxLd);
    float t = den > 0.0 ? clamp(-dot(cross(r, L0), rxLd) / den, 0.0, 1.0) : 0.0;
    vec3 p = L0 + t * Ld;
    vec3 centerToRay = dot(p, r) * r - p;
    float len = length(centerToRay);
    return normalize(p + centerToRay * (sourceRadius < len ? sourceRadius / len : 1.0));
}
