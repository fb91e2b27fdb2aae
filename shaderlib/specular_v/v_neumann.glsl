// Neumann visibility (Neumann, Neumann & Szirmay-Kalos 1999, "Compact Metallic Reflectance
// Models"): G = n.l n.v / max(n.l, n.v), so V = 1 / (4 max(n.l, n.v)). max >= n.v > 0.
float mb_v_neumann(Geometry g, float alpha) {
    return 0.25 / max(g.NoL, g.NoV);
}
