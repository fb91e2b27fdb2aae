// Internal to compiler/library: the LibraryLoader that ShaderLibrary::load runs, declared
// here so that its reading of files, manifest, slots and bricks (library_loader.cpp) and of
// the shading models (library_models.cpp) can live in two files. Not part of the library's
// interface: everything else includes shader_library.hpp.
#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/input_file.hpp"
#include "core/json_fields.hpp"
#include "library/shader_library.hpp"

namespace mb {

// Everything load() collects before it is moved into a ShaderLibrary.
struct LibraryData {
  std::vector<Unit> units;
  std::vector<Slot> slots;
  std::vector<Brick> bricks;
  std::vector<ShadingModel> models;
  std::map<std::string, RoughnessKind> roughnessKinds;  // input name -> its kind (not None)
  std::map<std::string, std::string> sources;           // relative file -> text
  GltfDefaults gltfDefaults;
};

// The whole file (core/input_file.hpp, at most a library file's limit), or nullopt when it
// cannot be read, with the reason in `error` when given.
std::optional<std::string> readFile(const std::filesystem::path& path, InputFileError* error = nullptr);

// Loads the library's JSON files and checks them. Every problem goes to the sink; the
// caller throws once at the end, so one run reports all mistakes of a new brick.
class LibraryLoader {
 public:
  LibraryLoader(std::filesystem::path root, DiagnosticSink& sink) : root_(std::move(root)), sink_(sink) {}

  LibraryData run();

 private:
  // --- files (library_loader.cpp) -----------------------------------------------------
  std::string diskPath(const std::string& relative) const;
  std::optional<JsonDocument> loadJson(const std::string& relative, const SourceLocation& referencedFrom);
  std::optional<std::string> readGlsl(JsonFields& f, const std::string& ptr, const std::string& baseDir);

  // --- manifest (library_loader.cpp) --------------------------------------------------
  void checkSchema(JsonFields& f);
  void readUnits(JsonFields& f);
  template <class Fn>
  void forEachName(JsonFields& f, const std::string& ptr, const std::string& what, Fn fn);

  // --- shared field readers (library_loader.cpp) --------------------------------------
  std::optional<std::string> identifier(JsonFields& f, const std::string& ptr, const std::string& what);
  std::optional<std::string> nonEmpty(JsonFields& f, const std::string& ptr);
  std::optional<ValueType> valueType(JsonFields& f, const std::string& ptr, bool allowGeometry);
  std::optional<Range> range(JsonFields& f, const std::string& ptr);
  std::vector<std::string> requiredUnits(JsonFields& f, const std::string& ptr);

  // --- slots and bricks (library_loader.cpp) ------------------------------------------
  void readSlot(const std::string& folder, const SourceLocation& listedAt);
  std::vector<SlotParam> readSlotParams(JsonFields& f);
  void readBrick(JsonFields& f, const std::string& ptr, const Slot& slot);
  void readUnstableVariant(JsonFields& f, const std::string& ptr, const Slot& slot, Brick& b);
  std::optional<std::string> brickId(JsonFields& f, const std::string& ptr);
  std::map<std::string, Range> readDomain(JsonFields& f, const std::string& ptr, const Slot& slot);
  GeometryDomain readGeometry(JsonFields& f, const std::string& ptr, const Slot& slot);
  Tolerance readTolerance(JsonFields& f, const std::string& ptr);

  // --- brick facts the compiler looks up by brick (brick_facts.cpp) -------------------
  void readFp16Twin(JsonFields& f, const std::string& ptr, Brick& b);
  void readBrickEnergy(JsonFields& f, const std::string& brickPtr, const Slot& slot, Brick& b);
  void readDistributionEnergy(JsonFields& f, const std::string& ptr, Brick& b);
  std::optional<std::string> oneOf(JsonFields& f, const std::string& ptr, const std::vector<std::string>& allowed);
  void readKernelRoles(JsonFields& f, const std::string& ptr, const Slot& slot, Brick& b);
  // Kernel role -> the brick that took it first, and where.
  std::map<std::string, std::pair<std::string, SourceLocation>> kernelRoleHolders_;
  // Brick ids named by other bricks' facts, checked once every slot is read (a fact may
  // name a brick of a slot listed later).
  void checkBrickReferences();
  struct BrickReference {
    std::string id;     // the brick named
    std::string slot;   // the slot it must belong to
    std::string what;   // the fact, for messages ("fp16_twin of 'roughness_clamped'")
    SourceLocation at;  // where it is named
  };
  std::vector<BrickReference> brickReferences_;
  // V bricks named by a D brick's "energy"."visibility": each must be a V brick of `lobe`.
  struct EnergyPair {
    std::string visibility;
    std::string lobe;
    std::string what;
    SourceLocation at;
  };
  std::vector<EnergyPair> energyPairs_;
  // "roughness" of a float slot parameter or model input (RoughnessKind None when absent),
  // recorded for every one so that checkRoughnessKinds can hold inputs of one name to one kind.
  RoughnessKind readRoughnessKind(JsonFields& f, const std::string& inputPtr, const std::string& name,
                                  std::optional<ValueType> type);
  void checkRoughnessKinds();
  struct RoughnessDeclaration {
    std::string name;
    RoughnessKind kind;
    SourceLocation at;  // the "roughness" value, or the input's object where it has none
  };
  std::vector<RoughnessDeclaration> roughnessDeclarations_;

  // --- models (library_models.cpp) ----------------------------------------------------
  void readModel(const std::string& name, const SourceLocation& listedAt);
  std::optional<std::string> roleBinding(JsonFields& f, const std::string& ptr, const std::string& roleName,
                                         const ShadingModel& m, const std::string& what);
  std::map<std::string, std::map<std::string, std::string>> readQuality(JsonFields& f, const ShadingModel& m);
  std::vector<BrickRule> readIncompatible(JsonFields& f, const ShadingModel& m);
  std::vector<LightMethodChoice> readLightMethods(JsonFields& f, const ShadingModel& m);
  void checkRoleMethods(JsonFields& f, const ShadingModel& m);
  std::vector<std::string> namesFrom(JsonFields& f, const std::string& ptr, const std::vector<std::string>& allowed,
                                     const std::string& what);
  std::vector<ModelFeature> readFeatures(JsonFields& f);
  std::vector<std::string> featureNames(const ShadingModel& m) const;
  std::string featureRef(JsonFields& f, const std::string& ptr, const ShadingModel& m);
  std::vector<ModelRole> readRoles(JsonFields& f, const ShadingModel& m);
  const Brick* findLoadedBrick(const std::string& id) const;
  std::vector<std::string> loadedBricksOf(const std::string& slot) const;
  std::vector<ModelInput> readModelInputs(JsonFields& f, const ShadingModel& m);

  // --- glTF defaults (gltf_defaults.cpp) ----------------------------------------------
  void readGltfDefaults(JsonFields& manifest);
  std::vector<GltfBinding> readGltfBindings(JsonFields& f, const std::string& ptr, const ShadingModel& m,
                                            const std::string& feature);

  std::filesystem::path root_;
  DiagnosticSink& sink_;
  LibraryData data_;
  std::map<std::string, SourceLocation> brickIdLocations_;
};

}  // namespace mb
