#include "report/preview_renderer.hpp"

#include <cstdio>
#include <map>
#include <memory>

#include "core/diagnostics.hpp"
#include "preview/preview.hpp"

namespace mb::report {

PreviewRenderer makePreviewRenderer(const ShaderLibrary& lib, std::vector<std::string> environments, uint32_t size) {
  // Shared by the copies of the returned function: one build of each environment per report.
  auto prepared = std::make_shared<std::map<std::string, preview::PreviewEnvironment>>();
  return [&lib, environments = std::move(environments), size, prepared](const MaterialDesc& material,
                                                                        harness::VulkanHarness& gpu) {
    PreviewSet set;
    preview::PreviewOptions options;
    options.size = size;
    try {
      preview::checkPreviewOptions(lib, {&material}, options);
    } catch (const DiagnosticError& e) {
      set.text = "No preview: " + (e.diagnostics().empty() ? std::string("refused") : e.diagnostics().front().message);
      return set;
    }
    for (const auto& name : environments) {
      auto it = prepared->find(name);
      if (it == prepared->end()) it = prepared->emplace(name, preview::prepareEnvironment(gpu, lib, name)).first;
      preview::PreviewResult r = preview::renderPreview(gpu, lib, material, options, it->second);
      set.images.push_back({"GPU, " + name, preview::encodePng(r.gpuImage)});
      set.images.push_back({"reference, " + name, preview::encodePng(r.referenceImage)});
      set.images.push_back({"difference, " + name, preview::encodePng(r.diffImage)});
      char line[320];
      std::snprintf(line, sizeof line,
                    "%s (%s, %ux%u): %llu pixels, max error / tolerance %.3g, max |GPU - reference| per channel "
                    "%.3g %.3g %.3g, %s. ",
                    r.key.c_str(), name.c_str(), r.width, r.height, static_cast<unsigned long long>(r.coveredPixels),
                    r.maxErrorRatio, r.channels[0].maxAbs, r.channels[1].maxAbs, r.channels[2].maxAbs,
                    r.passed() ? "every pixel within tolerance" : "OUTSIDE the tolerance");
      set.text += line;
      set.failed = set.failed || !r.passed();
    }
    return set;
  };
}

}  // namespace mb::report
