// The report's per-lobe chart: directional albedo A(n.v) from energy's white furnace
// (energy/white_furnace.hpp), one line per perceptual roughness through the GPU integrals, the
// double reference's integrals as hollow markers on it, and the line A = 1 that an
// energy-conserving lobe stays under. Hand-written SVG like bench's Pareto charts
// (bench_engine/svg_chart.hpp, whose axis step and escaping it shares).
#pragma once
#include <string>

#include "energy/energy_grid.hpp"
#include "energy/white_furnace.hpp"

namespace mb::report {

std::string albedoSvg(const energy::LobeAlbedo& albedo, const energy::EnergyGrid& grid);

}  // namespace mb::report
