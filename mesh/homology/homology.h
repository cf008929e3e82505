// Homology and cohomology requests (Homology, Cohomology in scripts), computed on a mesh once
// it is generated, their bases saved as physical groups.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/homology/homology_bases.h"

namespace geomesh {

// Bases of the spaces H_k(domain, subdomain) (or H^k) over the integers. `domain` and
// `subdomain` list physical tags (of any dimension): an empty domain is the whole mesh (its
// elements of the highest dimension; the subdomain is then left out, as the reference does),
// an empty subdomain gives absolute (co)homology. `dims` lists the dimensions whose bases are saved
// (empty: all). `origin`
// ("file:line:col" of the statement, may be empty) prefixes the warnings about the request.
struct HomologyRequest {
  HomologyKind kind = HomologyKind::Homology;
  std::vector<int> domain, subdomain, dims;
  std::string origin;
};

// Carries out the requests in the reference's order: grouped by (domain, subdomain),
// ascending; within a group in the order given, a request repeated exactly done once; the
// cell complex of a group built once. Logs the ranks of every space, and saves each basis
// element of a requested dimension through addChainGroup under a name such as
// "H_1{1},{70,71}2" (the second basis chain of H_1, domain {1}, subdomain {70,71}; "H^1" for
// cohomology; "{0}" for the whole mesh). A domain naming no physical group, or holding no
// element, is warned of and gives zero spaces; a subdomain naming none is warned of and left
// out. Throws std::overflow_error if the integer reduction overflows.
void computeHomology(std::span<const HomologyRequest> requests, Model& model, Mesh& mesh,
                     MessageSink& log);

}  // namespace geomesh
