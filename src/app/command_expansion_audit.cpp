// `grpvss expansion-audit --robot FILE --tolerance D [--json]`: does each tolerance expansion
// of each link hull contain every point within D of the hull? JSON schema and findings:
// docs/expansion-audit.md.
#include <cmath>
#include <memory>
#include <string>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/exact/expansion_audit.hpp"
#include "grpvss/io/robot_file.hpp"

namespace grpvss::app {
namespace {

constexpr int kJsonFormatVersion = 1;

nlohmann::ordered_json to_json(const geometry::ExpansionMeasure& m) {
  nlohmann::ordered_json j;
  j["method"] = geometry::to_string(m.method);
  j["applicable"] = m.applicable;
  if (!m.applicable) return j;
  j["contains_ball_sum"] = m.contains_ball_sum;
  j["worst_protrusion"] = m.worst_protrusion;
  j["worst_point"] = {m.worst_point.x(), m.worst_point.y(), m.worst_point.z()};
  j["vertex_count"] = m.vertex_count;
  j["volume"] = m.volume;
  j["over_inflation"] = m.over_inflation;
  if (m.max_midpoint_gap) {
    j["max_midpoint_gap"] = *m.max_midpoint_gap;
    j["parallel_pairs"] = m.parallel_pairs;
    j["origin_on_cap_plane"] = m.origin_on_cap_plane;
  }
  return j;
}

nlohmann::ordered_json to_json(const geometry::ExpansionAudit& audit, const std::string& robot_path) {
  nlohmann::ordered_json j;
  j["format_version"] = kJsonFormatVersion;
  j["robot"] = robot_path;
  j["tolerance"] = audit.tolerance;
  j["hull_count"] = audit.hulls.size();
  nlohmann::ordered_json hulls = nlohmann::ordered_json::array();
  for (const auto& row : audit.hulls) {
    nlohmann::ordered_json h;
    h["link"] = row.link;
    h["hull"] = row.hull;
    h["source_line"] = row.source_line;
    h["point_count"] = row.point_count;
    h["vertex_count"] = row.vertex_count;
    h["volume"] = row.volume;
    h["ball_sum_volume"] = row.ball_sum_volume;
    h["expansions"] = nlohmann::ordered_json::array();
    for (const auto& m : row.expansions) h["expansions"].push_back(to_json(m));
    hulls.push_back(std::move(h));
  }
  j["hulls"] = std::move(hulls);
  return j;
}

void print_table(const geometry::ExpansionAudit& audit, const std::string& robot_path) {
  fmt::print("expansion audit of {} at tolerance D = {}\n", robot_path, audit.tolerance);
  fmt::print("contains = every point within D of the hull is inside the expansion (exact);\n"
             "protrusion > 0: how far the worst such point lies outside, < 0: smallest margin;\n"
             "inflation = volume / volume of the ideal ball sum (Steiner); gap = largest\n"
             "midpoint gap of Eq. 4-10/4-11.\n\n");
  fmt::print("{:>4} {:>4} {:>5}  {:<20} {:>8} {:>12}  {:<30} {:>5} {:>10} {:>9} {:>10}\n",
             "link", "hull", "line", "expansion", "contains", "protrusion",
             "worst point (link frame)", "verts", "volume", "inflation", "gap");
  for (const auto& row : audit.hulls) {
    fmt::print("{:>4} {:>4} {:>5}  {:<20} {:>8} {:>12}  {:<30} {:>5} {:>10.4f} {:>9} {:>10}\n",
               row.link, row.hull, row.source_line, "original", "", "",
               fmt::format("ball-sum volume {:.4f}", row.ball_sum_volume), row.vertex_count,
               row.volume, "", "");
    for (const auto& m : row.expansions) {
      if (!m.applicable) {
        fmt::print("{:>4} {:>4} {:>5}  {:<20} {:>8}\n", "", "", "",
                   geometry::to_string(m.method), "n/a (not a 16-point prism)");
        continue;
      }
      const std::string point = fmt::format("({:.4f}, {:.4f}, {:.4f})", m.worst_point.x(),
                                            m.worst_point.y(), m.worst_point.z());
      const std::string gap = m.max_midpoint_gap ? fmt::format("{:.3e}", *m.max_midpoint_gap)
                                                 : std::string("-");
      fmt::print("{:>4} {:>4} {:>5}  {:<20} {:>8} {:>12.4e}  {:<30} {:>5} {:>10.4f} {:>9.5f} "
                 "{:>10}\n",
                 "", "", "", geometry::to_string(m.method), m.contains_ball_sum ? "yes" : "NO",
                 m.worst_protrusion, point, m.vertex_count, m.volume, m.over_inflation, gap);
    }
  }
}

}  // namespace

void register_expansion_audit_command(CLI::App& app, int& exit_code) {
  auto* command = app.add_subcommand(
      "expansion-audit",
      "Check, exactly, whether the thesis's expansion and the exact offsets of every link hull "
      "contain every point within the tolerance");
  // Options outlive this function: CLI11 writes them during parse, the callback reads them.
  struct Options {
    std::string robot_path;
    std::string tolerance_text;
    bool json = false;
    bool quiet = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("--robot", options->robot_path, "Robot file (thesis A.1.1.1 format)")
      ->required();
  command->add_option("--tolerance", options->tolerance_text,
                      "Tolerance D > 0 (file length units)")
      ->required();
  command->add_flag("--json", options->json, "Print a JSON document (docs/expansion-audit.md)");
  command->add_flag("--quiet", options->quiet, "Print nothing (the input is still checked)");
  command->callback([&exit_code, options] {
    const std::string& tolerance_text = options->tolerance_text;
    const std::string& robot_path = options->robot_path;
    double tolerance = 0.0;
    std::size_t used = 0;
    try {
      tolerance = std::stod(tolerance_text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != tolerance_text.size() || !std::isfinite(tolerance) || !(tolerance > 0.0)) {
      throw InputError("--tolerance", 0, "a finite number > 0", tolerance_text);
    }
    const RobotModel robot = io::read_robot_file(robot_path);
    const geometry::ExpansionAudit audit = geometry::audit_expansions(robot, tolerance);
    if (options->quiet) {
      // Nothing printed.
    } else if (options->json) {
      fmt::print("{}\n", to_json(audit, robot_path).dump(2));
    } else {
      print_table(audit, robot_path);
    }
    exit_code = kExitOk;
  });
}

}  // namespace grpvss::app
