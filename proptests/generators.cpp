#include "proptests/generators.hpp"

#include "model/io_dot.hpp"
#include "model/io_json.hpp"

namespace gmr::prop {

GMap MapCase::build() const {
  Rng rng(seed);
  switch (family) {
    case Generator::GluedPolygons: {
      GluedPolygonsOptions o;
      o.n = n;
      o.min_faces = 1;
      o.max_faces = size;
      o.max_extra_sews = size;
      return random_glued_polygons(rng, o);
    }
    case Generator::Polycube: {
      PolycubeOptions o;
      o.min_voxels = 1;
      o.max_voxels = size;
      return random_polycube(rng, o);
    }
    case Generator::SewSequence: {
      SewSequenceOptions o;
      o.n = n;
      o.min_cells = 1;
      o.max_cells = size;
      o.steps = 3 * size;
      return random_sewn_cells(rng, o);
    }
  }
  return GMap(n);
}

std::string MapCase::str() const {
  return std::string("MapCase{") + to_string(family) + ", n=" + std::to_string(n) +
         ", size=" + std::to_string(size) + ", seed=" + std::to_string(seed) + "}";
}

rc::Gen<MapCase> gen_map_case_of_dim(int n, size_t max_size) {
  const auto families = generators_for(n);
  return rc::gen::apply(
      [n, families](size_t fam, size_t size, uint64_t seed) {
        return MapCase{families[fam], n, size, seed};
      },
      rc::gen::inRange<size_t>(0, families.size()), rc::gen::inRange<size_t>(1, max_size + 1),
      rc::gen::inRange<uint64_t>(0, 1u << 20));
}

rc::Gen<MapCase> gen_map_case(size_t max_size) {
  return rc::gen::mapcat(rc::gen::inRange(1, 4),
                         [max_size](int n) { return gen_map_case_of_dim(n, max_size); });
}

rc::Gen<OrbitType> gen_orbit_type(int n) {
  return rc::gen::map(rc::gen::inRange<uint32_t>(0, 1u << (n + 1)), [n](uint32_t mask) {
    std::vector<int> dims;
    for (int i = 0; i <= n; ++i)
      if (mask >> i & 1u) dims.push_back(i);
    return OrbitType(std::move(dims));
  });
}

rc::Gen<std::vector<Dart>> gen_permutation(size_t k) {
  return rc::gen::map(rc::gen::arbitrary<uint64_t>(), [k](uint64_t seed) {
    Rng rng(seed);
    return random_permutation(rng, k);
  });
}

std::string describe_counterexample(const GMap& g) {
  std::string s = "--- counterexample (gmr.gmap) ---\n" + write_gmap_json(g, {});
  s += "\n--- diagram (DOT) ---\n" + to_dot(g);
  return s;
}

}  // namespace gmr::prop
