#include "support/panda_self_run.hpp"

#include "grpvss/io/path_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

namespace grpvss::test {

PandaSelfRun run_panda_self(const std::string& path, certify::ClearClaim claim) {
  const std::string cells = std::string(GRPVSS_SOURCE_DIR) + "/tests/data/cells/";
  PandaSelfRun r{cell::load_cell(cells + "panda-self.yaml"), {}, {}, {}};
  r.program = io::read_path_file(cells + path, r.cell.robot);
  r.kinematics = motion::make_kinematics_access(r.cell.robot, motion::select_ik({}, r.cell.robot, "panda"));
  certify::SetupRequest request;
  request.tolerance = r.cell.tolerance;
  request.motion.timing = motion::PtpTiming::kSynchronized;
  request.claim = claim;
  r.verified = certify::verify(r.cell.robot, r.cell.environment, r.program, r.kinematics,
                               certify::resolve_setup(request));
  return r;
}

certify::CheckReport check_panda_self(const PandaSelfRun& run, const certify::Certificate& certificate) {
  return certify::check_certificate(run.cell.robot, run.cell.environment, run.program, run.kinematics,
                                    certificate);
}

}  // namespace grpvss::test
