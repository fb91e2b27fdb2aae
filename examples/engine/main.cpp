// examples/engine: a minimal engine consuming a matbricks package (docs/package.md). It
// includes the generated header, refuses at compile time to build without the permutations
// it uses, loads their SPIR-V, fills the std140 parameter block from the generated struct and
// the shading records from the generated record layout, shades a 32x32 lit sphere on the
// Vulkan device, writes engine_<material>.ppm next to the binary, and checks the pixels.
// Then it draws the same materials as an engine draws: a UV sphere mesh through the reference
// vertex shader and each permutation's fragment shader (raster.hpp), checked against the
// kernel at the same n, v, l, written as engine_<material>_raster.ppm.
// Plain Vulkan 1.1, no matbricks library: this is what an outside engine would write.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera.hpp"
#include "engine_materials.hpp"
#include "gpu.hpp"
#include "raster.hpp"

namespace em = engine_materials;

// A permutation this engine needs but the package lacks is a build error, never a fallback.
constexpr std::string_view kMetalKey = "ue4_metal.standard.dir.none.fp32";
constexpr std::string_view kPlasticKey = "filament_plastic.standard.dir.none.fp32";
static_assert(em::hasPermutation(kMetalKey) && em::hasPermutation(kPlasticKey),
              "the package lacks a permutation this engine uses");
constexpr const em::Permutation* kMetal = em::findPermutation(kMetalKey);
constexpr const em::Permutation* kPlastic = em::findPermutation(kPlasticKey);
// This engine fills n, v and l only: refuse a record layout that asks for more.
static_assert(kMetal->inputCount == 3 && kPlastic->inputCount == 3, "unexpected shading record inputs");
static_assert(em::recordOffset(*kPlastic, "l") != ~0u, "records without a light direction");
static_assert(kPlastic->paramsSize <= sizeof(em::filament_plastic_Params), "parameter struct too small");
// The raster path binds no textures (docs/fragment-stage.md: bindings 4 + i).
static_assert(kMetal->fragmentTextureCount == 0 && kPlastic->fragmentTextureCount == 0, "textured permutation");
// Nor an environment (the permutations' environment mode is "none"): neither path fetches a
// texel, so the sampling share of the tolerance, which the device's subTexelPrecisionBits and
// mipmapPrecisionBits bound per fetch (docs/preview.md "Sampling share"), is exactly 0 here
// on any device. A permutation with an environment or textures would need that share.
static_assert(kMetalKey.find(".none.") != std::string_view::npos &&
                  kPlasticKey.find(".none.") != std::string_view::npos,
              "a permutation that samples an environment");

namespace {

constexpr int kSize = 32;
using namespace engine;

std::vector<uint32_t> readSpirv(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<uint32_t> words(static_cast<size_t>(in.tellg()) / 4);
  in.seekg(0);
  in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
  return words;
}

// A file of the package, by the name the generated header gives it.
std::vector<uint32_t> loadSpirv(std::string_view file) {
  return readSpirv(std::string(MATBRICKS_PACKAGE_DIR) + "/" + std::string(file));
}

struct Image {
  std::vector<float> rgb = std::vector<float>(kSize * kSize * 3, 0.0f);
};

// The one directional light of both paths, from the upper left, unit length.
constexpr float kLight[3] = {-0.408248f, 0.408248f, 0.816497f};

// The inputs of one shading record (the layout is the generated header's).
struct Record {
  float n[3], v[3], l[3];
};

// Shades `in` with p's kernel and returns each record's radiance (rgb).
std::vector<float> shadeRecords(Gpu& gpu, const em::Permutation& p, const void* params, size_t paramsBytes,
                                const std::vector<Record>& in) {
  const uint32_t count = static_cast<uint32_t>(in.size());
  Buffer records = gpu.buffer(sizeof(float) * p.recordStride * count, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  float* rec = static_cast<float*>(records.mapped);
  for (uint32_t i = 0; i < count; ++i) {
    float* r = rec + i * p.recordStride;
    std::memcpy(r + em::recordOffset(p, "n"), in[i].n, sizeof in[i].n);
    std::memcpy(r + em::recordOffset(p, "v"), in[i].v, sizeof in[i].v);
    std::memcpy(r + em::recordOffset(p, "l"), in[i].l, sizeof in[i].l);
  }
  Buffer results = gpu.buffer(sizeof(float) * p.resultStride * count, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  Buffer block;
  if (p.paramsSize) {
    block = gpu.buffer(paramsBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memcpy(block.mapped, params, paramsBytes);
  }
  gpu.run(loadSpirv(p.spirv), records, results, p.paramsSize ? &block : nullptr, count);
  std::vector<float> rgb(3 * count);
  const float* out = static_cast<const float*>(results.mapped);
  for (uint32_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = out[i * p.resultStride + c];
  gpu.release(records);
  gpu.release(results);
  if (p.paramsSize) gpu.release(block);
  return rgb;
}

// One record per pixel covered by a unit sphere seen head-on: n from the sphere, v toward
// the camera, the light from the upper left.
Image shadeSphere(Gpu& gpu, const em::Permutation& p, const void* params, size_t paramsBytes) {
  std::vector<int> pixels;
  std::vector<Record> records;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float sx = (x + 0.5f) / kSize * 2.0f - 1.0f, sy = 1.0f - (y + 0.5f) / kSize * 2.0f;
      const float r2 = sx * sx + sy * sy;
      if (r2 >= 1.0f) continue;
      records.push_back({{sx, sy, std::sqrt(1.0f - r2)}, {0.0f, 0.0f, 1.0f}, {kLight[0], kLight[1], kLight[2]}});
      pixels.push_back(y * kSize + x);
    }
  const std::vector<float> rgb = shadeRecords(gpu, p, params, paramsBytes, records);
  Image img;
  for (size_t i = 0; i < pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) img.rgb[pixels[i] * 3 + c] = rgb[i * 3 + c];
  return img;
}

int gFailures = 0;
void expect(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  gFailures += ok ? 0 : 1;
}

void checkImage(const Image& img, const std::string& name) {
  bool finite = true;
  float lo = img.rgb[0], hi = img.rgb[0];
  for (float v : img.rgb) {
    finite = finite && std::isfinite(v) && v >= 0.0f;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  expect(finite, name + ": every value finite and non-negative");
  expect(hi - lo > 1e-3f,
         name + ": the image is not constant (range " + std::to_string(lo) + " .. " + std::to_string(hi) + ")");
}

// Reinhard-tonemapped, gamma 2.2, binary PPM.
void writePpm(const Image& img, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << kSize << " " << kSize << "\n255\n";
  for (float v : img.rgb) {
    const float t = std::pow(v / (1.0f + v), 1.0f / 2.2f);
    out.put(static_cast<char>(static_cast<unsigned char>(std::lround(std::clamp(t, 0.0f, 1.0f) * 255.0f))));
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

// The raster path's frame block: the camera, and the compute path's light with the unit
// illuminance the kernel shades with (its probe scene's vec3(1.0)).
em::MbFrameBlock frameBlock(const Camera& camera) {
  em::MbFrameBlock f{};
  for (int i = 0; i < 3; ++i) f.cameraPosition[i] = float(camera.eye[i]);
  f.lightCounts[0] = 1;
  for (int i = 0; i < 3; ++i) {
    f.dirLights[0].direction[i] = kLight[i];
    f.dirLights[0].illuminance[i] = 1.0f;
  }
  return f;
}

// The record the fragment shader builds where the ray through (x + 0.5, y + 0.5) meets the
// mesh: the normalized interpolated normal, v towards the eye, the light.
std::optional<Record> recordAt(const Mesh& mesh, const Camera& camera, double x, double y) {
  double dir[3];
  camera.ray(x, y, kSize, dir);
  const std::optional<Hit> hit = castRay(mesh, camera.eye, dir);
  if (!hit) return std::nullopt;
  double v[3];
  for (int i = 0; i < 3; ++i) v[i] = camera.eye[i] - hit->position[i];
  const double nl = std::sqrt(hit->normal[0] * hit->normal[0] + hit->normal[1] * hit->normal[1] +
                              hit->normal[2] * hit->normal[2]),
               vl = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  Record r;
  for (int i = 0; i < 3; ++i) {
    r.n[i] = float(hit->normal[i] / nl);
    r.v[i] = float(v[i] / vl);
    r.l[i] = kLight[i];
  }
  return r;
}

// Draws p's fragment shader over a UV sphere with the reference vertex shader and checks it:
// pixels well inside the silhouette against p's compute kernel at the same n, v, l; pixels
// well outside are the clear colour.
Image renderSphere(Gpu& gpu, const em::Permutation& p, const void* params, size_t paramsBytes,
                   const std::vector<uint32_t>& vertexSpirv, const std::string& name) {
  const Camera camera;
  const Mesh mesh = uvSphere(32, 64);
  DrawSpec spec;
  spec.vertexSpirv = vertexSpirv;
  spec.fragmentSpirv = loadSpirv(p.fragmentSpirv);
  camera.pushConstants(spec.pushConstants);
  if (p.paramsSize)
    spec.params.assign(static_cast<const unsigned char*>(params),
                       static_cast<const unsigned char*>(params) + paramsBytes);
  const em::MbFrameBlock frame = frameBlock(camera);
  spec.frame.assign(reinterpret_cast<const unsigned char*>(&frame),
                    reinterpret_cast<const unsigned char*>(&frame) + sizeof frame);
  spec.size = kSize;
  const std::vector<float> rgba = draw(gpu, mesh, spec);

  // The rasterizer snaps vertices to 1/2^subPixelPrecisionBits of a pixel (Vulkan spec
  // "Rasterization"), which moves the point it samples on a triangle by up to half a step in x
  // and y. So the reference is the kernel at the pixel centre and at the four corners of that
  // +-half-step square: where shading is smooth, the rendered value lies between their minimum
  // and maximum, up to fp32 rounding (the two paths normalize and interpolate in a different
  // order: 1e-4 relative, ~800 ulps, plus 1e-6 absolute near zero).
  const double h = 0.5 / double(1u << gpu.limits().subPixelPrecisionBits);
  const double offsets[5][2] = {{0, 0}, {-h, -h}, {h, -h}, {-h, h}, {h, h}};
  const double pixelAtOrigin = 2.0 * camera.tanHalfFov * camera.eye[2] / kSize;
  std::vector<int> inside;
  std::vector<Record> records;
  int background = 0, notBackground = 0, missed = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double dir[3];
      camera.ray(x, y, kSize, dir);
      // Distance of the ray from the sphere's centre (the eye is on the z axis).
      const double d = camera.eye[2] * std::hypot(dir[0], dir[1]) / std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + 1.0);
      const float* px = &rgba[(y * kSize + x) * 4];
      if (d > 1.0 + pixelAtOrigin) {  // a pixel clear of the silhouette: the mesh is inside the sphere
        ++background;
        notBackground += px[0] != 0.0f || px[1] != 0.0f || px[2] != 0.0f || px[3] != 0.0f;
      } else if (d < 0.8) {
        for (const auto& o : offsets) {
          const std::optional<Record> r = recordAt(mesh, camera, x + o[0], y + o[1]);
          missed += r ? 0 : 1;
          if (r) records.push_back(*r);
        }
        inside.push_back(y * kSize + x);
      }
    }
  expect(missed == 0, name + " raster: every centre ray hits the mesh");
  expect(background > 100 && notBackground == 0, name + " raster: " + std::to_string(notBackground) + " of " +
                                                     std::to_string(background) +
                                                     " background pixels are not the clear colour");
  if (missed) return {};
  const std::vector<float> reference = shadeRecords(gpu, p, params, paramsBytes, records);
  int outside = 0, opaque = 0;
  double worst = 0.0, widest = 0.0;
  for (size_t k = 0; k < inside.size(); ++k) {
    const float* px = &rgba[inside[k] * 4];
    opaque += px[3] == 1.0f;
    for (int c = 0; c < 3; ++c) {
      float lo = reference[k * 15 + c], hi = lo;
      for (int o = 1; o < 5; ++o) {
        lo = std::min(lo, reference[(k * 5 + o) * 3 + c]);
        hi = std::max(hi, reference[(k * 5 + o) * 3 + c]);
      }
      const double scale = std::max(std::fabs(lo), std::fabs(hi));
      const double tol = 1e-4 * scale + 1e-6;
      outside += px[c] < lo - tol || px[c] > hi + tol;
      if (scale > 0.0) {
        worst = std::max(worst, std::fabs(px[c] - reference[k * 15 + c]) / scale);
        widest = std::max(widest, (hi - lo) / scale);
      }
    }
  }
  expect(inside.size() > 200 && outside == 0 && opaque == int(inside.size()),
         name + " raster: " + std::to_string(inside.size()) + " centre pixels, " + std::to_string(outside) +
             " channels outside the kernel's range, " + std::to_string(inside.size() - opaque) +
             " with alpha != 1 (largest difference from the kernel at the pixel centre " + std::to_string(worst) +
             " relative; widest snapping range " + std::to_string(widest) + ")");
  Image img;
  for (int i = 0; i < kSize * kSize; ++i)
    for (int c = 0; c < 3; ++c) img.rgb[i * 3 + c] = rgba[i * 4 + c];
  return img;
}

}  // namespace

int main(int, char** argv) {
  try {
    std::string dir = argv[0];
    dir = dir.find('/') == std::string::npos ? "." : dir.substr(0, dir.rfind('/'));
    Gpu gpu;
    std::printf(
        "engine example: subTexelPrecisionBits %u, mipmapPrecisionBits %u; no texture fetches, sampling share 0\n",
        gpu.limits().subTexelPrecisionBits, gpu.limits().mipmapPrecisionBits);

    em::ue4_metal_Params metal{};
    metal.roughness = 0.3f;
    const Image metalImage = shadeSphere(gpu, *kMetal, &metal, sizeof metal);
    checkImage(metalImage, "ue4_metal");
    writePpm(metalImage, dir + "/engine_ue4_metal.ppm");
    // The same material through its fragment shader, drawn as an engine draws.
    const std::vector<uint32_t> vertexSpirv = readSpirv(ENGINE_VERTEX_SPV);
    const Image metalRaster = renderSphere(gpu, *kMetal, &metal, sizeof metal, vertexSpirv, "ue4_metal");
    checkImage(metalRaster, "ue4_metal raster");
    writePpm(metalRaster, dir + "/engine_ue4_metal_raster.ppm");

    em::filament_plastic_Params plastic{};
    const float red[3] = {0.8f, 0.1f, 0.1f};
    std::memcpy(plastic.baseColor, red, sizeof red);
    plastic.metallic = 0.0f;
    plastic.roughness = 0.4f;
    const Image smooth = shadeSphere(gpu, *kPlastic, &plastic, sizeof plastic);
    checkImage(smooth, "filament_plastic");
    writePpm(smooth, dir + "/engine_filament_plastic.ppm");
    const Image plasticRaster = renderSphere(gpu, *kPlastic, &plastic, sizeof plastic, vertexSpirv, "filament_plastic");
    checkImage(plasticRaster, "filament_plastic raster");
    writePpm(plasticRaster, dir + "/engine_filament_plastic_raster.ppm");

    // The parameter block is live: a rougher plastic must shade differently.
    plastic.roughness = 0.9f;
    const Image rough = shadeSphere(gpu, *kPlastic, &plastic, sizeof plastic);
    checkImage(rough, "filament_plastic rough");
    float diff = 0.0f;
    for (size_t i = 0; i < rough.rgb.size(); ++i) diff = std::max(diff, std::fabs(rough.rgb[i] - smooth.rgb[i]));
    expect(diff > 1e-3f, "roughness 0.4 -> 0.9 changes the image (max difference " + std::to_string(diff) + ")");
    // And red stays red: the block's vec3 baseColor and the float after it are read where the
    // struct put them (a std140 mismatch would mix the channels).
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < smooth.rgb.size(); ++i) sum[i % 3] += smooth.rgb[i];
    expect(sum[0] > 2.0 * sum[1] && sum[0] > 2.0 * sum[2], "the red plastic is red");
    writePpm(rough, dir + "/engine_filament_plastic_rough.ppm");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine example: %s\n", e.what());
    return 1;
  }
  expect(gValidationMessages == 0, "no validation messages (" + std::to_string(gValidationMessages) + ")");
  return gFailures == 0 ? 0 : 1;
}
