// computeHomology: requests grouped by domain, complexes built, bases computed and saved.
#include "mesh/homology/homology.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>

#include "mesh/homology/chain_groups.h"

namespace geomesh {

namespace {

std::string tagList(const std::vector<int>& tags) {
  std::string text = "{";
  for (std::size_t i = 0; i < tags.size(); ++i) text += (i ? "," : "") + std::to_string(tags[i]);
  return text + "}";
}

// "{1},{70,71}" as the names of the groups show it; "{0}" stands for the whole mesh.
std::string domainText(const HomologyRequest& r) {
  return (r.domain.empty() ? std::string("{0}") : tagList(r.domain)) +
         (r.subdomain.empty() ? "" : "," + tagList(r.subdomain));
}

std::string spaceName(HomologyKind kind, int dim) {
  return (kind == HomologyKind::Homology ? "H_" : "H^") + std::to_string(dim);
}

const char* spacesWord(HomologyKind kind) {
  return kind == HomologyKind::Homology ? "homology" : "cohomology";
}

void warnAbout(MessageSink& log, const HomologyRequest& r, const std::string& message) {
  log.warning(r.origin.empty() ? message : r.origin + ": warning: " + message);
}

bool hasPhysicalTag(const Model& model, int tag) {
  for (const auto& [id, group] : model.physicalGroups())
    if (id.tag == tag) return true;
  return false;
}

// "v volumes, f faces, e edges and n vertices" for cell counts by dimension.
std::string describeSizes(const std::array<std::size_t, 4>& cells) {
  return std::to_string(cells[3]) + " volumes, " + std::to_string(cells[2]) + " faces, " +
         std::to_string(cells[1]) + " edges and " + std::to_string(cells[0]) + " vertices";
}

int meshDimension(const Mesh& mesh) {
  int top = 0;
  for (const auto& [id, em] : mesh.entities())
    if (em.elementCount() > 0) top = std::max(top, id.dim);
  return top;
}

// The cell complex of a request's domain relative to its subdomain, with warnings about the
// groups it names that the model lacks.
CellComplex requestComplex(const HomologyRequest& r, const Model& model, const Mesh& mesh,
                           MessageSink& log) {
  if (r.domain.empty()) {
    if (!r.subdomain.empty())
      log.info("The whole mesh is the domain: the subdomain " + tagList(r.subdomain) +
               " is left out");
    return buildCellComplex(highestDimensionElements(mesh), {});
  }
  for (const auto* list : {&r.domain, &r.subdomain})
    for (int tag : *list)
      if (!hasPhysicalTag(model, tag))
        warnAbout(log, r,
                  std::string(list == &r.domain ? "Homology domain" : "Homology subdomain") + " (" +
                      domainText(r) + "): there is no physical group " + std::to_string(tag));
  const std::vector<ComplexElement> domain = elementsOfGroups(model, mesh, r.domain);
  if (domain.empty())
    warnAbout(
        log, r,
        "Homology domain (" + domainText(r) + ") holds no mesh element: " + "every space is zero");
  return buildCellComplex(domain, elementsOfGroups(model, mesh, r.subdomain));
}

// The dimensions whose bases a request saves, with a warning for those out of range.
std::vector<int> savedDimensions(const HomologyRequest& r, int meshDim, MessageSink& log) {
  std::set<int> dims;
  for (int d : r.dims) {
    if (d >= 0 && d <= 3)
      dims.insert(d);
    else
      warnAbout(log, r, "Homology dimension " + std::to_string(d) + " is not 0 to 3; ignored");
  }
  if (r.dims.empty())
    for (int d = 0; d <= meshDim; ++d) dims.insert(d);
  return {dims.begin(), dims.end()};
}

void logRanks(const HomologyBases& bases, const std::string& text, MessageSink& log) {
  log.info("Ranks of domain (" + text + ") " + spacesWord(bases.kind) + " spaces:");
  for (int dim = 0; dim <= 3; ++dim) {
    std::string line = spaceName(bases.kind, dim) + " = " + std::to_string(bases.ranks[dim]);
    for (std::int64_t t : bases.torsion[dim]) line += " + Z/" + std::to_string(t);
    log.info(line);
  }
}

void saveBases(const HomologyRequest& r, const HomologyBases& bases, const CellComplex& complex,
               Model& model, Mesh& mesh, MessageSink& log) {
  const std::string text = domainText(r);
  for (int dim : savedDimensions(r, meshDimension(mesh), log)) {
    const auto& generators = bases.generators[dim];
    if (generators.empty()) continue;
    std::vector<int> tags;
    for (std::size_t i = 0; i < generators.size(); ++i)
      tags.push_back(addChainGroup(complex, generators[i], dim,
                                   spaceName(r.kind, dim) + text + std::to_string(i + 1), model,
                                   mesh));
    log.info("Basis of " + spaceName(r.kind, dim) + "(" + text + ") saved as physical groups " +
             tagList(tags));
  }
}

using DomainKey = std::pair<std::vector<int>, std::vector<int>>;

}  // namespace

void computeHomology(std::span<const HomologyRequest> requests, Model& model, Mesh& mesh,
                     MessageSink& log) {
  if (requests.empty()) return;
  std::map<DomainKey, std::vector<const HomologyRequest*>> groups;
  for (const HomologyRequest& r : requests) {
    auto& group = groups[{r.domain, r.subdomain}];
    const bool repeated = std::any_of(group.begin(), group.end(), [&](const auto* other) {
      return other->kind == r.kind && other->dims == r.dims;
    });
    if (!repeated) group.push_back(&r);
  }
  log.info("Homology and cohomology computation: " + std::to_string(groups.size()) +
           " cell complex" + (groups.size() == 1 ? "" : "es"));
  for (const auto& [key, group] : groups) {
    const std::string text = domainText(*group.front());
    const CellComplex complex = requestComplex(*group.front(), model, mesh, log);
    log.info("Cell complex of domain (" + text + "): " +
             describeSizes({complex.count(0), complex.count(1), complex.count(2),
                            complex.count(3)}));
    std::optional<HomologyBases> cached[2];
    for (const HomologyRequest* r : group) {
      auto& bases = cached[r->kind == HomologyKind::Homology ? 0 : 1];
      if (!bases) {
        bases = computeHomologyBases(complex, r->kind);
        log.info("Reduced for " + std::string(spacesWord(r->kind)) + " to " +
                 describeSizes(bases->reducedCells));
        logRanks(*bases, text, log);
      }
      saveBases(*r, *bases, complex, model, mesh, log);
    }
  }
}

}  // namespace geomesh
