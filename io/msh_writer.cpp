// The MSH writer: $MeshFormat, $PhysicalNames, each version's body, via a temporary file.
#include "io/msh_writer.h"

#include <map>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/msh_sections.h"

namespace geomesh {

void writeMeshFormat(MshEncoder& out, const char* version) {
  out.text("$MeshFormat\n");
  out.text(version);
  out.text(out.binary() ? " 1 8\n" : " 0 8\n");
  if (out.binary()) {
    out.integer(1);  // lets a reader detect the byte order
    out.text("\n");
  }
  out.text("$EndMeshFormat\n");
}

void endSection(MshEncoder& out, const char* endMarker) {
  if (out.binary()) out.text("\n");
  out.text(endMarker);
}

void writePhysicalNames(MshEncoder& out, const Model& model, const MeshPartitions* partitions) {
  std::map<EntityId, const PhysicalGroup*> groups;
  for (const auto& [id, group] : model.physicalGroups()) groups[id] = &group;
  if (partitions)
    for (const PhysicalGroup& group : partitions->physicalGroups)
      groups[{group.dim, group.tag}] = &group;
  std::string lines;
  std::size_t count = 0;
  for (const auto& [id, group] : groups) {
    if (group->name.empty()) continue;
    lines += std::to_string(id.dim) + " " + std::to_string(id.tag) + " \"" + group->name + "\"\n";
    ++count;
  }
  if (count == 0) return;
  out.text("$PhysicalNames\n" + std::to_string(count) + "\n" + lines + "$EndPhysicalNames\n");
}

void writeMsh(std::ostream& out, const Model& model, const Mesh& mesh,
              const MshWriteOptions& options) {
  const bool v41 = options.version == 4.1 || options.version == 4;
  if (!v41 && options.version != 2.2 && options.version != 2)
    throw std::invalid_argument("unsupported MSH version " + std::to_string(options.version) +
                                " (4.1 and 2.2 are supported)");
  const MshContent content =
      mesh.partitions()
          ? selectPartitionedContent(model, mesh, options.saveAll, options.onlyPartition)
          : selectMshContent(model, mesh, options.saveAll);
  MshEncoder encoder(out, options.binary);
  writeMeshFormat(encoder, v41 ? "4.1" : "2.2");
  writePhysicalNames(encoder, model, mesh.partitions());
  if (v41)
    writeMsh41Body(encoder, model, mesh, content);
  else
    writeMsh22Body(encoder, model, mesh, content, options);
  encoder.flush();
}

void writeMshFile(const std::string& path, const Model& model, const Mesh& mesh,
                  const MshWriteOptions& options) {
  writeFileAtomically(path, [&](std::ostream& out) { writeMsh(out, model, mesh, options); });
}

}  // namespace geomesh
