#include "grpvss/io/length_unit.hpp"

namespace grpvss::io {
namespace {

int unit_index(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMetre: return 0;
    case LengthUnit::kMillimetre: return 1;
    case LengthUnit::kInch: return 2;
  }
  return 0;
}

// kFactor[from][to]; 1 in = 25.4 mm exactly. Each entry is the decimal expansion of the exact
// ratio, to more digits than a double holds (rounded once, by the compiler).
constexpr double kFactor[3][3] = {
    {1.0, 1000.0, 39.370078740157480314960629921259842519685},
    {0.001, 1.0, 0.039370078740157480314960629921259842519685},
    {0.0254, 25.4, 1.0},
};

}  // namespace

std::string_view length_unit_name(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMetre: return "m";
    case LengthUnit::kMillimetre: return "mm";
    case LengthUnit::kInch: return "in";
  }
  return "m";
}

std::optional<LengthUnit> length_unit_from_name(std::string_view name) {
  if (name == "m") return LengthUnit::kMetre;
  if (name == "mm") return LengthUnit::kMillimetre;
  if (name == "in") return LengthUnit::kInch;
  return std::nullopt;
}

double length_unit_factor(LengthUnit from, LengthUnit to) {
  return kFactor[unit_index(from)][unit_index(to)];
}

bool length_unit_factor_is_exact(LengthUnit from, LengthUnit to) {
  return from == to || (from == LengthUnit::kMetre && to == LengthUnit::kMillimetre);
}

}  // namespace grpvss::io
