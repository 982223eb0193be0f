#pragma once
/// \file
/// \brief The obstacles of a cell as named convex hulls in the world frame, in model units,
/// with the bound on their rounding (Environment::point_error).

#include <vector>

#include "grpvss/cell/load_cell.hpp"

namespace grpvss::cell {

/// \brief Builds every obstacle (`scale` model units per cell unit).
/// \throws InputError naming the cell line or the mesh/environment file.
Environment load_cell_environment(const CellDescription& cell, double scale,
                                  std::vector<io::InputWarning>& warnings);

}  // namespace grpvss::cell
