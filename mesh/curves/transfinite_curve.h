// transfiniteFractions: where a Transfinite Curve's nodes go under Progression, Bump or Beta.
#pragma once

#include <vector>

#include "kernel/model.h"

namespace geomesh {

// Where a transfinite curve's nodes go: `law.nodes` fractions of the curve's length, from 0
// (its start) to 1 (its end), increasing.
//  Progression r: segment k is r^k times the first one.
//  Bump c: the nodes split evenly the integral of 1/h with h(s) = 1 + 4 (c - 1) (s - 1/2)^2,
//    a size c times smaller (c < 1) or larger (c > 1) at the ends than in the middle.
//  Beta b > 1: Roberts' stretching x(e) = ((b + 1) - (b - 1) q^(1 - e)) / (q^(1 - e) + 1),
//    q = (b + 1) / (b - 1), e evenly spaced: nodes packed towards the start.
// A reversed law is mirrored (x -> 1 - x). Invalid coefficients (r <= 0, c <= 0, b <= 1)
// give evenly spaced nodes.
std::vector<double> transfiniteFractions(const TransfiniteCurve& law);

}  // namespace geomesh
