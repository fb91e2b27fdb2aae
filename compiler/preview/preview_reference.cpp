#include "preview/preview_reference.hpp"

#include "core/texel_axis.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <thread>

#include "validate/probe_ltc_table.hpp"
#include "validate/probe_program.hpp"

namespace mb::preview {
namespace {

using ref::Vec3;

Vec3 at(const std::vector<float>& target, size_t pixel) {
  return {target[pixel * 4], target[pixel * 4 + 1], target[pixel * 4 + 2]};
}

}  // namespace

FilteredRgb sampleDfgLut(const lut::LutTable& table, double u, double v, const TexelFilter& filter) {
  const TexelAxis x = texelAxis(u, static_cast<int>(table.size)), y = texelAxis(v, static_cast<int>(table.size));
  Footprint f;
  f.a = x.w, f.b = y.w;
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 2; ++column)
      for (uint32_t k = 0; k < 3; ++k)
        f.t[row][column][k] =
            table.at(static_cast<uint32_t>(column ? x.i1 : x.i0), static_cast<uint32_t>(row ? y.i1 : y.i0), k);
  return filterBilinear(f, filter);
}

namespace {

// One texture fetch of the reference: sampled (and recorded) or, replaying, the recorded one
// with the moved component shifted by its bound.
template <class Sample>
Vec3 fetched(FetchLog* log, bool perChannel, const Sample& sample) {
  if (log && log->replay) {
    if (log->next >= log->fetches.size()) throw std::logic_error("a replayed reference fetched more than it recorded");
    const size_t k = log->next++;
    FilteredRgb f = log->fetches[k];
    if (k == log->moved)
      for (int c = 0; c < 3; ++c)
        if (log->component == 3 || log->component == c) f.value[c] += f.bound[c];
    return {f.value[0], f.value[1], f.value[2]};
  }
  const FilteredRgb f = sample();
  if (log) log->fetches.push_back(f), log->perChannel.push_back(perChannel);
  return {f.value[0], f.value[1], f.value[2]};
}

}  // namespace

ref::ModelEvalInput referenceWorkspace(const ReferenceScene& scene, size_t sphere, FetchLog* log) {
  ref::ModelEvalInput e;
  e.bricks = scene.bricks;
  e.features.insert(scene.features.begin(), scene.features.end());
  e.inputs = scene.sphereInputs.at(sphere);
  if (const ProbeLtcTable* table = scene.ltc) {
    // The fragment shader's mb_ltc_texel: the four entries around the point, blended in fp32
    // arithmetic (docs/fragment-stage.md "LTC table"); here in double, the same weights.
    e.fetchLtc = [table](ref::LtcLobe lobe, double NoV, double perceptualRoughness) {
      return table->texel(lobe, NoV, perceptualRoughness);
    };
  }
  if (scene.environmentMode == EnvironmentMode::None) return e;
  ref::Environment env;
  env.mode = environmentModeName(scene.environmentMode);  // the reference's own vocabulary
  const auto sh = frameSh(*scene.environment);
  std::copy(sh.begin(), sh.end(), env.sh);
  env.ao = 1.0;
  env.maxMip = static_cast<float>(scene.environment->maxMip());
  const TexelFilter filter{scene.samplerLimits, scene.quantizer};
  if (env.ibl()) {
    const EnvironmentMaps* maps = scene.environment;
    env.fetchPrefiltered = [maps, filter, log](const Vec3& r, double lod) {
      return fetched(log, true, [&] { return maps->sampleFiltered({r.x, r.y, r.z}, lod, filter); });
    };
  }
  if (usesDfgLut(scene.environmentMode)) {
    const lut::LutTable* table = scene.dfg;
    env.fetchDfg = [table, filter, log](double NoV, double perceptualRoughness) {
      return fetched(log, false, [&] { return sampleDfgLut(*table, NoV, perceptualRoughness, filter); });
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
  e.rect.reset();
  e.disk.reset();
  for (LightType type : scene.lightTypes) setLight(scene.lights, type, 0, position, e);
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

std::array<double, 3> samplingShare(const ReferenceScene& scene, const PixelAttributes& a, uint32_t x, uint32_t y,
                                    const ref::Vec3& reference, ref::ModelEvalInput& work, FetchLog& log) {
  std::array<double, 3> share{0, 0, 0};
  log.replay = true;
  for (size_t k = 0; k < log.fetches.size(); ++k)
    for (int c = log.perChannel[k] ? 3 : 0; c < (log.perChannel[k] ? 4 : 3); ++c) {
      const Rgb& b = log.fetches[k].bound;
      if (c < 3 ? b[c] == 0.0 : b == Rgb{0, 0, 0}) continue;  // equal texels: every device returns the same
      log.next = 0, log.moved = k, log.component = c;
      const Vec3 moved = referencePixel(scene, a, x, y, work);
      const double d[3] = {std::abs(moved.x - reference.x), std::abs(moved.y - reference.y),
                           std::abs(moved.z - reference.z)};
      for (int ch = 0; ch < 3; ++ch)
        if (std::isfinite(d[ch])) share[ch] += d[ch];
    }
  log.replay = false;
  return share;
}

std::vector<double> referenceImage(const ReferenceScene& scene, const PixelAttributes& a, unsigned threads,
                                   std::vector<double>* samplingBound) {
  std::vector<double> out(size_t{a.width} * a.height * 3, 0.0);
  if (samplingBound) samplingBound->assign(out.size(), 0.0);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, a.height);
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](unsigned t) {
    try {
      FetchLog log;
      std::vector<ref::ModelEvalInput> spheres;
      for (size_t s = 0; s < scene.sphereInputs.size(); ++s)
        spheres.push_back(referenceWorkspace(scene, s, samplingBound ? &log : nullptr));
      // Rows interleaved: the spheres fill the middle rows, so blocks of rows would not balance.
      for (uint32_t y = t; y < a.height; y += threads) {
        for (uint32_t x = 0; x < a.width; ++x) {
          const size_t pixel = size_t{y} * a.width + x;
          if (a.position[pixel * 4 + 3] != 1.0f) continue;
          log.fetches.clear(), log.perChannel.clear();
          ref::ModelEvalInput& work = spheres.at(x / scene.tile);
          const Vec3 r = referencePixel(scene, a, x, y, work);
          out[pixel * 3] = r.x;
          out[pixel * 3 + 1] = r.y;
          out[pixel * 3 + 2] = r.z;
          if (samplingBound) {
            const auto share = samplingShare(scene, a, x, y, r, work, log);
            std::copy(share.begin(), share.end(), samplingBound->begin() + pixel * 3);
          }
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
