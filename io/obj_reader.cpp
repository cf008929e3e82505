// Wavefront OBJ reader (ASCII). One statement a line; '#' starts a comment, and a backslash
// that ends a line (not within its comment) joins the next line to it. Read:
//   v x y z [w]   a vertex; numbers after z (a weight, a colour) are not used
//   f r1 r2 r3 ...  a face; each vertex reference is i, i/t, i//n or i/t/n, where the vertex
//                 index i counts from 1, or back from the last vertex read when negative (-1 is
//                 that vertex); a face uses the vertices read before it; the texture and normal
//                 indices t and n are checked but not used
//   o name, g name  the faces that follow belong to the surface of that name
// Faces of 3 vertices become triangles, of 4 quadrangles; a face of more vertices is split into
// triangles by a fan from its first vertex (right for convex faces). Each name becomes one
// discrete surface, numbered 1, 2, ... in the order of the names' first faces; faces before any
// o or g (or after an o or g without a name) are on the surface of the empty name. As with STL
// solids, the names themselves are not kept. Every other statement (vt, vn, vp, l, p, s,
// usemtl, mtllib, free-form geometry, ...) is skipped.
#include <algorithm>
#include <cstdint>
#include <istream>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"

namespace geomesh {

namespace {

std::string_view withoutComment(std::string_view line) {
  line = line.substr(0, line.find('#'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r'))
    line.remove_suffix(1);
  return line;
}

// The next statement: the next line without its comment and, while it ends with a backslash,
// joined with a space to the line that follows (kept in `joined`).
std::string_view nextStatement(MeshScanner& in, std::string& joined) {
  std::string_view line = withoutComment(in.line());
  if (!line.ends_with('\\')) return line;
  joined.assign(line.substr(0, line.size() - 1));
  while (in.hasLine()) {  // a backslash on the last line continues nothing
    line = withoutComment(in.line());
    joined += ' ';
    if (!line.ends_with('\\')) return joined += line;
    joined += line.substr(0, line.size() - 1);
  }
  return joined;
}

// The faces of each named surface, in the order of the names' first faces.
class ObjSurfaces {
 public:
  // The faces that follow belong to the surface named `name`.
  void select(std::string name) {
    currentName_ = std::move(name);
    const auto it = surfaceOfName_.find(currentName_);
    current_ = it == surfaceOfName_.end() ? kNone : it->second;
  }

  void addFace(const std::vector<NodeIndex>& vertices) {
    if (current_ == kNone) {
      current_ = surfaces_.size();
      surfaceOfName_.emplace(currentName_, current_);
      surfaces_.emplace_back();
    }
    Faces& faces = surfaces_[current_];
    if (vertices.size() == 4) {
      faces.quads.nodes.insert(faces.quads.nodes.end(), vertices.begin(), vertices.end());
      return;
    }
    for (std::size_t k = 1; k + 1 < vertices.size(); ++k)
      faces.triangles.nodes.insert(faces.triangles.nodes.end(),
                                   {vertices[0], vertices[k], vertices[k + 1]});
  }

  // Surface k + 1 of `mesh` gets the faces of the k-th name.
  void moveInto(Mesh& mesh) {
    for (std::size_t k = 0; k < surfaces_.size(); ++k) {
      EntityMesh& em = mesh.entity({2, static_cast<int>(k + 1)});
      for (ElementBlock* block : {&surfaces_[k].triangles, &surfaces_[k].quads})
        if (block->size() > 0) em.block(block->type) = std::move(*block);
    }
  }

 private:
  struct Faces {
    ElementBlock triangles{ElementType::Triangle3, {}};
    ElementBlock quads{ElementType::Quad4, {}};
  };
  static constexpr std::size_t kNone = ~std::size_t{0};

  std::vector<Faces> surfaces_;
  std::unordered_map<std::string, std::size_t> surfaceOfName_;
  std::string currentName_;
  std::size_t current_ = kNone;
};

void readVertex(MeshScanner& in, const std::vector<std::string_view>& words, Mesh& mesh) {
  if (words.size() < 4)
    in.fail("vertex " + std::to_string(mesh.nodeCount() + 1) + " has fewer than 3 coordinates");
  if (mesh.nodeCount() >= std::numeric_limits<NodeIndex>::max())
    in.fail("too many vertices: at most " +
            std::to_string(std::numeric_limits<NodeIndex>::max()) + " are read");
  mesh.addNode({parseNumber<double>(in, words[1], "a coordinate"),
                parseNumber<double>(in, words[2], "a coordinate"),
                parseNumber<double>(in, words[3], "a coordinate")});
}

// Checks the texture and normal indices after a vertex index: "", "/t", "//n" or "/t/n".
void checkTextureAndNormal(const MeshScanner& in, std::string_view reference,
                           std::string_view after) {
  if (after.empty()) return;
  const std::size_t slash = after.find('/', 1);
  const std::string_view texture = after.substr(1, slash - 1);
  const std::string_view normal =
      slash == std::string_view::npos ? std::string_view() : after.substr(slash + 1);
  if (slash == std::string_view::npos ? texture.empty() : normal.empty())
    in.fail("expected a vertex reference (i, i/t, i//n or i/t/n), found '" +
            std::string(reference.substr(0, 40)) + "'");
  if (!texture.empty()) parseNumber<std::int64_t>(in, texture, "a texture index");
  if (!normal.empty()) parseNumber<std::int64_t>(in, normal, "a normal index");
}

// The mesh node of a face's vertex reference (i, i/t, i//n or i/t/n), among the `count`
// vertices read before the face.
NodeIndex vertexOf(const MeshScanner& in, std::string_view reference, std::size_t count) {
  const std::size_t slash = std::min(reference.find('/'), reference.size());
  const auto i = parseNumber<std::int64_t>(in, reference.substr(0, slash), "a vertex index");
  checkTextureAndNormal(in, reference, reference.substr(slash));
  const auto n = static_cast<std::int64_t>(count);
  if (i == 0) in.fail("face uses vertex 0, but vertices are numbered from 1 (or back from -1)");
  if (i > n || i < -n)
    in.fail("face uses vertex " + std::to_string(i) + ", but " + std::to_string(count) +
            (count == 1 ? " vertex comes" : " vertices come") + " before it");
  return static_cast<NodeIndex>(i > 0 ? i - 1 : n + i);
}

void readFace(MeshScanner& in, const std::vector<std::string_view>& words, std::size_t count,
              std::vector<NodeIndex>& vertices, ObjSurfaces& surfaces) {
  vertices.clear();
  for (std::size_t k = 1; k < words.size(); ++k) vertices.push_back(vertexOf(in, words[k], count));
  if (vertices.size() < 3)
    in.fail("face has " + std::to_string(vertices.size()) +
            (vertices.size() == 1 ? " vertex" : " vertices") + ": at least 3 are needed");
  surfaces.addFace(vertices);
}

// The rest of an o or g statement, its words joined by single spaces.
std::string nameOf(const std::vector<std::string_view>& words) {
  std::string name;
  for (std::size_t k = 1; k < words.size(); ++k) {
    if (k > 1) name += ' ';
    name += words[k];
  }
  return name;
}

void readStatements(MeshScanner& in, Mesh& mesh) {
  ObjSurfaces surfaces;
  std::string joined;
  std::vector<NodeIndex> vertices;
  while (in.hasLine()) {
    const std::vector<std::string_view> words = wordsOf(nextStatement(in, joined));
    if (words.empty()) continue;
    if (words[0] == "v")
      readVertex(in, words, mesh);
    else if (words[0] == "f")
      readFace(in, words, mesh.nodeCount(), vertices, surfaces);
    else if (words[0] == "o" || words[0] == "g")
      surfaces.select(nameOf(words));
  }
  surfaces.moveInto(mesh);
}

}  // namespace

// Named by the obj row of io/formats.cpp.
void readObj(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    MeshScanner scanner(data, name);
    readStatements(scanner, mesh);
    addDiscreteEntities(model, mesh);
  });
}

}  // namespace geomesh
