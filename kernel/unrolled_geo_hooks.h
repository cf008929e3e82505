// Where other modules add their statements to an unrolled .geo script (-0, Save ".geo_unrolled").
#pragma once

#include <functional>
#include <iosfwd>

#include "kernel/model.h"

namespace geomesh {

// Where other modules add their statements to the unrolled script (the mesh constraints:
// "Transfinite Curve {1} = 10 Using Progression 1;", fields, ...), as the reference does:
// afterEntity runs after each curve, surface (after its embedded entities) and volume
// definition; atEnd after the physical groups.
struct UnrolledGeoHooks {
  std::function<void(EntityId, std::ostream&)> afterEntity;
  std::function<void(std::ostream&)> atEnd;
};

// Hooks writing the transfinite and recombination constraints as the reference does
// ("Transfinite Curve {-1} = 30 Using Progression 1.2;" after the curve, "Transfinite Surface
// {1} = {1,2,3,4};" and "Recombine Surface {1};" after the surface). Size fields are not
// written. `constraints` must outlive the hooks.
UnrolledGeoHooks meshConstraintHooks(const MeshConstraints& constraints);

}  // namespace geomesh
