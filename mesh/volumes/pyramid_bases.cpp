// addPyramids: each boundary quadrangle replaced by the side triangles of a pyramid on it.
#include "mesh/volumes/pyramid_bases.h"

#include <cmath>
#include <map>
#include <string>

#include "mesh/core/mesh_error.h"
#include "mesh/volumes/plc_containment.h"

namespace geomesh {

namespace {

// The complex's shells with each quadrangle as two triangles: what the parity test crosses.
VolumePlc closedShells(const VolumePlc& plc) {
  VolumePlc shells;
  shells.triangles.assign(plc.triangles.begin(),
                          plc.triangles.begin() + static_cast<std::ptrdiff_t>(plc.shellEnd));
  for (const auto& q : plc.quads) {
    shells.triangles.push_back({q[0], q[1], q[2]});
    shells.triangles.push_back({q[0], q[2], q[3]});
  }
  shells.shellEnd = shells.triangles.size();
  return shells;
}

}  // namespace

std::vector<Vec3> inwardNormals(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                int volumeTag) {
  std::vector<Vec3> normals;
  if (plc.quads.empty()) return normals;
  const VolumePlc shells = closedShells(plc);
  BoundingBox box;
  for (const PlcTriangle& t : shells.triangles)
    for (int k : t) box.include(xyz[k]);
  // A surface's elements all face along its normal: the exact test on its first quadrangle
  // gives the side of the volume for all of them.
  std::map<int, double> sideOfSurface;
  for (std::size_t i = 0; i < plc.quads.size(); ++i) {
    const auto& q = plc.quads[i];
    const Vec3 p[4] = {xyz[q[0]], xyz[q[1]], xyz[q[2]], xyz[q[3]]};
    const Vec3 normal = normalized(cross(p[2] - p[0], p[3] - p[1]));
    auto [side, first] = sideOfSurface.try_emplace(plc.quadSurfaceOf[i], 0.0);
    if (first) {
      // Just off the quadrangle on either side: exactly one lies in the volume.
      const Vec3 centre = (p[0] + p[1] + p[2] + p[3]) / 4;
      double edges = 0;
      for (int k = 0; k < 4; ++k) edges += distance(p[k], p[(k + 1) % 4]);
      const double probe = 5e-4 * edges / 4;
      const auto above = insideShells(centre + probe * normal, shells, xyz, box);
      const auto below = insideShells(centre - probe * normal, shells, xyz, box);
      if (!above || !below || *above == *below)
        throw MeshError({3, volumeTag}, "cannot tell on which side of a quadrangle of surface " +
                                            std::to_string(plc.quadSurfaceOf[i]) +
                                            " the volume lies");
      side->second = *above ? 1.0 : -1.0;
    }
    normals.push_back(side->second * normal);
  }
  return normals;
}

std::vector<Pyramid> addPyramids(VolumePlc& plc, std::vector<Vec3>& xyz,
                                 const std::vector<Vec3>& inward, double heightFactor) {
  if (plc.quads.empty()) return {};
  // Per shell, the side triangles to append after its own triangles.
  std::vector<std::vector<PlcTriangle>> sides(plc.shellStart.size());
  std::vector<std::vector<int>> sideSurfaces(plc.shellStart.size());
  std::vector<Pyramid> pyramids;
  for (std::size_t i = 0; i < plc.quads.size(); ++i) {
    const auto& q = plc.quads[i];
    const Vec3 p[4] = {xyz[q[0]], xyz[q[1]], xyz[q[2]], xyz[q[3]]};
    const Vec3 centre = (p[0] + p[1] + p[2] + p[3]) / 4;
    double edges = 0;
    for (int k = 0; k < 4; ++k) edges += distance(p[k], p[(k + 1) % 4]);
    const Vec3 apexAt = centre + heightFactor * edges / 4 * inward[i];
    const int local = static_cast<int>(plc.nodes.size());
    plc.nodes.push_back(kNoNode);
    xyz.push_back(apexAt);
    const std::size_t shell = plc.quadShellOf[i];
    for (int k = 0; k < 4; ++k) {
      sides[shell].push_back({q[k], q[(k + 1) % 4], local});
      sideSurfaces[shell].push_back(plc.quadSurfaceOf[i]);
    }
    Pyramid pyramid{q[0], q[1], q[2], q[3], local};
    if (dot(cross(p[1] - p[0], p[3] - p[0]), apexAt - p[0]) < 0) std::swap(pyramid[1], pyramid[3]);
    pyramids.push_back(pyramid);
  }

  // Rebuild the triangles shell by shell, the side triangles at the end of their shell's.
  std::vector<PlcTriangle> triangles;
  std::vector<int> surfaceOf;
  std::vector<std::size_t> shellStart;
  for (std::size_t s = 0; s < plc.shellStart.size(); ++s) {
    shellStart.push_back(triangles.size());
    for (std::size_t t = plc.shellStart[s]; t < plc.shellEndOf(s); ++t) {
      triangles.push_back(plc.triangles[t]);
      surfaceOf.push_back(plc.surfaceOf[t]);
    }
    triangles.insert(triangles.end(), sides[s].begin(), sides[s].end());
    surfaceOf.insert(surfaceOf.end(), sideSurfaces[s].begin(), sideSurfaces[s].end());
  }
  const std::size_t shellEnd = triangles.size();
  for (std::size_t t = plc.shellEnd; t < plc.triangles.size(); ++t) {
    triangles.push_back(plc.triangles[t]);
    surfaceOf.push_back(plc.surfaceOf[t]);
  }
  plc.triangles = std::move(triangles);
  plc.surfaceOf = std::move(surfaceOf);
  plc.shellStart = std::move(shellStart);
  plc.shellEnd = shellEnd;
  plc.quads.clear();
  plc.quadSurfaceOf.clear();
  plc.quadShellOf.clear();
  return pyramids;
}

}  // namespace geomesh
