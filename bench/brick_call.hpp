// A brick's double reference called by id on packed arguments, for the benches that compose
// bricks as a model does (bench_area_lights.cpp, area_lights_ltc.cpp).
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "common/reference.hpp"

namespace mb::bench {

// A brick's double reference by id, on packed arguments (Geometry = n, v, l).
inline std::vector<double> callBrick(const std::string& id, const std::vector<double>& args) {
  const ref::Reference* r = ref::Registry::references().find(id);
  if (!r) throw std::runtime_error("no reference for brick " + id);
  std::vector<double> out(3, 0.0);
  r->eval(args.data(), out.data());
  return out;
}
inline std::vector<double> pack(const ref::Geometry& g) {
  return {g.n.x, g.n.y, g.n.z, g.v.x, g.v.y, g.v.z, g.l.x, g.l.y, g.l.z};
}
inline void append(std::vector<double>& a, const ref::Vec3& v) { a.insert(a.end(), {v.x, v.y, v.z}); }

}  // namespace mb::bench
