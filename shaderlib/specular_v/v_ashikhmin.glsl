// Ashikhmin / Neubelt visibility for cloth (Ashikhmin & Premoze 2007 "smooth denominator";
// Neubelt & Pettineo 2013; seeds 000 and 004):
//   V = 1 / (4 (n.l + n.v - n.l n.v))
// The denominator is evaluated as n.l + n.v (1 - n.l): a sum of non-negative terms, no
// cancellation, >= n.v >= MB_MIN_N_DOT_V. Seed 000 wraps the result in saturate(), which
// changes V wherever the denominator is below 1/4 (n.l, n.v both small); the published form
// (seed 004, Neubelt 2013) has no clamp, and neither does this brick.
float mb_v_ashikhmin(Geometry g, float alpha) {
    return 1.0 / (4.0 * (g.NoL + g.NoV * (1.0 - g.NoL)));
}
