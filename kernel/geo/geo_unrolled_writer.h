// writeUnrolledGeo and its hooks: the .geo_unrolled script that `-0` saves.
#pragma once

#include <iosfwd>

#include "kernel/unrolled_geo_hooks.h"

namespace geomesh {

class GeoFactory;

// Writes the built-in kernel's entities as a flat .geo script (what `-0` saves as
// <script>.geo_unrolled): one variable per distinct point mesh size (cl__1, cl__2, ...; an
// unset size is written 1e+22), then points, curves, surfaces (each with its curve loop,
// holes appended to the outer loop, and the entities embedded in it), volumes (each with its
// surface loop) and physical groups, in ascending tags.
void writeUnrolledGeo(const GeoFactory& geo, std::ostream& out,
                      const UnrolledGeoHooks& hooks = {});

}  // namespace geomesh
