// The fragment stage's frame block (docs/fragment-stage.md): camera, lights and environment
// constants in world space, with one std140 layout shared by every permutation so that an
// engine fills one C++ struct (the package header's MbFrameBlock) for all of them.
#define MB_MAX_LIGHTS 4

struct MbDirectionalLightGpu {
    vec4 direction;    // xyz: unit, towards the light
    vec4 illuminance;  // rgb: illuminance at a surface facing the light
};

// Point, spot, sphere and tube lights share one record.
struct MbLocalLightGpu {
    vec4 position;   // xyz: world position (sphere centre, tube segment start); w: radius (sphere, tube)
    vec4 intensity;  // rgb: luminous intensity (colour times candela); w: falloff radius
    vec4 axis;       // spot: xyz unit axis the spot shines along, w: cos(outer half-angle)
                     // tube: xyz world position of the segment's end
    vec4 params;     // spot: x cos(inner half-angle)
};

// Rectangle and disk lights share one record (lights.glsl's RectLight and DiskLight).
struct MbAreaLightGpu {
    vec4 position;   // xyz: world position of the centre
    vec4 halfX;      // xyz: half the first edge (rect) or the first semi-axis (disk), world space
    vec4 halfY;      // xyz: the second; the light emits on the side cross(halfX, halfY) points to
    vec4 luminance;  // rgb: luminance (colour times nits)
};

layout(set = 0, binding = 1, std140) uniform MbFrameBlock {
    vec4 cameraPosition;  // xyz: world position of the eye
    uvec4 lightCounts;    // x dir, y point, z spot, w sphere (each <= MB_MAX_LIGHTS)
    uvec4 lightCounts2;   // x tube, y rect, z disk
    MbDirectionalLightGpu dirLights[MB_MAX_LIGHTS];
    MbLocalLightGpu pointLights[MB_MAX_LIGHTS];
    MbLocalLightGpu spotLights[MB_MAX_LIGHTS];
    MbLocalLightGpu sphereLights[MB_MAX_LIGHTS];
    MbLocalLightGpu tubeLights[MB_MAX_LIGHTS];
    vec4 sh[9];        // rgb: radiance SH9 coefficients L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22
    vec4 environment;  // x: ambient occlusion, y: mip level of the roughest prefiltered level
    MbAreaLightGpu rectLights[MB_MAX_LIGHTS];  // after the version 1 members, which keep their offsets
    MbAreaLightGpu diskLights[MB_MAX_LIGHTS];
} mbFrame;
