// Diffuse weight kD = (1 - kS)(1 - metallic) with kS = F (seed 003, the LearnOpenGL/URP
// hand-written PBR: "kD = 1 - kS; kD *= 1 - metalness"). Multiplies albedo/pi.
vec3 mb_kd_urp(vec3 F, float metallic) {
    return (vec3(1.0) - F) * (1.0 - metallic);
}
