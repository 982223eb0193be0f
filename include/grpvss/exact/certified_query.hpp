#pragma once
/// \file
/// \brief The certified pair query: double GJK proposes, directed-rounding arithmetic
/// certifies, the exact core (exact_contact.hpp, separation_witness.hpp) decides the rest.
///
/// A wrong answer is impossible by construction (proof: proofs/fast-path.md#certified-query):
/// - kSeparated from the filter: the plane inequalities
///   \f$\max_a n\cdot a \le o_a < o_b \le \min_b n\cdot b\f$ are evaluated with upward/downward
///   rounding, so they hold for the exact values; the lower bound
///   \f$\mathrm{RD}(\mathrm{RD}(o_b - o_a)/\mathrm{RU}(|n|))\f$ never exceeds the distance.
/// - kOverlapping from the filter: the origin is strictly inside the tetrahedron of four
///   exact differences \f$a_{i_k} - b_{j_k}\f$, proven by interval orientation signs; hence
///   \f$0 \in \mathrm{int}(\mathrm{conv}A - \mathrm{conv}B)\f$ and the interiors meet.
/// - Everything else (near contact, touching, GJK failure) is decided by classify_exact().

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/exact_contact.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/geometry/separation_witness.hpp"

namespace grpvss::geometry {

/// \brief Which stage produced the answer.
enum class DecidedBy {
  kIntervalFilter,  ///< GJK + directed-rounding certificate
  kExactFallback,   ///< classify_exact / exact_separation_witness
};

/// \brief Printable name: "interval-filter", "exact-fallback".
const char* to_string(DecidedBy decided_by);

/// \brief The answer of certified_pair_query().
struct CertifiedPairResult {
  Contact contact = Contact::kOverlapping;
  /// Present only if contact == kSeparated; passes check_witness_exactly(a, b, *witness,
  /// clearance_lower_bound). Normal points from A to B. Absent for a separated pair only when
  /// the gap is below what a double slab can express (~1e-16 of the coordinates; see
  /// exact_separation_witness()): then decided_by == kExactFallback, the separation rests on
  /// classify_exact() alone and clearance_lower_bound == 0.
  std::optional<SeparationWitness> witness;
  /// Proven \f$0 \le\f$ clearance_lower_bound \f$\le \mathrm{dist}(\mathrm{conv}A,
  /// \mathrm{conv}B)\f$; 0 unless separated.
  double clearance_lower_bound = 0.0;
  /// Double GJK distance (reports only, never a decision); 0 unless GJK saw a gap.
  double distance_estimate = 0.0;
  DecidedBy decided_by = DecidedBy::kExactFallback;
};

/// \brief Certified three-way contact of conv(a) and conv(b), with a separation witness and a
/// proven clearance lower bound when separated.
/// \param warm_start_direction optional normal believed to separate A (below) from B (above),
///        e.g. the previous step's witness normal.
/// \throws std::invalid_argument if a set is empty; DegenerateHullError if the exact fallback
///         is needed and a set does not span 3-D.
/// \param a_skeleton optional vertex graph of conv(a) for GJK's support search (gjk()); the
///        certificate is decided over all points whatever GJK proposes.
/// \param a_climb_hint optional, with a_skeleton: in, where GJK's first climb starts; out, the
///        last support point of A it found (the next query of the pair starts there).
/// \param b_skeleton, b_climb_hint the same for B.
CertifiedPairResult certified_pair_query(const std::vector<Eigen::Vector3d>& a,
                                         const std::vector<Eigen::Vector3d>& b,
                                         const Eigen::Vector3d* warm_start_direction = nullptr,
                                         const HullSkeleton* a_skeleton = nullptr,
                                         int* a_climb_hint = nullptr,
                                         const HullSkeleton* b_skeleton = nullptr,
                                         int* b_climb_hint = nullptr);

/// \brief A separation proven by the filter: the witness and its rounded-down bound.
struct CertifiedSeparation {
  SeparationWitness witness;
  double lower_bound = 0.0;  ///< \f$\ge 0\f$ and \f$\le (o_b - o_a)/|n|\f$
};

/// \brief The slab {n, o_a, o_b} with its bound RD(RD(o_b - o_a) / RU|n|) when o_b > o_a, for
/// offsets already proven (every a has n.a <= o_a, every b has n.b >= o_b); nullopt otherwise.
/// Needs an active rounding::UpwardRoundingScope. proof: proofs/fast-path.md#certified-separation
std::optional<CertifiedSeparation> slab_between(const Eigen::Vector3d& normal_AB, double offset_a,
                                                double offset_b);

/// \brief The filter's answer for a proven separation (decided_by kIntervalFilter).
CertifiedPairResult filter_separation(const CertifiedSeparation& separation, double distance_estimate);

/// \brief Tries to prove that the plane family with normal \p normal_AB (from A to B)
/// separates conv(a) and conv(b) strictly. nullopt if the rounded offsets leave no gap.
std::optional<CertifiedSeparation> certify_separation(const std::vector<Eigen::Vector3d>& a,
                                                      const std::vector<Eigen::Vector3d>& b,
                                                      const Eigen::Vector3d& normal_AB);

/// \brief Tries to prove that the origin lies strictly inside the tetrahedron with vertices
/// \f$a_{ia[k]} - b_{ib[k]}\f$, k = 0..3 (which proves the interiors of conv(a) and conv(b)
/// intersect). False when the interval signs are not conclusive.
bool certify_overlap(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                     const std::array<int, 4>& ia, const std::array<int, 4>& ib);

}  // namespace grpvss::geometry
