#include "io/dataset_docs.hpp"

#include <array>

namespace orogen {
namespace {

constexpr std::array<DatasetDoc, 17> kDocs = {{
    {"x", "d", "disc centre, horizontal coordinate"},
    {"y", "d", "disc centre, vertical coordinate (up)"},
    {"theta", "rad", "disc rotation angle, counter-clockwise"},
    {"vx", "sqrt(g d)", "velocity, horizontal component"},
    {"vy", "sqrt(g d)", "velocity, vertical component"},
    {"omega", "rad / sqrt(d/g)", "angular velocity, counter-clockwise"},
    {"radius", "d", "disc radius"},
    {"id", "-", "stable disc id (links a disc across outputs)"},
    {"cluster_id", "-", "stable id of the rigid cluster the disc belongs to, -1 for a free disc"},
    {"motion", "-", "0 dynamic (moved by forces), 1 kinematic (moved by the boundary conditions)"},
    {"x0", "d", "disc centre at the start of the experiment, horizontal coordinate"},
    {"y0", "d", "disc centre at the start of the experiment, vertical coordinate"},
    {"depth0", "d", "depth below the settled layer's surface at the start of the experiment"},
    {"material", "-", "index of the disc's material (a run with [materials]: the order of materials_names in the file's attributes)"},
    {"slip", "d", "frictional slip the disc has accumulated on its contacts, which weakens its material's friction (a run with [materials])"},
    {"walls", "d", "wall segments, one row each: end points ax, ay, bx, by"},
    {"xy", "d", "disc centres as (x, y) rows: a virtual view of x and y (no copy), the XDMF sidecar's geometry"},
}};

}  // namespace

const DatasetDoc* find_dataset_doc(std::string_view name) {
  for (const auto& d : kDocs)
    if (d.name == name) return &d;
  return nullptr;
}

}  // namespace orogen
