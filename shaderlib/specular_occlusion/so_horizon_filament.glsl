// Horizon specular occlusion as in Filament (Filament "Physically Based Rendering in
// Filament", sec. 5.3.5 "horizon occlusion", after Russell 2014): fade = 1,
//   h = min(1 + r.n_geometric, 1),  occlusion = h^2   (r.n_geometric >= -1 keeps h >= 0)
// ao and perceptualRoughness are unused.
float mb_so_horizon_filament(Geometry g, vec3 geometricNormal, float ao, float perceptualRoughness) {
    vec3 r = reflect(-g.v, g.n);
    float horizon = min(1.0 + dot(r, normalize(geometricNormal)), 1.0);
    return horizon * horizon;
}
