#version 450
// The fragment stage's reference vertex shader (docs/fragment-stage.md, interface version 1):
// object-space attributes in, the world-space attributes every permutation's fragment shader
// reads out. The preview draws its spheres with it (compiler/preview/); an engine uses its
// own, writing the same four outputs.
//
// The model transform is a uniform scale plus a translation, so normals and tangents keep
// their direction and need no inverse-transpose matrix.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;  // xyz tangent, w handedness (glTF)
layout(location = 3) in vec2 inUv0;

layout(push_constant) uniform MbVertexPush {
    mat4 viewProjection;      // world to clip (Vulkan: y down, depth 0..1)
    vec4 modelOffsetScale;    // xyz: world position of the object's origin, w: uniform scale
} mbVertex;

layout(location = 0) out vec3 mbWorldPosition;
layout(location = 1) out vec3 mbWorldNormal;
layout(location = 2) out vec4 mbWorldTangent;
layout(location = 3) out vec2 mbUv0;

void main() {
    vec3 world = inPosition * mbVertex.modelOffsetScale.w + mbVertex.modelOffsetScale.xyz;
    mbWorldPosition = world;
    mbWorldNormal = inNormal;
    mbWorldTangent = inTangent;
    mbUv0 = inUv0;
    gl_Position = mbVertex.viewProjection * vec4(world, 1.0);
}
