#pragma once
/// \file
/// \brief The names of a cell's links and obstacles in a certificate (docs/certificate.md#names).
///
/// Informative for a reader of the file; never trusted: the checker re-derives them from the
/// inputs with certificate_names() and rejects a certificate whose names differ. Written only
/// when the inputs have names (thesis certificates are unchanged).

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

struct CertificateNames {
  std::vector<std::string> links;      ///< links[i]: link i's name ("" when it has none)
  std::vector<std::string> obstacles;  ///< obstacles[o]: obstacle_label() of hull o
  bool empty() const { return links.empty() && obstacles.empty(); }
  friend bool operator==(const CertificateNames& a, const CertificateNames& b) {
    return a.links == b.links && a.obstacles == b.obstacles;
  }
  friend bool operator!=(const CertificateNames& a, const CertificateNames& b) { return !(a == b); }
};

/// The names of `robot`'s links (all of them, when one has a name) and of `environment`'s
/// obstacle hulls (when it has names); empty lists where there are none.
CertificateNames certificate_names(const RobotModel& robot, const Environment& environment);

/// `{"links": [...], "obstacles": [...]}`, a list only when non-empty.
nlohmann::json certificate_names_to_json(const CertificateNames& names);

/// \throws InputError (file = `file_name`) when `value` is not an object of string lists.
CertificateNames certificate_names_from_json(const nlohmann::json& value,
                                             const std::string& file_name);

}  // namespace grpvss::certify
