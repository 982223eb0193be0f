#include "shared_inputs.hpp"

#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/report/input_digests.hpp"

namespace grpvss::batch {

std::shared_ptr<const LoadedRobot> SharedInputs::robot(const std::string& path) {
  return robots_.get(path, [&] {
    const std::string text = io::read_text_file(path);
    return std::make_shared<const LoadedRobot>(
        LoadedRobot{io::parse_robot_file(text, path), report::sha256_hex(text)});
  });
}

std::shared_ptr<const LoadedEnvironment> SharedInputs::environment(const std::string& path) {
  return environments_.get(path, [&] {
    const std::string text = io::read_text_file(path);
    return std::make_shared<const LoadedEnvironment>(
        LoadedEnvironment{io::parse_environment_file(text, path), report::sha256_hex(text)});
  });
}

std::shared_ptr<const motion::ProfileTable> SharedInputs::profile_table(const std::string& path) {
  return tables_.get(path, [&] {
    return std::make_shared<const motion::ProfileTable>(io::read_profile_table_file(path));
  });
}

std::shared_ptr<const LoadedCellModel> SharedInputs::cell_model(const cell::ModelSources& sources) {
  std::string key = sources.cell_file;
  for (const std::string& directory : sources.package_paths) key += '\n' + directory;
  return cell_models_.get(key, [&] {
    const std::string digest = report::sha256_hex(io::read_text_file(sources.cell_file));
    cell::ModelInputs inputs = cell::load_model_inputs(sources);
    auto robot = std::make_shared<const LoadedRobot>(LoadedRobot{std::move(inputs.robot), digest});
    auto environment = std::make_shared<const LoadedEnvironment>(
        LoadedEnvironment{std::move(inputs.environment), digest});
    inputs.robot = {};
    inputs.environment = {};
    return std::make_shared<const LoadedCellModel>(
        LoadedCellModel{std::move(robot), std::move(environment), std::move(inputs)});
  });
}

std::shared_ptr<const SharedCell> SharedInputs::cell(
    const std::shared_ptr<const LoadedRobot>& robot,
    const std::shared_ptr<const LoadedEnvironment>& environment,
    const certify::CellSettings& settings) {
  const CellKey key{robot->sha256, environment->sha256, settings.tolerance,
                    static_cast<int>(settings.offset_shape)};
  return cells_.get(key, [&] {
    return std::make_shared<const SharedCell>(robot, environment, settings);
  });
}

}  // namespace grpvss::batch
