#include "model/core/huge_pages.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gmr {
namespace {

TEST(HugePages, ReserveKeepsTheElements) {
  std::vector<uint32_t> v(1000000);
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<uint32_t>(i * 7);
  reserve_in_huge_pages(v, 8000000);
  ASSERT_GE(v.capacity(), 8000000u);
  ASSERT_EQ(v.size(), 1000000u);
  for (size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i * 7) << i;
}

// A per-dart table: the new elements get the value, the storage at least doubles when it grows.
TEST(HugePages, ResizeSetsTheNewElementsAndGrowsGeometrically) {
  std::vector<uint32_t> v{1, 2, 3};
  v.shrink_to_fit();
  resize_in_huge_pages(v, 5, 9u);
  EXPECT_EQ(v, (std::vector<uint32_t>{1, 2, 3, 9, 9}));
  EXPECT_GE(v.capacity(), 6u);
  resize_in_huge_pages(v, 2, 0u);  // never shrinks
  EXPECT_EQ(v.size(), 5u);
}

// Kilobytes of huge pages in the mappings that meet [p, p + bytes) (/proc/self/smaps; the advice
// splits a mapping at the 2 MiB boundaries).
long anon_huge_kb(const void* p, size_t bytes) {
  std::ifstream smaps("/proc/self/smaps");
  const auto begin = reinterpret_cast<uintptr_t>(p), end = begin + bytes;
  bool inside = false;
  long kb = 0;
  for (std::string line; std::getline(smaps, line);) {
    uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (line.find('-') < line.find(' ') && head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo < end && begin < hi;
      continue;
    }
    if (inside && line.rfind("AnonHugePages:", 0) == 0) kb += std::stol(line.substr(14));
  }
  return kb;
}

// The storage is advised before the elements move into it: the pages they are written to are
// faulted in as huge pages (v.reserve then advice would fault them in 4 KiB first).
TEST(HugePages, TheMovedElementsLandInHugePages) {
  std::ifstream policy("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes((std::istreambuf_iterator<char>(policy)), std::istreambuf_iterator<char>());
  if (modes.find("[madvise]") == std::string::npos && modes.find("[always]") == std::string::npos)
    GTEST_SKIP() << "transparent huge pages are off: " << modes;
  std::vector<uint64_t> v(size_t(2) << 20, 1);  // 16 MiB
  reserve_in_huge_pages(v, size_t(8) << 20);    // 64 MiB: a fresh mapping
  EXPECT_GE(anon_huge_kb(v.data(), v.size() * sizeof(uint64_t)), 2048);
}

}  // namespace
}  // namespace gmr
