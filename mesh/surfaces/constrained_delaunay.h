// recoverSegments and classifyInside: a constrained Delaunay triangulation and its domain.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/surfaces/delaunay2d.h"

namespace geomesh {

// An edge that must appear in the triangulation, between two inserted vertices.
struct ConstrainedSegment {
  std::uint32_t a = 0, b = 0;
  EdgeKind kind = EdgeKind::Boundary;
};

// Makes every segment an edge of the triangulation by flipping the edges it crosses (no vertex
// is added), marks it with its kind, then restores the constrained Delaunay property.
// Returns the index of the first segment that cannot be recovered (it passes through a
// vertex or crosses another segment), or -1 on success.
long recoverSegments(Triangulation2D& tri, std::span<const ConstrainedSegment> segments);

// Per triangle: 1 if it lies inside the domain (an odd number of boundary edges separate it
// from the enclosing vertices), else 0. Embedded edges do not change the side.
std::vector<std::uint8_t> classifyInside(const Triangulation2D& tri);

}  // namespace geomesh
