// The mesh constraints' statements in the unrolled script (Transfinite, Recombine).
#include "kernel/unrolled_geo_hooks.h"

#include <cstdio>
#include <ostream>
#include <string>

namespace geomesh {

namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.16g", x);
  return text;
}

const char* lawKeyword(TransfiniteCurve::Law law) {
  switch (law) {
    case TransfiniteCurve::Law::Bump: return "Bump";
    case TransfiniteCurve::Law::Beta: return "Beta";
    case TransfiniteCurve::Law::Progression: return "Progression";
  }
  return "Progression";
}

void writeCurveConstraints(const MeshConstraints& constraints, int tag, std::ostream& out) {
  auto it = constraints.transfiniteCurves.find(tag);
  if (it == constraints.transfiniteCurves.end()) return;
  const TransfiniteCurve& t = it->second;
  out << "Transfinite Curve {" << (t.reversed ? -tag : tag) << "} = " << t.nodes << " Using "
      << lawKeyword(t.law) << " " << number(t.coefficient) << ";\n";
}

void writeSurfaceConstraints(const MeshConstraints& constraints, int tag, std::ostream& out) {
  if (auto it = constraints.transfiniteSurfaces.find(tag);
      it != constraints.transfiniteSurfaces.end()) {
    out << "Transfinite Surface {" << tag << "}";
    if (!it->second.corners.empty()) {
      std::string corners;
      for (int c : it->second.corners) corners += (corners.empty() ? "" : ",") + std::to_string(c);
      out << " = {" << corners << "}";
    }
    out << ";\n";
  }
  if (constraints.recombinedSurfaces.contains(tag))
    out << "Recombine Surface {" << tag << "};\n";
}

}  // namespace

UnrolledGeoHooks meshConstraintHooks(const MeshConstraints& constraints) {
  UnrolledGeoHooks hooks;
  hooks.afterEntity = [&constraints](EntityId e, std::ostream& out) {
    if (e.dim == 1) writeCurveConstraints(constraints, e.tag, out);
    if (e.dim == 2) writeSurfaceConstraints(constraints, e.tag, out);
  };
  return hooks;
}

}  // namespace geomesh
