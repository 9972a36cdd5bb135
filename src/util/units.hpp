#pragma once
// Constants shared by the experiments' reports.
#include <numbers>

namespace orogen {
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// Mass of a disc of diameter 1 (unit density): the model's unit of mass, m in m g / d.
constexpr double kUnitDiscMass = std::numbers::pi / 4.0;
}  // namespace orogen
