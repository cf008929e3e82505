// OFF reader (ASCII): the header keyword (OFF, or a variant with colours, normals or texture
// coordinates: COFF, NOFF, STOFF, ...), the vertex, face and edge counts, a line per vertex
// (its first three numbers) and a line per face (its vertex count, its vertices; a colour may
// follow). Faces of 3 or 4 vertices become triangles and quadrangles of one discrete surface.
// '#' starts a comment.
#include <cstdint>
#include <istream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"
#include "io/polygon_faces.h"

namespace geomesh {

namespace {

// The words of the next line that has any, without its comment; fails at the end of the file.
std::vector<std::string_view> nextWords(MeshScanner& in) {
  for (;;) {
    if (!in.hasLine()) in.fail("unexpected end of file");
    std::string_view line = in.line();
    std::vector<std::string_view> words = wordsOf(line.substr(0, line.find('#')));
    if (!words.empty()) return words;
  }
}

bool isOffKeyword(std::string_view word) {
  if (!word.ends_with("OFF")) return false;
  word.remove_suffix(3);
  return word.find_first_not_of("STCN") == std::string_view::npos;
}

struct OffCounts {
  std::uint64_t vertices = 0;
  std::uint64_t faces = 0;
};

OffCounts readHeader(MeshScanner& in) {
  std::vector<std::string_view> words = nextWords(in);
  if (!isOffKeyword(words[0]))
    in.fail("not an OFF file: expected 'OFF', found '" + std::string(words[0].substr(0, 40)) +
            "'");
  words.erase(words.begin());  // the counts may follow on the same line
  if (words.empty()) words = nextWords(in);
  if (words.size() < 2) in.fail("expected the vertex, face and edge counts");
  OffCounts counts{parseNumber<std::uint64_t>(in, words[0], "a vertex count"),
                   parseNumber<std::uint64_t>(in, words[1], "a face count")};
  // Each vertex and face takes a line of at least two characters.
  if (counts.vertices > in.remaining() / 2 || counts.faces > in.remaining() / 2)
    in.fail("the counts exceed the size of the file");
  return counts;
}

void readVertices(MeshScanner& in, std::uint64_t count, Mesh& mesh) {
  mesh.reserveNodes(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::vector<std::string_view> words = nextWords(in);
    if (words.size() < 3) in.fail("vertex " + std::to_string(i) + " has fewer than 3 coordinates");
    mesh.addNode({parseNumber<double>(in, words[0], "a coordinate"),
                  parseNumber<double>(in, words[1], "a coordinate"),
                  parseNumber<double>(in, words[2], "a coordinate")});
  }
}

void readFaces(MeshScanner& in, std::uint64_t count, PolygonFaces& faces) {
  std::vector<std::int64_t> vertices;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::vector<std::string_view> words = nextWords(in);
    const auto n = parseNumber<std::uint64_t>(in, words[0], "a vertex count");
    if (n >= words.size()) in.fail("face " + std::to_string(i) + " lists fewer than " +
                                   std::to_string(n) + " vertices");
    vertices.clear();
    for (std::uint64_t k = 1; k <= n; ++k)
      vertices.push_back(parseNumber<std::int64_t>(in, words[k], "a vertex index"));
    faces.add(vertices, i);
  }
}

}  // namespace

// Named by the off row of io/formats.cpp.
void readOff(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    MeshScanner scanner(data, name);
    const OffCounts counts = readHeader(scanner);
    readVertices(scanner, counts.vertices, mesh);
    PolygonFaces faces(scanner, counts.vertices);
    readFaces(scanner, counts.faces, faces);
    faces.moveInto(mesh);
    addDiscreteEntities(model, mesh);
  });
}

}  // namespace geomesh
