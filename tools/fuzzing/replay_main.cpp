// The fuzz targets without libFuzzer (any compiler, the CTest runs in the release and the sanitizer
// builds): every seed file, then `--mutations N` deterministic mutations of each (bit flips,
// interesting bytes, dictionary tokens, deleted, duplicated and truncated ranges, oversized
// numbers). A finding (an exception other than gmr::Error escaping the target, or a sanitizer
// report) stops the run with the seed, the mutation index and the input written to --crash-dir.
//
//   gmr_fuzz_<target> [--mutations N] [--dict FILE] [--crash-dir DIR] FILE|DIR...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {
namespace fs = std::filesystem;

struct Options {
  size_t mutations = 0;
  fs::path dict, crash_dir = ".";
  std::vector<fs::path> inputs;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// libFuzzer dictionary lines: name="token" or "token", with \\, \" and \xNN escapes.
std::vector<std::string> read_dictionary(const fs::path& p) {
  std::vector<std::string> tokens;
  std::ifstream in(p);
  for (std::string line; std::getline(in, line);) {
    const size_t open = line.find('"'), close = line.rfind('"');
    if (line.empty() || line[0] == '#' || open == std::string::npos || close <= open) continue;
    std::string t;
    for (size_t k = open + 1; k < close; ++k) {
      if (line[k] != '\\' || k + 1 >= close) {
        t += line[k];
      } else if (line[k + 1] == 'x' && k + 3 < close) {
        t += static_cast<char>(std::stoi(line.substr(k + 2, 2), nullptr, 16));
        k += 3;
      } else {
        t += line[++k];
      }
    }
    tokens.push_back(t);
  }
  return tokens;
}

std::string mutate(std::string s, std::mt19937_64& rng, const std::vector<std::string>& dict) {
  static const std::vector<std::string> numbers = {
      "-1",  "0",         "4294967295", "4294967296", "1e999", "-0.0", "99999999999999999999",
      "1.5", "2147483648"};
  static const std::string bytes = std::string("\0\xff[]{}\"-9<>/,:\n", 16);
  auto pick = [&](size_t n) { return n == 0 ? size_t{0} : static_cast<size_t>(rng() % n); };
  const size_t steps = 1 + pick(4);
  for (size_t k = 0; k < steps; ++k) {
    const size_t at = pick(s.size() + 1);
    switch (pick(7)) {
      case 0:
        if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1u << pick(8));
        break;
      case 1:
        if (!s.empty()) s[pick(s.size())] = bytes[pick(bytes.size())];
        break;
      case 2:
        if (!dict.empty()) s.insert(at, dict[pick(dict.size())]);
        break;
      case 3:
        s.erase(at, 1 + pick(16));
        break;
      case 4: {
        const std::string chunk = s.substr(pick(s.size() + 1), 1 + pick(64));
        s.insert(pick(s.size() + 1), chunk);
        break;
      }
      case 5:
        s.resize(pick(s.size() + 1));
        break;
      default: {  // replace a run of digits by an oversized or odd number
        const size_t d = s.find_first_of("0123456789", at);
        if (d == std::string::npos) break;
        const size_t e = s.find_first_not_of("0123456789", d);
        s.replace(d, (e == std::string::npos ? s.size() : e) - d, numbers[pick(numbers.size())]);
      }
    }
  }
  return s;
}

int run(const Options& o) {
  std::vector<fs::path> seeds;
  for (const fs::path& p : o.inputs) {
    if (fs::is_directory(p)) {
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file()) seeds.push_back(e.path());
    } else {
      seeds.push_back(p);
    }
  }
  std::sort(seeds.begin(), seeds.end());
  const std::vector<std::string> dict =
      o.dict.empty() ? std::vector<std::string>{} : read_dictionary(o.dict);
  size_t executed = 0;
  for (const fs::path& seed : seeds) {
    const std::string original = read_all(seed);
    std::mt19937_64 rng(std::hash<std::string>{}(seed.filename().string()));
    for (size_t m = 0; m <= o.mutations; ++m) {
      const std::string input = m == 0 ? original : mutate(original, rng, dict);
      try {
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.data()), input.size());
      } catch (const std::exception& e) {
        const fs::path crash =
            o.crash_dir / ("crash-" + seed.filename().string() + "-" + std::to_string(m));
        std::ofstream(crash, std::ios::binary) << input;
        std::cerr << "finding: " << e.what() << "\n  seed " << seed.string() << ", mutation " << m
                  << "\n  input written to " << crash.string() << "\n";
        return 1;
      }
      ++executed;
    }
  }
  std::cout << executed << " inputs (" << seeds.size() << " seeds, " << o.mutations
            << " mutations each), no finding\n";
  return seeds.empty() ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if ((a == "--mutations" || a == "--dict" || a == "--crash-dir") && k + 1 < argc) {
      const std::string v = argv[++k];
      if (a == "--mutations")
        o.mutations = std::stoul(v);
      else if (a == "--dict")
        o.dict = v;
      else
        o.crash_dir = v;
    } else {
      o.inputs.emplace_back(a);
    }
  }
  if (o.inputs.empty()) {
    std::cerr << "usage: " << argv[0]
              << " [--mutations N] [--dict FILE] [--crash-dir DIR] FILE|DIR...\n";
    return 2;
  }
  return run(o);
}
