// writeUnrolledGeo: the built-in kernel's entities and mesh constraints as a flat .geo script.
#include "kernel/geo/geo_unrolled_writer.h"

#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "kernel/geo/geo_factory.h"

namespace geomesh {

namespace {

constexpr double kUnsetMeshSize = 1e22;

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.16g", x);
  return text;
}

std::string tagList(const std::vector<int>& tags) {
  std::string text = "{";
  for (std::size_t i = 0; i < tags.size(); ++i)
    text += (i ? ", " : "") + std::to_string(tags[i]);
  return text + "}";
}

const char* curveKeyword(GeoFactory::CurveKind kind) {
  switch (kind) {
    case GeoFactory::CurveKind::Line: return "Line";
    case GeoFactory::CurveKind::CircleArc: return "Circle";
    case GeoFactory::CurveKind::EllipseArc: return "Ellipse";
    case GeoFactory::CurveKind::Spline: return "Spline";
    case GeoFactory::CurveKind::BSpline: return "BSpline";
    case GeoFactory::CurveKind::Bezier: return "Bezier";
    case GeoFactory::CurveKind::Other: break;  // the built-in kernel defines none
  }
  return "Line";
}

void writePoints(const GeoFactory& geo, std::ostream& out) {
  std::map<double, int> sizeVariable;  // mesh size -> n of cl__n, numbered as first met
  std::vector<double> order;
  for (const auto& [tag, p] : geo.points()) {
    if (p.discrete) continue;  // the merged file's statements make it again
    const double size = p.meshSize > 0 ? p.meshSize : kUnsetMeshSize;
    if (sizeVariable.emplace(size, static_cast<int>(order.size()) + 1).second)
      order.push_back(size);
  }
  for (std::size_t i = 0; i < order.size(); ++i)
    out << "cl__" << i + 1 << " = " << number(order[i]) << ";\n";
  for (const auto& [tag, p] : geo.points()) {
    if (p.discrete) continue;
    const double size = p.meshSize > 0 ? p.meshSize : kUnsetMeshSize;
    out << "Point(" << tag << ") = {" << number(p.xyz.x) << ", " << number(p.xyz.y) << ", "
        << number(p.xyz.z) << ", cl__" << sizeVariable.at(size) << "};\n";
  }
}

void writeEmbedded(const char* what, const std::vector<int>& tags, const char* host, int hostTag,
                   std::ostream& out) {
  if (tags.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < tags.size(); ++i)
    list += (i ? ", " : "") + std::to_string(tags[i]);
  out << what << " {" << list << "} In " << host << " {" << hostTag << "};\n";
}

void after(const UnrolledGeoHooks& hooks, EntityId e, std::ostream& out) {
  if (hooks.afterEntity) hooks.afterEntity(e, out);
}

void writeSurfaces(const GeoFactory& geo, std::ostream& out, const UnrolledGeoHooks& hooks) {
  std::set<std::string> merged;
  for (const auto& [tag, s] : geo.surfaces()) {
    if (s.kind == GeoFactory::SurfaceKind::Discrete) {
      // The file's surfaces come back with their tags when it is merged again.
      const std::string& file = geo.discreteFiles().at(tag);
      if (merged.insert(file).second) {
        out << "Merge \"" << file << "\";\n";
        for (const std::string& statement : geo.discreteStatements()) out << statement << "\n";
      }
      after(hooks, {2, tag}, out);
      continue;
    }
    std::vector<int> loop;
    for (const auto& part : s.loops) loop.insert(loop.end(), part.begin(), part.end());
    out << "Curve Loop(" << tag << ") = " << tagList(loop) << ";\n";
    out << (s.kind == GeoFactory::SurfaceKind::Plane ? "Plane Surface(" : "Surface(") << tag
        << ") = {" << tag << "};\n";
    writeEmbedded("Line", s.embeddedCurves, "Surface", tag, out);
    writeEmbedded("Point", s.embeddedPoints, "Surface", tag, out);
    after(hooks, {2, tag}, out);
  }
}

void writeVolumes(const GeoFactory& geo, std::ostream& out, const UnrolledGeoHooks& hooks) {
  for (const auto& [tag, v] : geo.volumes()) {
    std::vector<int> shell;
    for (const auto& s : v.shells) shell.insert(shell.end(), s.begin(), s.end());
    out << "Surface Loop(" << tag << ") = " << tagList(shell) << ";\n";
    out << "Volume(" << tag << ") = {" << tag << "};\n";
    writeEmbedded("Surface", v.embeddedSurfaces, "Volume", tag, out);
    writeEmbedded("Line", v.embeddedCurves, "Volume", tag, out);
    writeEmbedded("Point", v.embeddedPoints, "Volume", tag, out);
    after(hooks, {3, tag}, out);
  }
}

void writePhysicals(const GeoFactory& geo, std::ostream& out) {
  static constexpr const char* kWords[] = {"Point", "Curve", "Surface", "Volume"};
  for (const auto& [id, group] : geo.physicalGroups()) {
    out << "Physical " << kWords[id.dim];
    if (group.name.empty())
      out << "(" << id.tag << ")";
    else
      out << "(\"" << group.name << "\")";
    out << " = " << tagList(group.entities) << ";\n";
  }
}

}  // namespace

void GeoFactory::writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const {
  writeUnrolledGeo(*this, out, hooks);
}

void writeUnrolledGeo(const GeoFactory& geo, std::ostream& out, const UnrolledGeoHooks& hooks) {
  writePoints(geo, out);
  for (const auto& [tag, c] : geo.curves()) {
    if (!c.trace.empty()) {  // discrete: made again with the merged file's surfaces
      after(hooks, {1, tag}, out);
      continue;
    }
    if (c.knots.empty()) {
      out << curveKeyword(c.kind) << "(" << tag << ") = " << tagList(c.points) << ";\n";
    } else {
      out << "Nurbs(" << tag << ") = " << tagList(c.points) << " Knots {";
      for (std::size_t i = 0; i < c.knots.size(); ++i) out << (i ? ", " : "") << number(c.knots[i]);
      out << "} Order " << c.degree << ";\n";
    }
    writeEmbedded("Point", c.embeddedPoints, "Curve", tag, out);
    after(hooks, {1, tag}, out);
  }
  writeSurfaces(geo, out, hooks);
  writeVolumes(geo, out, hooks);
  writePhysicals(geo, out);
  if (hooks.atEnd) hooks.atEnd(out);
}

}  // namespace geomesh
