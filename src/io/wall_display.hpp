#pragma once
// Walls as the viewers (ParaView, VisIt) draw them. A wall may stand for a half-infinite line
// (the wedge's pro-side base runs to x = -1e7 d); drawn as stored, it makes a viewer's camera
// zoom out to 1e7 d and its float32 vertices lose the discs entirely. So the XDMF sidecar and
// the .vtp files clip the walls to a box around the discs; `walls` in the HDF5 files stays exact.
#include <array>
#include <vector>

namespace orogen {

// Each wall clipped to the discs' bounding box grown on every side by its larger span (at
// least 1 d); walls wholly outside are left out. With no discs the walls are returned as given.
std::vector<std::array<double, 4>> walls_for_display(const std::vector<std::array<double, 4>>& walls,
                                                     const std::vector<double>& x, const std::vector<double>& y);

}  // namespace orogen
