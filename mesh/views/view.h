// Views: post-processing data (values on points, lines, ... hexahedra) that scripts define,
// merge from files, compute with plugins, save, and use as mesh sizes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/core/element_type.h"

namespace geomesh::post {

// The element shapes a view holds, in the order of the parsed format's letters
// (P, L, T, Q, S, H, I, Y).
enum class ElementShape : std::uint8_t {
  Point, Line, Triangle, Quadrangle, Tetrahedron, Hexahedron, Prism, Pyramid
};
inline constexpr int kShapeCount = 8;
int cornerCount(ElementShape shape);     // 1, 2, 3, 4, 4, 8, 6, 5
int shapeDimension(ElementShape shape);  // 0 .. 3
char shapeLetter(ElementShape shape);    // 'P', 'L', 'T', 'Q', 'S', 'H', 'I', 'Y'
// Mesh element families and view shapes name the same kinds in the same order.
static_assert(static_cast<int>(ElementFamily::Pyramid) == static_cast<int>(ElementShape::Pyramid) &&
              static_cast<int>(ElementFamily::Tet) == static_cast<int>(ElementShape::Tetrahedron));
constexpr ElementShape shapeOfFamily(ElementFamily family) {
  return static_cast<ElementShape>(family);
}
constexpr ElementFamily familyOfShape(ElementShape shape) {
  return static_cast<ElementFamily>(shape);
}

// What each node carries: 1 (scalar), 3 (vector) or 9 (tensor, row by row) components.
enum class FieldKind : std::uint8_t { Scalar, Vector, Tensor };
int componentCount(FieldKind kind);
char kindLetter(FieldKind kind);  // 'S', 'V', 'T'

// The type of a list record by its name, as .pos files, View blocks and the API spell it: the
// field letter (S, V, T), the shape letter (P L T Q S H I Y), then "2" for second order (not
// for points): "SP", "VL", "ST2"...; nullopt for any other name.
struct ListType {
  FieldKind field = FieldKind::Scalar;
  ElementShape shape = ElementShape::Point;
  int order = 1;
};
std::optional<ListType> listTypeOf(std::string_view name);

// Elements of one shape, one field kind and one order (ST for scalar triangles, VS2 for
// vector second-order tetrahedra...). Element e has `nodesPerElement` nodes whose
// coordinates are coordinates[3 * (e * nodesPerElement + i) + {0,1,2}], and its values for
// every time step, step after step, each step node after node, each node its components:
// values[e * valuesPerElement() + (step * nodesPerElement + i) * components + c].
struct ElementList {
  ElementShape shape = ElementShape::Point;
  FieldKind kind = FieldKind::Scalar;
  int order = 1;            // 2 for the second-order records (SL2, ST2, ...)
  int nodesPerElement = 1;  // corners for order 1; corners and edge/face nodes for order 2
  int steps = 1;            // time steps of the values
  std::vector<double> coordinates;
  std::vector<double> values;

  int components() const;
  std::size_t size() const;  // elements
  std::size_t valuesPerElement() const;
  double value(std::size_t element, int step, int node, int component) const;
};

// A text annotation (T2: at window coordinates x, y; T3: at model coordinates x, y, z), one
// string per time step. `style` is the record's style number or its encoded attributes.
struct TextItem {
  int dimension = 2;
  double x = 0, y = 0, z = 0;
  double style = 0;
  std::vector<std::string> text;
};

// Data as a mesh file gave it ($NodeData, $ElementData, $ElementNodeData), kept so that a
// view read from an MSH file is written back the way it came. Tags are those of the mesh's
// nodes or elements; `counts` (element-node data only) gives each element's node count.
struct MeshData {
  enum class Kind : std::uint8_t { Node, Element, ElementNode };
  struct Step {
    double time = 0;
    int index = 0;  // the time step number the file gave
    std::vector<std::size_t> tags;
    std::vector<int> counts;
    std::vector<double> values;  // components per node (or per element's node)
  };
  Kind kind = Kind::Node;
  int components = 1;
  std::vector<Step> steps;
};

// One view: its tag (unique in the store, never reused), name, elements, time values, text
// items and the View[n].Option values scripts set (display options kept as given).
struct View {
  int tag = 0;
  std::string name;
  std::vector<ElementList> lists;
  std::vector<double> times;  // one per time step when the data gave them
  std::vector<TextItem> texts;
  std::map<std::string, double> numbers;       // View[n].X = 1;
  std::map<std::string, std::string> strings;  // View[n].Name = "..."; (Name is `name`)
  std::optional<MeshData> meshData;             // when read from (or made on) a mesh

  // The list of a shape, kind and order, made empty if there is none yet.
  ElementList& list(ElementShape shape, FieldKind kind, int order = 1);
  // Time steps: the most any list holds (at least 1 when the view has data), and the
  // smallest and largest value over all of them (for vectors and tensors, of the norm).
  int stepCount() const;
  double minimum() const;
  double maximum() const;
  bool empty() const;  // no element and no text
  std::size_t elementCount() const;
};

// The views of a session, in the order they were made: index 0 is the first (View[0] in a
// script names the view at index 0; views keep their tag when earlier ones are deleted).
class ViewStore {
 public:
  View& add(std::string name);  // a new empty view with the next tag
  std::size_t size() const { return views_.size(); }
  View& at(std::size_t index) { return *views_.at(index); }
  const View& at(std::size_t index) const { return *views_.at(index); }
  // The view of a tag; null if none has it.
  View* withTag(int tag);
  const View* withTag(int tag) const;
  // Index of the view of a tag; -1 if none.
  int indexOfTag(int tag) const;
  void remove(std::size_t index);
  void clear();

 private:
  std::vector<std::unique_ptr<View>> views_;
  int nextTag_ = 0;
};

}  // namespace geomesh::post
