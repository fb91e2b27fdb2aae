#include "energy/white_furnace.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace mb::energy {
namespace {

// The quadrature nodes of one family (lobes sharing a D brick) over every grid cell.
struct FamilyNodes {
  std::vector<AlbedoNode> nodes;
  std::vector<uint32_t> cellOf;
};

FamilyNodes familyNodes(const Lobe& lobe, const std::vector<GridCell>& cells, const QuadratureResolution& res) {
  FamilyNodes f;
  for (uint32_t c = 0; c < cells.size(); ++c) {
    HalfVectorMap map(lobe.map, mapAlpha(lobe, cells[c].inputs));
    for (const AlbedoNode& n : albedoNodes(ref::normalize(cells[c].inputs.v), map, res)) {
      f.nodes.push_back(n);
      f.cellOf.push_back(c);
    }
  }
  return f;
}

// A_ref at another resolution, references only.
double referenceAlbedo(const Lobe& lobe, ProbeCache& probes, const GridCell& cell, const QuadratureResolution& res) {
  std::vector<const ProbeProgram*> programs;
  for (const Brick* b : lobe.factors) programs.push_back(&probes.get(*b));
  HalfVectorMap map(lobe.map, mapAlpha(lobe, cell.inputs));
  double sum = 0.0;
  ProbeInputs in = cell.inputs;
  for (const AlbedoNode& n : albedoNodes(ref::normalize(cell.inputs.v), map, res)) {
    in.l = n.l;
    double f = 1.0;
    for (const ProbeProgram* p : programs) f *= referenceAt(*p, in);
    sum += n.weight * f;
  }
  return sum;
}

}  // namespace

const AlbedoCell& LobeAlbedo::maxCell() const {
  return *std::max_element(cells.begin(), cells.end(),
                           [](const AlbedoCell& a, const AlbedoCell& b) { return a.gpu < b.gpu; });
}

double LobeAlbedo::maxMismatchRatio() const {
  double m = 0.0;
  for (const auto& c : cells) m = std::max(m, std::abs(c.gpu - c.reference) / std::max(c.bound, 1e-300));
  return m;
}

double LobeAlbedo::maxConvergence() const {
  double m = 0.0;
  for (const auto& c : cells) m = std::max(m, c.convergence);
  return m;
}

bool LobeAlbedo::gpuMatchesReference() const { return outsideTolerance == 0 && maxMismatchRatio() <= 1.0; }

bool LobeAlbedo::exceedsOne() const {
  for (const auto& c : cells)
    if (c.gpu - 1.0 > c.bound + 2.0 * c.convergence) return true;
  return false;
}

std::vector<LobeAlbedo> whiteFurnace(harness::VulkanHarness& gpu, ProbeCache& probes, const std::vector<Lobe>& lobes,
                                     const EnergyGrid& grid, ProgressSink* progress) {
  const std::vector<GridCell> cells = gridCells(grid);
  std::map<std::string, std::vector<size_t>> families;
  for (size_t i = 0; i < lobes.size(); ++i) families[lobes[i].familyKey()].push_back(i);

  std::vector<LobeAlbedo> out(lobes.size());
  for (const auto& [key, members] : families) {
    FamilyNodes fam = familyNodes(lobes[members.front()], cells, grid.resolution);
    auto recordAt = [&](size_t i) {
      ProbeInputs in = cells[fam.cellOf[i]].inputs;
      in.l = fam.nodes[i].l;
      return in;
    };
    // The family's shared brick (its D) runs once and is kept; the others (the V of each
    // lobe) run per lobe and are dropped after it, which bounds memory to two bricks' values.
    const std::string shared = lobes[members.front()].factors.front()->id;
    std::map<std::string, BrickValues> values;
    auto valuesOf = [&](const Brick* b) -> const BrickValues& {
      auto it = values.find(b->id);
      if (it == values.end())
        it = values.emplace(b->id, sweepBrick(gpu, probes.get(*b), fam.nodes.size(), recordAt)).first;
      return it->second;
    };

    for (size_t li : members) {
      const Lobe& lobe = lobes[li];
      LobeAlbedo& r = out[li];
      r.lobe = &lobe;
      r.nodes = fam.nodes.size();
      r.cells.resize(cells.size());
      std::vector<const BrickValues*> factors;
      for (const Brick* b : lobe.factors) {
        factors.push_back(&valuesOf(b));
        r.gpuMs += factors.back()->gpuMs;
      }
      for (size_t i = 0; i < fam.nodes.size(); ++i) {
        double g = 1.0, ref = 1.0;
        bool outside = false;
        for (const BrickValues* f : factors) {
          g *= f->gpu[i];
          ref *= f->reference[i];
          outside |= !(std::abs(f->gpu[i] - f->reference[i]) <= f->tolerance[i]);
        }
        r.outsideTolerance += outside;
        AlbedoCell& c = r.cells[fam.cellOf[i]];
        double w = fam.nodes[i].weight;
        c.gpu += w * g;
        c.reference += w * ref;
        c.bound += w * productBound(factors, i);
      }
      for (size_t c = 0; c < cells.size(); ++c) {
        r.cells[c].NoV = cells[c].NoV;
        r.cells[c].perceptualRoughness = cells[c].perceptualRoughness;
        double coarser = referenceAlbedo(lobe, probes, cells[c], grid.resolution.halved());
        r.cells[c].convergence = std::abs(r.cells[c].reference - coarser);
      }
      std::erase_if(values, [&](const auto& kv) { return kv.first != shared; });
      if (progress) progress->advance();
    }
  }
  return out;
}

}  // namespace mb::energy
