#version 450
// The preview's attributes pass (docs/preview.md): the interpolated inputs of the fragment
// stage written as they arrive, to four RGBA32F targets, so that the CPU reference render
// shades each pixel from exactly the values the permutation's fragment shader received (same
// vertex shader, state and draws: Vulkan's invariance rules give the same fragments and the
// same interpolated values). Target 0's w = 1 marks a covered pixel (the clear value is 0).
layout(location = 0) in vec3 mbWorldPosition;
layout(location = 1) in vec3 mbWorldNormal;
layout(location = 2) in vec4 mbWorldTangent;
layout(location = 3) in vec2 mbUv0;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outTangent;
layout(location = 3) out vec4 outUv0;

void main() {
    outPosition = vec4(mbWorldPosition, 1.0);
    outNormal = vec4(mbWorldNormal, 0.0);
    outTangent = mbWorldTangent;
    outUv0 = vec4(mbUv0, 0.0, 0.0);
}
