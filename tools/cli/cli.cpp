#include "tools/cli/cli.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "model/core/position.hpp"
#include "model/draw/render.hpp"
#include "model/map_io/atomic_write.hpp"
#include "model/map_io/json_reader.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/map_io/map_json.hpp"
#include "model/map_io/obj.hpp"
#include "model/map_io/off.hpp"
#include "model/map_io/read_file.hpp"
#include "model/map_io/validity_report.hpp"
#include "model/map_io/voxels.hpp"

namespace gmr::cli {
using namespace gmr::io;
using namespace gmr::draw;

namespace {
int g_exit = kExitOk;
}

void set_action(CLI::App* sub, std::function<int()> action) {
  sub->callback([action = std::move(action)] { g_exit = action(); });
}

int exit_code() { return g_exit; }

const char* to_string(Format f) {
  switch (f) {
    case Format::Json:
      return "json";
    case Format::Off:
      return "off";
    case Format::Obj:
      return "obj";
    case Format::Dot:
      return "dot";
    case Format::Svg:
      return "svg";
    case Format::Png:
      return "png";
  }
  return "?";
}

std::optional<Format> parse_format(const std::string& name) {
  for (Format f : {Format::Json, Format::Off, Format::Obj, Format::Dot, Format::Svg, Format::Png})
    if (name == to_string(f)) return f;
  return std::nullopt;
}

namespace {

Format detect(const std::string& path, const std::string& override, const char* option,
              const char* formats) {
  if (!override.empty()) {
    if (auto f = parse_format(override)) return *f;
    throw Error(ErrorCode::Usage, "unknown format \"" + override + "\"", option);
  }
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (!ext.empty())
    if (auto f = parse_format(ext.substr(1))) return *f;
  if (ext == ".jme")
    throw Error(ErrorCode::Usage,
                "a Jerboa rule file (.jme) holds rules, not a map: give it to check, apply or dot "
                "as the rule",
                path);
  throw Error(ErrorCode::Usage,
              "cannot tell the format from the file name" +
                  std::string(ext.empty() ? "" : " (extension " + ext + ")") + "; name it with " +
                  option + " " + formats,
              path);
}

}  // namespace

Format input_format(const std::string& path, const std::string& override) {
  const Format f = detect(path, override, "--from", kInputFormats);
  if (f != Format::Json && f != Format::Off && f != Format::Obj)
    throw Error(
        ErrorCode::Usage,
        std::string("cannot read ") + to_string(f) + " maps (input formats: " + kInputFormats + ")",
        path);
  return f;
}

Format output_format(const std::string& path, const std::string& override) {
  return detect(path, override, "--to", kOutputFormats);
}

Format drawing_format(const std::string& path, const std::string& override) {
  const Format out = path == "-" && override.empty() ? Format::Dot : output_format(path, override);
  if (out != Format::Dot && out != Format::Svg && out != Format::Png)
    throw Error(ErrorCode::Usage,
                std::string("drawings are written as dot, svg or png, not ") + to_string(out),
                path);
  return out;
}

EmbeddedMap load_map(const std::string& path, const std::string& from) {
  const Format f = input_format(path, from);
  if (f == Format::Off)
    return path == "-" ? read_off(read_text_file(path), "<stdin>") : read_off_file(path);
  if (f == Format::Obj) return read_obj(read_text_file(path), path == "-" ? "<stdin>" : path);
  // JSON: a gmr.gmap document, or a gmr.voxels set read as its polycube (builders.hpp).
  const std::string source = path == "-" ? "<stdin>" : path;
  const nlohmann::json doc = parse_json(read_text_file(path), source);
  const JsonAt at(doc, source);
  if (doc.is_object() && doc.contains("format") && doc["format"] == "gmr.voxels")
    return EmbeddedMap(make_polycube(voxels_from_json(at)));
  return map_from_json(at);
}

void write_output(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text << std::flush;
    return;
  }
  write_file_atomic(path, text);
}

void write_drawing(const std::string& path, const std::string& dot, Format format) {
  if (format == Format::Dot) {
    write_output(path, dot);
    return;
  }
  if (path == "-") throw Error(ErrorCode::Usage, "images are not written to standard output", path);
  render_dot_file(dot, format == Format::Svg ? ImageFormat::Svg : ImageFormat::Png, path);
}

namespace {

// The positions a mesh format needs, or an error located at the output naming what is missing.
const PositionEmbedding& positions_for_output(const EmbeddedMap& f, const std::string& path,
                                              Format format) {
  if (!f.find(kPositionName))
    throw Error(ErrorCode::Schema,
                std::string("the map has no \"position\" embedding: ") + to_string(format) +
                    " output needs vertex coordinates (write json, dot or svg instead)",
                path);
  return f.position();
}

}  // namespace

void save_map(const EmbeddedMap& f, const std::string& path, Format format, const DotOptions& dot,
              size_t max_rendered_darts) {
  switch (format) {
    case Format::Json:
      write_output(path, write_map_json(f));
      return;
    case Format::Off: {
      write_output(path, write_off(f.map, positions_for_output(f, path, format)));
      return;
    }
    case Format::Obj: {
      write_output(path, write_obj(f.map, positions_for_output(f, path, format)));
      return;
    }
    case Format::Dot:
      write_output(path, to_dot(f.map, dot));
      return;
    case Format::Svg:
    case Format::Png: {
      if (path == "-")
        throw Error(ErrorCode::Usage, "images are not written to standard output", path);
      if (f.map.size() > max_rendered_darts)
        throw Error(ErrorCode::Usage,
                    "the map has " + std::to_string(f.map.size()) +
                        " darts; Graphviz is not asked to lay out more than " +
                        std::to_string(max_rendered_darts) +
                        " (it would run for minutes to hours): write .dot instead, or raise the "
                        "limit with gmr dot --max-darts N",
                    path);
      render_dot_file(to_dot(f.map, dot),
                      format == Format::Svg ? ImageFormat::Svg : ImageFormat::Png, path);
      return;
    }
  }
}

const CLI::Validator& non_negative_integer() {
  static const CLI::Validator check(
      [](std::string& text) -> std::string {
        const bool digits =
            !text.empty() && std::all_of(text.begin(), text.end(),
                                         [](unsigned char c) { return std::isdigit(c) != 0; });
        return digits ? std::string()
                      : "expected a non-negative integer, found \"" + abbreviate(text) + "\"";
      },
      "UINT");
  return check;
}

std::string abbreviate(const std::string& text, size_t max_chars) {
  if (text.size() <= max_chars) return text;
  const size_t keep = max_chars / 2;
  return text.substr(0, keep) + "[... " + std::to_string(text.size() - 2 * keep) +
         " characters ...]" + text.substr(text.size() - keep);
}

void print_violations(const ValidityReport& r) { std::cout << io::to_text(r); }

void print_json(const nlohmann::ordered_json& j) { std::cout << dump_json(j) << std::flush; }

}  // namespace gmr::cli
