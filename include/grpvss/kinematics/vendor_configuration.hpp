#pragma once
/// \file
/// \brief Controller configuration data of OPW arms: KUKA KRL Status/Turn and ABB RAPID
/// confdata, computed from the chain's joint values q (docs/ik.md has the definitions and
/// their sources).
///
/// The geometric bits use the fitted model (family_recognition.hpp): "in front of axis 1" is
/// +x of the axis-1 frame, x pointing to the side of the shoulder offset a1 (KUKA's and ABB's
/// front); the axis-value bits use q as the controller shows it, so the chain must be in the
/// vendor's joint convention (zero and direction of each axis).

#include <Eigen/Core>

#include "grpvss/kinematics/family_recognition.hpp"

namespace grpvss::kinematics {

/// \brief KUKA Status (bits 0-2) and Turn (bits 0-5).
/// Status bit 0: wrist centre behind axis 1 (x < 0 in the A1 frame, "overhead area");
/// bit 1: wrist centre in front of the line through A2 and A3 (A3 >= phi, with phi the
/// stretched position); bit 2: A5 < 0. Turn bit i: A(i+1) < 0.
struct KukaStatusTurn {
  int status = 0;
  int turn = 0;
};

/// \brief ABB confdata of a 6-axis arm: cf1, cf4, cf6 the quadrant floor(q / 90 deg) of axes
/// 1, 4, 6; cfx = 4 [wrist centre behind axis 1] + 2 [wrist centre behind the lower arm]
/// + [axis 5 < 0] (0..7, the table of the RAPID reference manual).
struct AbbConfdata {
  int cf1 = 0;
  int cf4 = 0;
  int cf6 = 0;
  int cfx = 0;
};

bool operator==(const KukaStatusTurn& a, const KukaStatusTurn& b);
bool operator==(const AbbConfdata& a, const AbbConfdata& b);

/// \brief Status and Turn of joint values q (6 values, rad).
KukaStatusTurn kuka_status_turn(const OpwChainModel& model, const Eigen::VectorXd& q);

/// \brief confdata of joint values q (6 values, rad).
AbbConfdata abb_confdata(const OpwChainModel& model, const Eigen::VectorXd& q);

/// \brief ABB's quadrant number of an axis angle (rad): floor(angle / (pi/2)); 0 for
/// [0, 90) deg, -1 for [-90, 0) deg, 1 for [90, 180) deg, ...
int abb_quadrant(double angle);

}  // namespace grpvss::kinematics
