// write: the engine-ready package (docs/package.md): file names, deduplication by SPIR-V hash,
// and the parts of package_parts.hpp. Every output is a pure function of the inputs (no time,
// no host paths beyond those given, std::map-sorted JSON keys), so packages are byte-identical
// across runs and job counts.
#include "write/package_contents.hpp"

#include <algorithm>
#include <set>

#include "compile/reference_vertex.hpp"
#include "compile/targets.hpp"
#include "write/package_parts.hpp"

namespace mb {
namespace {

// One stage's files, one per target it was built for, at pathOf(target); written only when
// `fresh` (identical SPIR-V gives identical cross-compiled text: one file serves every
// permutation, and the first permutation of a hash always carries its code, build.hpp
// BuiltSink).
template <typename PathOf>
void addStageFiles(PackageWriter& pkg, const StageArtifacts& a, bool fresh, PathOf pathOf,
                   std::map<std::string, std::string>& files) {
  for (Target target : allTargets()) {
    const bool isSpirv = target == Target::Spirv;
    const std::string& name = targetName(target);
    auto text = a.targets.find(name);
    if (!isSpirv && text == a.targets.end()) continue;
    const std::string path = pathOf(target);
    files[name] = path;
    if (!fresh) continue;
    if (isSpirv)
      pkg.addFile(path, a.spirv);
    else
      pkg.addFile(path, text->second);
  }
}

}  // namespace

PackageStream::PackageStream(PackageWriter& pkg, const PackageInputs& in)
    : pkg_(pkg), in_(in), manifest_(new ManifestWriter(in)), header_(new HeaderWriter(in)) {}

PackageStream::~PackageStream() = default;

void PackageStream::add(const Permutation& perm, const BuiltPermutation& built) {
  PackagedPermutation p;
  p.perm = &perm;
  p.built = &built;
  const std::string& hash = built.spirvHash;
  if (!hash.empty()) {
    const bool fresh = written_.insert(hash).second;
    addStageFiles(
        pkg_, built.artifacts, fresh, [&](Target t) { return targetName(t) + "/" + hash + targetExtension(t); },
        p.files);
  }
  // The fragment shader (docs/fragment-stage.md), deduplicated by its own hash.
  if (!built.fragmentHash.empty()) {
    const bool freshFragment = written_.insert("fragment/" + built.fragmentHash).second;
    addStageFiles(
        pkg_, built.artifacts.fragment, freshFragment,
        [&](Target t) { return fragmentPath(targetName(t), built.fragmentHash); }, p.fragmentFiles);
  }
  p.include = "include/" + built.shader.key + ".glsl";
  pkg_.addFile(p.include, engineInclude(p));
  p.includes["glsl"] = p.include;
  for (const auto& [target, body] : built.artifacts.includes) {
    p.includes[target] = crossIncludePath(built.shader.key, target);
    pkg_.addFile(p.includes[target], crossInclude(p, target, body));
  }
  manifest_->add(p);
  header_->add(p);
}

void PackageStream::finish() {
  // WebGL 2.0 links a vertex and a fragment shader of one language: the webgl2 package ships the
  // reference vertex shader in ESSL 3.00, once for every permutation (compile/reference_vertex.hpp).
  if (in_.stages.fragment && std::find(in_.targets.begin(), in_.targets.end(), Target::Webgl2) != in_.targets.end())
    pkg_.addFile(kWebgl2VertexPath, referenceVertexShader(*in_.lib, Target::Webgl2));
  pkg_.addFileStreamed("manifest.json", [&](std::ostream& out) { manifest_->write(out); });
  pkg_.addFileStreamed(in_.headerName, [&](std::ostream& out) { header_->write(out); });
}

void addPackageFiles(PackageWriter& pkg, const PackageInputs& in) {
  PackageStream stream(pkg, in);
  for (size_t i = 0; i < in.built->size(); ++i) stream.add(in.plan->required[i], (*in.built)[i]);
  stream.finish();
}

}  // namespace mb
