// Scratch vectors kept by the thread between uses.
//
// A whole-map rewrite needs tables as large as the map (orbit indices, classes, memoised values),
// and fresh memory is paid page by page on first touch (a page fault per 4 KiB; several
// microseconds each on a virtual machine). Applying a scheme again and again (subdivision
// iterations) would pay it at every call: a Pooled<T> takes a vector, with its storage, from the
// thread's pool and gives it back when destroyed, so the next call writes into pages already
// mapped. The pool keeps at most 16 vectors per element type; contents are cleared on take.
#pragma once
#include <vector>

namespace gmr {

template <class T>
class Pooled {
 public:
  Pooled() : v_(take()) {}
  ~Pooled() { give(std::move(v_)); }
  Pooled(Pooled&& o) noexcept : v_(std::move(o.v_)) {}
  Pooled& operator=(Pooled&& o) noexcept {
    std::swap(v_, o.v_);
    return *this;
  }
  Pooled(const Pooled&) = delete;
  Pooled& operator=(const Pooled&) = delete;

  std::vector<T>& operator*() { return v_; }
  const std::vector<T>& operator*() const { return v_; }
  std::vector<T>* operator->() { return &v_; }
  const std::vector<T>* operator->() const { return &v_; }

 private:
  static std::vector<std::vector<T>>& pool() {
    thread_local std::vector<std::vector<T>> p;
    return p;
  }
  static std::vector<T> take() {
    auto& p = pool();
    if (p.empty()) return {};
    std::vector<T> v = std::move(p.back());
    p.pop_back();
    v.clear();
    return v;
  }
  static void give(std::vector<T>&& v) {
    if (v.capacity() == 0) return;
    auto& p = pool();
    if (p.size() < 16) p.push_back(std::move(v));
  }
  std::vector<T> v_;
};

}  // namespace gmr
