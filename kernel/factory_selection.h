// The geometry factories of one session and the one SetFactory selected.
#pragma once

#include <memory>
#include <string>

#include "kernel/discrete_entities.h"
#include "kernel/fallback_factory.h"

namespace geomesh {

// Owns the built-in and the OpenCASCADE factories. Scripts start with the built-in one;
// SetFactory("OpenCASCADE") selects the OpenCASCADE one, which hands what it cannot do yet to
// the built-in one (see FallbackFactory). Both synchronize into the same model.
class FactorySelection {
 public:
  FactorySelection();
  ~FactorySelection();
  FactorySelection(const FactorySelection&) = delete;
  FactorySelection& operator=(const FactorySelection&) = delete;

  GeometryFactory& current() { return *current_; }
  // The OpenCASCADE factory's solid modeling, whichever factory is selected (Merge "x.step").
  SolidModeling& solidModeler();
  const GeometryFactory& current() const { return *current_; }
  // "OpenCASCADE"; "Built-in" (or "built-in", "Geo"). False for another name (nothing changes).
  bool select(const std::string& name);
  // Told of every operation the selected factory hands over to the built-in one.
  void onHandover(FallbackFactory::Handover handover);

  // The built-in factory, whichever is selected (what a merged mesh file adds goes there).
  GeometryFactory& builtIn();
  // The built-in factory's discrete entities (merged triangulations).
  DiscreteEntities& discrete();
  const DiscreteEntities& discrete() const;

  // Clears the model's entities, then adds those of every factory.
  void synchronize(Model& model) const;
  void clear();
  bool hasEntities() const;  // whether any factory holds an entity
  // The tags of dimension `dim` in either factory, ascending (Surface{:}: a file merged into
  // the OpenCASCADE model while the built-in factory is selected is listed too).
  std::vector<int> tags(int dim) const;
  // The unrolled script (-0, Save "x.geo_unrolled") of both factories. When the OpenCASCADE
  // factory holds shapes, they are written to the XAO file `cadPath` and the script starts by
  // selecting that factory and merging the file (by its name: it sits next to the script),
  // then states their mesh constraints; the built-in factory's entities and the physical
  // groups follow.
  void writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks,
                     const std::string& cadPath) const;

 private:
  struct Factories;  // kernel/factory_selection.cpp
  std::unique_ptr<Factories> factories_;
  GeometryFactory* current_;
};

}  // namespace geomesh
