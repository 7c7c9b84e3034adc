// tests/fuzz/support/replay_main.cpp: runs a fuzz target without libFuzzer (g++ builds): every
// file of its seed corpus, then deterministic byte-level mutations of each, so inputs that once
// crashed stay regression tests. Usage: <target> <corpus-dir-or-file>... [--mutations N]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::uint8_t> read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One mutation in the spirit of libFuzzer's: flip, overwrite, insert, erase or duplicate bytes.
void mutate(std::vector<std::uint8_t>& d, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 4);
  auto pos = [&](std::size_t n) { return n ? std::uniform_int_distribution<std::size_t>(0, n - 1)(rng) : 0; };
  switch (d.empty() ? 2 : kind(rng)) {
    case 0: d[pos(d.size())] ^= static_cast<std::uint8_t>(1u << (rng() % 8)); break;
    case 1: d[pos(d.size())] = static_cast<std::uint8_t>(rng()); break;
    case 2: d.insert(d.begin() + static_cast<long>(pos(d.size() + 1)), static_cast<std::uint8_t>(rng())); break;
    case 3: d.erase(d.begin() + static_cast<long>(pos(d.size()))); break;
    case 4: {
      std::size_t a = pos(d.size()), n = std::min<std::size_t>(d.size() - a, 1 + rng() % 16);
      std::vector<std::uint8_t> chunk(d.begin() + static_cast<long>(a), d.begin() + static_cast<long>(a + n));
      d.insert(d.begin() + static_cast<long>(pos(d.size() + 1)), chunk.begin(), chunk.end());
      break;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 2000;
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--mutations") == 0 && i + 1 < argc) mutations = std::atol(argv[++i]);
    else if (std::filesystem::is_directory(argv[i])) {
      for (const auto& e : std::filesystem::recursive_directory_iterator(argv[i]))
        if (e.is_regular_file()) inputs.push_back(e.path());
    } else if (std::filesystem::exists(argv[i])) {
      inputs.push_back(argv[i]);
    }
  }
  std::sort(inputs.begin(), inputs.end());
  std::vector<std::vector<std::uint8_t>> seeds;
  for (const auto& p : inputs) seeds.push_back(read_file(p));
  if (seeds.empty()) seeds.push_back({});

  // Seeds as they are, then mutated copies (a fixed seed keeps the run reproducible).
  for (const auto& s : seeds) LLVMFuzzerTestOneInput(s.data(), s.size());
  std::mt19937_64 rng(0x5eed);
  for (long i = 0; i < mutations; ++i) {
    std::vector<std::uint8_t> d = seeds[i % seeds.size()];
    int rounds = 1 + static_cast<int>(rng() % 8);
    for (int r = 0; r < rounds; ++r) mutate(d, rng);
    LLVMFuzzerTestOneInput(d.data(), d.size());
  }
  std::printf("replayed %zu seeds and %ld mutations without a crash\n", seeds.size(), mutations);
  return 0;
}
