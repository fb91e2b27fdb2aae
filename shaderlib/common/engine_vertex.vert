#version 450
// Reference vertex shader of the fragment stage (docs/fragment-stage.md, interface version 1):
// object-space mesh attributes to the world-space attributes every permutation's fragment
// shader reads at locations 0-3. An engine may write its own; only the outputs are the
// interface. tests/test_fragment_vertex.cpp checks that they match the fragment inputs.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;  // xyz: tangent; w: handedness (glTF, +-1)
layout(location = 3) in vec2 inUv0;

// Two matrices fill the 128 bytes of push constants every Vulkan device offers, and leave
// descriptor set 0 to the fragment stage.
layout(push_constant) uniform MbVertexPush {
    mat4 model;           // object -> world
    mat4 viewProjection;  // world -> clip
} mbVertex;

layout(location = 0) out vec3 mbWorldPosition;
layout(location = 1) out vec3 mbWorldNormal;
layout(location = 2) out vec4 mbWorldTangent;
layout(location = 3) out vec2 mbUv0;

void main() {
    vec4 world = mbVertex.model * vec4(inPosition, 1.0);
    mat3 linear = mat3(mbVertex.model);
    mbWorldPosition = world.xyz;
    // Normals transform by the inverse transpose (non-uniform scale); the fragment shader
    // normalizes after interpolation.
    mbWorldNormal = transpose(inverse(linear)) * inNormal;
    // A mirroring transform (negative determinant) flips the bitangent w * cross(n, t).
    mbWorldTangent = vec4(linear * inTangent.xyz, inTangent.w * (determinant(linear) < 0.0 ? -1.0 : 1.0));
    mbUv0 = inUv0;
    gl_Position = mbVertex.viewProjection * world;
}
