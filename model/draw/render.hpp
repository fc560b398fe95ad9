// Rendering of DOT text to SVG or PNG through Graphviz's C library (libgvc): agmemread parses the
// text, gvLayout lays it out (engine "dot" by default), gvRenderData produces the image in memory,
// and the file is written atomically (write_file_atomic), so a failed rendering leaves no file.
// Graphviz's own diagnostics are captured and returned in the Error, never printed.
// One Graphviz context serves the whole process (see render.cpp).
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace gmr::draw {

enum class ImageFormat { Svg, Png };
const char* to_string(ImageFormat f);  // "svg", "png"

// The image bytes. Throws Error(Parse) for DOT text Graphviz rejects, Error(Usage) for an unknown
// layout engine, Error(Io) when rendering fails.
std::string render_dot(std::string_view dot, ImageFormat format, const std::string& engine = "dot");
void render_dot_file(std::string_view dot, ImageFormat format, const std::filesystem::path& out,
                     const std::string& engine = "dot");

}  // namespace gmr::draw
