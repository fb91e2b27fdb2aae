// Facts about single bricks that the compiler acts on (docs/architecture.md "Adding a
// brick"): kept in the brick's own manifest entry so that a new brick brings them along
// instead of needing a C++ table beside it. Read here, checked once every slot is loaded.
#include "library/library_loader.hpp"

namespace mb {

// "fp16_twin": the brick an fp16 permutation binds instead of this one. Only a brick of the
// same slot can stand in (same signature, same role).
void LibraryLoader::readFp16Twin(JsonFields& f, const std::string& ptr, Brick& b) {
  if (!f.find(ptr)) return;
  auto twin = identifier(f, ptr, "fp16_twin");
  if (!twin) return;
  if (*twin == b.id) {
    f.error("E-INVALID-VALUE", f.valueAt(ptr), "brick '" + b.id + "' cannot be its own fp16_twin");
    return;
  }
  b.fp16Twin = *twin;
  brickReferences_.push_back({*twin, b.slot, "fp16_twin of '" + b.id + "'", f.valueAt(ptr)});
}

void LibraryLoader::checkBrickReferences() {
  for (const auto& r : brickReferences_) {
    const Brick* b = findLoadedBrick(r.id);
    if (b && b->slot == r.slot) continue;
    sink_.error("E-UNKNOWN-BRICK", r.at,
                r.what + " names '" + r.id + "', which is not a brick of slot '" + r.slot + "'",
                didYouMean(r.id, loadedBricksOf(r.slot)));
  }
}

}  // namespace mb
