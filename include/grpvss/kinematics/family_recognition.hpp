#pragma once
/// \file
/// \brief Recognising an OPW or UR arm in a general KinematicChain (DH-built or URDF-built:
/// joint frames with any origins and axes) and deriving the model's parameters and placement.
///
/// The derivation reads the joint axes at q = 0 (lines in W), checks the family's structure
/// (perpendicular / parallel / intersecting axes) and fits the model; then the fitted model's
/// FK must equal the chain's FK at q = 0 and at 256 pseudo-random configurations (every joint
/// uniform in [-pi, pi], fixed seed) within kFamilyFkTolerance: position error relative to the
/// chain's length scale (sum of the lengths of all fixed translations), rotation error in rad.
/// Otherwise no model and a reason.
///
/// Conventions of the fit (documented in docs/ik.md): B's origin is the foot of W's origin on
/// axis 1; B's z axis points from there toward the shoulder (axis 2) - toward W's +z when the
/// shoulder is level with it; offsets are chosen small (|theta_4|, |theta_5| offsets <= pi/2)
/// and joint 1's offset is 0. OPW: B's x axis points to the side of axis 2's offset a1 (to the
/// wrist centre's side at q = 0 when a1 = 0), c3 >= 0. UR: joint 2's sign is +1 and a2, a3 < 0
/// (UR's own convention).

#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/model_placement.hpp"
#include "grpvss/kinematics/opw_kinematics.hpp"
#include "grpvss/kinematics/ur_kinematics.hpp"

namespace grpvss::kinematics {

/// Largest admitted difference between the fitted model's FK and the chain's (relative).
constexpr double kFamilyFkTolerance = 1e-9;

/// \brief An OPW model fitted to a chain.
struct OpwChainModel {
  OpwParameters parameters;
  ModelPlacement placement;
  Eigen::Isometry3d X_ET = Eigen::Isometry3d::Identity();  ///< the tool T on the chain's E
  /// Largest FK difference the check saw (relative, as kFamilyFkTolerance); 0 up to rounding
  /// for chains that are exactly of the family.
  double fk_deviation = 0.0;
};

/// \brief A UR model fitted to a chain.
struct UrChainModel {
  UrParameters parameters;
  ModelPlacement placement;
  Eigen::Isometry3d X_ET = Eigen::Isometry3d::Identity();
  double fk_deviation = 0.0;
};

/// \brief A model when the chain is of the family, otherwise the reason it is not.
template <class Model>
struct Recognition {
  std::optional<Model> model;
  std::string reason;  ///< why the chain is not of the family; empty when recognised
};

/// \brief The OPW model of `chain` with tool X_ET on its last frame, or why there is none.
Recognition<OpwChainModel> recognise_opw(const KinematicChain& chain,
                                         const Eigen::Isometry3d& X_ET = Eigen::Isometry3d::Identity());

/// \brief The UR model of `chain` with tool X_ET on its last frame, or why there is none.
Recognition<UrChainModel> recognise_ur(const KinematicChain& chain,
                                       const Eigen::Isometry3d& X_ET = Eigen::Isometry3d::Identity());

}  // namespace grpvss::kinematics
