/// \file
/// \brief The hull / parts / exact decomposition modes (proofs/shape-containment.md#theorem-mesh-cover).

#include "grpvss/exact/mesh_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_group_decomposition.hpp"
#include "grpvss/exact/exact_volume.hpp"
#include "grpvss/exact/mesh_point_hull.hpp"
#include "grpvss/exact/mesh_validation.hpp"

namespace grpvss::geometry {

namespace {

/// A group's triangles as a compact surface: its welded vertices and local triangles.
struct LocalSurface {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

LocalSurface local_surface(const MeshTopology& topology, const std::vector<int>& group) {
  LocalSurface surface;
  std::map<int, int> local;  // welded id -> local index, in welded-id order
  for (int t : group) {
    for (int w : topology.triangles[static_cast<std::size_t>(t)]) local.emplace(w, 0);
  }
  for (auto& [welded, index] : local) {
    index = static_cast<int>(surface.vertices.size());
    surface.vertices.push_back(topology.welded_points[static_cast<std::size_t>(welded)]);
  }
  for (int t : group) {
    const auto& w = topology.triangles[static_cast<std::size_t>(t)];
    surface.triangles.push_back({local[w[0]], local[w[1]], local[w[2]]});
  }
  return surface;
}

std::string percent_text(double ratio) {
  return std::to_string(static_cast<long long>(std::lround((ratio - 1.0) * 100.0))) + "%";
}

/// Collects pieces, their exact volumes and the warnings of one decompose_mesh() call.
class PieceCollector {
 public:
  PieceCollector(const TriangleMesh& mesh, const MeshTopology& topology,
                 const DecompositionOptions& options)
      : mesh_(mesh), topology_(topology), options_(options) {}

  void warn(std::string text) { out_.warnings.push_back({mesh_.source, 0, std::move(text)}); }

  void add(const ConvexPolytope& piece, std::string origin) {
    six_volume_sum_ += six_volume(piece);
    out_.pieces.push_back(piece.vertices());
    out_.piece_origins.push_back(std::move(origin));
  }

  /// The verified hull of the group's vertices (proofs/shape-containment.md#lemma-hull-cover).
  ConvexPolytope hull(const std::vector<int>& group, const std::string& origin) {
    return mesh_point_hull(local_surface(topology_, group).vertices, options_.flat_thickness,
                           mesh_.source, origin, out_.warnings);
  }

  void add_hull(const std::vector<int>& group, const std::string& origin) {
    add(hull(group, origin), origin);
  }

  void add_exact(const std::vector<int>& group, const std::string& origin);

  std::string label(const std::vector<int>& group) const {
    std::string text = "component of triangle " + std::to_string(group.front());
    if (mesh_.part_names.empty()) return text;
    const int part = mesh_.triangle_part[static_cast<std::size_t>(group.front())];
    for (int t : group) {
      if (mesh_.triangle_part[static_cast<std::size_t>(t)] != part) return text;
    }
    return "part '" + mesh_.part_names[static_cast<std::size_t>(part)] + "', " + text;
  }

  ConvexPieces finish();

 private:
  const TriangleMesh& mesh_;
  const MeshTopology& topology_;
  const DecompositionOptions& options_;
  ConvexPieces out_;
  mpq_class six_volume_sum_ = 0;
};

void PieceCollector::add_exact(const std::vector<int>& group, const std::string& origin) {
  if (const auto problem = oriented_manifold_problem(mesh_, topology_, group)) {
    warn(origin + ": not decomposed exactly (" + *problem + "); its convex hull is used");
    add_hull(group, origin);
    return;
  }
  const ConvexPolytope group_hull = hull(group, origin);
  LocalSurface surface = local_surface(topology_, group);
  ExactGroupPieces exact =
      exact_group_pieces(surface.vertices, std::move(surface.triangles), group_hull,
                         options_.merge_volume_fraction);
  if (exact.fallback_reason) {
    warn(origin + ": not decomposed exactly (" + *exact.fallback_reason +
         "); its convex hull is used");
    add(group_hull, origin);
    return;
  }
  if (exact.convex) {
    add(exact.pieces.front(), origin);
    return;
  }
  for (std::size_t i = 0; i < exact.pieces.size(); ++i) {
    add(exact.pieces[i], "exact piece " + std::to_string(i) + " of " + origin);
  }
}

ConvexPieces PieceCollector::finish() {
  if (topology_.closed_and_oriented()) {
    const mpq_class mesh_six =
        abs(six_signed_volume(topology_.welded_points, topology_.triangles));
    if (sgn(mesh_six) > 0) out_.volume_ratio = mpq_class(six_volume_sum_ / mesh_six).get_d();
  }
  if (out_.volume_ratio && *out_.volume_ratio > options_.warn_volume_ratio) {
    const double ratio = *out_.volume_ratio;
    const std::string count = std::to_string(out_.pieces.size());
    switch (options_.mode) {
      case DecomposeMode::kHull:
        warn("one convex hull adds " + percent_text(ratio) +
             " volume; consider decompose: parts or exact");
        break;
      case DecomposeMode::kParts:
        warn("the " + count + " part hulls add " + percent_text(ratio) +
             " volume; consider decompose: exact");
        break;
      case DecomposeMode::kExact:
        warn("the " + count + " pieces add " + percent_text(ratio) +
             " volume (hulls where the exact decomposition did not apply)");
        break;
    }
  }
  return std::move(out_);
}

void warn_about_structure(const MeshTopology& topology, PieceCollector& collector) {
  if (topology.unused_vertices == 1) {
    collector.warn("1 vertex is used by no triangle and is ignored");
  } else if (topology.unused_vertices > 1) {
    collector.warn(std::to_string(topology.unused_vertices) +
                   " vertices are used by no triangle and are ignored");
  }
  if (!topology.closed()) {
    std::string text = "the mesh is not closed: " + std::to_string(topology.odd_edges) +
                       " edges are used by an odd number of triangles";
    if (const auto& e = topology.first_open_edge) {
      text += " (first open edge: " + std::to_string(e->from) + "-" + std::to_string(e->to) +
              " of triangle " + std::to_string(e->triangle) + ")";
    }
    collector.warn(text + "; it bounds no solid: the pieces contain every triangle, and its "
                          "open part is covered by one convex hull");
  }
}

/// parts / exact: closed (part, component) groups, then closed components of the rest, then
/// one hull for the triangles left (proofs/shape-containment.md#theorem-mesh-cover).
void add_group_pieces(const TriangleMesh& mesh, const MeshTopology& topology, bool exact,
                      PieceCollector& collector) {
  std::vector<int> rest(mesh.triangles.size());
  for (std::size_t t = 0; t < rest.size(); ++t) rest[t] = static_cast<int>(t);
  for (const bool by_part : {true, false}) {
    if (!by_part && mesh.part_names.empty()) continue;  // the first pass already did this
    std::vector<int> open;
    for (const auto& group : connected_triangle_groups(mesh, topology, rest, by_part)) {
      if (!group_is_closed(mesh, topology, group)) {
        open.insert(open.end(), group.begin(), group.end());
      } else if (exact) {
        collector.add_exact(group, collector.label(group));
      } else {
        collector.add_hull(group, collector.label(group));
      }
    }
    std::sort(open.begin(), open.end());
    rest = std::move(open);
  }
  if (!rest.empty()) collector.add_hull(rest, "open triangles");
}

}  // namespace

std::optional<DecomposeMode> parse_decompose_mode(std::string_view name) {
  if (name == "hull") return DecomposeMode::kHull;
  if (name == "parts") return DecomposeMode::kParts;
  if (name == "exact") return DecomposeMode::kExact;
  return std::nullopt;
}

std::string_view decompose_mode_name(DecomposeMode mode) {
  switch (mode) {
    case DecomposeMode::kHull: return "hull";
    case DecomposeMode::kParts: return "parts";
    case DecomposeMode::kExact: return "exact";
  }
  return "hull";
}

// proof: proofs/shape-containment.md#theorem-mesh-cover
ConvexPieces decompose_mesh(const TriangleMesh& mesh, const DecompositionOptions& options) {
  if (!(options.warn_volume_ratio >= 1.0)) {
    throw std::invalid_argument("warn_volume_ratio must be >= 1");
  }
  if (!(options.merge_volume_fraction >= 0.0 && options.merge_volume_fraction <= 1.0)) {
    throw std::invalid_argument("merge_volume_fraction must be in [0, 1]");
  }
  validate_mesh(mesh);
  const MeshTopology topology = mesh_topology(mesh);
  PieceCollector collector(mesh, topology, options);
  warn_about_structure(topology, collector);
  if (options.mode == DecomposeMode::kHull) {
    std::vector<int> all(mesh.triangles.size());
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
    collector.add_hull(all, "all triangles");
  } else {
    add_group_pieces(mesh, topology, options.mode == DecomposeMode::kExact, collector);
  }
  return collector.finish();
}

}  // namespace grpvss::geometry
