#include "grpvss/kinematics/ik_plugin_loader.hpp"

#include <dlfcn.h>

#include <array>
#include <string>
#include <utility>

#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/ik_plugin.h"
#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::kinematics {
namespace {

// Roundoff may leave an exact boundary solution a few ulps outside a limit.
constexpr double kLimitSlack = 1e-9;

using AbiVersionFunction = int (*)();
using SolveFunction = int (*)(const double*, const double*, int, double*);
using NameFunction = const char* (*)();

std::string last_dl_error() {
  const char* message = dlerror();
  return message != nullptr ? message : "unknown dlopen error";
}

// Owns the dlopen handle; the library stays loaded as long as the solver lives.
class PluginIk final : public InverseKinematics {
 public:
  PluginIk(std::string path, void* handle, SolveFunction solve_function, std::string name,
           const RobotModel& model)
      : path_(std::move(path)),
        handle_(handle),
        solve_(solve_function),
        name_(std::move(name)),
        chain_(make_chain(model)),
        joint_count_(model.joint_count()) {}
  PluginIk(const PluginIk&) = delete;
  PluginIk& operator=(const PluginIk&) = delete;
  ~PluginIk() override { dlclose(handle_); }

  IkSolution solve(const Eigen::Isometry3d& X_WE_target,
                   const Eigen::VectorXd& q_near) const override {
    if (q_near.size() != joint_count_) {
      throw std::logic_error("PluginIk: q_near has the wrong size");
    }
    std::array<double, 16> X_row_major{};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        X_row_major[static_cast<std::size_t>(4 * r + c)] = X_WE_target.matrix()(r, c);
      }
    }
    Eigen::VectorXd q_out = q_near;
    const int code = solve_(X_row_major.data(), q_near.data(), joint_count_, q_out.data());
    if (code == GRPVSS_IK_SOLVED) {
      // The plug-in is user code: hold it to its contract before anything moves.
      if (!chain_.within_limits(q_out, kLimitSlack) || !q_out.allFinite()) {
        throw InputError(path_, 0, "grpvss_ik_solve to return finite joint values within the limits");
      }
      return {IkStatus::kSolved, q_out};
    }
    if (code == GRPVSS_IK_OUT_OF_WORKSPACE) return {IkStatus::kOutOfWorkspace, {}};
    throw InputError(path_, 0, "grpvss_ik_solve to return 0 (solved) or 1 (out of workspace)",
                     std::to_string(code));
  }

  std::string name() const override { return name_; }

 private:
  std::string path_;
  void* handle_;
  SolveFunction solve_;
  std::string name_;
  KinematicChain chain_;
  int joint_count_;
};

}  // namespace

std::unique_ptr<InverseKinematics> load_ik_plugin(const std::string& shared_library_path,
                                                  const RobotModel& model) {
  void* handle = dlopen(shared_library_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    throw InputError(shared_library_path, 0, "a loadable IK plug-in shared library",
                     last_dl_error());
  }
  // dlsym returns void*; POSIX guarantees the conversion to a function pointer works.
  auto resolve = [&](const char* symbol, bool required) -> void* {
    dlerror();
    void* address = dlsym(handle, symbol);
    if (address == nullptr && required) {
      const std::string message = last_dl_error();
      dlclose(handle);
      throw InputError(shared_library_path, 0,
                       std::string("the IK plug-in symbol ") + symbol + " (see ik_plugin.h)",
                       message);
    }
    return address;
  };
  auto abi_version = reinterpret_cast<AbiVersionFunction>(resolve("grpvss_ik_abi_version", true));
  auto solve = reinterpret_cast<SolveFunction>(resolve("grpvss_ik_solve", true));
  auto name_function = reinterpret_cast<NameFunction>(resolve("grpvss_ik_name", false));
  const int version = abi_version();
  if (version != GRPVSS_IK_ABI_VERSION) {
    dlclose(handle);
    throw InputError(shared_library_path, 0,
                     "IK plug-in ABI version " + std::to_string(GRPVSS_IK_ABI_VERSION),
                     std::to_string(version));
  }
  std::string name = "plug-in " + shared_library_path;
  if (name_function != nullptr && name_function() != nullptr) name = name_function();
  return std::make_unique<PluginIk>(shared_library_path, handle, solve, name, model);
}

}  // namespace grpvss::kinematics
