// Translation of Jerboa embedding expressions (Java code in .jme files, thesis §6.3.3 and
// Ch. 8's generated code) into gmr's expression language (docs/embeddings.md).
//
// Translated: `return E;` bodies with local variables (`Vec3 v = E;`, `Vec3 v = new Vec3();
// v.barycenter(M);`), node values `n0.pos`, `n0@1@0.pos`, collects `<0,1>_pos(n0)`,
// `new Vec3(x, y, z)` (a point), `new Vec3(E)` (a copy), `Vec3.mid(a, b)` and
// `Point3.middle(a, b)` / `Point3.middle(M)` (barycentres), `E.addn(x, y, z)` (translation by a
// vector), `new Color(r, g, b)` (java.awt integers 0..255) and `new Color3(r, g, b)` (0..1).
// Everything else (rule parameters such as `weight`, `Vec3.segmentABByWeight`, `scale`, control
// flow, ...) is reported as unsupported with the first construct that is not understood: the
// sources give no semantics for it that this translation could be checked against.
#pragma once
#include <optional>
#include <string>

namespace gmr::io {

struct JerboaTranslation {
  std::optional<std::string> code;  // the expression in gmr's language
  std::string unsupported;          // why not, when !code
};

JerboaTranslation translate_jerboa_expression(const std::string& java);

}  // namespace gmr::io
