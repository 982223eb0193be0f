/// \file
/// \brief Greedy merging of convex pieces into hulls of unions (containment is kept by
/// construction: proofs/shape-containment.md#merging).

#include "grpvss/exact/piece_merging.hpp"

#include <limits>
#include <optional>
#include <utility>

namespace grpvss::geometry {

namespace {

struct Box {
  Eigen::Vector3d lo, hi;
};

Box bounding_box(const ConvexPolytope& p) {
  Box box{p.vertices().front(), p.vertices().front()};
  for (const auto& v : p.vertices()) {
    box.lo = box.lo.cwiseMin(v);
    box.hi = box.hi.cwiseMax(v);
  }
  return box;
}

bool touching(const Box& a, const Box& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

ConvexPolytope hull_of_union(const ConvexPolytope& a, const ConvexPolytope& b) {
  std::vector<Eigen::Vector3d> points = a.vertices();
  points.insert(points.end(), b.vertices().begin(), b.vertices().end());
  return ConvexPolytope::from_points(points);
}

/// Index of the thinnest live, unsettled piece, or -1.
int thinnest(const std::vector<std::optional<ConvexPolytope>>& pieces,
             const std::vector<char>& settled) {
  int best = -1;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (!pieces[i] || settled[i]) continue;
    if (best < 0 || pieces[i]->volume() < pieces[static_cast<std::size_t>(best)]->volume()) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace

// proof: proofs/shape-containment.md#merging (conv(A u B) contains A and B)
std::vector<ConvexPolytope> merge_pieces(std::vector<ConvexPolytope> input, double volume_budget) {
  std::vector<std::optional<ConvexPolytope>> pieces(input.begin(), input.end());
  std::vector<char> settled(pieces.size(), 0);
  double spent = 0.0;
  for (int i = thinnest(pieces, settled); i >= 0; i = thinnest(pieces, settled)) {
    const auto ii = static_cast<std::size_t>(i);
    const Box box = bounding_box(*pieces[ii]);
    std::optional<ConvexPolytope> best;
    std::size_t best_partner = 0;
    double best_added = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < pieces.size(); ++j) {
      if (j == ii || !pieces[j] || !touching(box, bounding_box(*pieces[j]))) continue;
      ConvexPolytope merged = hull_of_union(*pieces[ii], *pieces[j]);
      const double added = merged.volume() - pieces[ii]->volume() - pieces[j]->volume();
      if (added < best_added) {
        best_added = added;
        best = std::move(merged);
        best_partner = j;
      }
    }
    if (best && spent + std::max(best_added, 0.0) <= volume_budget) {
      spent += std::max(best_added, 0.0);
      pieces[best_partner] = std::move(best);
      settled[best_partner] = 0;  // the union may merge on
      pieces[ii].reset();
    } else {
      settled[ii] = 1;
    }
  }
  std::vector<ConvexPolytope> out;
  for (auto& p : pieces) {
    if (p) out.push_back(std::move(*p));
  }
  return out;
}

}  // namespace grpvss::geometry
