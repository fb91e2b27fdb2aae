#include "bench_engine/ibl_bench.hpp"

#include <cstdio>

#include "common/ibl_reference.hpp"
#include "core/parallel.hpp"
#include "emit/emitter.hpp"
#include "validate/sampler.hpp"

namespace mb::bench {

bool measureDfgLuts(const ShaderLibrary& lib, const BenchOptions& o, IblSection& out, ProgressSink* progress) {
  std::vector<std::string> envBricks = lib.bricksOfSlot("env_brdf");
  if (envBricks.empty()) return false;
  // The samples of the first env_brdf brick: validate and bench draw the same ones for it.
  const Brick& b = *lib.findBrick(envBricks.front());
  ProbeLayout layout = emitBrickProbe(lib, b).layout;
  const ProbeInput *f0 = layout.find("f0"), *rough = layout.find("perceptualRoughness"), *nov = layout.find("NoV");
  if (!f0 || !rough || !nov || f0->type != ValueType::Vec3) return false;
  SampleDomain domain{b.domain, b.geometry, {}};
  std::vector<float> in = generateSamples(layout, domain, o.samples, o.seed);
  // One unit for the exact integrals of every sample, one per LUT measured.
  if (progress) progress->addToTotal(1 + 2 * o.lutSizes.size());

  // The integrals once per sample; each LUT is then compared on every channel of f0.
  struct Point {
    double f0[3], roughness, NoV;
    ref::DfgIntegrals truth;
  };
  std::vector<Point> points(o.samples);
  parallelFor(o.samples, [&](size_t s) {
    const float* r = in.data() + s * layout.inStride;
    Point& p = points[s];
    for (int c = 0; c < 3; ++c) p.f0[c] = r[f0->offset + c];
    p.roughness = r[rough->offset];
    p.NoV = r[nov->offset];
    p.truth = ref::dfgIntegrals(p.NoV, p.roughness * p.roughness);
  });
  if (progress) progress->advance();

  out.samplesFrom = b.id;
  out.samples = o.samples;
  for (uint32_t size : o.lutSizes) {
    lut::DfgLut exact = lut::buildDfgLut(size);
    for (lut::LutFormat format : {lut::LutFormat::Fp16, lut::LutFormat::Fp32}) {
      lut::DfgLut table = lut::quantize(exact, format);
      LutItem item{size, format, table.bytes(format), {}};
      for (const Point& p : points) {
        lut::DfgSample d = lut::sampleBilinear(table, p.NoV, p.roughness);
        // Split sum with Schlick's F: f0 Int Gv + (1 - f0) Int Gv Fc (ibl_reference.hpp).
        for (double f : p.f0) item.error.add(f * d.y + (1.0 - f) * d.x, f * p.truth.gv + (1.0 - f) * p.truth.gvFc);
      }
      if (progress) progress->advance();
      out.luts.push_back(item);
    }
  }
  return true;
}

}  // namespace mb::bench
