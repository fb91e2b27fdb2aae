// Reference for v_kelemen: Kelemen & Szirmay-Kalos 2001, G / (n.l n.v) ~ 1 / (l.h)^2, so
// V = G / (4 n.l n.v) = 1 / (4 (l.h)^2). Ground truth: exact height-correlated Smith-GGX (the
// visibility it stands in for in Filament's clear coat).
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double vKelemen(Geometry g, double) { return 1.0 / (4.0 * g.LoH * g.LoH); }

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_kelemen", vKelemen);
MB_GROUND_TRUTH("v_kelemen", exactCorrelated);

}  // namespace mb::ref
