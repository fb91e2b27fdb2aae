// matbricks report: a static HTML report of materials (or a scene's permutations), their
// errors, costs, the per-slot Pareto charts, the lobes' albedo and the DFG LUT, measured in
// this run (compiler/report/, docs/report.md). Written like a package: staged, then renamed
// into place, into a directory that is new, empty or one matbricks wrote.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>

#include "cli/cli_common.hpp"
#include "cli/progress.hpp"
#include "bench_engine/report.hpp"
#include "core/data_dir.hpp"
#include "load/scene_desc.hpp"
#include "permute/axes.hpp"
#include "permute/scene_plan.hpp"
#include "preview/environment.hpp"
#include "report/preview_renderer.hpp"
#include "report/report_html.hpp"
#include "report/report_run.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

namespace fs = std::filesystem;

struct ReportArgs {
  std::vector<std::string> materials;
  std::string scene;
  std::string out;
  std::vector<std::string> lights, environments;  // empty: all the model shades / supports
  bool noSlots = false, noEnergy = false, noLut = false, noCache = false, noPreviews = false, quiet = false,
       noLightMethods = false;
  uint32_t previewSize = 128;
  std::vector<std::string> previewEnvironments = preview::environmentNames();
  report::ReportOptions options;
};

// What a report of MATERIAL files shows: what `validate` runs for each.
std::vector<report::MaterialPermutations> materialPermutations(const std::vector<MaterialDesc>& materials,
                                                               const ShaderLibrary& lib, const ReportArgs& a) {
  std::vector<report::MaterialPermutations> out;
  for (const auto& m : materials) {
    report::MaterialPermutations mp{&m, {}, {}};
    mp.permutations = permutationsToValidate(m, lib, parseLightTypes(a.lights), parseEnvironmentModes(a.environments),
                                             Precision::Fp32, mp.notes);
    out.push_back(std::move(mp));
  }
  return out;
}

// A scene's required permutations, grouped by material in the plan's (key) order.
std::vector<report::MaterialPermutations> scenePermutations(const ScenePlan& plan) {
  std::vector<report::MaterialPermutations> out;
  std::map<std::string, size_t> index;
  for (const auto& perm : plan.required) {
    auto [it, added] = index.emplace(perm.material->name, out.size());
    if (added) out.push_back({perm.material, {}, {}});
    out[it->second].permutations.push_back(perm);
  }
  return out;
}

std::string commandLine(const ReportArgs& a) {
  std::string c = "matbricks report";
  if (!a.scene.empty()) c += " --scene " + a.scene;
  for (const auto& m : a.materials) c += " " + m;
  auto joined = [](const std::vector<std::string>& v) {
    std::string j;
    for (const auto& s : v) j += (j.empty() ? "" : ",") + s;
    return j;
  };
  if (!a.lights.empty()) c += " --lights " + joined(a.lights);
  if (!a.environments.empty()) c += " --environment " + joined(a.environments);
  const report::ReportOptions d;
  const report::ReportOptions& o = a.options;
  if (o.samples != d.samples) c += " --samples " + std::to_string(o.samples);
  if (o.slotSamples != d.slotSamples) c += " --slot-samples " + std::to_string(o.slotSamples);
  if (o.seed != d.seed) c += " --seed " + std::to_string(o.seed);
  if (o.cost.repeats != d.cost.repeats) c += " --repeats " + std::to_string(o.cost.repeats);
  if (o.cost.targetDispatchMs != d.cost.targetDispatchMs)
    c += " --target-ms " + bench::printfDouble("%g", o.cost.targetDispatchMs);
  for (const auto& s : o.slotFilter) c += " --slot " + s;
  if (a.noSlots) c += " --no-slots";
  if (a.noEnergy) c += " --no-energy";
  if (a.noPreviews) c += " --no-previews";
  if (a.previewSize != ReportArgs{}.previewSize) c += " --preview-size " + std::to_string(a.previewSize);
  if (a.noLightMethods) c += " --no-light-methods";
  if (a.noLut) c += " --no-lut";
  if (o.lutSize != d.lutSize) c += " --lut-size " + std::to_string(o.lutSize);
  if (a.noCache) c += " --no-cache";
  return c + " -o " + a.out;
}

int runReport(ReportArgs& a, const GlobalOptions& g) {
  if (!a.scene.empty() && !a.materials.empty())
    throw CLI::ValidationError("report takes MATERIAL files or --scene FILE, not both");
  ShaderLibrary lib = loadLibrary(g);
  std::vector<std::string> slotNames;
  for (const auto& s : lib.slots()) slotNames.push_back(s.name);
  checkKnownNames(a.options.slotFilter, slotNames, "E-UNKNOWN-SLOT", "slot");

  std::vector<std::string> paths = a.materials;
  if (a.scene.empty() && paths.empty()) {  // the shipped library
    for (const auto& e : fs::directory_iterator(dataRoot() / "materials"))
      if (e.path().extension() == ".json") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
  }
  std::vector<MaterialDesc> materials;
  SceneDesc scene;
  ScenePlan plan;
  std::vector<report::MaterialPermutations> groups;
  std::vector<const MaterialDesc*> read;
  if (!a.scene.empty()) {
    scene = loadScene(a.scene, lib);
    if (!scene.warnings.empty()) printDiagnostics(scene.warnings, g);
    plan = planScene(scene, lib);
    groups = scenePermutations(plan);
    for (const auto& m : scene.materials) read.push_back(&m.material);
  } else {
    materials = loadMaterials(paths, lib, g);
    groups = materialPermutations(materials, lib, a);
    for (const auto& m : materials) read.push_back(&m);
  }
  // The result cache is a folder of the compile cache's directory (the probe cache's, which
  // is ShaderCache::defaultDir()); --no-cache turns both off.
  if (a.noCache) setProbeCacheDir({});
  if (const fs::path cacheRoot = probeCacheDir(); !cacheRoot.empty()) a.options.resultCacheDir = cacheRoot / "results";
  std::vector<ProtectedPath> inputs = libraryInputs(lib);
  addMaterialInputs(inputs, read, a.scene);
  if (!a.options.resultCacheDir.empty()) inputs.push_back({a.options.resultCacheDir, "result cache directory"});
  checkDirectoryOutput(a.out, inputs);

  a.options.slots = !a.noSlots;
  a.options.energy = !a.noEnergy;
  a.options.lut = !a.noLut;
  a.options.lightMethods = !a.noLightMethods;
  if (!a.noPreviews) a.options.previews = report::makePreviewRenderer(lib, a.previewEnvironments, a.previewSize);
  auto gpu = openDevice(g);
  size_t units = groups.size();
  for (const auto& mp : groups) units += mp.permutations.size();
  Progress progress("report", units, a.quiet);
  report::ReportData data = report::runReport(lib, *gpu, groups, a.options, &progress);
  progress.finish();
  data.command = commandLine(a);
  data.layerMessages = reportLayerMessages(*gpu);

  // Everything is rendered in memory, then staged and renamed into place in one step.
  PackageWriter w("report");
  for (auto& [path, bytes] : report::renderReport(data)) w.addFile(path, std::move(bytes));
  w.commit(a.out);
  if (!a.quiet) std::cout << "report: " << (fs::path(a.out) / "index.html").string() << "\n";
  for (const auto& f : data.failures()) std::cerr << "error: " << f << "\n";
  return data.failures().empty() ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addReportCommand(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report", "A static HTML report: errors, costs, Pareto charts, albedo and the DFG LUT, measured on the device");
  cmd->add_option("materials", a->materials,
                  std::string(kMaterialFilesHelp) + " (default with no --scene: the shipped materials/*.json)");
  CLI::Option* scene =
      cmd->add_option("--scene", a->scene, std::string(kSceneFileHelp) + "; report exactly the permutations it needs");
  cmd->add_option("--lights", a->lights,
                  "Light types shaded together in each material permutation (default: all the model shades)")
      ->delimiter(',')
      ->check(CLI::IsMember(allLightTypeNames()))
      ->excludes(scene);
  cmd->add_option("--environment", a->environments,
                  "Environment modes, one permutation each (default: all the model supports)")
      ->delimiter(',')
      ->check(CLI::IsMember(allEnvironmentModeNames()))
      ->excludes(scene);
  cmd->add_option("-o,--output-dir", a->out, "Report directory (new, empty or a matbricks output); index.html inside")
      ->required();
  cmd->add_option("--samples", a->options.samples, "Validation and error samples per permutation and brick")
      ->check(CLI::Range(uint64_t{1}, uint64_t{10000000}));
  cmd->add_option("--slot-samples", a->options.slotSamples, "Error samples per brick of the slot charts (default 256)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{10000000}));
  cmd->add_option("--seed", a->options.seed, "Sampler seed");
  cmd->add_option("--repeats", a->options.cost.repeats,
                  "Timed dispatches per cost measurement (median and 95% interval; default 6)")
      ->check(CLI::Range(1u, 1000u));
  cmd->add_option("--target-ms", a->options.cost.targetDispatchMs, "Dispatch length the cost calibration aims at")
      ->check(CLI::Range(0.1, 10000.0));
  CLI::Option* slot =
      cmd->add_option("--slot", a->options.slotFilter,
                      "Pareto charts for this slot (repeatable; default: every slot the permutations' shaders call)");
  cmd->add_flag("--no-slots", a->noSlots, "No per-slot Pareto charts (the slowest part)")->excludes(slot);
  cmd->add_flag("--no-energy", a->noEnergy, "No albedo charts");
  cmd->add_flag("--no-lut", a->noLut, "No DFG LUT section");
  cmd->add_flag("--no-light-methods", a->noLightMethods,
                "No chart of the area lights' methods (run time against error per light shape and method)");
  cmd->add_flag("--no-previews", a->noPreviews, "No preview pictures (GPU, reference, difference)");
  cmd->add_option("--preview-size", a->previewSize, "Preview edge in pixels (default 128)")
      ->check(CLI::Range(16u, 1024u));
  cmd->add_option("--preview-environment", a->previewEnvironments,
                  "Environments the previews are lit by (default: studio,sky)")
      ->delimiter(',')
      ->check(CLI::IsMember(preview::environmentNames()));
  cmd->add_flag("-q,--quiet", a->quiet, "No progress and no path line on success");
  cmd->add_option("--lut-size", a->options.lutSize, "DFG LUT texels per side (default 64)")
      ->check(CLI::Range(2u, 1024u));
  cmd->add_flag("--no-cache", a->noCache,
                "Compile every probe and measure every cost, slot item and albedo (no probe cache, no result cache)");
  return {cmd, [a, &g] { return runReport(*a, g); }};
}

}  // namespace mb::cli
