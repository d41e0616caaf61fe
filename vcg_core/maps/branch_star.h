// The star of a branch point: its one-ring in order, and the rings around it re-embedded.
//
// In:  face incidence and a vertex; for the re-embedding also the mesh, the sphere positions, a
//      branch vertex whose image is the branch value with its one-ring already placed to wind
//      twice around it, and how many rings out to go.
// Out: `ordered_ring`: the one-ring counter-clockwise seen from outside (faces (vertex, ring[j],
//      ring[j + 1])), starting at the first face's neighbour; empty if it is not a simple cycle.
//      `reembed_around_branch`: the vertices 2 to `rings` rings from the branch vertex placed
//      between its one-ring and the next ring out (both kept) so that the map stays a double
//      cover there: in the gnomonic chart at the branch value, unwound by a square root (the
//      one-ring and the outer ring each turn twice around the value, so once after it), by
//      Floater's embedding (floater_embedding.h), and wound up again. With `OneRing::moves`
//      the one-ring is placed too (1 to `rings` rings, the branch vertex pinned at the value): for
//      a fold inside the star itself. Returns the new positions (the caller judges them), or
//      nothing where the rings do not turn twice or leave the chart.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/mesh_edges.h"

namespace meromorph {

std::vector<int> ordered_ring(const FaceIncidence &in, int vertex);

enum class OneRing { kept, moves };

std::optional<std::vector<std::pair<int, Eigen::Vector3d>>>
reembed_around_branch(const Mesh &mesh, const FaceIncidence &in,
                      const std::vector<Eigen::Vector3d> &sphere, int branch, int rings,
                      OneRing one_ring = OneRing::kept);

} // namespace meromorph
