// composePicture: the faces (or lines) of a mesh seen through an orthographic camera, fitted
// into the picture, flat-shaded by a light at the viewer and sorted far to near.
#include "io/picture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "mesh/partition/partition_sets.h"

namespace geomesh {

namespace {

// The view of a mesh that does not lie in a plane z = const, when the script chose none.
constexpr std::array<double, 3> kObliqueRotation{-60, 0, -30};
// Light from the viewer: a face turned edge-on keeps this share of its colour.
constexpr double kAmbient = 0.35;
constexpr double kShades = 20;

// A face to draw, before projection: its corner nodes and the entity it shows.
struct MeshFace {
  std::array<NodeIndex, 4> corners{};
  int cornerCount = 3;
  EntityId entity;
};

bool hasSurfaceElements(const EntityMesh& entity) {
  for (const ElementBlock& block : entity.blocks)
    if (dimension(block.type) == 2 && block.size() > 0) return true;
  return false;
}

// Whether any surface of the volume's boundary has 2D elements; a volume unknown to the model
// (or without a boundary) has none.
bool boundaryIsMeshed(const Model& model, const Mesh& mesh, EntityId volume) {
  if (!model.contains(volume)) return false;
  for (int tag : model.boundary(volume))
    if (const EntityMesh* surface = mesh.find({2, std::abs(tag)}))
      if (hasSurfaceElements(*surface)) return true;
  return false;
}

void addSurfaceFaces(EntityId id, const EntityMesh& entity, std::vector<MeshFace>& faces) {
  for (const ElementBlock& block : entity.blocks) {
    if (dimension(block.type) != 2) continue;
    const int corners = vertexCount(block.type);
    for (std::size_t i = 0; i < block.size(); ++i) {
      MeshFace face{{}, corners, id};
      std::copy_n(block.element(i).begin(), corners, face.corners.begin());
      faces.push_back(face);
    }
  }
}

// Calls f(corners) for every facet of every volume element of `entity`, oriented outwards.
template <class F>
void forEachVolumeFacet(const EntityMesh& entity, F f) {
  for (const ElementBlock& block : entity.blocks) {
    if (dimension(block.type) != 3) continue;
    const auto& facets = facetsOf(family(block.type));
    for (std::size_t i = 0; i < block.size(); ++i) {
      const auto element = block.element(i);
      for (const std::vector<int>& facet : facets) {
        std::array<NodeIndex, 4> corners{};
        for (std::size_t k = 0; k < facet.size(); ++k)
          corners[k] = element[static_cast<std::size_t>(facet[k])];
        f(std::span<const NodeIndex>(corners.data(), facet.size()));
      }
    }
  }
}

// The facets of the volume's elements that belong to one element only, in element order.
void addVolumeBoundaryFaces(EntityId id, const EntityMesh& entity,
                            std::vector<MeshFace>& faces) {
  std::unordered_map<FacetKey, int, FacetHash> uses;
  forEachVolumeFacet(entity, [&](std::span<const NodeIndex> c) { ++uses[facetKey(c)]; });
  forEachVolumeFacet(entity, [&](std::span<const NodeIndex> c) {
    if (uses.at(facetKey(c)) != 1) return;
    MeshFace face{{}, static_cast<int>(c.size()), id};
    std::copy(c.begin(), c.end(), face.corners.begin());
    faces.push_back(face);
  });
}

std::vector<MeshFace> facesToDraw(const Model& model, const Mesh& mesh) {
  std::vector<MeshFace> faces;
  for (const auto& [id, entity] : mesh.entities()) {
    if (id.dim == 2) addSurfaceFaces(id, entity, faces);
    if (id.dim == 3 && !boundaryIsMeshed(model, mesh, id))
      addVolumeBoundaryFaces(id, entity, faces);
  }
  return faces;
}

std::vector<std::array<NodeIndex, 2>> linesToDraw(const Mesh& mesh) {
  std::vector<std::array<NodeIndex, 2>> lines;
  for (const auto& [id, entity] : mesh.entities())
    for (const ElementBlock& block : entity.blocks)
      if (family(block.type) == ElementFamily::Line)
        for (std::size_t i = 0; i < block.size(); ++i)
          lines.push_back({block.element(i)[0], block.element(i)[1]});
  return lines;
}

// Rows of the rotation that turns the model about z, then y, then x (degrees).
using Rotation = std::array<Vec3, 3>;

Rotation rotationOf(const std::array<double, 3>& degrees) {
  constexpr double kDegree = std::numbers::pi / 180;
  const double a = degrees[0] * kDegree, b = degrees[1] * kDegree, c = degrees[2] * kDegree;
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  const double cc = std::cos(c), sc = std::sin(c);
  // Rx(a) * Ry(b) * Rz(c), row by row.
  return {Vec3{cb * cc, -cb * sc, sb},
          Vec3{sa * sb * cc + ca * sc, -sa * sb * sc + ca * cc, -sa * cb},
          Vec3{-ca * sb * cc + sa * sc, ca * sb * sc + sa * cc, ca * cb}};
}

Vec3 rotate(const Rotation& r, Vec3 p) { return {dot(r[0], p), dot(r[1], p), dot(r[2], p)}; }

// The nodes of the faces and lines, ascending.
std::vector<NodeIndex> nodesUsed(const Mesh& mesh, const std::vector<MeshFace>& faces,
                                 const std::vector<std::array<NodeIndex, 2>>& lines) {
  std::vector<char> used(mesh.nodeCount(), 0);
  for (const MeshFace& face : faces)
    for (int k = 0; k < face.cornerCount; ++k) used[face.corners[k]] = 1;
  for (const auto& line : lines) used[line[0]] = used[line[1]] = 1;
  std::vector<NodeIndex> nodes;
  for (std::size_t n = 0; n < used.size(); ++n)
    if (used[n]) nodes.push_back(static_cast<NodeIndex>(n));
  return nodes;
}

// Whether the nodes lie in a plane z = const (to rounding, against the mesh's extent).
bool liesInPlaneZ(const Mesh& mesh, const std::vector<NodeIndex>& nodes) {
  BoundingBox box;
  for (NodeIndex n : nodes) box.include(mesh.node(n));
  const Vec3 extent = box.max - box.min;
  return extent.z <= 1e-9 * std::max({extent.x, extent.y, extent.z});
}

// Maps eye coordinates (x right, y up) into the picture: `box` centred, as large as fits
// inside a margin of 4% of the smaller side, y flipped downwards; depth scaled alike.
class PictureFit {
 public:
  PictureFit(const BoundingBox& box, int width, int height) : width_(width), height_(height) {
    const double margin = std::max(2.0, std::round(0.04 * std::min(width, height)));
    const double dx = box.max.x - box.min.x, dy = box.max.y - box.min.y;
    const double sx = dx > 0 ? (width - 2 * margin) / dx : 0;
    const double sy = dy > 0 ? (height - 2 * margin) / dy : 0;
    scale_ = sx > 0 && sy > 0 ? std::min(sx, sy) : std::max({sx, sy, 1.0});
    centre_ = 0.5 * (box.min + box.max);
  }
  Vec3 operator()(Vec3 eye) const {
    return {0.5 * width_ + (eye.x - centre_.x) * scale_,
            0.5 * height_ - (eye.y - centre_.y) * scale_, (eye.z - centre_.z) * scale_};
  }

 private:
  int width_, height_;
  double scale_ = 1;
  Vec3 centre_;
};

// The face's colour lit from the viewer (both sides alike): full where it faces the viewer,
// kAmbient of it edge-on.
Rgb shaded(Rgb color, const PictureFace& face) {
  const auto& c = face.corners;
  const Vec3 normal = face.cornerCount == 4 ? cross(c[2] - c[0], c[3] - c[1])
                                            : cross(c[1] - c[0], c[2] - c[0]);
  const double length = norm(normal);
  const double facing = length > 0 ? std::abs(normal.z) / length : 0;
  // In kShades steps: few colours, so that a PNG picture is an indexed one.
  const double light = kAmbient + (1 - kAmbient) * std::round(facing * kShades) / kShades;
  const auto channel = [&](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::lround(std::min(255.0, v * light)));
  };
  return {channel(color.r), channel(color.g), channel(color.b)};
}

double meanDepth(const PictureFace& face) {
  double sum = 0;
  for (int k = 0; k < face.cornerCount; ++k) sum += face.corners[k].z;
  return sum / face.cornerCount;
}

// Painter's order by mean depth; faces at the same depth keep their order.
void sortFarToNear(std::vector<PictureFace>& faces) {
  std::vector<double> depth(faces.size());
  std::vector<std::size_t> order(faces.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
    depth[i] = meanDepth(faces[i]);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return depth[a] < depth[b]; });
  std::vector<PictureFace> sorted;
  sorted.reserve(order.size());
  for (std::size_t i : order) sorted.push_back(faces[i]);
  faces = std::move(sorted);
}

// Where each of `nodes` lands in pixel space (indexed by node; other entries unset): turned
// as the options say (or by the default view), then fitted into the picture.
std::vector<Vec3> placeNodes(const Mesh& mesh, const std::vector<NodeIndex>& nodes,
                             const PictureOptions& options) {
  const std::array<double, 3> angles =
      options.rotation ? *options.rotation
                       : (liesInPlaneZ(mesh, nodes) ? std::array<double, 3>{0, 0, 0}
                                                    : kObliqueRotation);
  const Rotation rotation = rotationOf(angles);
  std::vector<Vec3> placed(mesh.nodeCount());
  BoundingBox eyeBox;
  for (NodeIndex n : nodes) {
    placed[n] = rotate(rotation, mesh.node(n));
    eyeBox.include(placed[n]);
  }
  const PictureFit fit(eyeBox, options.width, options.height);
  for (NodeIndex n : nodes) placed[n] = fit(placed[n]);
  return placed;
}

}  // namespace

Rgb entityColor(int tag) {
  // Hue from the fractional part of tag / golden ratio; saturation and value fixed.
  double hue = std::fmod(tag * 0.6180339887498949, 1.0);
  if (hue < 0) hue += 1;
  constexpr double kSaturation = 0.5, kValue = 0.93;
  const double h = hue * 6;
  const int sector = static_cast<int>(h) % 6;
  const double f = h - std::floor(h);
  const double p = kValue * (1 - kSaturation), q = kValue * (1 - kSaturation * f);
  const double t = kValue * (1 - kSaturation * (1 - f));
  const std::array<std::array<double, 3>, 6> rgb = {{{kValue, t, p},
                                                     {q, kValue, p},
                                                     {p, kValue, t},
                                                     {p, q, kValue},
                                                     {t, p, kValue},
                                                     {kValue, p, q}}};
  const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(v * 255)); };
  return {byte(rgb[sector][0]), byte(rgb[sector][1]), byte(rgb[sector][2])};
}

PictureOptions pictureOptionsOf(const MeshWriteOptions& options) {
  return {options.pictureWidth, options.pictureHeight, options.viewRotation};
}

Picture composePicture(const Model& model, const Mesh& mesh, const PictureOptions& options,
                       std::string_view format) {
  const std::string what(format);
  if (options.width <= 0 || options.height <= 0)
    throw std::invalid_argument(what + " pictures need a positive size, not " +
                                std::to_string(options.width) + "x" +
                                std::to_string(options.height));
  const std::vector<MeshFace> meshFaces = facesToDraw(model, mesh);
  const std::vector<std::array<NodeIndex, 2>> meshLines =
      meshFaces.empty() ? linesToDraw(mesh) : std::vector<std::array<NodeIndex, 2>>{};
  if (meshFaces.empty() && meshLines.empty())
    throw std::invalid_argument(what + " pictures show line, surface and volume elements: the " +
                                "mesh to save has none");

  const std::vector<Vec3> placed =
      placeNodes(mesh, nodesUsed(mesh, meshFaces, meshLines), options);
  Picture picture;
  picture.width = options.width;
  picture.height = options.height;
  picture.faces.reserve(meshFaces.size());
  for (const MeshFace& m : meshFaces) {
    PictureFace face;
    face.cornerCount = m.cornerCount;
    face.entity = m.entity;
    for (int k = 0; k < m.cornerCount; ++k) face.corners[k] = placed[m.corners[k]];
    face.fill = shaded(entityColor(m.entity.tag), face);
    picture.faces.push_back(face);
  }
  for (const auto& line : meshLines) picture.lines.push_back({placed[line[0]], placed[line[1]]});
  sortFarToNear(picture.faces);
  return picture;
}

}  // namespace geomesh
