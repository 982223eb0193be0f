#include "step_proposal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grpvss::certify {

double transition_slack(const TransitionRecord& transition) {
  double slack = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < transition.hull_motion_bounds.size(); ++i) {
    if (transition.hull_motion_bounds[i] > 0.0) {
      slack = std::min(slack, transition.hull_allowances[i] / transition.hull_motion_bounds[i]);
    }
  }
  for (std::size_t p = 0; p < transition.self_pair_motion_bounds.size(); ++p) {
    if (transition.self_pair_motion_bounds[p] > 0.0) {
      slack = std::min(slack,
                       transition.self_pair_allowances[p] / transition.self_pair_motion_bounds[p]);
    }
  }
  return slack;
}

void loose_terms(const TransitionRecord& transition, double held_margin, const std::vector<double>& hull_radii,
                 const std::vector<double>& pair_distances, LooseTerms& out) {
  constexpr double kNotLoose = std::numeric_limits<double>::infinity();
  const auto ratio = [&](double allowance, double bound) {
    return bound > 0.0 ? (allowance - held_margin) / bound : std::numeric_limits<double>::infinity();
  };
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < transition.hull_motion_bounds.size(); ++i) {
    smallest = std::min(smallest, ratio(transition.hull_allowances[i], transition.hull_motion_bounds[i]));
  }
  for (std::size_t p = 0; p < transition.self_pair_motion_bounds.size(); ++p) {
    smallest = std::min(smallest,
                        ratio(transition.self_pair_allowances[p], transition.self_pair_motion_bounds[p]));
  }
  // A limit that is not positive leaves no scale to compare with: nothing is loose but what
  // did not move.
  const double loose_from = smallest > 0.0 ? kLooseFactor * smallest : std::numeric_limits<double>::infinity();
  const auto floor_of = [&](double allowance, double bound, double clearance) {
    if (bound > 0.0 && !(ratio(allowance, bound) >= loose_from)) return kNotLoose;
    return held_margin + kLooseRoom * std::max(bound, 0.0) - clearance;
  };
  out.hull_floors.resize(transition.hull_motion_bounds.size());
  for (std::size_t i = 0; i < out.hull_floors.size(); ++i) {
    out.hull_floors[i] = floor_of(transition.hull_allowances[i], transition.hull_motion_bounds[i], hull_radii.at(i));
  }
  out.pair_floors.resize(transition.self_pair_motion_bounds.size());
  for (std::size_t p = 0; p < out.pair_floors.size(); ++p) {
    const bool by_revolution = p < transition.self_pair_by_revolution.size() && transition.self_pair_by_revolution[p];
    out.pair_floors[p] = by_revolution ? kNotLoose
                                       : floor_of(transition.self_pair_allowances[p],
                                                  transition.self_pair_motion_bounds[p], pair_distances.at(p));
  }
}

double basic_resolution_slack(const TransitionRecord& transition, double two_delta) {
  double slack = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < transition.hull_motion_bounds.size(); ++i) {
    const double bound = transition.hull_motion_bounds[i];
    if (bound > 0.0) {
      slack = std::min(slack, std::max(transition.hull_allowances[i], two_delta) / bound);
    }
  }
  for (std::size_t p = 0; p < transition.self_pair_motion_bounds.size(); ++p) {
    const double bound = transition.self_pair_motion_bounds[p];
    if (bound > 0.0) {
      slack = std::min(slack, std::max(transition.self_pair_allowances[p], two_delta) / bound);
    }
  }
  return slack;
}

double predicted_ptp_step(const std::function<Eigen::VectorXd(double)>& joints_at,
                          const Eigen::VectorXd& q_now, double max_step,
                          const std::vector<double>& weights,
                          const std::vector<ProposalHull>& hulls, bool has_trend,
                          double previous_step, const std::vector<double>& axis_distances) {
  const std::size_t joints = static_cast<std::size_t>(q_now.size());
  Eigen::VectorXd dq;
  const auto entry_fits = [&](std::size_t i, double candidate) {
    const double radius = hulls[i].radius;
    // In contact or refining next to one (raw clearances): the trials and the basic
    // resolution size the step there; extrapolating a shrinking raw clearance would creep.
    if (!(radius > 0.0) || hulls[i].expanded_interferes) return !hulls[i].alternative_only;
    // A proposal needs no rounding care: M_h in plain double (judge_transition decides).
    double bound = 0.0;
    double tail = 0.0;  // what the joints after j may move the hull during the step
    for (std::size_t j = joints; j-- > 0;) {
      const double weight = weights[i * joints + j];
      const double near = axis_distances.empty() ? weight : axis_distances[i * joints + j] + tail;
      bound += std::min(weight, near) * dq[static_cast<Eigen::Index>(j)];
      tail += weight * dq[static_cast<Eigen::Index>(j)];
    }
    const double trend = has_trend ? radius - hulls[i].previous_radius : 0.0;
    const double expected_far_radius =
        std::max(radius - bound, radius + trend * candidate / previous_step);
    return !(bound > 0.95 * (radius + expected_far_radius - hulls[i].held_margin));
  };
  const auto fits = [&](double candidate) {
    dq = (joints_at(candidate) - q_now).cwiseAbs();
    for (std::size_t i = 0; i < hulls.size(); ++i) {
      if (hulls[i].alternative_only || entry_fits(i, candidate)) continue;
      const int alternative = hulls[i].alternative;
      if (alternative >= 0 && entry_fits(static_cast<std::size_t>(alternative), candidate)) continue;
      return false;
    }
    return true;
  };
  if (fits(max_step)) return max_step;
  double low = 0.0;
  double high = max_step;
  for (int iteration = 0; iteration < 10; ++iteration) {
    const double middle = 0.5 * (low + high);
    (fits(middle) ? low : high) = middle;
  }
  return low;
}

double cp_model_retry_fraction(double deviation) {
  return deviation < 4.0 ? 0.9 / std::sqrt(deviation) : 0.5;  // NaN < 4 is false
}

double cp_model_growth_cap(double deviation) {
  if (!(deviation > 0.0)) return std::numeric_limits<double>::infinity();
  return std::max(1.0, 0.95 / std::sqrt(deviation));
}

bool CpModelFailures::record(double s, double length, double deviation) {
  const bool kept = from_ == s && length < length_ && deviation >= 0.5 * deviation_;
  from_ = s;
  length_ = length;
  deviation_ = deviation;
  return kept;
}

}  // namespace grpvss::certify
