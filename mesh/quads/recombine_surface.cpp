// recombineSurface (declared in recombine.h): the stages of one surface's recombination.
#include "mesh/quads/recombine.h"

namespace geomesh {

std::size_t recombineSurface(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em,
                             const RecombinationSettings& settings,
                             const std::vector<std::uint64_t>& keptEdges) {
  const bool blossom = settings.algorithm == RecombinationAlgorithm::Blossom;
  recombineTriangles(mesh, em, settings.algorithm, keptEdges);
  if (blossom) pairLeftoverTriangles(g, mesh, em, keptEdges);
  // One light pass before the quality cut and between the clean-up passes, the full
  // smoothing after: so the cut judges the quadrangles much as recombination made them.
  constexpr int early = 1;
  auto smooth = [&](int passes) {
    if (settings.repositionNodes) smoothMixedMesh(g, mesh, em, passes);
  };
  smooth(early);
  // Only the Blossom mesh is cleaned up, as in the reference.
  for (int pass = 0; blossom && pass < settings.topologyPasses; ++pass) {
    const std::size_t removed = removeTwoQuadNodes(mesh, em) + removeDiamonds(g, mesh, em);
    if (removed == 0) break;
    smooth(early);
  }
  splitPoorQuadrangles(mesh, em, settings.minQuality);
  smooth(settings.smoothingPasses);
  const ElementBlock* quads = em.findBlock(ElementType::Quad4);
  return quads ? quads->size() : 0;
}

}  // namespace geomesh
