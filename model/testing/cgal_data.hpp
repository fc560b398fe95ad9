// CGAL's data meshes for tests and benchmarks: Debian's libcgal-demo ships them in data.tar.gz
// (tools/setup.sh installs it); a mesh is unpacked on first use into ./cgal-data (git-ignored).
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

namespace gmr::testing {

inline constexpr const char* kCgalDataArchive = "/usr/share/doc/libcgal-dev/data.tar.gz";

// The path of data/meshes/<name>.off unpacked from CGAL's archive, or "" when the archive is
// absent.
inline std::string cgal_mesh(const std::string& name) {
  namespace fs = std::filesystem;
  if (!fs::exists(kCgalDataArchive)) return {};
  const fs::path dir = fs::current_path() / "cgal-data";
  const fs::path off = dir / "data" / "meshes" / (name + ".off");
  if (!fs::exists(off)) {
    fs::create_directories(dir);
    const std::string cmd = "tar xzf " + std::string(kCgalDataArchive) + " -C '" + dir.string() +
                            "' data/meshes/" + name + ".off";
    if (std::system(cmd.c_str()) != 0) return {};
  }
  return off.string();
}

}  // namespace gmr::testing
