#pragma once
// One snapshot output written in formats other tools read: a LAMMPS data file (atom_style
// sphere) and text dump, extended XYZ, CSV. Each function returns the whole file as text;
// the caller writes it atomically. Lengths stay in Orogen's units (d, sqrt(d/g)); 2-D, z = 0.
#include <string>

#include "io/snapshot_reader.hpp"

namespace orogen {

enum class ExportFormat { LammpsData, LammpsDump, Xyz, Csv };

// "lammps-data" -> LammpsData ...; throws std::invalid_argument naming the allowed names.
ExportFormat parse_export_format(const std::string& name);
const char* export_format_names();  // "lammps-data, lammps-dump, xyz, csv"

// Where the exported frame came from, written into each format's header.
struct ExportSource {
  std::string run;  // the run folder
  std::int64_t output = 0;
};

// LAMMPS ids must be positive: an atom's id is the disc's stable id + 1. Atom type 1 is a free
// disc, 2 a disc of a rigid cluster. The unit of the LAMMPS density column is areal (Orogen's
// disc mass is density x pi r^2, density 1).
std::string export_snapshot(const Snapshot& s, ExportFormat format, const ExportSource& source);

// The contact law in LAMMPS's terms (gran/hooke/history): stiffnesses, dashpot coefficients per
// unit effective mass, friction, and the time step.
struct LammpsLaw {
  double kn, kt, gamma_n, gamma_t, mu, dt;
};

// A LAMMPS input that reads `data_file` (the lammps-data export of `s`) and runs it: the law,
// gravity, 2-D, and the snapshot's walls as `fix wall/gran` planes (walls along x or y; a tilted
// one is named in a comment). The Orogen run's own base conditions (a traction base, other
// friction on the bases) are not LAMMPS's: the walls take the discs' law.
std::string lammps_input(const Snapshot& s, const LammpsLaw& law, const std::string& data_file);

}  // namespace orogen
