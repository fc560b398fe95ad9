#include "checker/smt/map_encoding.hpp"

#include <string>

namespace gmr::smt {

const char* to_string(DartSort s) { return s == DartSort::Int ? "int" : "bitvec"; }

namespace {
unsigned bits_for(unsigned values) {
  unsigned b = 1;
  while ((1u << b) < values + 1) ++b;  // + 1: `size` itself may equal the capacity
  return b;
}
z3::sort make_sort(z3::context& c, DartSort s, unsigned values) {
  return s == DartSort::Int ? c.int_sort() : c.bv_sort(bits_for(values));
}
}  // namespace

MapEncoding::MapEncoding(z3::context& ctx, MapSpec spec, unsigned capacity, unsigned extra,
                         DartSort sort, const std::string& prefix)
    : ctx_(ctx),
      spec_(spec),
      capacity_(capacity),
      sort_kind_(sort),
      sort_(make_sort(ctx, sort, capacity + extra)),
      size_(ctx.constant((prefix + "size").c_str(), sort_)) {
  for (int i = 0; i <= spec_.n; ++i) {
    const std::string name = prefix + (spec_.is_omap() ? "beta" : "alpha") + std::to_string(i);
    alpha_.push_back(ctx_.function(name.c_str(), sort_, sort_));
    inverse_.push_back(ctx_.function((name + "_inv").c_str(), sort_, sort_));
  }
}

z3::expr MapEncoding::dart(unsigned v) const {
  return sort_kind_ == DartSort::Int ? ctx_.int_val(v) : ctx_.bv_val(v, sort_.bv_size());
}

z3::expr MapEncoding::lt(const z3::expr& a, const z3::expr& b) const {
  return sort_kind_ == DartSort::Int ? a < b : z3::ult(a, b);
}

z3::expr MapEncoding::active_term(const z3::expr& t) const {
  return sort_kind_ == DartSort::Int ? (t >= 0 && t < size_) : z3::ult(t, size_);
}

z3::expr MapEncoding::alpha(int i, const z3::expr& d) const { return alpha_[i](d); }

z3::expr MapEncoding::alpha_inverse(int i, const z3::expr& d) const {
  return spec_.is_involutive_dim(i) ? alpha_[i](d) : inverse_[i](d);
}

z3::expr_vector MapEncoding::constraints() const {
  z3::expr_vector out(ctx_);
  out.push_back(lt(dart(0), size_));
  out.push_back(!lt(dart(capacity_), size_));
  for (unsigned v = 0; v < capacity_; ++v) {
    const z3::expr d = dart(v);
    z3::expr_vector here(ctx_);
    for (int i : spec_.labels()) {
      const z3::expr a = alpha(i, d);
      if (sort_kind_ == DartSort::Int) here.push_back(a >= 0);
      here.push_back(lt(a, size_));
      if (spec_.is_involutive_dim(i)) {
        here.push_back(alpha(i, a) == d);  // I(i) and O(i): an involution
      } else {
        const z3::expr b = inverse_[i](d);  // I(i): a permutation
        if (sort_kind_ == DartSort::Int) here.push_back(b >= 0);
        here.push_back(lt(b, size_));
        here.push_back(inverse_[i](a) == d);
        here.push_back(alpha(i, b) == d);
      }
    }
    for (auto [i, j] : spec_.cycle_pairs())
      here.push_back(alpha(j, alpha(i, alpha(j, alpha(i, d)))) == d);
    out.push_back(z3::implies(active(v), z3::mk_and(here)));
  }
  return out;
}

}  // namespace gmr::smt
