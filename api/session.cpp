// Session: running scripts, synchronizing the model, reading .msh files, meshing, origins.
#include "api/session.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "api/discrete_model.h"
#include "api/partitioning.h"
#include "io/formats.h"
#include "mesh/pipeline/generate.h"
#include "stdlib/clamped_integer.h"

namespace geomesh {

Session::Session(MessageSink& log) : Session(log, std::cout) {}

Session::Session(MessageSink& log, std::ostream& out) : log_(log), out_(out) {}

Session::~Session() = default;

void Session::synchronize() {
  if (!meshFromFile_ || addsToDiscreteSurfaces()) {
    factories_.synchronize(model_);
    warnOfSkippedMembers();
    return;
  }
  if (hasGeometry() && discreteSurfaces_.empty())
    throw std::runtime_error(
        "the script defines geometry besides a merged mesh file: mixing both is not supported yet");
}

bool Session::addsToDiscreteSurfaces() const {
  if (discreteSurfaces_.empty()) return false;
  for (int dim : {0, 1, 3})
    if (!factories_.tags(dim).empty()) return true;
  const std::vector<int> surfaces = factories_.tags(2);
  if (!std::equal(surfaces.begin(), surfaces.end(), discreteSurfaces_.begin(),
                  discreteSurfaces_.end()))
    return true;
  return factories_.current().physicalGroups().size() != discretePhysicals_;
}

// The surfaces of a file that holds surfaces only (no curve, no volume, no point element)
// join the built-in factory as discrete surfaces, with the file's surface groups. Whether
// they close is seen when a volume is meshed (checkDiscreteShells).
bool Session::registerDiscreteSurfaces(const std::string& file, bool dropLowerEntities) {
  // Dropping: the file's curves, points and volumes without elements are left out.
  const bool others =
      !model_.curves().empty() || !model_.points().empty() || !model_.volumes().empty();
  if (model_.surfaces().empty() || mesh_.elementCount(3) > 0 || (others && !dropLowerEntities))
    return false;
  for (const auto& [tag, surface] : model_.surfaces()) {
    BoundingBox box;
    if (const EntityMesh* em = mesh_.find({2, tag}))
      for (NodeIndex n : em->nodes) box.include(mesh_.node(n));
    factories_.discrete().addDiscreteSurface(tag, box, file, {});
    discreteSurfaces_.insert(tag);
  }
  // The groups of a file with curves name entities that classification replaces: left out.
  for (const auto& [id, group] : model_.physicalGroups()) {
    if (id.dim != 2 || dropLowerEntities) continue;
    factories_.builtIn().addPhysicalGroup(2, id.tag, group.name, group.entities);
    ++discretePhysicals_;
  }
  discreteMesh_ = mesh_;
  discrete_.reset();
  if (discreteFile_.empty()) discreteFile_ = file;
  return true;
}

// As the reference does, a physical group keeps the members the model has and skips the
// others with a warning: a tag the script got wrong, or an entity a Boolean renumbered. Each
// is told of once, however often the model is synchronized.
void Session::warnOfSkippedMembers() {
  static const char* const kKinds[] = {"point", "curve", "surface", "volume"};
  for (const auto& [id, group] : factories_.current().physicalGroups()) {
    if (id.dim < 0 || id.dim > 3) continue;
    for (int member : group.entities) {
      const int tag = std::abs(member);
      if (model_.contains({id.dim, tag}) || !skippedMembers_.insert({id.dim, id.tag, tag}).second)
        continue;
      log_.warning(std::string("Skipping unknown ") + kKinds[id.dim] + " " + std::to_string(tag) +
                   " in physical " + kKinds[id.dim] + " " + std::to_string(id.tag));
    }
  }
}

bool Session::hasGeometry() const {
  return factories_.hasEntities();
}

void Session::readMesh(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  const MeshFormat* format = findReaderByExtension(extension);
  if (!format)
    throw std::runtime_error("cannot read '" + path + "': the '" + extension +
                             "' format is not supported (read: " + readExtensionList() + ")");
  readMeshFile(path, *format, model_, mesh_);
  meshFromFile_ = true;
  meshIsMergedFile_ = registerDiscreteSurfaces(path);
  if (meshIsMergedFile_) reportMergedEdges(path);
  if (!meshIsMergedFile_ && !model_.surfaces().empty() && mesh_.elementCount(3) == 0 &&
      discreteSurfaces_.empty())
    surfaceMeshFile_ = path;
}

void Session::adoptSurfaceMeshFile() {
  if (surfaceMeshFile_.empty() || !discreteSurfaces_.empty() || discrete_) return;
  const std::string file = std::exchange(surfaceMeshFile_, std::string());
  const std::size_t curves = model_.curves().size(), points = model_.points().size();
  if (!registerDiscreteSurfaces(file, true)) return;
  meshIsMergedFile_ = true;
  log_.info("Merged '" + file + "': its " + std::to_string(model_.surfaces().size()) +
            " surfaces are taken as merged triangles; its " + std::to_string(curves) +
            " curves, " + std::to_string(points) + " points and physical groups are left out");
  reportMergedEdges(file);
}

MeshOptions Session::meshOptions() const {
  MeshOptions m;
  const OptionRegistry& o = options_;
  m.sizeMin = o.number("Mesh.MeshSizeMin");
  m.sizeMax = o.number("Mesh.MeshSizeMax");
  m.sizeFactor = o.number("Mesh.MeshSizeFactor");
  m.sizeFromPoints = o.number("Mesh.MeshSizeFromPoints") != 0;
  m.sizeExtendFromBoundary = o.number("Mesh.MeshSizeExtendFromBoundary") != 0;
  m.algorithm2D = clampedInteger<int>(o.number("Mesh.Algorithm"));
  m.algorithm3D = clampedInteger<int>(o.number("Mesh.Algorithm3D"));
  m.smoothing = clampedInteger<int>(o.number("Mesh.Smoothing"));
  m.elementOrder = clampedInteger<int>(o.number("Mesh.ElementOrder"));
  m.secondOrderLinear = o.number("Mesh.SecondOrderLinear") != 0;
  m.secondOrderIncomplete = o.number("Mesh.SecondOrderIncomplete") != 0;
  m.highOrderOptimize = clampedInteger<int>(o.number("Mesh.HighOrderOptimize"));
  m.highOrderThresholdMin = o.number("Mesh.HighOrderThresholdMin");
  m.highOrderThresholdMax = o.number("Mesh.HighOrderThresholdMax");
  m.highOrderNumLayers = clampedInteger<int>(o.number("Mesh.HighOrderNumLayers"));
  m.numThreads = clampedInteger<int>(o.number("General.NumThreads"));
  m.randomFactor = o.number("Mesh.RandomFactor");
  m.recombineAll = o.number("Mesh.RecombineAll") != 0;
  m.recombinationAlgorithm = clampedInteger<int>(o.number("Mesh.RecombinationAlgorithm"));
  m.recombineMinQuality = o.number("Mesh.RecombineMinimumQuality");
  m.recombineOptimizeTopology = clampedInteger<int>(o.number("Mesh.RecombineOptimizeTopology"));
  m.recombineNodeRepositioning = o.number("Mesh.RecombineNodeRepositioning") != 0;
  m.sizeFromCurvature = o.number("Mesh.MeshSizeFromCurvature");
  m.minCircleNodes = clampedInteger<int>(o.number("Mesh.MinimumCircleNodes"));
  m.minCurveNodes = clampedInteger<int>(o.number("Mesh.MinimumCurveNodes"));
  m.subdivisionAlgorithm = clampedInteger<int>(o.number("Mesh.SubdivisionAlgorithm"));
  m.optimize = o.number("Mesh.Optimize") != 0;
  m.optimizeThreshold = o.number("Mesh.OptimizeThreshold");
  m.anisoMax = o.number("Mesh.AnisoMax");
  m.smoothRatio = o.number("Mesh.SmoothRatio");
  m.compoundSizeFactor = o.number("Mesh.CompoundMeshSizeFactor");
  m.compoundClassify = clampedInteger<int>(o.number("Mesh.CompoundClassify"));
  m.views = &views_;
  return m;
}

void Session::generate(int dim) {
  synchronize();
  const bool discrete = meshFromFile_ && addsToDiscreteSurfaces();
  if (meshFromFile_ && !discrete) {
    log_.info("Keeping the mesh read from file: it has no geometry to mesh again");
    computeHomology(homologyRequests_, model_, mesh_, log_);
    return;
  }
  MeshOptions options = meshOptions();
  if (discrete) options.discreteMesh = &discreteMesh_;
  meshIsMergedFile_ = false;
  generateMesh(model_, options, dim, mesh_, log_);
  computeHomology(homologyRequests_, model_, mesh_, log_);
  const int partitions = clampedInteger<int>(options_.number("Mesh.NbPartitions"));
  if (partitions > 0) api::partitionMesh(*this, partitions);
}

void Session::clearModel() {
  factories_.clear();
  model_ = Model();
  mesh_ = Mesh();
  homologyRequests_.clear();
  origins_.clear();
  meshFromFile_ = false;
  meshIsMergedFile_ = false;
  discreteMesh_ = Mesh();
  discreteSurfaces_.clear();
  discretePhysicals_ = 0;
  discrete_.reset();
  discreteFile_.clear();
  surfaceMeshFile_.clear();
}

void Session::recordOrigin(EntityId entity, const SourceLocation& where) {
  // Scripts define entities file after file: the last file name is nearly always the one.
  if (lastOriginFile_ >= originFiles_.size() || originFiles_[lastOriginFile_] != where.file) {
    auto it = std::find(originFiles_.begin(), originFiles_.end(), where.file);
    if (it == originFiles_.end()) it = originFiles_.insert(it, where.file);
    lastOriginFile_ = static_cast<std::uint32_t>(it - originFiles_.begin());
  }
  origins_[entity] = {lastOriginFile_, where.line, where.column};
}

std::optional<SourceLocation> Session::origin(EntityId entity) const {
  auto it = origins_.find(entity);
  if (it == origins_.end()) return std::nullopt;
  return SourceLocation{originFiles_[it->second.file], it->second.line, it->second.column};
}

void Session::noteIgnoredStatement(const SourceLocation& where) {
  if (ignoredPlaces_.emplace(where.file, where.line, where.column).second && !firstIgnored_)
    firstIgnored_ = where;
}

}  // namespace geomesh
