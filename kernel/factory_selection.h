// The geometry factories of one session and the one SetFactory selected.
#pragma once

#include <memory>
#include <string>

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
  const GeometryFactory& current() const { return *current_; }
  // "OpenCASCADE"; "Built-in" (or "built-in", "Geo"). False for another name (nothing changes).
  bool select(const std::string& name);
  // Told of every operation the selected factory hands over to the built-in one.
  void onHandover(FallbackFactory::Handover handover);

  // Clears the model's entities, then adds those of every factory.
  void synchronize(Model& model) const;
  void clear();
  bool hasEntities() const;  // whether any factory holds an entity

 private:
  struct Factories;  // kernel/factory_selection.cpp
  std::unique_ptr<Factories> factories_;
  GeometryFactory* current_;
};

}  // namespace geomesh
