// spatialOrder: a BRIO insertion order along a Hilbert curve for incremental Delaunay.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/vec3.h"

namespace geomesh {

// A biased randomized insertion order (BRIO) of the points, each round sorted along a Hilbert
// curve: consecutive points are close, so walking point location stays short, while the
// rounds keep incremental Delaunay insertion expected O(n log n). Deterministic.
std::vector<std::uint32_t> spatialOrder(std::span<const Vec2> points);
std::vector<std::uint32_t> spatialOrder(std::span<const Vec3> points);

}  // namespace geomesh
