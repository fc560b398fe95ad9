#include "model/map_io/map_json.hpp"

#include <charconv>

#include "model/core/orbit.hpp"
#include "model/map_io/atomic_write.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/map_io/read_file.hpp"
#include "model/map_io/read_limits.hpp"

namespace gmr::io {

namespace {

// A dimension key: a decimal integer without sign or leading zeros.
bool parse_dim_key(const std::string& key, int& dim) {
  if (key.empty() || key.size() > 2 || (key.size() > 1 && key[0] == '0')) return false;
  auto [p, ec] = std::from_chars(key.data(), key.data() + key.size(), dim);
  return ec == std::errc() && p == key.data() + key.size();
}

// Checks the dimension keys of "alpha" and that each link array has one entry per dart, before
// any dart is allocated (a small file may declare billions of darts).
void check_link_arrays(const JsonAt& alpha, const Map& g, Dart n_darts) {
  alpha.require_object();
  const int lo = g.lowest_dim(), n = g.dimension();
  const std::string dims = std::to_string(lo) + ".." + std::to_string(n);
  for (auto it = alpha.value().begin(); it != alpha.value().end(); ++it) {
    int dim = -1;
    if (!parse_dim_key(it.key(), dim) || !g.has_dim(dim))
      alpha.fail_at(alpha.child_path(it.key()), "\"" + it.key() + "\" is not a dimension of this " +
                                                    to_string(g.kind()) + " (expected " + dims +
                                                    ")");
  }
  for (int i = lo; i <= n; ++i) {
    const JsonAt links = alpha[std::to_string(i)];
    const size_t count = links.array_size();
    if (count != n_darts)
      links.fail("expected " + std::to_string(n_darts) + " entries (one per dart), found " +
                 std::to_string(count));
  }
}

void read_links(const JsonAt& alpha, Map& g, Dart n_darts) {
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
    const JsonAt links = alpha[std::to_string(i)];
    const nlohmann::json& arr = links.value();
    for (Dart d = 0; d < n_darts; ++d) {
      const nlohmann::json& t = arr[d];
      if (!t.is_number_integer() && !t.is_number_unsigned())
        links.fail_at(links.child_path(d),
                      "expected a dart index (an integer), found " + describe_json(t));
      if (!t.is_number_unsigned() || t.get<uint64_t>() >= n_darts) {
        const std::string what = t.dump();
        links.fail_at(links.child_path(d), "dart index " + what + " out of range: the map has " +
                                               std::to_string(n_darts) + " darts (0.." +
                                               std::to_string(static_cast<int64_t>(n_darts) - 1) +
                                               ")");
      }
      g.set_alpha(i, d, static_cast<Dart>(t.get<uint64_t>()));
    }
  }
}

EmbeddingField read_embedding(const JsonAt& at, const Map& g, Dart n_darts) {
  at.require_object();
  at.allow_only({"name", "orbit", "values"});
  const JsonAt name_at = at["name"];
  const std::string name = name_at.as_string();
  if (name.empty()) name_at.fail("an embedding name must not be empty");
  const JsonAt orbit_at = at["orbit"];
  OrbitType type;
  try {
    type = OrbitType::parse(orbit_at.as_string());
    require_orbit_type(g, type);
  } catch (const Error& e) {
    orbit_at.fail(e.message());
  }
  std::vector<std::pair<Dart, nlohmann::json>> read;
  const JsonAt values = at["values"];
  const size_t count = values.array_size();
  std::vector<uint32_t> entry_of(n_darts,
                                 UINT32_MAX);  // which entry gave the value of a dart's orbit
  for (size_t k = 0; k < count; ++k) {
    const JsonAt entry = values[k];
    entry.require_object();
    entry.allow_only({"dart", "value"});
    const JsonAt dart_at = entry["dart"];
    const nlohmann::json& dv = dart_at.value();
    if (!dv.is_number_integer() && !dv.is_number_unsigned())
      dart_at.fail("expected a dart index (an integer), found " + describe_json(dv));
    if (!dv.is_number_unsigned() || dv.get<uint64_t>() >= n_darts)
      dart_at.fail("dart index " + dv.dump() + " out of range: the map has " +
                   std::to_string(n_darts) + " darts");
    const auto d = static_cast<Dart>(dv.get<uint64_t>());
    const JsonAt value_at = entry["value"];
    const std::vector<Dart> darts = orbit(g, type, d);
    for (Dart e : darts) {
      if (entry_of[e] != UINT32_MAX)
        entry.fail("the " + type.str() + "-orbit of dart " + std::to_string(d) +
                   " already has a value (" + values.child_path(entry_of[e]) + ")");
    }
    for (Dart e : darts) entry_of[e] = static_cast<uint32_t>(k);
    read.emplace_back(d, value_at.value());
  }
  return field_from_json(g, name, type, read);
}

}  // namespace

EmbeddedMap map_from_json(const JsonAt& doc) {
  doc.check_header(kGMapFormat, kGMapVersion);
  doc.allow_only({"format", "version", "kind", "dimension", "darts", "alpha", "embeddings"});
  const JsonAt kind_at = doc["kind"];
  const std::string kind_text = kind_at.as_string();
  if (kind_text != "gmap" && kind_text != "omap")
    kind_at.fail("expected \"gmap\" or \"omap\", found \"" + kind_text + "\"");
  const MapKind kind = kind_text == "gmap" ? MapKind::GMap : MapKind::OMap;
  const auto n =
      static_cast<int>(doc["dimension"].as_int(MapSpec{0, kind}.lowest_dim(), kMaxDim - 1));
  const auto n_darts = static_cast<Dart>(doc["darts"].as_int(0, static_cast<int64_t>(kNoDart) - 1));
  EmbeddedMap f(Map(n, kind));
  check_dart_limit(n_darts, doc["darts"].location());
  check_link_arrays(doc["alpha"], f.map, n_darts);
  f.map.add_darts(n_darts);
  read_links(doc["alpha"], f.map, n_darts);
  if (auto embs = doc.get("embeddings")) {
    const size_t count = embs->array_size();
    for (size_t k = 0; k < count; ++k) {
      const JsonAt e = (*embs)[k];
      EmbeddingField field = read_embedding(e, f.map, n_darts);
      if (f.find(field.name())) e["name"].fail("duplicate embedding name \"" + field.name() + "\"");
      f.fields.push_back(std::move(field));
    }
  }
  return f;
}

EmbeddedMap read_map_json(std::string_view text, const std::string& source) {
  const nlohmann::json doc = parse_json(text, source);
  return map_from_json(JsonAt(doc, source));
}

EmbeddedMap read_map_json_file(const std::filesystem::path& path) {
  return read_map_json(read_text_file(path), path.string());
}

nlohmann::ordered_json map_to_json(const Map& g, const std::vector<EmbeddingField>& fields) {
  // Dense renumbering of the live darts.
  std::vector<Dart> index(g.capacity(), kNoDart);
  Dart next = 0;
  g.for_each_dart([&](Dart d) { index[d] = next++; });
  nlohmann::ordered_json j;
  j["format"] = kGMapFormat;
  j["version"] = kGMapVersion;
  j["kind"] = to_string(g.kind());
  j["dimension"] = g.dimension();
  j["darts"] = next;
  nlohmann::ordered_json alpha = nlohmann::ordered_json::object();
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
    nlohmann::ordered_json arr = nlohmann::ordered_json::array();
    g.for_each_dart([&](Dart d) {
      const Dart t = g.alpha(i, d);
      if (!g.alive(t))
        throw Error(ErrorCode::InvalidMap,
                    "cannot write a link to a dart that does not exist (" + std::to_string(t) + ")",
                    "dart " + std::to_string(d));
      arr.push_back(index[t]);
    });
    alpha[std::to_string(i)] = std::move(arr);
  }
  j["alpha"] = std::move(alpha);
  nlohmann::ordered_json embs = nlohmann::ordered_json::array();
  for (const EmbeddingField& e : fields) {
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (Dart rep : orbit_representatives(g, e.orbit())) {
      if (!e.has(rep)) continue;
      nlohmann::ordered_json v;
      v["dart"] = index[rep];
      v["value"] = nlohmann::ordered_json(e.value_json(rep));
      values.push_back(std::move(v));
    }
    nlohmann::ordered_json je;
    je["name"] = e.name();
    je["orbit"] = e.orbit().str();
    je["values"] = std::move(values);
    embs.push_back(std::move(je));
  }
  j["embeddings"] = std::move(embs);
  return j;
}

std::string write_map_json(const Map& g, const std::vector<EmbeddingField>& fields) {
  return dump_json(map_to_json(g, fields));
}

void write_map_json_file(const std::filesystem::path& path, const EmbeddedMap& f) {
  write_file_atomic(path, write_map_json(f));
}

}  // namespace gmr::io
