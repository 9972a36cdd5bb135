// The world seen from Python: every per-disc array as a numpy view (no copy), and the
// changes of World's API (world/world.hpp), which keep the neighbour list and the clusters
// consistent. Views are read-only unless asked for; after writing into one, `changed()` tells
// the world (World::discs_changed).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"

namespace orogen::py {

World& WorldHandle::get() const {
  if (!world) throw std::runtime_error("this world handle is no longer valid (a hook's world lives during the call only)");
  return *world;
}

namespace {

// A numpy view of one per-disc array; `base` (the handle) keeps the owner of the memory alive.
pyb::array view(const pyb::object& base, World& w, const std::string& name, bool writable) {
  pyb::array out;
  // The arrays' memory for the view: read-only unless asked (then `changed` follows the writes).
  w.discs_for_writing().for_each_array([&](const char* n, auto& v) {
    if (name != n) return;
    using T = typename std::decay_t<decltype(v)>::value_type;
    out = pyb::array_t<T>({static_cast<pyb::ssize_t>(v.size())}, {static_cast<pyb::ssize_t>(sizeof(T))}, v.data(), base);
  });
  if (!out) throw pyb::key_error("no per-disc array named '" + name + "'");
  if (!writable) out.attr("flags").attr("writeable") = false;
  return out;
}

std::vector<std::string> array_names(World& w) {
  std::vector<std::string> names;
  w.discs().for_each_array([&](const char* n, auto&) { names.emplace_back(n); });
  return names;
}

void check_index(const World& w, std::size_t i) {
  if (i >= w.discs().size())
    throw pyb::index_error("disc index " + std::to_string(i) + " out of range (" + std::to_string(w.discs().size()) + " discs)");
}

// Free discs only: a member disc sits where its cluster's pose puts it.
void check_free(const World& w, std::size_t i) {
  check_index(w, i);
  if (w.discs().cluster[i] != kNoCluster)
    throw pyb::value_error("disc " + std::to_string(i) + " belongs to a cluster: move or pin the cluster instead");
}

RemovalReason reason_of(const std::string& r) {
  if (r == "eroded") return RemovalReason::Eroded;
  if (r == "left_domain") return RemovalReason::LeftDomain;
  if (r == "other") return RemovalReason::Other;
  if (r == "eroded_hillslope") return RemovalReason::ErodedHillslope;
  if (r == "eroded_fluvial") return RemovalReason::ErodedFluvial;
  if (r == "eroded_script") return RemovalReason::ErodedScript;
  throw pyb::value_error("removal reason '" + r +
                         "': expected eroded, eroded_hillslope, eroded_fluvial, eroded_script, left_domain or other");
}

WallFriction friction_of(const std::string& f) {
  if (f == "smooth") return WallFriction::Smooth;
  if (f == "rough") return WallFriction::Rough;
  if (f == "traction") return WallFriction::Traction;
  throw pyb::value_error("wall friction '" + f + "': expected smooth, rough or traction");
}

pyb::dict wall_dict(const Wall& w) {
  static const char* kinds[] = {"smooth", "rough", "traction"};
  pyb::dict d;
  d["name"] = w.name; d["ax"] = w.ax; d["ay"] = w.ay; d["bx"] = w.bx; d["by"] = w.by;
  d["vx"] = w.vx; d["vy"] = w.vy; d["surface_speed"] = w.surface_speed;
  d["friction"] = kinds[static_cast<int>(w.friction)]; d["mu"] = w.mu; d["enabled"] = w.enabled;
  return d;
}

void set_motion(World& w, const std::vector<std::size_t>& idx, Motion m, double vx, double vy) {
  for (auto i : idx) check_index(w, i);
  w.edit_motion([&](MotionEdit& e) {
    for (auto i : idx) e.body_of(i, m, vx, vy);
  });
}

}  // namespace

void bind_world(pyb::module_& m) {
  pyb::class_<WorldHandle>(m, "World")
      .def_property_readonly("step", [](const WorldHandle& h) { return h.get().step(); })
      // The layer thickness h0 [d] (a wedge's unit of length) and the resolved configuration as
      // a nested dict ({"wedge": {"s_end": 8.0, ...}}), as the run's config.toml holds them.
      .def_property_readonly("h0",
                             [](const WorldHandle& h) {
                               h.get();  // a stale handle raises
                               return h.experiment ? h.experiment->h0() : std::numeric_limits<double>::quiet_NaN();
                             })
      .def_property_readonly("config",
                             [](const WorldHandle& h) -> pyb::object {
                               h.get();
                               if (h.config == nullptr) return pyb::none();
                               return pyb::module_::import("tomllib").attr("loads")(h.config->to_toml());
                             })
      .def_property_readonly("time", [](const WorldHandle& h) { return h.get().time(); })
      .def_property_readonly("dt", [](const WorldHandle& h) { return h.get().dt(); })
      .def_property_readonly("n_clusters", [](const WorldHandle& h) { return h.get().clusters().size(); })
      .def("__len__", [](const WorldHandle& h) { return h.get().discs().size(); })
      .def_property_readonly("array_names", [](const WorldHandle& h) { return array_names(h.get()); })
      .def("array",
           [](pyb::object self, const std::string& name, bool writable) {
             return view(self, self.cast<WorldHandle&>().get(), name, writable);
           },
           pyb::arg("name"), pyb::arg("writable") = false,
           "a numpy view of a per-disc array (valid until the discs are added, removed or re-ordered: "
           "the next step or change)")
      .def("changed",
           [](const WorldHandle& h) {
             World& w = h.get();
             w.discs_changed();
           },
           "after writing into a view: member discs back on their bodies, the neighbour list rebuilt")
      .def("move",
           [](const WorldHandle& h, const std::vector<std::size_t>& idx, const std::vector<double>& x,
              const std::vector<double>& y) {
             World& w = h.get();
             if (x.size() != idx.size() || y.size() != idx.size()) throw pyb::value_error("move: indices, x and y differ in length");
             for (auto i : idx) check_free(w, i);
             for (std::size_t k = 0; k < idx.size(); ++k) w.move_disc(idx[k], x[k], y[k]);
           },
           pyb::arg("indices"), pyb::arg("x"), pyb::arg("y"), "puts free discs at new centres")
      .def("set_velocity",
           [](const WorldHandle& h, const std::vector<std::size_t>& idx, double vx, double vy, double omega) {
             World& w = h.get();
             for (auto i : idx) check_free(w, i);
             for (auto i : idx) w.set_disc_velocity(i, vx, vy, omega);
           },
           pyb::arg("indices"), pyb::arg("vx"), pyb::arg("vy"), pyb::arg("omega") = 0.0)
      .def("pin", [](const WorldHandle& h, const std::vector<std::size_t>& idx, double vx,
                     double vy) { set_motion(h.get(), idx, Motion::Kinematic, vx, vy); },
           pyb::arg("indices"), pyb::arg("vx") = 0.0, pyb::arg("vy") = 0.0,
           "kinematic at (vx, vy): a disc, or the whole cluster of a member disc")
      .def("release", [](const WorldHandle& h, const std::vector<std::size_t>& idx) {
             set_motion(h.get(), idx, Motion::Dynamic, 0, 0);
           }, pyb::arg("indices"), "dynamic again (moved by forces)")
      .def("add_disc",
           [](const WorldHandle& h, double x, double y, double r) {
             if (!(r > 0)) throw pyb::value_error("add_disc: the radius must be positive");
             return h.get().add_disc(x, y, r);
           },
           pyb::arg("x"), pyb::arg("y"), pyb::arg("radius"), "a free dynamic disc at rest; returns its index")
      .def("remove",
           [](const WorldHandle& h, const std::vector<std::size_t>& idx, const std::string& reason) {
             World& w = h.get();
             std::vector<std::uint8_t> flags(w.discs().size(), 0);
             for (auto i : idx) check_index(w, i), flags[i] = 1;
             return w.remove(flags, reason_of(reason));
           },
           pyb::arg("indices"), pyb::arg("reason") = "other",
           "removes discs (a member disc removes its cluster), logged in removals.csv")
      .def("remove_above", [](const WorldHandle& h, double height,
                              const std::string& reason) { return h.get().remove_above(height, reason_of(reason)); },
           pyb::arg("height"), pyb::arg("reason") = "eroded")
      .def_property("friction", [](const WorldHandle& h) { return h.get().friction(); },
                    [](const WorldHandle& h, double mu) { h.get().set_friction(mu); })
      .def_property_readonly("walls",
                             [](const WorldHandle& h) {
                               pyb::list out;
                               for (const auto& w : h.get().walls()) out.append(wall_dict(w));
                               return out;
                             })
      .def("add_wall",
           [](const WorldHandle& h, const std::string& name, double ax, double ay, double bx, double by,
              const std::string& friction, double mu, double vx, double vy) {
             World& w = h.get();
             for (const auto& wall : w.walls())
               if (wall.name == name) throw pyb::value_error("a wall named '" + name + "' exists already");
             auto walls = w.walls();
             Wall nw;
             nw.name = name; nw.ax = ax; nw.ay = ay; nw.bx = bx; nw.by = by;
             nw.friction = friction_of(friction); nw.mu = mu; nw.vx = vx; nw.vy = vy;
             walls.push_back(nw);
             w.set_walls(std::move(walls));
           },
           pyb::arg("name"), pyb::arg("ax"), pyb::arg("ay"), pyb::arg("bx"), pyb::arg("by"),
           pyb::arg("friction") = "smooth", pyb::arg("mu") = 0.0, pyb::arg("vx") = 0.0, pyb::arg("vy") = 0.0)
      .def("set_wall_velocity", [](const WorldHandle& h, const std::string& name, double vx,
                                   double vy) { h.get().set_wall_velocity(name, vx, vy); },
           pyb::arg("name"), pyb::arg("vx"), pyb::arg("vy"))
      .def("set_wall_ends", [](const WorldHandle& h, const std::string& name, double ax, double ay, double bx,
                               double by) { h.get().set_wall_ends(name, ax, ay, bx, by); },
           pyb::arg("name"), pyb::arg("ax"), pyb::arg("ay"), pyb::arg("bx"), pyb::arg("by"))
      .def("set_wall_friction", [](const WorldHandle& h, const std::string& name, const std::string& kind,
                                   double mu) { h.get().set_wall_friction(name, friction_of(kind), mu); },
           pyb::arg("name"), pyb::arg("friction"), pyb::arg("mu"))
      .def("enable_wall", [](const WorldHandle& h, const std::string& name,
                             bool on) { h.get().enable_wall(name, on); },
           pyb::arg("name"), pyb::arg("enabled"))
      .def("wall_contacts",
           [](const WorldHandle& h, const std::string& name) {
             const World& w = h.get();
             const auto s = w.wall_contact_stats(w.wall_index(name));
             return pyb::make_tuple(s.touching, s.at_limit);
           },
           pyb::arg("name"), "(touching, at the Coulomb limit) in the last force pass")
      .def("touching",
           [](const WorldHandle& h, const std::string& name) {
             const World& w = h.get();
             std::vector<std::size_t> idx;
             w.for_each_touching(w.wall_index(name), [&](std::size_t i) { idx.push_back(i); });
             return pyb::array_t<std::size_t>(idx.size(), idx.data());
           },
           pyb::arg("name"), "indices of the discs that touched the wall in the last force pass")
      .def("scalars",
           [](const WorldHandle& h) {
             pyb::dict d;
             d["step"] = h.get().step();
             d["time"] = h.get().time();
             if (h.experiment)
               for (const auto& [k, v] : h.experiment->scalars(h.get())) d[pyb::str(k)] = v;
             return d;
           },
           "the experiment's scalars of an output (S of a wedge), with step and time")
      .def("status", [](const WorldHandle& h) { return h.experiment ? h.experiment->status(h.get()) : std::string(); })
      .def("kinetic_energy", [](const WorldHandle& h) { return h.get().kinetic_energy(); })
      .def_property_readonly("n_removals", [](const WorldHandle& h) { return h.get().removals().size(); });
}

}  // namespace orogen::py
