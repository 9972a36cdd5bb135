#pragma once
// Reads a TOML file (configuration, sweep or ensemble file) with the checks every such file
// gets: a regular file of at most 1 MiB, nested at most kMaxConfigNesting deep (toml++ would
// overflow the stack), and syntax errors as ConfigError naming the file, line and column.
#include <toml++/toml.h>

#include <filesystem>

namespace orogen {

toml::table parse_toml_file(const std::filesystem::path& file);

}  // namespace orogen
