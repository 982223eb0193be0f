// Session.check_configurations(q rows): the certified verdict of single configurations
// (certify::ConfigurationCheck), with every finding named as the reports name it. One check
// per call keeps each term's last slab for the next row: a planner's edge or a trajectory's
// samples, given in order, are cheapest. The GIL is released while the rows are checked.
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "grpvss/certify/configuration_check.hpp"
#include "grpvss/common/input_error.hpp"

namespace py = pybind11;

namespace grpvss::python {
namespace {

/// A finding as Python sees it: names, not indices alone.
struct NamedFinding {
  std::string kind;   ///< "collision", "within tolerance", "self-collision", "undecided"
  std::string link;   ///< hull_label of the link hull
  std::string other;  ///< obstacle_label, or the other link hull's hull_label
  int obstacle = -1;  ///< index within the environment; -1 for a self pair
  std::string text;   ///< certify::describe
};

struct NamedVerdict {
  certify::Verdict verdict = certify::Verdict::kClear;
  std::vector<NamedFinding> findings;
};

NamedVerdict named(const certify::ConfigurationVerdict& verdict, const Session& session) {
  const RobotModel& robot = session.robot().model;
  const Environment& environment = session.environment().model;
  NamedVerdict out{verdict.verdict, {}};
  for (const certify::ConfigurationFinding& f : verdict.findings) {
    out.findings.push_back({certify::to_string(f.kind), hull_label(robot, f.link, f.hull),
                            f.obstacle >= 0 ? obstacle_label(environment, f.obstacle)
                                            : hull_label(robot, f.other_link, f.other_hull),
                            f.obstacle, certify::describe(f, robot, environment)});
  }
  return out;
}

using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<NamedVerdict> check_configurations(const Session& session, const Rows& rows) {
  if (session.request().mode != certify::ResolutionMode::kCertified) {
    throw InputError("mode", 0, "certified (a configuration's verdict is a certified claim)",
                     std::string("'") + certify::to_string(session.request().mode) + "'");
  }
  const int joints = session.robot().model.joint_count();
  if (rows.cols() != joints) {
    throw InputError("configurations", 0, std::to_string(joints) + " columns (one per joint)",
                     std::to_string(rows.cols()));
  }
  std::vector<certify::ConfigurationVerdict> verdicts;
  {
    py::gil_scoped_release release;
    certify::ConfigurationCheck check(session.cell());
    for (Eigen::Index r = 0; r < rows.rows(); ++r) {
      try {
        verdicts.push_back(check.check(rows.row(r).transpose()));
      } catch (const std::invalid_argument& error) {
        throw InputError("configurations", static_cast<int>(r + 1), "finite joint values", error.what());
      }
    }
  }
  std::vector<NamedVerdict> named_verdicts;
  for (const auto& verdict : verdicts) named_verdicts.push_back(named(verdict, session));
  return named_verdicts;
}

}  // namespace

void bind_configuration_check(py::module_& module, SessionClass& session) {
  py::class_<NamedFinding>(module, "ConfigurationFinding",
                           "One term that keeps a configuration from CLEAR")
      .def_readonly("kind", &NamedFinding::kind,
                    "'collision', 'within tolerance', 'self-collision' or 'undecided'")
      .def_readonly("link", &NamedFinding::link, "the link hull (as reports name it)")
      .def_readonly("other", &NamedFinding::other, "the obstacle, or the other link hull of a self pair")
      .def_readonly("obstacle", &NamedFinding::obstacle, "the obstacle's index; -1 for a self pair")
      .def("__str__", [](const NamedFinding& f) { return f.text; })
      .def("__repr__", [](const NamedFinding& f) { return "<ConfigurationFinding " + f.text + ">"; });
  py::class_<NamedVerdict>(module, "ConfigurationVerdict",
                           "A configuration's certified verdict and its findings")
      .def_readonly("verdict", &NamedVerdict::verdict)
      .def_readonly("findings", &NamedVerdict::findings)
      .def_property_readonly("clear", [](const NamedVerdict& v) { return v.verdict == certify::Verdict::kClear; })
      .def("__repr__", [](const NamedVerdict& v) {
        std::string text = std::string("<ConfigurationVerdict ") + certify::to_string(v.verdict);
        for (const NamedFinding& f : v.findings) text += "; " + f.text;
        return text + ">";
      });
  session.def("_check_configurations", &check_configurations, py::arg("configurations"),
              "The certified verdict of each row (joint values, rad / length), in order");
}

}  // namespace grpvss::python
