// drawOnGl (compiler/glrun/gl_draw.hpp): a DrawJob drawn with OpenGL 4.5 core (GLSL 450) and
// OpenGL ES 3.1 (ESSL 3.10, and ESSL 3.00 for WebGL 2.0's language) on llvmpipe through EGL's
// surfaceless platform. The vertex shaders write Vulkan's clip space (y down, depth 0..1), as
// the preview's do, and every check is in the result's rows, which are the Vulkan path's rows
// (draw_job.hpp): row 0 is where clip y = -1 lands.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "glrun/gl_draw.hpp"

using namespace mb;
using gl::DrawJob;
using gl::DrawResult;
using gl::GlApi;

namespace {

// A shading language and the API it runs on.
struct Language {
  GlApi api;
  const char* version;  // "450", "310 es" or "300 es"
};
const std::vector<Language> kLanguages = {{GlApi::Gl45Core, "450"}, {GlApi::Es31, "310 es"}};
const Language kEssl300 = {GlApi::Es31, "300 es"};

// `body` after the #version line (and ES's highp defaults). BLOCK(n) in it becomes a std140
// layout with binding n where the language has bindings (not ESSL 3.00): drawOnGl binds blocks
// by name, whatever binding the shader gives them.
std::string shader(const Language& language, std::string body) {
  const bool es = language.api == GlApi::Es31;
  const bool bindings = std::string(language.version) != "300 es";
  for (size_t at; (at = body.find("BLOCK(")) != std::string::npos;) {
    const size_t close = body.find(')', at);
    const std::string n = body.substr(at + 6, close - at - 6);
    body.replace(at, close + 1 - at, bindings ? "layout(binding = " + n + ", std140)" : "layout(std140)");
  }
  return std::string("#version ") + language.version + "\n" +
         (es ? "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
               "precision highp samplerCube;\n"
             : "") +
         body;
}

// Positions in Vulkan's clip space, passed through unchanged.
const char* kPassThroughVertex = R"(
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

const char* kConstantFragment = R"(
layout(location = 0) out vec4 color;
void main() { color = vec4(0.25, 0.5, 0.75, 1.0); }
)";

// A mesh of positions (x, y, z in clip space), one attribute at location 0.
gl::DrawMesh positions(std::vector<float> xyz, std::vector<uint32_t> indices) {
  gl::DrawMesh mesh;
  mesh.vertices = std::move(xyz);
  mesh.floatsPerVertex = 3;
  mesh.attributes = {{0, 3, 0}};
  mesh.indices = std::move(indices);
  return mesh;
}

// The rectangle x0..x1, y0..y1 of clip space at depth z: two triangles counter-clockwise by
// Vulkan's rule (front faces), (x0, y0) being the corner at the lowest row and column.
gl::DrawMesh rectangle(float x0, float y0, float x1, float y1, float z = 0.5f) {
  return positions({x0, y0, z, x0, y1, z, x1, y1, z, x1, y0, z}, {0, 1, 2, 0, 2, 3});
}

std::vector<uint8_t> bytesOf(const std::vector<float>& floats) {
  std::vector<uint8_t> bytes(floats.size() * sizeof(float));
  std::memcpy(bytes.data(), floats.data(), bytes.size());
  return bytes;
}

DrawJob job(const Language& language, const std::string& vertex, const std::string& fragment, uint32_t width,
            uint32_t height, gl::DrawMesh mesh) {
  DrawJob j;
  j.vertexSource = shader(language, vertex);
  j.fragmentSource = shader(language, fragment);
  j.width = width;
  j.height = height;
  j.mesh = std::move(mesh);
  j.draws.resize(1);
  return j;
}

std::array<float, 4> pixel(const DrawResult& r, uint32_t target, uint32_t width, uint32_t column, uint32_t row) {
  const float* p = r.targets.at(target).data() + (size_t{row} * width + column) * 4;
  return {p[0], p[1], p[2], p[3]};
}

using Rgba = std::array<float, 4>;

// Every pixel of `target` is `inside` where covered(column, row) holds, else `outside`.
template <class Covered>
void checkCoverage(const DrawResult& r, uint32_t target, uint32_t width, uint32_t height, Covered covered,
                   const Rgba& inside, const Rgba& outside) {
  for (uint32_t row = 0; row < height; ++row)
    for (uint32_t column = 0; column < width; ++column) {
      INFO("target " << target << ", row " << row << ", column " << column);
      REQUIRE(pixel(r, target, width, column, row) == (covered(column, row) ? inside : outside));
    }
}

bool within(const Rgba& a, const Rgba& b, float tolerance) {
  for (int i = 0; i < 4; ++i)
    if (std::abs(a[i] - b[i]) > tolerance) return false;
  return true;
}

}  // namespace

TEST_CASE("drawOnGl: clip y -1 is row 0, as on the Vulkan path", "[gl]") {
  for (const Language& language : kLanguages) {
    INFO(language.version);
    // Vulkan's top half of the clip square: y from -1 to 0.
    DrawJob j = job(language, kPassThroughVertex, kConstantFragment, 8, 8, rectangle(-1, -1, 1, 0));
    j.clearColors = {{0.0f, 0.0f, 0.0f, 0.5f}};
    const DrawResult r = gl::drawOnGl(language.api, j);
    REQUIRE(r.targets.size() == 1);
    REQUIRE(r.targets[0].size() == 8 * 8 * 4);
    checkCoverage(r, 0, 8, 8, [](uint32_t, uint32_t row) { return row < 4; }, {0.25f, 0.5f, 0.75f, 1.0f},
                  {0.0f, 0.0f, 0.0f, 0.5f});
    CHECK(r.device.find("llvmpipe") != std::string::npos);
    CHECK(r.device.find(", ") != std::string::npos);
    CHECK(r.compileMs > 0);
    CHECK(r.renderMs > 0);
  }
}

TEST_CASE("drawOnGl binds uniform blocks by name in both stages and skips a block the program lacks", "[gl]") {
  std::vector<Language> languages = kLanguages;
  languages.push_back(kEssl300);
  // Both blocks at binding 0 where the language has bindings: drawOnGl gives each its own.
  const std::string vertex = R"(
layout(location = 0) in vec3 position;
BLOCK(0) uniform MbVertexPush { mat4 transform; } push;
void main() { gl_Position = push.transform * vec4(position, 1.0); }
)";
  const std::string fragment = R"(
BLOCK(0) uniform MbFrameBlock { vec4 tint; vec4 scale; } frame;
layout(location = 0) out vec4 color;
void main() { color = frame.tint * frame.scale.x; }
)";
  for (const Language& language : languages) {
    INFO(language.version);
    DrawJob j = job(language, vertex, fragment, 8, 8, rectangle(-1, -1, 1, 1));
    // Column-major (std140): x' = 0.5 x + 0.5, the whole square onto the right half.
    const std::vector<float> transform = {0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
    j.draws[0].uniformBlocks["MbVertexPush"] = bytesOf(transform);
    j.draws[0].uniformBlocks["MbFrameBlock"] = bytesOf({0.5f, 0.25f, 0.125f, 1.0f, 2.0f, 0, 0, 0});
    j.draws[0].uniformBlocks["MbAbsentBlock"] = bytesOf({1, 2, 3, 4});
    const DrawResult r = gl::drawOnGl(language.api, j);
    checkCoverage(r, 0, 8, 8, [](uint32_t column, uint32_t) { return column >= 4; }, {1.0f, 0.5f, 0.25f, 2.0f},
                  {0, 0, 0, 0});
  }
}

TEST_CASE("drawOnGl refuses a draw without contents for a block the program reads", "[gl]") {
  const std::string fragment = R"(
BLOCK(1) uniform MbFrameBlock { vec4 tint; } frame;
layout(location = 0) out vec4 color;
void main() { color = frame.tint; }
)";
  for (const Language& language : kLanguages) {
    INFO(language.version);
    DrawJob j = job(language, kPassThroughVertex, fragment, 4, 4, rectangle(-1, -1, 1, 1));
    CHECK_THROWS_WITH(gl::drawOnGl(language.api, j),
                      Catch::Contains("draw 0: the program's uniform block MbFrameBlock has no contents"));
    j.draws[0].uniformBlocks["MbFrameBlock"] = bytesOf({1, 2});  // 8 bytes of 16
    CHECK_THROWS_WITH(gl::drawOnGl(language.api, j), Catch::Contains("uniform block MbFrameBlock has 8 bytes"));
  }
}

TEST_CASE("drawOnGl writes four colour targets, each cleared to its own colour", "[gl]") {
  const std::string fragment = R"(
layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;
layout(location = 3) out vec4 out3;
void main() {
  out0 = vec4(1.0, 0.0, 0.0, 1.0);
  out1 = vec4(0.0, 2.0, 0.0, 1.0);
  out2 = vec4(0.0, 0.0, -3.0, 1.0);  // float targets: neither clamped nor quantized
  out3 = vec4(0.1, 0.2, 0.3, 1e6);
}
)";
  for (const Language& language : kLanguages) {
    INFO(language.version);
    DrawJob j = job(language, kPassThroughVertex, fragment, 8, 8, rectangle(-1, -1, 1, 0));
    j.colorTargets = 4;
    j.clearColors = {{0.5f, 0, 0, 0}, {0, 0.5f, 0, 0}, {0, 0, 0.5f, 0}};  // the fourth clears to 0
    const DrawResult r = gl::drawOnGl(language.api, j);
    REQUIRE(r.targets.size() == 4);
    const std::array<Rgba, 4> drawn = {Rgba{1, 0, 0, 1}, Rgba{0, 2, 0, 1}, Rgba{0, 0, -3, 1},
                                       Rgba{0.1f, 0.2f, 0.3f, 1e6f}};
    const std::array<Rgba, 4> cleared = {Rgba{0.5f, 0, 0, 0}, Rgba{0, 0.5f, 0, 0}, Rgba{0, 0, 0.5f, 0}, Rgba{}};
    for (uint32_t t = 0; t < 4; ++t)
      checkCoverage(
          r, t, 8, 8, [](uint32_t, uint32_t row) { return row < 4; }, drawn[t], cleared[t]);
  }
}

TEST_CASE("drawOnGl samples a 2D texture bilinearly and a cube map trilinearly, by sampler name", "[gl]") {
  // One pixel per sample: column i samples the 2D texture at uv[i] (target 0) and the cube
  // map in direction dir[i] at lod 0.5 (target 1).
  const std::string fragment = R"(
BLOCK(3) uniform MbSamples { vec4 uv[6]; vec4 dir[6]; } samples;
uniform sampler2D mbTexture;
uniform samplerCube mbCube;
layout(location = 0) out vec4 flat2d;
layout(location = 1) out vec4 cube;
void main() {
  int i = int(gl_FragCoord.x);
  flat2d = textureLod(mbTexture, samples.uv[i].xy, 0.0);
  cube = textureLod(mbCube, samples.dir[i].xyz, 0.5);
}
)";
  // 2x2 texels: row 0 = a, b; row 1 = c, d.
  const Rgba a{1, 0.5f, 0, 1}, b{0, 0.25f, 1, 0}, c{0.5f, 1, 0.25f, 0.5f}, d{0.125f, 0.125f, 0.5f, 1};
  gl::DrawTexture flat;
  flat.levels = {
      {2, 2, {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3], c[0], c[1], c[2], c[3], d[0], d[1], d[2], d[3]}}};
  // Two levels of six uniform faces, exact binary fractions: face f is (f / 8, 0.125, 0.25, 1) at
  // level 0 and (f / 8, 0.375, 0.75, 0) at level 1, so lod 0.5 gives (f / 8, 0.25, 0.5, 0.5).
  gl::DrawTexture cube;
  cube.cube = true;
  for (uint32_t size : {2u, 1u}) {
    gl::DrawTextureLevel level{size, size, {}};
    for (int f = 0; f < 6; ++f)
      for (uint32_t texel = 0; texel < size * size; ++texel) {
        const bool first = size == 2;
        level.rgba.insert(level.rgba.end(),
                          {f / 8.0f, first ? 0.125f : 0.375f, first ? 0.25f : 0.75f, first ? 1.0f : 0.0f});
      }
    cube.levels.push_back(level);
  }
  // uv: texel centres a, b, c, then halfway between a and b, a and c, and the middle of all four.
  const std::vector<float> uv = {0.25f, 0.25f, 0, 0, 0.75f, 0.25f, 0, 0, 0.25f, 0.75f, 0, 0,
                                 0.5f,  0.25f, 0, 0, 0.25f, 0.5f,  0, 0, 0.5f,  0.5f,  0, 0};
  // +X, -X, +Y, -Y, +Z, -Z: faces 0..5.
  const std::vector<float> dir = {1, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0};
  auto mix = [](const Rgba& p, const Rgba& q) {
    return Rgba{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2, (p[3] + q[3]) / 2};
  };
  const std::array<Rgba, 6> expected2d = {a, b, c, mix(a, b), mix(a, c), mix(mix(a, b), mix(c, d))};
  std::vector<Language> languages = kLanguages;
  languages.push_back(kEssl300);
  for (const Language& language : languages) {
    INFO(language.version);
    DrawJob j = job(language, kPassThroughVertex, fragment, 6, 1, rectangle(-1, -1, 1, 1));
    j.colorTargets = 2;
    j.textures = {cube, flat};
    std::vector<float> block = uv;
    block.insert(block.end(), dir.begin(), dir.end());
    j.draws[0].uniformBlocks["MbSamples"] = bytesOf(block);
    j.draws[0].samplers = {{"mbTexture", 1}, {"mbCube", 0}, {"mbAbsentSampler", 1}};
    const DrawResult r = gl::drawOnGl(language.api, j);
    for (uint32_t i = 0; i < 6; ++i) {
      INFO("sample " << i);
      CHECK(within(pixel(r, 0, 6, i, 0), expected2d[i], 1e-6f));
      CHECK(within(pixel(r, 1, 6, i, 0), Rgba{i / 8.0f, 0.25f, 0.5f, 0.5f}, 1e-6f));
    }
  }
}

TEST_CASE("drawOnGl draws each call in its own viewport with its own blocks", "[gl]") {
  const std::string fragment = R"(
BLOCK(0) uniform MbFrameBlock { vec4 tint; } frame;
layout(location = 0) out vec4 color;
void main() { color = frame.tint; }
)";
  for (const Language& language : kLanguages) {
    INFO(language.version);
    // The top half of each viewport's clip square: rows y .. y + h/2 - 1 of the viewport.
    DrawJob j = job(language, kPassThroughVertex, fragment, 16, 16, rectangle(-1, -1, 1, 0));
    j.draws.resize(3);
    j.draws[0].viewport = {0, 0, 8, 8};
    j.draws[0].uniformBlocks["MbFrameBlock"] = bytesOf({1, 0, 0, 1});
    j.draws[1].viewport = {8, 0, 8, 8};
    j.draws[1].uniformBlocks["MbFrameBlock"] = bytesOf({0, 1, 0, 1});
    j.draws[2].viewport = {8, 8, 8, 8};
    j.draws[2].uniformBlocks["MbFrameBlock"] = bytesOf({0, 0, 1, 1});
    const DrawResult r = gl::drawOnGl(language.api, j);
    for (uint32_t row = 0; row < 16; ++row)
      for (uint32_t column = 0; column < 16; ++column) {
        INFO("row " << row << ", column " << column);
        Rgba expected{};
        if (row < 4) expected = column < 8 ? Rgba{1, 0, 0, 1} : Rgba{0, 1, 0, 1};
        if (row >= 8 && row < 12 && column >= 8) expected = {0, 0, 1, 1};
        REQUIRE(pixel(r, 0, 16, column, row) == expected);
      }
  }
}

TEST_CASE("drawOnGl names the driver's message for a shader it rejects", "[gl]") {
  for (const Language& language : kLanguages) {
    INFO(language.version);
    const std::string fragment = R"(
layout(location = 0) out vec4 color;
void main() { color = vec4(mbUndeclared); }
)";
    DrawJob j = job(language, kPassThroughVertex, fragment, 4, 4, rectangle(-1, -1, 1, 1));
    CHECK_THROWS_AS(gl::drawOnGl(language.api, j), gl::GlError);
    CHECK_THROWS_WITH(gl::drawOnGl(language.api, j),
                      Catch::StartsWith("the driver's GLSL compiler rejected the fragment shader: ") &&
                          Catch::Contains("mbUndeclared"));
    j = job(language, "void main() { gl_Position = vec4(0.0) }", kConstantFragment, 4, 4, rectangle(-1, -1, 1, 1));
    CHECK_THROWS_WITH(gl::drawOnGl(language.api, j),
                      Catch::StartsWith("the driver's GLSL compiler rejected the vertex shader: "));
  }
}

TEST_CASE("drawOnGl tests depth LESS: the nearer draw wins in either order, the first of equals", "[gl]") {
  // The draw's depth and colour from its block.
  const std::string vertex = R"(
layout(location = 0) in vec3 position;
BLOCK(0) uniform MbVertexPush { vec4 depth; } push;
void main() { gl_Position = vec4(position.xy, push.depth.x, 1.0); }
)";
  const std::string fragment = R"(
BLOCK(1) uniform MbFrameBlock { vec4 tint; } frame;
layout(location = 0) out vec4 color;
void main() { color = frame.tint; }
)";
  const Rgba near0{1, 0, 0, 1}, far0{0, 1, 0, 1};
  auto call = [](float depth, const Rgba& tint) {
    gl::DrawCall c;
    c.uniformBlocks["MbVertexPush"] = bytesOf({depth, 0, 0, 0});
    c.uniformBlocks["MbFrameBlock"] = bytesOf({tint[0], tint[1], tint[2], tint[3]});
    return c;
  };
  for (const Language& language : kLanguages) {
    INFO(language.version);
    DrawJob j = job(language, vertex, fragment, 4, 4, rectangle(-1, -1, 1, 1));
    auto only = [&](const DrawResult& r, const Rgba& expected) {
      checkCoverage(
          r, 0, 4, 4, [](uint32_t, uint32_t) { return true; }, expected, expected);
    };
    j.draws = {call(0.25f, near0), call(0.75f, far0)};
    only(gl::drawOnGl(language.api, j), near0);
    j.draws = {call(0.75f, far0), call(0.25f, near0)};
    only(gl::drawOnGl(language.api, j), near0);
    j.draws = {call(0.5f, far0), call(0.5f, near0)};
    only(gl::drawOnGl(language.api, j), far0);
    // Vulkan's clip depth is 0..1: depth -0.25 is in front of the near plane and clipped, and
    // depth 0 is drawn (GL's default -1..1 would draw both).
    j.draws = {call(-0.25f, near0)};
    only(gl::drawOnGl(language.api, j), Rgba{});
    j.draws = {call(0.0f, near0)};
    only(gl::drawOnGl(language.api, j), near0);
  }
}

TEST_CASE("drawOnGl culls the triangles Vulkan culls: clockwise with row 0 at the top", "[gl]") {
  // Rows grow with clip y. Left: (-1, -1) top-left, (-1, 1) bottom-left, (0, -1) top-middle,
  // counter-clockwise seen with row 0 at the top (Vulkan's front face). Right: (0, -1)
  // top-middle, (1, -1) top-right, (0, 1) bottom-middle, clockwise: a back face.
  gl::DrawMesh mesh =
      positions({-1, -1, 0.5f, -1, 1, 0.5f, 0, -1, 0.5f, 0, -1, 0.5f, 1, -1, 0.5f, 0, 1, 0.5f}, {0, 1, 2, 3, 4, 5});
  for (const Language& language : kLanguages) {
    INFO(language.version);
    DrawJob j = job(language, kPassThroughVertex, kConstantFragment, 16, 16, mesh);
    const DrawResult r = gl::drawOnGl(language.api, j);
    const Rgba drawn{0.25f, 0.5f, 0.75f, 1.0f};
    CHECK(pixel(r, 0, 16, 1, 1) == drawn);   // near the left triangle's right angle
    CHECK(pixel(r, 0, 16, 9, 1) == Rgba{});  // near the right one's
    // The left triangle: column + row / 2 < 8, at pixel centres.
    checkCoverage(
        r, 0, 16, 16, [](uint32_t column, uint32_t row) { return (column + 0.5f) + (row + 0.5f) / 2 < 8; }, drawn,
        Rgba{});
  }
}

TEST_CASE("drawOnGl refuses a malformed job before drawing", "[gl]") {
  DrawJob j = job(kLanguages[0], kPassThroughVertex, kConstantFragment, 4, 4, rectangle(-1, -1, 1, 1));
  j.mesh.indices.insert(j.mesh.indices.end(), {0, 1, 7});
  CHECK_THROWS_WITH(gl::drawOnGl(GlApi::Gl45Core, j), Catch::Contains("index 7 past the last vertex"));
  j.mesh.indices.resize(6);
  gl::DrawTexture incomplete;
  incomplete.levels = {{4, 4, std::vector<float>(64)}, {1, 1, std::vector<float>(4)}};  // 2x2 missing
  j.textures = {incomplete};
  CHECK_THROWS_WITH(gl::drawOnGl(GlApi::Gl45Core, j), Catch::Contains("texture 0 level 1 is not half"));
}

TEST_CASE("a GlCompute context stays usable across drawOnGl's own contexts", "[gl]") {
  // EGL has one surfaceless display per process; drawOnGl's context must not terminate it
  // under a GlCompute (test_languages.cpp keeps one of each API for the whole binary).
  const std::string kernel = R"(#version 310 es
layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer MbIn { float mbIn[]; };
layout(binding = 1, std430) writeonly buffer MbOut { float mbOut[]; };
layout(binding = 2, std140) uniform MbPush { uint count; } mbPush;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < mbPush.count) mbOut[i] = 2.0 * mbIn[i];
}
)";
  gl::GlCompute compute(GlApi::Es31);
  CHECK(compute.run(kernel, {1, 2, 3}, 1, 1, 3).outputs == std::vector<float>{2, 4, 6});
  for (const Language& language : kLanguages) {
    DrawJob j = job(language, kPassThroughVertex, kConstantFragment, 4, 4, rectangle(-1, -1, 1, 1));
    CHECK(pixel(gl::drawOnGl(language.api, j), 0, 4, 0, 0) == Rgba{0.25f, 0.5f, 0.75f, 1.0f});
  }
  CHECK(compute.run(kernel, {1, 2, 3}, 1, 1, 3).outputs == std::vector<float>{2, 4, 6});
  CHECK(compute.deviceName().find("OpenGL ES") != std::string::npos);
}
