// matbricks lut: generate the split-sum DFG LUT on the GPU (a compute kernel built from the
// library's bricks), check it against the CPU evaluation of the identical sum and against the
// high-accuracy quadrature, and write it as raw, KTX2, CSV or a C header (docs/lut.md).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "cli/progress.hpp"
#include "lut/lut_check.hpp"
#include "lut/lut_formats.hpp"
#include "lut/lut_gpu.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

struct LutArgs {
  uint32_t size = 128;
  uint32_t samples = 0;  // 0: deterministic quadrature
  std::string precision = "fp32";
  std::string output;
  std::string outputFormat;
  uint32_t checkGrid = 16;
  bool json = false;
  bool quiet = false;
};

// The output format, decided before any GPU work so that a bad command line costs nothing.
lut::OutputFormat resolveFormat(const LutArgs& a) {
  if (a.output.empty()) {
    if (!a.outputFormat.empty()) throw CLI::ValidationError("lut", "--output-format needs -o FILE");
    return lut::OutputFormat::Raw;
  }
  if (!a.outputFormat.empty()) return *lut::parseOutputFormat(a.outputFormat);
  auto f = lut::formatFromExtension(a.output);
  if (!f) {
    throw CLI::ValidationError("lut", "cannot tell the format of '" + a.output +
                                          "' from its extension (.bin, .raw, .ktx2, .csv, .h); give --output-format");
  }
  return *f;
}

nlohmann::json channelJson(const std::array<lut::ChannelError, lut::kChannels>& e) {
  nlohmann::json out = nlohmann::json::object();
  for (uint32_t c = 0; c < lut::kChannels; ++c)
    out[lut::kChannelNames[c]] = {{"max_abs", e[c].maxAbs}, {"mean_abs", e[c].meanAbs}, {"max_rel", e[c].maxRel}};
  return out;
}

void printChannels(const char* title, const std::array<lut::ChannelError, lut::kChannels>& e) {
  std::printf("%s\n", title);
  for (uint32_t c = 0; c < lut::kChannels; ++c)
    std::printf("  channel %u %-10s max_abs=%-12.4g mean_abs=%-12.4g max_rel=%.4g\n", c, lut::kChannelNames[c],
                e[c].maxAbs, e[c].meanAbs, e[c].maxRel);
}

int runLut(const LutArgs& a, const GlobalOptions& g) {
  const lut::OutputFormat format = resolveFormat(a);
  const lut::Precision precision = a.precision == "fp16" ? lut::Precision::Fp16 : lut::Precision::Fp32;
  ShaderLibrary lib = loadLibrary(g);
  if (!a.output.empty()) checkFileOutput(a.output, "LUT file", libraryInputs(lib));
  auto gpu = openDevice(g);
  // One unit for the GPU generation, then one per texel checked on the CPU (checkLut adds them).
  Progress progress("lut", 1, a.quiet, a.json);
  lut::GpuLut generated = lut::generateDfgLutOnGpu(*gpu, lib, a.size, a.samples);
  progress.advance();
  lut::LutCheck check = lut::checkLut(lib, generated.table, a.checkGrid, true, &progress);
  progress.finish();
  const bool layerMessages = reportLayerMessages(*gpu);
  const bool ok = check.passed() && !layerMessages;
  // A LUT that fails its check is not written.
  if (ok && !a.output.empty())
    PackageWriter::writeFileAtomically(a.output, lut::encodeLut(generated.table, format, precision));

  const uint32_t worstI = check.worstTexel < 0 ? 0 : static_cast<uint32_t>(check.worstTexel % a.size);
  const uint32_t worstJ = check.worstTexel < 0 ? 0 : static_cast<uint32_t>(check.worstTexel / a.size);
  if (a.json) {
    nlohmann::json out{
        {"size", a.size},
        {"samples", a.samples},
        {"estimator", a.samples ? "hammersley" : "quadrature"},
        {"precision", a.precision},
        {"output", a.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.output)},
        {"output_format", a.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(lut::formatName(format))},
        {"written", ok && !a.output.empty()},
        {"device", gpu->deviceName()},
        {"compile_ms", generated.compileMs},
        {"spirv_instructions", generated.spirvInstructions},
        {"gpu_ms", generated.gpuMs},
        {"warmup_gpu_ms", generated.warmupGpuMs},
        {"gpu_timestamps", generated.gpuTimestamps},
        {"checked_texels", check.texels},
        {"check_cpu_ms", check.cpuMs},
        {"judged_against", a.samples ? "same_sum" : "exact"},
        {"check",
         {{"max_bound", check.maxBound},
          {"max_error_over_bound", check.maxBoundRatio},
          {"worst_texel", {{"i", worstI}, {"j", worstJ}}},
          {"failures", check.failures},
          {"non_finite", check.nonFinite}}},
        {"vs_same_sum", a.samples ? nlohmann::json{{"channels", channelJson(check.sameSum)}} : nlohmann::json(nullptr)},
        {"vs_quadrature", {{"channels", channelJson(check.quadrature)}}},
        {"passed", ok}};
    std::cout << out.dump(2) << "\n";
  } else if (a.quiet && ok) {
    // -q: nothing on success; the exit code says it.
  } else {
    if (a.samples)
      std::printf("DFG LUT %ux%u, %u Hammersley samples per texel, on %s\n", a.size, a.size, a.samples,
                  gpu->deviceName().c_str());
    else
      std::printf("DFG LUT %ux%u, deterministic quadrature, on %s\n", a.size, a.size, gpu->deviceName().c_str());
    std::printf("compile %.1f ms; GPU %.1f ms (%s; warm-up dispatch %.1f ms)\n", generated.compileMs, generated.gpuMs,
                generated.gpuTimestamps ? "timestamps" : "host time, no timestamps", generated.warmupGpuMs);
    std::printf("checked %llu texels on the CPU in %.0f ms\n", static_cast<unsigned long long>(check.texels),
                check.cpuMs);
    if (a.samples) printChannels("vs CPU evaluation of the identical sum:", check.sameSum);
    std::printf("  max |error| / %s = %.3g at texel (i=%u, j=%u); %llu outside the bound, %llu NaN/Inf\n",
                a.samples ? "fp32 bound of the identical sum" : "promised accuracy vs the exact integrals",
                check.maxBoundRatio, worstI, worstJ, static_cast<unsigned long long>(check.failures),
                static_cast<unsigned long long>(check.nonFinite));
    printChannels(
        a.samples
            ? "vs the exact integrals (Monte-Carlo error of the sample count):"
            : "vs the exact integrals (judged: 1e-4 absolute in channels 0, 1; 1e-3 relative + 1e-7 in channel 2):",
        check.quadrature);
    if (!a.output.empty())
      std::printf("%s %s (%s, %s)\n", ok ? "wrote" : "NOT written:", a.output.c_str(), lut::formatName(format),
                  a.precision.c_str());
    std::printf("%s\n", ok ? "passed"
                           : (a.samples ? "FAILED: GPU LUT outside the fp32 bound of the identical sum"
                                        : "FAILED: GPU LUT outside its promised accuracy"));
  }
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addLutCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<LutArgs>();
  CLI::App* cmd = app.add_subcommand("lut", "Generate the split-sum DFG LUT on the GPU and check it against the CPU");
  cmd->add_option("--size", args->size, "Texels per side (default 128)")->check(CLI::Range(1u, lut::kMaxSize));
  cmd->add_option(
         "--samples", args->samples,
         "0 (default): deterministic quadrature; N > 0: Filament's Hammersley estimators with N samples per texel")
      ->check(CLI::Range(0u, lut::kMaxSamples));
  cmd->add_option("--format", args->precision, "Stored precision: fp32 (default) or fp16")
      ->check(CLI::IsMember({"fp32", "fp16"}));
  cmd->add_option("-o,--output", args->output, "Output file, written atomically (format from the extension)");
  cmd->add_option("--output-format", args->outputFormat, "raw, ktx2, csv or header (default: from the -o extension)")
      ->check(CLI::IsMember({"raw", "ktx2", "csv", "header"}));
  cmd->add_option(
      "--check-grid", args->checkGrid,
      "Texels per axis checked on the CPU (default 16, evenly spread, first and last included; 0 = every texel)");
  cmd->add_flag("--json", args->json, "JSON report");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress; without --json, print the report only when the check fails");
  return {cmd, [args, &g] { return runLut(*args, g); }};
}

}  // namespace mb::cli
