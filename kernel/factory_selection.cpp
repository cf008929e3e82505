// The one place that knows the concrete factories: built-in (kernel/geo) and OpenCASCADE
// (kernel/occ).
#include "kernel/factory_selection.h"

#include <filesystem>
#include <ostream>

#include "kernel/geo/geo_factory.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {

struct FactorySelection::Factories {
  GeoFactory builtIn;
  OccFactory occ;
  FallbackFactory occFirst{occ, builtIn};  // selected by SetFactory("OpenCASCADE")
};

FactorySelection::FactorySelection()
    : factories_(std::make_unique<Factories>()), current_(&factories_->builtIn) {}

FactorySelection::~FactorySelection() = default;

bool FactorySelection::select(const std::string& name) {
  if (name == "OpenCASCADE") {
    current_ = &factories_->occFirst;
    return true;
  }
  if (name == "Built-in" || name == "built-in" || name == "Geo") {
    current_ = &factories_->builtIn;
    return true;
  }
  return false;
}

SolidModeling& FactorySelection::solidModeler() { return factories_->occ; }

GeometryFactory& FactorySelection::builtIn() { return factories_->builtIn; }

DiscreteEntities& FactorySelection::discrete() { return factories_->builtIn; }

const DiscreteEntities& FactorySelection::discrete() const { return factories_->builtIn; }

void FactorySelection::onHandover(FallbackFactory::Handover handover) {
  factories_->occFirst.onHandover(std::move(handover));
}

// The built-in factory goes last: its physical groups may name OpenCASCADE entities.
void FactorySelection::synchronize(Model& model) const {
  model.clear();
  factories_->occ.synchronize(model);
  factories_->builtIn.synchronize(model);
}

void FactorySelection::clear() {
  factories_->builtIn.clear();
  factories_->occ.clear();
}

void FactorySelection::writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks,
                                     const std::string& cadPath) const {
  if (factories_->occ.hasShapes()) {
    factories_->occ.exportShapes(cadPath);
    // The factory first, so that the statements after the merge (MeshSize, ...) reach it.
    out << "SetFactory(\"OpenCASCADE\");\n";
    out << "Merge \"" << std::filesystem::path(cadPath).filename().string() << "\";\n";
    factories_->occ.writeUnrolled(out, hooks);
    bool builtInEntities = false;
    for (int dim = 0; dim <= 3; ++dim) builtInEntities |= factories_->builtIn.maxTag(dim) > 0;
    if (builtInEntities) out << "SetFactory(\"Built-in\");\n";  // its entities stay its own
  }
  factories_->builtIn.writeUnrolled(out, hooks);
}

std::vector<int> FactorySelection::tags(int dim) const { return factories_->occFirst.tags(dim); }

bool FactorySelection::hasEntities() const {
  for (int dim = 0; dim <= 3; ++dim)
    if (factories_->builtIn.maxTag(dim) > 0 || factories_->occ.maxTag(dim) > 0) return true;
  return false;
}

}  // namespace geomesh
