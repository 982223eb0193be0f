#pragma once
/// \file
/// \brief The length units a cell file declares (`units: m | mm | in`) and the factors
/// between them. Inside the library every length of a cell run is in the cell's unit;
/// URDF (SI) and mesh files are converted on input. docs/cell-format.md#units.

#include <optional>
#include <string_view>

#include "grpvss/model/cell_description.hpp"

namespace grpvss::io {

/// \brief "m", "mm" or "in".
std::string_view length_unit_name(LengthUnit unit);

/// \brief The unit spelled `name` ("m", "mm", "in"), or nullopt.
std::optional<LengthUnit> length_unit_from_name(std::string_view name);

/// \brief The factor f with (length in `to`) = f x (length in `from`): the double nearest to
/// the exact ratio (1 m = 1000 mm, 1 in = 25.4 mm exactly), written as a literal so that the
/// compiler rounds it once.
double length_unit_factor(LengthUnit from, LengthUnit to);

/// \brief True when length_unit_factor(from, to) is the exact ratio (1 and 1000 only).
bool length_unit_factor_is_exact(LengthUnit from, LengthUnit to);

}  // namespace grpvss::io
