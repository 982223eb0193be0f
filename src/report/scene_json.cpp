#include "grpvss/report/scene_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>
#include <vector>
#include <stdexcept>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::report {

namespace {

using nlohmann::json;

double finite_scene_number(double value, const char* what) {
  if (!std::isfinite(value)) throw std::logic_error(fmt::format("scene: {} is {}", what, value));
  return value;
}

/// Vertices, face loops (CCW from outside) and edges of the exact hull of `points`, in a
/// canonical order: the hull's own vertex, face and edge order is not reproducible from run to
/// run, the report must be. Vertices sorted lexicographically, each face loop rotated to start
/// at its smallest index (orientation kept), faces and edges sorted.
json polytope_json(const std::vector<Eigen::Vector3d>& points, const char* vertices_key) {
  const auto polytope = geometry::ConvexPolytope::from_points(points);
  const auto& vertices = polytope.vertices();
  std::vector<int> order(vertices.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&vertices](int a, int b) {
    const auto& u = vertices[static_cast<std::size_t>(a)];
    const auto& v = vertices[static_cast<std::size_t>(b)];
    return std::tie(u.x(), u.y(), u.z()) < std::tie(v.x(), v.y(), v.z());
  });
  std::vector<int> new_index(vertices.size());
  json vertex_list = json::array();
  for (std::size_t k = 0; k < order.size(); ++k) {
    new_index[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
    const auto& v = vertices[static_cast<std::size_t>(order[k])];
    vertex_list.push_back({finite_scene_number(v.x(), "vertex"), finite_scene_number(v.y(), "vertex"), finite_scene_number(v.z(), "vertex")});
  }
  std::vector<std::vector<int>> faces;
  for (const auto& loop : polytope.faces()) {
    std::vector<int> face;
    for (int index : loop) face.push_back(new_index[static_cast<std::size_t>(index)]);
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    faces.push_back(face);
  }
  std::sort(faces.begin(), faces.end());
  std::vector<std::array<int, 2>> edges;
  for (const auto& edge : polytope.edges()) {
    const int u = new_index[static_cast<std::size_t>(edge[0])];
    const int v = new_index[static_cast<std::size_t>(edge[1])];
    edges.push_back({std::min(u, v), std::max(u, v)});
  }
  std::sort(edges.begin(), edges.end());
  return {{vertices_key, vertex_list}, {"faces", faces}, {"edges", edges}};
}

json pose_rows(const Eigen::Isometry3d& X_WL) {
  json values = json::array();
  const Eigen::Matrix4d m = X_WL.matrix();
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) values.push_back(finite_scene_number(m(row, col), "pose"));
  }
  return values;
}

json link_poses(const kinematics::KinematicChain& chain, const Eigen::VectorXd& q,
                kinematics::Workspace& workspace) {
  if (q.size() != chain.joint_count()) {
    throw std::logic_error(fmt::format("scene: step has {} joint values, robot has {} joints",
                                       q.size(), chain.joint_count()));
  }
  kinematics::forward_kinematics(chain, q, workspace);
  json poses = json::array();
  for (const auto& X_WL : workspace.X_WL) poses.push_back(pose_rows(X_WL));
  return poses;
}

}  // namespace

nlohmann::json scene_to_json(const certify::VerificationResult& result,
                             const certify::RobotCell& cell) {
  // The cell the run used: the expanded hulls drawn are the ones it tested.
  const RobotModel& robot = cell.robot();
  const Environment& environment = cell.environment();
  json links = json::array();
  for (std::size_t link = 0; link < robot.links.size(); ++link) {
    links.push_back({{"link", static_cast<int>(link)}, {"hulls", json::array()}});
    // Names only where the model has them (thesis reports are unchanged).
    if (!robot.links[link].name.empty()) links.back()["name"] = robot.links[link].name;
  }
  for (const certify::LinkHull& hull : cell.hulls()) {
    json entry = polytope_json(hull.raw_L, "vertices_L");
    entry["hull"] = hull.hull;
    const std::string& hull_name = robot.links[static_cast<std::size_t>(hull.link)]
                                       .hulls[static_cast<std::size_t>(hull.hull)].name;
    if (!hull_name.empty()) entry["name"] = hull_name;
    entry["expanded"] = polytope_json(hull.expanded_L, "vertices_L");
    links.at(hull.link)["hulls"].push_back(entry);
  }
  json obstacles = json::array();
  for (std::size_t o = 0; o < environment.obstacles.size(); ++o) {
    json entry = polytope_json(environment.obstacles[o].points, "vertices_W");
    entry["obstacle"] = static_cast<int>(o);
    if (environment.has_names()) entry["name"] = obstacle_label(environment, static_cast<int>(o));
    obstacles.push_back(entry);
  }
  SceneStepPoses poses(robot);
  json steps = json::array();
  for (const auto& step : result.steps) steps.push_back(poses.step(step));
  json start = nullptr;
  if (result.start) {
    certify::StepRecord start_step = *result.start;
    start_step.index = 0;
    start = poses.step(start_step);
  }
  json scene = {{"expansion",
                 {{"radius", finite_scene_number(cell.expansion_radius(), "expansion radius")},
                  {"shape", geometry::to_string(cell.offset_shape())}}},
                {"links", links},
                {"obstacles", obstacles},
                {"start", start},
                {"steps", steps}};
  if (!environment.allowed_contacts.empty()) {
    json allowed = json::array();
    for (const AllowedContactPair& pair : environment.allowed_contacts) {
      allowed.push_back({{"link", pair.link}, {"hull", pair.hull}, {"obstacle", pair.obstacle}});
    }
    scene["allowed_contacts"] = allowed;
  }
  return scene;
}

struct SceneStepPoses::Kinematics {
  explicit Kinematics(const RobotModel& robot)
      : chain(kinematics::make_chain(robot)), workspace(robot) {}
  kinematics::KinematicChain chain;
  kinematics::Workspace workspace;
};

SceneStepPoses::SceneStepPoses(const RobotModel& robot)
    : kinematics_(std::make_unique<Kinematics>(robot)) {}

SceneStepPoses::~SceneStepPoses() = default;

nlohmann::json SceneStepPoses::step(const certify::StepRecord& step) {
  return {{"step", step.index},
          {"X_WL", link_poses(kinematics_->chain, step.q, kinematics_->workspace)}};
}

}  // namespace grpvss::report
