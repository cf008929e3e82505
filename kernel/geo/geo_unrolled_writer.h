#pragma once

#include <functional>
#include <iosfwd>

#include "kernel/model.h"

namespace geomesh {

class GeoFactory;

// Where other modules add their statements to the unrolled script (the mesh constraints:
// "Transfinite Curve {1} = 10 Using Progression 1;", fields, ...), as the reference does:
// afterEntity runs after each curve, surface (after its embedded entities) and volume
// definition; atEnd after the physical groups.
struct UnrolledGeoHooks {
  std::function<void(EntityId, std::ostream&)> afterEntity;
  std::function<void(std::ostream&)> atEnd;
};

// Writes the built-in kernel's entities as a flat .geo script (what `-0` saves as
// <script>.geo_unrolled): one variable per distinct point mesh size (cl__1, cl__2, ...; an
// unset size is written 1e+22), then points, curves, surfaces (each with its curve loop,
// holes appended to the outer loop, and the entities embedded in it), volumes (each with its
// surface loop) and physical groups, in ascending tags.
void writeUnrolledGeo(const GeoFactory& geo, std::ostream& out,
                      const UnrolledGeoHooks& hooks = {});

// Hooks writing the transfinite and recombination constraints as the reference does
// ("Transfinite Curve {-1} = 30 Using Progression 1.2;" after the curve, "Transfinite Surface
// {1} = {1,2,3,4};" and "Recombine Surface {1};" after the surface). Size fields are not
// written. `constraints` must outlive the hooks.
UnrolledGeoHooks meshConstraintHooks(const MeshConstraints& constraints);

}  // namespace geomesh
