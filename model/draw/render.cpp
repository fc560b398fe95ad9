#include "model/draw/render.hpp"

#include <graphviz/gvc.h>

#include "model/core/error.hpp"
#include "model/map_io/atomic_write.hpp"

namespace gmr::draw {
using namespace gmr::io;

const char* to_string(ImageFormat f) { return f == ImageFormat::Svg ? "svg" : "png"; }

namespace {

std::string& captured() {
  static std::string text;
  return text;
}

int capture(char* msg) {
  captured() += msg;
  return 0;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

// One Graphviz context for the whole process, never freed: the pango text-layout plugin of
// Graphviz 2.43 keeps a pointer to the last font name in a static, which a gvFreeContext frees,
// so a second context would read freed memory (seen with AddressSanitizer).
GVC_t* context() {
  static GVC_t* const gvc = gvContext();
  return gvc;
}

// Owns the graph and its layout; restores the error handler on exit.
struct Session {
  GVC_t* gvc = nullptr;
  Agraph_t* graph = nullptr;
  bool laid_out = false;
  agusererrf previous = nullptr;
  Session() {
    captured().clear();
    previous = agseterrf(capture);
    agseterr(AGERR);
    gvc = context();
  }
  ~Session() {
    if (laid_out) gvFreeLayout(gvc, graph);
    if (graph) agclose(graph);
    agseterrf(previous);
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

}  // namespace

std::string render_dot(std::string_view dot, ImageFormat format, const std::string& engine) {
  Session s;
  if (!s.gvc) throw Error(ErrorCode::Io, "cannot create a Graphviz context");
  const std::string text(dot);
  s.graph = agmemread(text.c_str());
  if (!s.graph)
    throw Error(ErrorCode::Parse, "Graphviz rejected the DOT text: " + trimmed(captured()));
  if (gvLayout(s.gvc, s.graph, engine.c_str()) != 0)
    throw Error(ErrorCode::Usage,
                "Graphviz layout with engine \"" + engine + "\" failed: " + trimmed(captured()));
  s.laid_out = true;
  char* data = nullptr;
  unsigned int length = 0;
  if (gvRenderData(s.gvc, s.graph, to_string(format), &data, &length) != 0 || !data) {
    if (data) gvFreeRenderData(data);
    throw Error(ErrorCode::Io, std::string("Graphviz could not render ") + to_string(format) +
                                   ": " + trimmed(captured()));
  }
  std::string out(data, length);
  gvFreeRenderData(data);
  return out;
}

void render_dot_file(std::string_view dot, ImageFormat format, const std::filesystem::path& out,
                     const std::string& engine) {
  write_file_atomic(out, render_dot(dot, format, engine));
}

}  // namespace gmr::draw
