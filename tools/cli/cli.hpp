// Shared plumbing of the `gmr` subcommands (tools/cli/cmd_*.cpp).
//
// Exit codes: 0 success, 1 negative verdict (e.g. an invalid map), 2 bad
// input or usage. A subcommand's action returns 0 or 1; bad input is a thrown gmr::Error, which
// main.cpp prints as "gmr: error: <location>: <message>" and maps to 2.
//
// Map files: the format comes from the extension (.json, .off for input; .json, .off, .obj, .dot,
// .svg, .png for output) unless --from/--to names it. "-" is standard input (with --from) or
// standard output (text formats, with --to).
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "model/core/embedded_map.hpp"
#include "model/core/validity.hpp"
#include "model/draw/map_dot.hpp"

namespace gmr::cli {
using draw::DotOptions;

inline constexpr int kExitOk = 0;
inline constexpr int kExitNegative = 1;
inline constexpr int kExitBadInput = 2;

// Attaches `action` to subcommand `sub`; its result becomes the exit code of the process.
void set_action(CLI::App* sub, std::function<int()> action);
int exit_code();

enum class Format { Json, Off, Obj, Dot, Svg, Png };
const char* to_string(Format f);
// "json" -> Json, ...; nullopt for an unknown name.
std::optional<Format> parse_format(const std::string& name);
// The format of `path` from `override` when given, else from its extension. Error(Usage) when
// neither tells, or when the format cannot be read (input) / written (output).
Format input_format(const std::string& path, const std::string& override);
Format output_format(const std::string& path, const std::string& override);
// The format of a drawing (`gmr dot`): dot on standard output without --to, else output_format;
// Error(Usage) for a format other than dot, svg or png.
Format drawing_format(const std::string& path, const std::string& override);
// Help text for --from / --to.
inline constexpr const char* kInputFormats = "json|off|obj";
inline constexpr const char* kOutputFormats = "json|off|obj|dot|svg|png";

EmbeddedMap load_map(const std::string& path, const std::string& from = {});
// Graphviz lays out a few hundred darts in seconds and a 300,000-dart map in hours: drawings
// rendered to SVG/PNG are refused above this many darts unless raised (`gmr dot --max-darts`).
inline constexpr size_t kMaxRenderedDarts = 1000;

// Writes `f` to `path` (atomically; "-" = standard output for text formats). SVG/PNG of maps with
// more than `max_rendered_darts` darts are refused with Error(Usage).
void save_map(const EmbeddedMap& f, const std::string& path, Format format,
              const DotOptions& dot = {}, size_t max_rendered_darts = kMaxRenderedDarts);
// Writes text to `path` atomically, or to standard output for "-".
void write_output(const std::string& path, const std::string& text);
// Writes a drawing in `format` (drawing_format): the DOT text itself, or its SVG/PNG rendering
// through Graphviz (Error(Usage) for an image on standard output).
void write_drawing(const std::string& path, const std::string& dot, Format format);

// The violations of a validity report, one per line, then "... and N more (--limit)".
void print_violations(const ValidityReport& r);

// Pretty JSON on standard output (model/json_writer.hpp layout).
void print_json(const nlohmann::ordered_json& j);

// Option check for counts and limits: digits only (CLI11 would read "-1" into a size_t as its
// largest value).
const CLI::Validator& non_negative_integer();

// `text` itself when short, else its first and last characters around "[... N characters ...]":
// messages quote user input (an orbit type, a file name) without echoing megabytes of it.
std::string abbreviate(const std::string& text, size_t max_chars = 200);

// Directory of the example data files: tools/data of the current directory when it is a gmr
// checkout, else the source tree's tools/data recorded at build time.
std::string default_data_dir();

}  // namespace gmr::cli
