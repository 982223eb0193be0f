// `grpvss expansion-audit (--robot FILE --tolerance D | --cell CELL) [--json]`: does each tolerance expansion
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
#include "model_inputs.hpp"

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

nlohmann::ordered_json to_json(const geometry::ExpansionAudit& audit, const std::string& robot_path,
                               const RobotModel& robot) {
  nlohmann::ordered_json j;
  j["format_version"] = kJsonFormatVersion;
  j["robot"] = robot_path;
  j["tolerance"] = audit.tolerance;
  j["hull_count"] = audit.hulls.size();
  nlohmann::ordered_json hulls = nlohmann::ordered_json::array();
  for (const auto& row : audit.hulls) {
    nlohmann::ordered_json h;
    h["link"] = row.link;
    const std::string& name = robot.links[static_cast<std::size_t>(row.link)].name;
    if (!name.empty()) h["link_name"] = name;  // cells only: thesis documents stay as they were
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

void print_table(const geometry::ExpansionAudit& audit, const std::string& robot_path,
                 const RobotModel& robot) {
  fmt::print("expansion audit of {} at tolerance D = {}\n", robot_path, audit.tolerance);
  if (!robot.links.empty() && !robot.links.back().name.empty()) {
    fmt::print("links:");
    for (std::size_t i = 0; i < robot.links.size(); ++i) fmt::print(" {} {}", i, robot.links[i].name);
    fmt::print("; lengths in metres\n");
  }
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

/// `--tolerance` as given (with a cell: in its unit, converted upward), > 0.
double parse_tolerance(const std::string& text, const ModelInputs& model) {
  double tolerance = 0.0;
  std::size_t used = 0;
  try {
    tolerance = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(tolerance) || !(tolerance > 0.0)) {
    throw InputError("--tolerance", 0,
                     text.empty() && model.from_cell
                         ? "--tolerance, or `tolerance` in the cell file"
                         : "a finite number > 0",
                     text);
  }
  return cell::to_model_units(tolerance, model);
}

}  // namespace

void register_expansion_audit_command(CLI::App& app, int& exit_code) {
  auto* command = app.add_subcommand(
      "expansion-audit",
      "Check, exactly, whether the thesis's expansion and the exact offsets of every link hull "
      "contain every point within the tolerance");
  // Options outlive this function: CLI11 writes them during parse, the callback reads them.
  struct Options {
    ModelSources model;
    std::string tolerance_text;
    bool json = false;
    bool quiet = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("--robot", options->model.robot_file, "Robot file (thesis A.1.1.1 format)");
  command->add_option("--cell", options->model.cell_file,
                      "Cell file: its robot, on its base with its TCP (docs/cell-format.md)");
  command->add_option("--package-path", options->model.package_paths,
                      "Directory searched for package://NAME/... (repeatable; before the cell's)");
  command->add_option("--tolerance", options->tolerance_text,
                      "Tolerance D > 0 (file length units; with a cell its unit, default its "
                      "tolerance)");
  command->add_flag("--json", options->json, "Print a JSON document (docs/expansion-audit.md)");
  command->add_flag("--quiet", options->quiet, "Print nothing (the input is still checked)");
  command->callback([&exit_code, options] {
    const std::string& tolerance_text = options->tolerance_text;
    const ModelInputs model = load_model_inputs(options->model, options->quiet, ObstaclesNeeded::kNo);
    const RobotModel& robot = model.robot;
    const std::string& robot_path = model.robot_label_file;
    double tolerance = 0.0;
    if (tolerance_text.empty() && model.tolerance) {
      tolerance = *model.tolerance;
    } else {
      tolerance = parse_tolerance(tolerance_text, model);
    }
    const geometry::ExpansionAudit audit = geometry::audit_expansions(robot, tolerance);
    if (options->quiet) {
      // Nothing printed.
    } else if (options->json) {
      fmt::print("{}\n", to_json(audit, robot_path, robot).dump(2));
    } else {
      print_table(audit, robot_path, robot);
    }
    exit_code = kExitOk;
  });
}

}  // namespace grpvss::app
