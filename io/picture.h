// Picture: what a view of a mesh shows, ready to draw: its faces projected into pixel space,
// flat-shaded and in painter's order (farthest first), or its lines when it has no face.
// The SVG writer draws it as polygons, the PNG writer rasterizes it (io/picture_raster.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "io/formats.h"
#include "kernel/model.h"
#include "kernel/vec3.h"
#include "mesh/core/mesh.h"

namespace geomesh {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

inline constexpr Rgb kPictureBackground{255, 255, 255};
inline constexpr Rgb kPictureEdge{34, 34, 34};  // element edges and line elements

// The colour of the faces of surface (or volume) `tag` before shading: hues spread by the
// golden ratio, so that neighbouring tags differ, the same for a tag in every picture.
Rgb entityColor(int tag);

struct PictureOptions {
  int width = 800;
  int height = 600;
  // Euler angles in degrees, as General.RotationX, Y, Z: the model is turned about z, then y,
  // then x, and seen from +z. Unset: a mesh in a plane z = const is seen from +z, any other
  // mesh from an oblique direction above its (+x, -y) side, -y the side seen most.
  std::optional<std::array<double, 3>> rotation;
};

// The size and view that the writers' options ask for.
PictureOptions pictureOptionsOf(const MeshWriteOptions& options);

// A point in pixel space: x to the right, y down, z towards the viewer (larger is nearer).
struct PictureFace {
  std::array<Vec3, 4> corners;
  int cornerCount = 3;  // 3 or 4
  Rgb fill;             // the entity's colour, shaded
  EntityId entity;      // the surface, or the volume whose boundary face it is
};

struct PictureLine {
  Vec3 from, to;
};

struct Picture {
  int width = 0, height = 0;
  std::vector<PictureFace> faces;  // farthest first
  std::vector<PictureLine> lines;  // only when there is no face
};

// The view of `mesh` that `options` ask for, fitted into the picture with a margin. Faces are
// the 2D elements of every entity (high-order ones by their corners), and for a volume whose
// boundary surfaces have no element, the faces its elements do not share; lines are the 1D
// elements, drawn when there is no face. Throws std::invalid_argument naming `format` when
// there is nothing to draw, or when the size is not positive.
Picture composePicture(const Model& model, const Mesh& mesh, const PictureOptions& options,
                       std::string_view format);

}  // namespace geomesh
