// 3D points: vertex positions of meshes (OFF/OBJ interop) and of the "position" embedding.
#pragma once
#include <array>

namespace gmr {

using Vec3 = std::array<double, 3>;

}  // namespace gmr
