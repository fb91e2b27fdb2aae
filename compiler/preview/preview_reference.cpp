#include "preview/preview_reference.hpp"

#include "core/texel_axis.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <thread>

#include "validate/probe_program.hpp"

namespace mb::preview {
namespace {

using ref::Vec3;

Vec3 at(const std::vector<float>& target, size_t pixel) {
  return {target[pixel * 4], target[pixel * 4 + 1], target[pixel * 4 + 2]};
}

}  // namespace

ref::Vec3 sampleDfgLut(const lut::LutTable& table, double u, double v) {
  const TexelAxis x = texelAxis(u, static_cast<int>(table.size)), y = texelAxis(v, static_cast<int>(table.size));
  const int i0 = x.i0, i1 = x.i1, j0 = y.i0, j1 = y.i1;
  const double wu = x.w, wv = y.w;
  double c[3];
  for (uint32_t k = 0; k < 3; ++k) {
    auto texel = [&](int i, int j) {
      return static_cast<double>(table.at(static_cast<uint32_t>(i), static_cast<uint32_t>(j), k));
    };
    const double top = texel(i0, j0) * (1 - wu) + texel(i1, j0) * wu;
    const double bottom = texel(i0, j1) * (1 - wu) + texel(i1, j1) * wu;
    c[k] = top * (1 - wv) + bottom * wv;
  }
  return {c[0], c[1], c[2]};
}

ref::ModelEvalInput referenceWorkspace(const ReferenceScene& scene, size_t sphere) {
  ref::ModelEvalInput e;
  e.bricks = scene.bricks;
  e.features.insert(scene.features.begin(), scene.features.end());
  e.inputs = scene.sphereInputs.at(sphere);
  if (scene.environmentMode == "none") return e;
  ref::Environment env;
  env.mode = scene.environmentMode;
  const auto sh = frameSh(*scene.environment);
  std::copy(sh.begin(), sh.end(), env.sh);
  env.ao = 1.0;
  env.maxMip = static_cast<float>(scene.environment->maxMip());
  if (env.ibl()) {
    const EnvironmentMaps* maps = scene.environment;
    env.fetchPrefiltered = [maps](const Vec3& r, double lod) {
      const auto s = maps->sample({r.x, r.y, r.z}, lod);
      return Vec3{s[0], s[1], s[2]};
    };
  }
  if (env.mode == "ibl_lut") {
    const lut::LutTable* table = scene.dfg;
    env.fetchDfg = [table](double NoV, double perceptualRoughness) {
      return sampleDfgLut(*table, NoV, perceptualRoughness);
    };
  }
  e.env = std::move(env);
  return e;
}

ref::Vec3 referencePixel(const ReferenceScene& scene, const PixelAttributes& a, uint32_t x, uint32_t y,
                         ref::ModelEvalInput& e, int perturb) {
  const size_t pixel = size_t{y} * a.width + x;
  const Vec3 position = at(a.position, pixel);
  const auto camera = cameraPosition();
  double n[3] = {a.normal[pixel * 4], a.normal[pixel * 4 + 1], a.normal[pixel * 4 + 2]};
  double v[3] = {camera[0] - position.x, camera[1] - position.y, camera[2] - position.z};
  if (perturb >= 0) {
    // probe_program.cpp's RecordEvaluator::conditioning, on the six direction components.
    const double sign = perturb % 2 ? -1.0 : 1.0, eps = kDirectionInputUlps * 0x1p-23;
    double* columns[6] = {&n[0], &n[1], &n[2], &v[0], &v[1], &v[2]};
    for (uint32_t c = 0; c < 6; ++c) {
      const uint32_t bit = ((c + 1) * 0x9E3779B9u >> (7 + perturb / 2)) & 1u;
      *columns[c] *= 1.0 + (bit ? sign : -sign) * eps;
    }
  }
  // The fragment shader's frame (docs/fragment-stage.md): n = ng = normalize(worldNormal),
  // v = normalize(camera - worldPosition), t = normalize(worldTangent.xyz).
  ref::ShadingFrame& f = e.frame;
  f.n = ref::normalize(Vec3{n[0], n[1], n[2]});
  f.ng = f.n;
  f.v = ref::normalize(Vec3{v[0], v[1], v[2]});
  f.t = ref::normalize(at(a.tangent, pixel));
  e.dir.reset();
  e.point.reset();
  e.spot.reset();
  e.sphere.reset();
  e.tube.reset();
  for (const auto& type : scene.lightTypes) setLight(scene.lights, type, 0, position, e);
  return scene.model(e);
}

std::array<double, 3> conditioningAllowance(const ReferenceScene& scene, const PixelAttributes& a, uint32_t x,
                                            uint32_t y, const ref::Vec3& reference, ref::ModelEvalInput& work) {
  std::array<double, 3> allowance{0, 0, 0};
  for (uint32_t pattern = 0; pattern < kConditioningPatterns; ++pattern) {
    const double sign = pattern % 2 ? -1.0 : 1.0;
    ref::ScopedHalfVectorSumSkew skew(sign * kDirectionInputUlps * 0x1p-23);
    const Vec3 moved = referencePixel(scene, a, x, y, work, static_cast<int>(pattern));
    const double d[3] = {std::abs(moved.x - reference.x), std::abs(moved.y - reference.y),
                         std::abs(moved.z - reference.z)};
    for (int c = 0; c < 3; ++c)
      if (std::isfinite(d[c])) allowance[c] = std::max(allowance[c], d[c]);
  }
  return allowance;
}

std::vector<double> referenceImage(const ReferenceScene& scene, const PixelAttributes& a, unsigned threads) {
  std::vector<double> out(size_t{a.width} * a.height * 3, 0.0);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, a.height);
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](unsigned t) {
    try {
      std::vector<ref::ModelEvalInput> spheres;
      for (size_t s = 0; s < scene.sphereInputs.size(); ++s) spheres.push_back(referenceWorkspace(scene, s));
      // Rows interleaved: the spheres fill the middle rows, so blocks of rows would not balance.
      for (uint32_t y = t; y < a.height; y += threads) {
        for (uint32_t x = 0; x < a.width; ++x) {
          const size_t pixel = size_t{y} * a.width + x;
          if (a.position[pixel * 4 + 3] != 1.0f) continue;
          const Vec3 r = referencePixel(scene, a, x, y, spheres.at(x / scene.tile));
          out[pixel * 3] = r.x;
          out[pixel * 3 + 1] = r.y;
          out[pixel * 3 + 2] = r.z;
        }
      }
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace mb::preview
