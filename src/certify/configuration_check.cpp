#include "grpvss/certify/configuration_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

#include "cell_probe.hpp"
#include "configuration_verdict.hpp"

namespace grpvss::certify {
namespace {

using Kind = ConfigurationFinding::Kind;

ConfigurationFinding obstacle_finding(const RobotCell& cell, const PairEvidence& pair, Kind kind) {
  const LinkHull& hull = cell.hulls()[static_cast<std::size_t>(pair.hull_index)];
  ConfigurationFinding finding;
  finding.kind = kind;
  finding.link = hull.link;
  finding.hull = hull.hull;
  finding.obstacle = pair.obstacle;
  return finding;
}

// The raw hull's proof for a pair whose offset interferes: a raw witness (within tolerance),
// a raw contact (collision), or none when the gap is below a double slab (undecided).
Kind raw_kind(const ProbeResult& probed, const PairEvidence& expanded) {
  for (const PairEvidence& raw : probed.evidence) {
    if (!raw.expanded && raw.hull_index == expanded.hull_index && raw.obstacle == expanded.obstacle) {
      return raw.separated ? Kind::kWithinTolerance : Kind::kCollision;
    }
  }
  return Kind::kUndecided;
}

// A self pair is clear only when its witness leaves a positive distance between the exactly
// placed hulls (SelfPairEvidence::distance); a contact is a self-collision; anything else
// proves neither.
void add_self_findings(const RobotCell& cell, const ProbeResult& probed,
                       std::vector<ConfigurationFinding>& findings) {
  for (std::size_t p = 0; p < probed.self_pairs.size(); ++p) {
    const SelfPairEvidence& evidence = probed.self_pairs[p];
    if (evidence.separated && evidence.distance > 0.0) continue;
    const LinkHull& a = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].a)];
    const LinkHull& b = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].b)];
    ConfigurationFinding finding;
    finding.kind = evidence.contact ? Kind::kSelfCollision : Kind::kUndecided;
    finding.link = a.link;
    finding.hull = a.hull;
    finding.other_link = b.link;
    finding.other_hull = b.hull;
    findings.push_back(finding);
  }
}

Verdict worst(const std::vector<ConfigurationFinding>& findings) {
  const auto any = [&](auto predicate) { return std::any_of(findings.begin(), findings.end(), predicate); };
  if (any([](const auto& f) { return f.kind == Kind::kCollision || f.kind == Kind::kSelfCollision; })) {
    return Verdict::kCollision;
  }
  if (any([](const auto& f) { return f.kind == Kind::kUndecided; })) return Verdict::kUndecided;
  if (!findings.empty()) return Verdict::kWithinTolerance;
  return Verdict::kClear;
}

}  // namespace

std::string to_string(ConfigurationFinding::Kind kind) {
  switch (kind) {
    case Kind::kCollision: return "collision";
    case Kind::kWithinTolerance: return "within tolerance";
    case Kind::kSelfCollision: return "self-collision";
    case Kind::kUndecided: return "undecided";
  }
  return "?";
}

std::string describe(const ConfigurationFinding& finding, const RobotModel& robot,
                     const Environment& environment) {
  const std::string other = finding.obstacle >= 0
                                ? obstacle_label(environment, finding.obstacle)
                                : hull_label(robot, finding.other_link, finding.other_hull);
  return hull_label(robot, finding.link, finding.hull) + " / " + other + ": " + to_string(finding.kind);
}

// proof: proofs/configuration-check.md#lemma-configuration-verdict
ConfigurationVerdict verdict_of(const RobotCell& cell, const ProbeResult& probed) {
  ConfigurationVerdict out;
  for (const PairEvidence& pair : probed.evidence) {
    if (pair.expanded && !pair.separated) out.findings.push_back(obstacle_finding(cell, pair, raw_kind(probed, pair)));
  }
  add_self_findings(cell, probed, out.findings);
  // One order whatever the order the probe decided its pairs in.
  std::sort(out.findings.begin(), out.findings.end(), [](const auto& a, const auto& b) {
    return std::tie(a.other_link, a.link, a.hull, a.obstacle, a.other_hull) <
           std::tie(b.other_link, b.link, b.hull, b.obstacle, b.other_hull);
  });
  out.verdict = worst(out.findings);
  return out;
}

struct ConfigurationCheck::Workspace {
  explicit Workspace(const RobotCell& cell) : probe(cell) { probe.set_need(ProbeNeed::kVerdict); }
  CellProbe probe;
  ProbeResult probed;
};

ConfigurationCheck::ConfigurationCheck(const RobotCell& cell)
    : cell_(&cell), workspace_(std::make_unique<Workspace>(cell)) {}
ConfigurationCheck::~ConfigurationCheck() = default;
ConfigurationCheck::ConfigurationCheck(ConfigurationCheck&&) noexcept = default;
ConfigurationCheck& ConfigurationCheck::operator=(ConfigurationCheck&&) noexcept = default;

ConfigurationVerdict ConfigurationCheck::check(const Eigen::VectorXd& q) {
  const int joints = cell_->robot().joint_count();
  if (q.size() != joints) {
    throw std::invalid_argument("configuration: expected " + std::to_string(joints) +
                                " joint values, found " + std::to_string(q.size()));
  }
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    if (!std::isfinite(q[j])) {
      throw std::invalid_argument("configuration: joint " + std::to_string(j + 1) +
                                  ": expected a finite value, found " + std::to_string(q[j]));
    }
  }
  workspace_->probe.probe(q, false, workspace_->probed);
  return verdict_of(*cell_, workspace_->probed);
}

}  // namespace grpvss::certify
