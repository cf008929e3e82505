// Session: options, geometry factory, model, mesh and output of one run, without globals.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "grammar/source.h"
#include "kernel/factory_selection.h"
#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"
#include "mesh/homology/homology.h"
#include "mesh/views/view.h"
#include "stdlib/options.h"

namespace geomesh {

struct DiscreteModel;     // api/discrete_model.h
struct DiscreteTopology;  // mesh/discrete/classification.h
struct FairingOptions;    // mesh/discrete/surface_fairing.h
struct Triangulation;     // mesh/discrete/triangulation.h

// Everything one run owns: options, the geometry factories, the model, the mesh, and where
// messages and script output go. No global state: several sessions can coexist. Scripts run
// in a session through interpreter/run_script.h; the command line and scripts act on it
// through the functions of api/.
class Session {
 public:
  explicit Session(MessageSink& log);
  Session(MessageSink& log, std::ostream& out);
  ~Session();

  OptionRegistry& options() { return options_; }
  const OptionRegistry& options() const { return options_; }
  // The geometry factory SetFactory selected (the built-in one at first), and the selection.
  GeometryFactory& factory() { return factories_.current(); }
  FactorySelection& factories() { return factories_; }
  Model& model() { return model_; }
  const Model& model() const { return model_; }
  Mesh& mesh() { return mesh_; }
  const Mesh& mesh() const { return mesh_; }
  // The post-processing views (View "..." {...}; Merge "f.pos"; plugins): they outlive
  // NewModel and Delete Model, as background meshes are often merged before the geometry.
  post::ViewStore& views() { return views_; }
  const post::ViewStore& views() const { return views_; }
  MessageSink& log() const { return log_; }
  std::ostream& out() { return out_; }  // what scripts print (Printf)

  // Values given by -setnumber / -setstring: they override DefineConstant / DefineNumber /
  // DefineString of the same name.
  std::map<std::string, double>& numberOverrides() { return numberOverrides_; }
  std::map<std::string, std::string>& stringOverrides() { return stringOverrides_; }

  // Whether scripts may run shell commands (SystemCall "..."); off unless the user asks.
  bool systemCallsAllowed() const { return systemCallsAllowed_; }
  void allowSystemCalls(bool allow) { systemCallsAllowed_ = allow; }
  // A sandboxed session (the fuzz target) lets its scripts neither write files nor mesh:
  // Printf into a file, Save, Print and Mesh are skipped with a warning.
  bool sandboxed() const { return sandboxed_; }
  void setSandboxed(bool sandboxed) { sandboxed_ = sandboxed; }

  // Rebuilds the model from the geometry factories.
  void synchronize();
  // The Mesh.* options, as the generators read them.
  MeshOptions meshOptions() const;
  // Synchronizes, then meshes up to `dim`; throws MeshError.
  void generate(int dim);
  // Homology and Cohomology statements: carried out at the end of each generate(), their
  // bases saved as physical groups of the mesh.
  std::vector<HomologyRequest>& homologyRequests() { return homologyRequests_; }
  // Forgets every entity, mesh constraint and mesh element (Delete Model; NewModel;).
  void clearModel();
  // Replaces the model and the mesh by those of a mesh file, read by the format its
  // extension names (Merge "f.msh"; in a script). The mesh is then kept as read: meshing
  // leaves it alone. When the file holds surfaces only (an STL, PLY, OFF file...), they
  // also become discrete surfaces of the built-in factory, which Surface Loop, Volume
  // and Physical statements may use: a script that adds to them makes the model from the
  // factories, and meshing copies their triangles from the file and meshes the rest (the
  // volumes they bound). Other geometry besides a merged mesh is refused when the model is
  // next synchronized. Throws std::runtime_error (MshReadError for a malformed MSH file).
  void readMesh(const std::string& path);
  bool meshFromFile() const { return meshFromFile_; }

  // On the merged discrete surfaces (api/discrete_surfaces.cpp), as the statements of the same
  // names. ClassifySurfaces{angle, boundary, forReparametrization, curveAngle}: welds the
  // triangles, orients them alike, and splits them into surfaces where neighbours meet at more
  // than `angle` (radians; with `includeBoundary`, also where the merged surfaces meet), with
  // curves where surfaces meet (broken where they turn by more than `curveAngle`) and points
  // where curves meet; the merged surfaces are replaced by them. CreateTopology: the same
  // entities for the surfaces as they are. CreateGeometry: gives every discrete curve and
  // surface a geometry (a surface: a one-to-one map of its triangles to the plane, after
  // splitting those that have none), so that they are meshed anew. Each throws
  // std::runtime_error when there are no merged triangles.
  void classifySurfaces(double angle, bool includeBoundary, bool forReparametrization,
                        double curveAngle);
  void createTopology();
  void createGeometry();
  // The merged triangles of the discrete surfaces (welded and consistently oriented, as
  // ClassifySurfaces takes them); null when no surface file was merged or it has no triangle.
  const Triangulation* mergedTriangulation();
  // Plugin(Simplify) and Plugin(Fair) (api/merged_triangles.cpp): replace the merged triangles
  // by fewer (each merged surface simplified apart, their common edges kept) or by smoother
  // ones, before ClassifySurfaces; while the session's mesh is still the merged file's, it
  // is replaced too (so that Save and the curvature plugins see the change). Throw
  // std::runtime_error when there are no merged triangles or they were classified already.
  // simplifyMergedTriangles collapses edges until at most `targetTriangles` are left or the next
  // collapse would put a vertex farther than `maxDistance` from the planes of the triangles it
  // replaces (0: no such bound); it returns the triangle counts before and after.
  std::pair<std::size_t, std::size_t> simplifyMergedTriangles(std::size_t targetTriangles,
                                                              double maxDistance);
  // Returns how far a vertex moved at most.
  double fairMergedTriangles(const FairingOptions& options);
  // Whether any geometry factory holds an entity.
  bool hasGeometry() const;

  // Where the script defined a curve, surface or volume, so that a failure met later (while
  // meshing) can point at the statement. Null when unknown.
  void recordOrigin(EntityId entity, const SourceLocation& where);
  std::optional<SourceLocation> origin(EntityId entity) const;

  // Statements the script contained but that were skipped as not supported yet (with a
  // warning), each place once, in the order met: meshing a model they left empty is an error
  // that points at the first.
  void noteIgnoredStatement(const SourceLocation& where);
  std::size_t ignoredStatementCount() const { return ignoredPlaces_.size(); }
  std::optional<SourceLocation> firstIgnoredStatement() const { return firstIgnored_; }

 private:
  MessageSink& log_;
  std::ostream& out_;
  OptionRegistry options_;
  FactorySelection factories_;
  Model model_;
  Mesh mesh_;
  post::ViewStore views_;
  std::vector<HomologyRequest> homologyRequests_;
  std::map<std::string, double> numberOverrides_;
  std::map<std::string, std::string> stringOverrides_;
  struct Origin {
    std::uint32_t file;  // index in originFiles_
    int line, column;
  };
  std::map<EntityId, Origin> origins_;
  std::vector<std::string> originFiles_;
  std::uint32_t lastOriginFile_ = 0;
  std::set<std::tuple<std::string, int, int>> ignoredPlaces_;
  std::optional<SourceLocation> firstIgnored_;
  bool systemCallsAllowed_ = false;
  bool sandboxed_ = false;
  bool meshFromFile_ = false;
  // Merged closed surfaces registered as discrete surfaces (see readMesh): the file's mesh,
  // their tags, and how many physical groups came with them.
  Mesh discreteMesh_;
  std::set<int> discreteSurfaces_;
  std::size_t discretePhysicals_ = 0;
  // dropLowerEntities: the file may hold curves and points too; they are left out.
  bool registerDiscreteSurfaces(const std::string& file, bool dropLowerEntities = false);
  // A merged mesh file of surfaces with curves or points (no volume) is kept as it was read,
  // unless a statement on merged triangles (ClassifySurfaces, Plugin(Fair)...) asks for them:
  // then its surfaces become discrete surfaces (adoptSurfaceMeshFile).
  std::string surfaceMeshFile_;
  void adoptSurfaceMeshFile();
  // Whether mesh_ is still the mesh of the merged surface file, as read.
  bool meshIsMergedFile_ = false;
  // A merged file's open and non-manifold edges, told of once it is read.
  void reportMergedEdges(const std::string& file) const;
  // The merged triangles before classification, for Plugin(Simplify) and Plugin(Fair).
  DiscreteModel& unclassifiedTriangles(const char* plugin);
  void mergedTrianglesChanged(std::string statement);
  // The triangles of the discrete surfaces, gathered from discreteMesh_ on first use.
  std::unique_ptr<DiscreteModel> discrete_;
  std::string discreteFile_;
  DiscreteModel& discreteModel();
  void replaceDiscreteTopology(const DiscreteTopology& topology);
  void rebuildDiscreteMesh();
  // Whether the script defined anything besides the merged discrete surfaces.
  bool addsToDiscreteSurfaces() const;
  // Physical group members the model lacked at a synchronization: (dim, group, member).
  std::set<std::tuple<int, int, int>> skippedMembers_;
  void warnOfSkippedMembers();
};

}  // namespace geomesh
