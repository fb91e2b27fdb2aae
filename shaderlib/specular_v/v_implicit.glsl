// Implicit visibility (Hoffman 2013, "Background: Physics and Math of Shading", G_implicit =
// n.l n.v): V = G / (4 n.l n.v) = 1/4. The cheapest V; roughness-independent.
float mb_v_implicit(Geometry g, float alpha) {
    return 0.25;
}
