// Reference for energy_compensation_filament: the missing multiple-scattering energy scales
// the single-scattering lobe by 1 + F0 (1 - E) / E with E = Int Gv (Filament sec. 5.3.4.7;
// Turquin 2019, "Practical multiple scattering compensation for microfacet models", eq. 16).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 energyCompensationFilament(Vec3 f0, double E) { return splat(1.0) + f0 * ((1.0 - E) / E); }

MB_REFERENCE("energy_compensation_filament", energyCompensationFilament);

}  // namespace mb::ref
