// surfaceTopologyLines: surfaceTopology on each connected part.
#include "app/surface_check.h"

#include <sstream>

#include "mesh/discrete/mesh_triangles.h"
#include "mesh/discrete/self_intersections.h"
#include "mesh/discrete/surface_topology.h"

namespace geomesh {

std::vector<std::string> surfaceTopologyLines(const Triangulation& t) {
  if (t.triangles.empty()) return {"Check: no surface triangles"};
  const std::vector<Triangulation> parts = connectedParts(t);
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const SurfaceTopologyReport r = surfaceTopology(parts[k]);
    lines.push_back("Check: surface part " + std::to_string(k + 1) + " of " +
                    std::to_string(parts.size()) + ": " + std::to_string(r.triangles) +
                    " triangles, Euler characteristic " + std::to_string(r.euler) + ", genus " +
                    std::to_string(r.genus) + ", " + std::to_string(r.boundaryLoops) +
                    " boundary loops, " + std::to_string(r.nonManifoldEdges) +
                    " non-manifold edges, " + std::to_string(r.inconsistentEdges) +
                    " inconsistently oriented edges");
  }
  const SelfIntersections crossing = selfIntersections(t, 1);
  if (crossing.count > 0) {
    const Vec3 p = crossing.points.front();
    std::ostringstream line;
    line << "Check: " << crossing.count
         << " pairs of surface triangles cross each other (sharing no node), the first at (" << p.x
         << ", " << p.y << ", " << p.z << ")";
    lines.push_back(line.str());
  }
  return lines;
}

}  // namespace geomesh
