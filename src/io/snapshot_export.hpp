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

}  // namespace orogen
