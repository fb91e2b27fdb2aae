// write: the engine-ready package (docs/package.md): file names, deduplication by SPIR-V hash,
// and the parts of package_parts.hpp. Every output is a pure function of the inputs (no time,
// no host paths beyond those given, std::map-sorted JSON keys), so packages are byte-identical
// across runs and job counts.
#include "write/package_contents.hpp"

#include <set>

#include "compile/targets.hpp"
#include "write/package_parts.hpp"

namespace mb {

void addPackageFiles(PackageWriter& pkg, const PackageInputs& in) {
  std::vector<PackagedPermutation> perms;
  std::set<std::string> written;  // SPIR-V hashes whose files are already added
  for (size_t i = 0; i < in.built->size(); ++i) {
    PackagedPermutation p;
    p.perm = &in.plan->required[i];
    p.built = &(*in.built)[i];
    const std::string& hash = p.built->spirvHash;
    const bool fresh = written.insert(hash).second;
    for (const auto& target : allTargets()) {
      const bool isSpirv = target == "spirv";
      auto text = p.built->artifacts.targets.find(target);
      if (!isSpirv && text == p.built->artifacts.targets.end()) continue;
      std::string path = target + "/" + hash + targetExtension(target);
      p.files[target] = path;
      // Identical SPIR-V gives identical cross-compiled text: one file serves every permutation.
      if (!fresh) continue;
      if (isSpirv)
        pkg.addFile(path, p.built->artifacts.spirv);
      else
        pkg.addFile(path, text->second);
    }
    p.include = "include/" + p.built->shader.key + ".glsl";
    pkg.addFile(p.include, engineInclude(p));
    perms.push_back(std::move(p));
  }
  pkg.addFile("manifest.json", packageManifest(in, perms).dump(2) + "\n");
  pkg.addFile(in.headerName, packageHeader(in, perms));
}

}  // namespace mb
