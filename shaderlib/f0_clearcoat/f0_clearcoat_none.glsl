// Base F0 under a clear coat, KHR_materials_clearcoat: unchanged. glTF layers the coat over
// the base material (fresnel_coat) without re-deriving the base's F0 for the coat's IOR.
vec3 mb_f0_clearcoat_none(vec3 f0) {
    return f0;
}
