#pragma once
// What a run computes, as a fingerprint of its resolved configuration: the keys that make up
// a run's identity, those a resume may change, and the comparison of two stored
// configurations. Used wherever files are checked to be of one run (the run driver, a
// branch's source, `orogen analyze`).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace orogen {

class Config;
class SnapshotReader;
struct OutputStamp;

// "contact.kn = 5000.0 in config.toml, 10000.0 in the checkpoint; ..." for every key whose
// value differs between two resolved configurations (Config::to_toml texts), the extension,
// analysis and display keys aside; "" if none.
std::string config_differences(std::string_view here, std::string_view there, std::string_view here_name,
                               std::string_view there_name);

// "section.key" -> value text of each assignment line of a resolved configuration (Config::to_toml).
std::map<std::string, std::string> key_values(std::string_view toml);

// Keys a resume may change: they move a run's end and the spacing of its outputs, never what
// it computes up to there (`orogen run --resume DIR --set wedge.s_end=30`).
bool is_extension_key(std::string_view key);
// The [analysis] keys: outside the run identity and free to change on a resume.
bool is_analysis_key(std::string_view key);
// Keys that change how fast or how visibly a run goes, never what it computes (threads,
// thread tuning, progress, checkpoint interval, .vtp output): outside the run identity, and a
// resume may set them for itself (`--resume DIR --set output.progress=never`).
bool is_display_key(std::string_view key);
std::string extension_keys_text();  // "wedge.s_end, wedge.outputs"
// "wedge.s_end 8.0 -> 16.0, ..." for the extension keys that differ from `before` to `now`.
std::string extension_changes(std::string_view now, std::string_view before);

// 16 hex digits identifying what a run computes: a hash of the resolved configuration without
// the keys that change only speed or display (threads, thread tuning, progress, checkpoint
// interval, .vtp output) and the extension keys. Stored with the outputs and the checkpoint.
std::string run_identity(const Config& config);
// The same from a stored resolved configuration (Config::to_toml text, as every output file
// carries it), so that a file copied alone says which run it belongs to.
std::string run_identity_of_toml(std::string_view toml);

// "" when output k, whose attributes are `stamp`, is of the run with this identity (or
// predates outputs that carry their configuration); otherwise why not, naming its file and
// the keys that differ from `config_toml`.
std::string foreign_output(const SnapshotReader& reader, std::int64_t k, const OutputStamp& stamp,
                           const std::string& identity, const std::string& config_toml);

}  // namespace orogen
