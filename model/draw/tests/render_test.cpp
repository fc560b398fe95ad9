// DOT rendering through Graphviz (tools/render.hpp): SVG and PNG bytes, rejected DOT text reported
// as Error(Parse) with Graphviz's diagnostic, no file left behind on failure.
#include "model/draw/render.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/draw/map_dot.hpp"
#include "model/map_io/read_file.hpp"
#include "model/testing/scratch_dir.hpp"

using namespace gmr;
using namespace gmr::io;
using namespace gmr::draw;
namespace fs = std::filesystem;

TEST(Render, SvgAndPng) {
  const std::string dot = to_dot(make_cube());
  const std::string svg = render_dot(dot, ImageFormat::Svg);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"blue\""), std::string::npos);
  const std::string png = render_dot(dot, ImageFormat::Png);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(Render, BadDotIsAParseErrorAndLeavesNoFile) {
  const fs::path dir = gmr::testing::scratch_path("gmr_render_test");
  fs::remove_all(dir);
  fs::create_directories(dir);
  try {
    render_dot_file("graph { 0 -- ", ImageFormat::Svg, dir / "bad.svg");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Parse);
    EXPECT_NE(e.message().find("syntax error"), std::string::npos) << e.message();
  }
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_THROW(render_dot("graph { a -- b }", ImageFormat::Svg, "no-such-engine"), Error);
  render_dot_file("graph { a -- b }", ImageFormat::Svg, dir / "ok.svg");
  EXPECT_NE(read_text_file(dir / "ok.svg").find("<svg"), std::string::npos);
  fs::remove_all(dir);
}
