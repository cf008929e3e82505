// generateMesh: the 0D to 3D stages, surface algorithm choice, recombination, timing lines.
#include "mesh/pipeline/generate.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <vector>
#include <chrono>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <cstdio>
#include <string>

#include "mesh/curves/curve_mesher.h"
#include "mesh/pipeline/compound.h"
#include "mesh/pipeline/discrete_copy.h"
#include "mesh/high_order/set_order.h"
#include "mesh/structured/extrusion_mesher.h"
#include "mesh/structured/meshing_order.h"
#include "mesh/sizes/size_field.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/checks/touching_volumes.h"
#include "mesh/structured/periodic.h"
#include "mesh/structured/transfinite_volume.h"
#include "mesh/quads/recombine.h"
#include "mesh/sizes/size_rules.h"
#include "mesh/quads/subdivision.h"
#include "mesh/surfaces/surface_algorithms.h"
#include "mesh/surfaces/surface_mesher.h"
#include "mesh/structured/transfinite_surface.h"
#include "mesh/volumes/volume_algorithms.h"
#include "mesh/volumes/volume_mesher.h"

namespace geomesh {
namespace {

std::string stageName(int dim) { return "Meshing " + std::to_string(dim) + "D"; }

// Times one stage; done() reports "Meshing <dim>D... done (<seconds> s, <count> <elements>)".
class StageTimer {
 public:
  explicit StageTimer(int dim) : dim_(dim), start_(std::chrono::steady_clock::now()) {}
  void done(MessageSink& log, std::size_t count, const char* what) const {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    log.progress(stageName(dim_), 1);
    char line[128];
    std::snprintf(line, sizeof line, "Meshing %dD... done (%.3g s, %zu %s)", dim_, seconds, count,
                  what);
    log.info(line);
  }

 private:
  int dim_;
  std::chrono::steady_clock::time_point start_;
};

// The progress of a stage made of parts (surfaces, volumes), each from 0 to 1, given to the
// log as their mean. Parts may report from several threads at once.
class StageProgress {
 public:
  StageProgress(MessageSink& log, int dim, std::size_t parts)
      : log_(log), stage_(stageName(dim)), done_(std::max<std::size_t>(parts, 1), 0.0) {}
  void set(std::size_t part, double fraction) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (part >= done_.size()) return;
    sum_ += fraction - done_[part];
    done_[part] = fraction;
    log_.progress(stage_, std::clamp(sum_ / static_cast<double>(done_.size()), 0.0, 1.0));
  }

 private:
  MessageSink& log_;
  std::string stage_;
  std::vector<double> done_;
  double sum_ = 0;
  std::mutex mutex_;
};

void meshPoints(const Model& model, const SizeRules& rules, const SizeFields& fields,
                Mesh& mesh) {
  for (const auto& [tag, point] : model.points()) {
    if (mesh.find({0, tag})) continue;  // a corner of a merged triangulation, copied
    const NodeIndex node = mesh.addNode(point.xyz);
    const double field = fields.at(point.xyz, {0, tag});
    mesh.setNodeSize(node, rules.finish(std::min(rules.pointSize(point), field)));
    EntityMesh& em = mesh.entity({0, tag});
    em.nodes.push_back(node);
    em.block(ElementType::Point1).nodes.push_back(node);
  }
}

bool hasMesh(const Mesh& mesh, EntityId id) {
  const EntityMesh* em = mesh.find(id);
  return em && em->elementCount() > 0;
}

// Curves in meshingOrder: sweeps and copies after what they copy. The curves of boundary
// layers grown from surfaces wait for them (`layers`: those whose surfaces are meshed now and
// that have no mesh yet, else all the curves that do not wait).
void meshCurves(const Model& model, const SizeRules& rules, const SizeFields& fields,
                const post::ViewStore* views, Mesh& mesh, bool layers = false) {
  const std::map<int, Periodicity> links = periodicCurves(model);
  const ExtrusionMesher extruded(model, views);
  const PeriodicCopier periodic(model);
  std::vector<int> followers;  // curves that end where a boundary layer moves their ends
  for (const PlannedEntity& p : meshingOrder(model, 1, links)) {
    const EntityId id{1, p.tag};
    if (extruded.waitsForSurfaces(id) != layers || model.curve(p.tag)->discrete) continue;
    if (layers && (hasMesh(mesh, id) || !extruded.layerReady(id, mesh))) continue;
    if (p.method == MeshingMethod::Own && extruded.touchesLayer(id))
      followers.push_back(p.tag);
    else if (p.method == MeshingMethod::Own)
      meshCurve(model, *model.curve(p.tag), rules, mesh, &fields);
    else if (p.method == MeshingMethod::Swept)
      extruded.meshSwept(id, mesh);
    else if (p.method == MeshingMethod::ExtrusionImage)
      extruded.meshImage(id, mesh);
    else
      periodic.copyCurve(p.tag, links.at(p.tag), mesh);
  }
  for (int tag : followers) {
    meshCurve(model, *model.curve(tag), rules, mesh, &fields);
    extruded.followLayerEnds({1, tag}, mesh);
  }
  if (!layers) periodic.linkEndPoints(links, mesh);
}

// Recombine Surface{t} = angle, else Mesh.RecombineAll with the default angle; nullopt: none.
std::optional<double> recombinationAngle(const Model& model, const MeshOptions& options,
                                         int tag) {
  constexpr double kDefaultAngle = 45;
  const auto& recombined = model.meshConstraints().recombinedSurfaces;
  if (const auto it = recombined.find(tag); it != recombined.end()) return it->second;
  if (options.recombineAll) return kDefaultAngle;
  return std::nullopt;
}

// Edges recombination must keep: those of the curves embedded in a surface, and of its seams
// (a curve its loops use twice, once from each side: a periodic surface's seam, whose two
// sides are one edge in space but far apart in the parameter plane).
std::vector<std::uint64_t> edgesToKeep(const ModelSurface& surface, const Mesh& mesh) {
  std::vector<int> curves = surface.embeddedCurves;
  std::vector<int> bounding;
  for (const std::vector<int>& loop : surface.loops)
    for (int c : loop) bounding.push_back(std::abs(c));
  std::sort(bounding.begin(), bounding.end());
  for (std::size_t k = 1; k < bounding.size(); ++k)
    if (bounding[k] == bounding[k - 1]) curves.push_back(bounding[k]);
  std::vector<std::uint64_t> keys;
  for (int curve : curves)
    if (const EntityMesh* em = mesh.find({1, std::abs(curve)}))
      if (const ElementBlock* lines = em->findBlock(ElementType::Line2))
        for (std::size_t e = 0; e < lines->size(); ++e)
          keys.push_back(edgeKey(lines->element(e)[0], lines->element(e)[1]));
  std::sort(keys.begin(), keys.end());
  return keys;
}

// The part of a surface's mesh beyond its boundary layer (EntityMesh::layer): its own
// nodes and elements, taken out of `em`, which keeps the layer's.
EntityMesh restBeyondLayer(EntityMesh& em) {
  const EntityMesh::LayerPart part = *em.layer;
  EntityMesh rest;
  rest.entity = em.entity;
  rest.nodes.assign(em.nodes.begin() + static_cast<std::ptrdiff_t>(part.nodes), em.nodes.end());
  em.nodes.resize(part.nodes);
  if (em.parametric.size() >= 2 * part.nodes) {
    rest.parametric.assign(em.parametric.begin() + static_cast<std::ptrdiff_t>(2 * part.nodes),
                           em.parametric.end());
    em.parametric.resize(2 * part.nodes);
  }
  for (ElementBlock& block : em.blocks) {
    const std::size_t kept = block.type == ElementType::Triangle3 ? part.triangles
                             : block.type == ElementType::Quad4   ? part.quadrangles
                                                                  : block.size();
    const std::size_t split = kept * nodeCount(block.type);
    ElementBlock& moved = rest.block(block.type);
    moved.nodes.assign(block.nodes.begin() + static_cast<std::ptrdiff_t>(split), block.nodes.end());
    block.nodes.resize(split);
  }
  return rest;
}

// Puts the rest of a surface's mesh back after its boundary layer's, in that order.
void joinLayerAndRest(EntityMesh& em, EntityMesh rest) {
  em.nodes.insert(em.nodes.end(), rest.nodes.begin(), rest.nodes.end());
  em.parametric.insert(em.parametric.end(), rest.parametric.begin(), rest.parametric.end());
  for (const ElementBlock& block : rest.blocks) {
    ElementBlock& into = em.block(block.type);
    into.nodes.insert(into.nodes.end(), block.nodes.begin(), block.nodes.end());
  }
  std::erase_if(em.blocks, [](const ElementBlock& b) { return b.nodes.empty(); });
}

// What the 2D stage reads.
struct SurfaceStage {
  const Model& model;
  const MeshOptions& options;
  const SizeRules& rules;
  const SizeFields& fields;
  int dim;  // of the whole run
  MessageSink& log;
};

// A recombined surface keeps its quadrangles whatever volumes it bounds: a tetrahedral
// volume stands pyramids on them (see addPyramids), as the reference does.
std::optional<double> surfaceRecombination(const SurfaceStage& stage, int tag) {
  std::optional<double> angle = recombinationAngle(stage.model, stage.options, tag);
  return angle;
}

// MeshAlgorithm Surface{t} = n, else Mesh.Algorithm; what is not available falls back (the
// global option's warning is given once by meshSurfaces).
const SurfaceAlgorithm& surfaceAlgorithm(const SurfaceStage& stage, const ModelSurface& surface) {
  const auto& chosen = stage.model.meshConstraints().surfaceAlgorithms;
  const auto it = chosen.find(surface.tag);
  if (it == chosen.end()) return surfaceAlgorithmFor(stage.options.algorithm2D);
  const std::string why = whyUnavailable(it->second);
  if (!why.empty())
    stage.log.warning("MeshAlgorithm of surface " + std::to_string(surface.tag) + ": " + why +
                      "; meshed with " + fallbackText(it->second));
  return surfaceAlgorithmFor(it->second);
}

void meshOneSurface(const SurfaceStage& stage, const ModelSurface& surface, Mesh& mesh) {
  const Model& model = stage.model;
  const MeshOptions& options = stage.options;
  const std::optional<double> angle = surfaceRecombination(stage, surface.tag);
  const auto& transfinite = model.meshConstraints().transfiniteSurfaces;
  if (const auto it = transfinite.find(surface.tag); it != transfinite.end()) {
    try {
      meshTransfiniteSurface(model, surface, it->second, angle.has_value(), mesh);
      return;
    } catch (const TransfiniteSidesMismatch& mismatch) {
      stage.log.warning(entityName(mismatch.entity) + " is meshed as if not transfinite: " +
                        mismatch.reason);
    }
  }
  meshSurface(model, surface, stage.rules, options.smoothing, mesh, &stage.fields,
              surfaceAlgorithm(stage, surface), {options.anisoMax, options.smoothRatio});
  if (!angle || !surface.geometry) return;
  EntityMesh& em = mesh.entity({2, surface.tag});
  const bool simple = options.recombinationAlgorithm == 0 || options.recombinationAlgorithm == 2;
  RecombinationSettings settings;
  settings.algorithm = simple ? RecombinationAlgorithm::Simple : RecombinationAlgorithm::Blossom;
  settings.minQuality = options.recombineMinQuality;
  settings.topologyPasses = options.recombineOptimizeTopology;
  settings.repositionNodes = options.recombineNodeRepositioning;
  settings.smoothingPasses = std::max(options.smoothing, 1) * 3;
  if (!em.layer) {
    recombineSurface(*surface.geometry, mesh, em, settings, edgesToKeep(surface, mesh));
    return;
  }
  // A boundary layer stays as it was built: only the rest of the surface is recombined, its
  // nodes on the layer's fronts held still.
  EntityMesh rest = restBeyondLayer(em);
  recombineSurface(*surface.geometry, mesh, rest, settings, edgesToKeep(surface, mesh));
  joinLayerAndRest(em, std::move(rest));
}

// Mesh.RecombinationAlgorithm 2 and 3: simple or blossom, then split into quadrangles.
bool isFullQuad(const MeshOptions& options) {
  return options.recombinationAlgorithm == 2 || options.recombinationAlgorithm == 3;
}

bool wantsAllQuadrangles(const Model& model, const MeshOptions& options) {
  if (options.subdivisionAlgorithm == 1) return true;
  if (!isFullQuad(options)) return false;
  return options.recombineAll || !model.meshConstraints().recombinedSurfaces.empty();
}

void meshSurfaces(const SurfaceStage& stage, Mesh& mesh) {
  const Model& model = stage.model;
  const MeshOptions& options = stage.options;
  MessageSink& log = stage.log;
  const auto& chosen = model.meshConstraints().surfaceAlgorithms;
  const bool anyByOption =
      std::any_of(model.surfaces().begin(), model.surfaces().end(),
                  [&](const auto& entry) { return !chosen.contains(entry.first); });
  const std::string why = whyUnavailable(options.algorithm2D);
  if (!why.empty() && anyByOption)
    log.warning("Mesh.Algorithm " + why + ": surfaces are meshed with " +
                fallbackText(options.algorithm2D));
  if (options.subdivisionAlgorithm == 3)
    log.warning("Mesh.SubdivisionAlgorithm " + std::to_string(options.subdivisionAlgorithm) +
                " is not available; elements are not split");
  const ExtrusionMesher extruded(model, options.views);
  const PeriodicCopier periodic(model);
  // Boundary layers grown from surfaces (their curves too) come once those surfaces are meshed.
  std::vector<PlannedEntity> layers;
  StageProgress progress(log, 2, model.surfaces().size());
  std::size_t meshed = 0;
  auto meshPlanned = [&](const PlannedEntity& p) {
    const EntityId id{2, p.tag};
    if (p.method == MeshingMethod::Own)
      meshOneSurface(stage, *model.surface(p.tag), mesh);
    else if (p.method == MeshingMethod::Swept)
      extruded.meshSwept(id, mesh);
    else if (p.method == MeshingMethod::ExtrusionImage)
      extruded.meshImage(id, mesh);
    else
      periodic.copySurface(p.tag, mesh);
    progress.set(meshed++, 1);
  };
  for (const PlannedEntity& p : meshingOrder(model, 2, {})) {
    if (model.surface(p.tag)->discrete) continue;  // copied from the merged file
    if (extruded.waitsForSurfaces({2, p.tag}))
      layers.push_back(p);
    else
      meshPlanned(p);
  }
  // In rounds: a layer grown from the top of another layer comes a round after it.
  while (!layers.empty()) {
    meshCurves(model, stage.rules, stage.fields, options.views, mesh, true);
    std::vector<PlannedEntity> waiting;
    for (const PlannedEntity& p : layers) {
      if (extruded.layerReady({2, p.tag}, mesh))
        meshPlanned(p);
      else
        waiting.push_back(p);
    }
    if (waiting.size() == layers.size()) {
      // Nothing could be meshed: the first one is meshed as it is, and names what it lacks.
      meshPlanned(waiting.front());
      waiting.erase(waiting.begin());
    }
    layers = std::move(waiting);
  }
  for (const std::string& line : extruded.layerWarnings()) log.warning(line);
  mesh.dropUnheldNodes();  // the nodes recombination took out
  const MeshCheckReport report = checkMesh(model, mesh);
  for (const MeshProblem& problem : report.problems)
    if (problem.entity.dim == 2) throw MeshError(problem.entity, problem.message);
}

bool hasQuadrangles(const Mesh& mesh) {
  for (const auto& entry : mesh.entities())
    if (entry.first.dim == 2 && entry.second.findBlock(ElementType::Quad4)) return true;
  return false;
}

bool hasOnlyTetrahedra(const Mesh& mesh) {
  for (const auto& entry : mesh.entities())
    for (const ElementBlock& block : entry.second.blocks)
      if (dimension(block.type) == 3 && block.type != ElementType::Tet4) return false;
  return true;
}

}  // namespace

namespace {

// Meshes the volumes with tetrahedra: each one planned on one of up to General.NumThreads
// threads, then added to the mesh in the order of their tags, so that the mesh is the same,
// byte for byte, for any number of threads. The size fields are evaluated under a lock (they
// are not made to be read by several threads at once). The first volume in that order that
// fails stops the meshing there, as it would on one thread.
void meshTetrahedralVolumes(const Model& model, const MeshOptions& options,
                            const std::vector<int>& tags, const SizeFields& fields, Mesh& mesh,
                            MessageSink& log) {
  StageProgress progress(log, 3, tags.size());
  const std::size_t threads =
      std::clamp<std::size_t>(options.numThreads > 0 ? options.numThreads : 1, 1, tags.size());
  std::vector<VolumeMeshing> planned(tags.size());
  std::vector<std::exception_ptr> failed(tags.size());
  std::mutex fieldLock;
  std::atomic<std::size_t> next{0};
  auto plan = [&] {
    for (std::size_t i = next++; i < tags.size(); i = next++) {
      try {
        InteriorSize interiorSize;
        if (fields.hasBackground())
          interiorSize = [&fields, &fieldLock, where = EntityId{3, tags[i]}](Vec3 p) {
            const std::lock_guard<std::mutex> lock(fieldLock);
            return fields.at(p, where);
          };
        const VolumeProgress report = [&progress, i](double f) { progress.set(i, f); };
        planned[i] = planVolumeMesh(model, options, tags[i], interiorSize, mesh, report);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(plan);
  plan();
  for (std::thread& t : pool) t.join();
  for (std::size_t i = 0; i < tags.size(); ++i) {
    if (failed[i]) std::rethrow_exception(failed[i]);
    commitVolumeMesh(model, std::move(planned[i]), mesh);
  }
}

}  // namespace

namespace {

// The stages from points to volumes, with the background sizes `fields`.
void meshStages(const Model& model, const MeshOptions& options, int dim,
                const SizeFields& fields, Mesh& mesh, MessageSink& log) {
  if (options.discreteMesh && dim >= 1)
    copyDiscreteEntities(model, *options.discreteMesh, dim, mesh);
  SizeRules rules = SizeRules::from(model, options);
  // Full-quad recombination (of every surface, or of those asked for) meshes twice as coarse,
  // then splits each element into quadrangles, which halves the sizes back.
  if (isFullQuad(options) && wantsAllQuadrangles(model, options) && dim >= 2) rules.factor *= 2;
  meshPoints(model, rules, fields, mesh);
  if (dim >= 1) {
    const StageTimer timer(1);
    meshCurves(model, rules, fields, options.views, mesh);
    timer.done(log, mesh.elementCount(1), "lines");
  }
  if (dim >= 2) {
    const StageTimer timer(2);
    meshSurfaces({model, options, rules, fields, dim, log}, mesh);
    if (wantsAllQuadrangles(model, options)) {
      if (dim == 2 || model.volumes().empty())
        subdivideIntoQuadrangles(model, mesh);
      else
        log.warning("splitting into quadrangles is only done for 2D meshes; ignored");
    }
    timer.done(log, mesh.elementCount(2), hasQuadrangles(mesh) ? "elements" : "triangles");
  }
  if (dim >= 3) {
    const StageTimer timer(3);
    const ExtrusionMesher extruded(model, options.views);
    if (options.discreteMesh) checkDiscreteShells(model, mesh);
    for (const std::string& touching : touchingVolumes(model, mesh)) log.warning(touching);
    const VolumeAlgorithm& volume = volumeAlgorithmFor(options.algorithm3D);
    const std::string why = volumeAlgorithmUnavailable(options.algorithm3D);
    bool warned = why.empty();
    std::vector<int> tetrahedral;
    for (const auto& entry : model.volumes()) {
      if (extruded.meshesVolume(entry.first)) continue;
      const auto& transfinite = model.meshConstraints().transfiniteVolumes;
      if (const auto it = transfinite.find(entry.first); it != transfinite.end()) {
        const std::string why = meshTransfiniteVolume(model, entry.first, it->second, mesh);
        if (why.empty()) continue;
        log.warning("Transfinite Volume " + std::to_string(entry.first) + ": " + why +
                    "; meshed with tetrahedra");
      }
      if (!warned)
        log.warning("Mesh.Algorithm3D " + why + ": volumes are meshed with " + volume.title +
                    " (" + std::to_string(volume.code) + ")");
      warned = true;
      tetrahedral.push_back(entry.first);
    }
    // Every available row of the registry is meshVolume, planned and committed apart here.
    meshTetrahedralVolumes(model, options, tetrahedral, fields, mesh, log);
    extruded.meshVolumes(mesh);
    const MeshCheckReport report = checkVolumeElements(model, mesh);
    if (!report.ok())
      throw MeshError(report.problems.front().entity, report.problems.front().message);
    timer.done(log, mesh.elementCount(3), hasOnlyTetrahedra(mesh) ? "tetrahedra" : "elements");
    if (options.subdivisionAlgorithm == 2 && !model.volumes().empty())
      if (const std::string why = subdivideIntoHexahedra(model, mesh); !why.empty())
        log.warning("Mesh.SubdivisionAlgorithm 2: " + why + "; elements are not split");
  }
}

}  // namespace

void generateMesh(const Model& model, const MeshOptions& options, int dim, Mesh& mesh,
                  MessageSink& log) {
  mesh.clear();
  if (const std::string why = unsupportedOrderReason(options.elementOrder); !why.empty())
    throw std::invalid_argument("Mesh.ElementOrder: " + why);
  const SizeFields fields(model, log, options);
  // Compounds: the surfaces of each first meshed on their own, finer, with nothing but their
  // sizes (no recombination, order 1), then the model with each compound as one entity.
  const PartMesher meshParts = [&](const Model& parts, double factor, Mesh& partsMesh) {
    MeshOptions fine = options;
    fine.sizeFactor *= factor;
    fine.discreteMesh = nullptr;
    fine.recombineAll = false;
    fine.subdivisionAlgorithm = 0;
    SilentSink quiet;
    meshStages(parts, fine, 2, fields, partsMesh, quiet);
  };
  const std::optional<CompoundMeshing> compounds =
      dim >= 1 ? planCompounds(model, options, dim, meshParts, log) : std::nullopt;
  meshStages(compounds ? compounds->model : model, options, dim, fields, mesh, log);
  if (compounds) compounds->classify(model, mesh);
  if (options.elementOrder > 1 && dim >= 1) raiseOrder(model, options, mesh, log);
}

void raiseOrder(const Model& model, const MeshOptions& options, Mesh& mesh, MessageSink& log) {
  const auto start = std::chrono::steady_clock::now();
  const HighOrderSummary summary = setOrder(model, options, mesh, log);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char line[160];
  std::snprintf(line, sizeof line, "Meshing order %d (%s)... done (%.3g s, %zu nodes added)",
                options.elementOrder, options.secondOrderLinear ? "straight" : "curved",
                seconds, summary.nodesAdded);
  log.info(line);
}

}  // namespace geomesh
