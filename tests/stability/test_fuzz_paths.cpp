// Fuzz of every law over random pair and wall paths (fuzz_paths.hpp): no NaN, no Inf, no energy
// created on closed quasi-static cycles. The CI test runs 5000 paths (a wall and a pair path each:
// 1e4 contact paths) per law and precision; the hidden "[.long]" test runs EPAC_FUZZ_PATHS of them
// (default 5e5: 1e6 contact paths) and prints the counts: `bash cmake/dev.sh fuzz`, or
// EPAC_FUZZ_PATHS=500000 test_fuzz "[.long]".
// Options of the long test (environment):
//   EPAC_FUZZ_LAWS=name   only the laws whose name contains it ("mdr": mdr and mdr+growth);
//                         with a leading '=' only the law of exactly that name ("=mdr")
//   EPAC_FUZZ_TYPES=float only that precision (float or double)
//   EPAC_FUZZ_REFINE=N    the same paths on an N times finer grid (fuzz_paths.hpp)
//   EPAC_FUZZ_FIRST=k     paths before the group that holds path k are drawn but not run (to
//                         rerun the paths near an index a longer run reported; fuzz_paths.hpp)
//   EPAC_FUZZ_SEED=s      every law runs with seed s instead of its own (1001 to 1010 in the
//                         order below): the same paths through another law, e.g. mdr+growth's
//                         float paths (1010) through mdr without growth
//   EPAC_FUZZ_DUMP=1      prints the path of every MDR pair cycle that created energy
//   EPAC_FUZZ_DUMP_PATH=k prints the work put in and returned on path k's closed cycles
#include "fuzz_paths.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace epac;
using namespace epac::test;

namespace {
template <template <class> class Make, class T>
FuzzCounts run_law(long n, std::uint64_t seed, int refine = 1, long first = 0) {
  return fuzz_paths<Make<T>, T>(n, seed, 512, refine, first);
}

template <template <class> class Make, class T>
void check_law(long n, std::uint64_t seed) {
  const FuzzCounts c = run_law<Make, T>(n, seed);
  INFO(Make<T>::name << (sizeof(T) == 4 ? " float" : " double") << ": paths " << c.paths << ", rejected " << c.rejected
                     << ", NaN " << c.nan << ", Inf " << c.inf << ", energy created " << c.energy_created << " of "
                     << c.energy_checked << " (worst " << c.worst_energy << "); " << c.first_failure);
  CHECK(c.paths == n);
  CHECK(c.nan == 0);
  CHECK(c.inf == 0);
  CHECK(c.energy_created == 0);
  CHECK(c.energy_checked > n / 4);  // the check ran (wall and pair of every other path, most touching)
}

template <template <class> class Make, class T>
void report_law(long n, std::uint64_t seed) {
  // the options: see the header
  const char* laws = std::getenv("EPAC_FUZZ_LAWS");
  const std::string name = Make<T>::name;
  if (laws && laws[0] == '=' && name != laws + 1) return;
  if (laws && laws[0] != '=' && name.find(laws) == std::string::npos) return;
  const char* types = std::getenv("EPAC_FUZZ_TYPES");
  if (types && std::string(types) != (sizeof(T) == 4 ? "float" : "double")) return;
  const char* ref = std::getenv("EPAC_FUZZ_REFINE");
  const char* first = std::getenv("EPAC_FUZZ_FIRST");
  const char* seed_env = std::getenv("EPAC_FUZZ_SEED");
  if (seed_env) seed = std::strtoull(seed_env, nullptr, 10);
  const auto start = std::chrono::steady_clock::now();
  const FuzzCounts c =
      run_law<Make, T>(n, seed, ref ? std::max(1, std::atoi(ref)) : 1, first ? std::max(0L, std::atol(first)) : 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "%-14s %-6s paths %8ld contacts %10ld rejected %6ld NaN %ld Inf %ld energy created %ld of %ld "
      "(worst (out-in)/in %.3g); MDR plastic pairs: energy created %ld of %ld (worst %.3g); %.0f s%s%s\n",
      Make<T>::name, sizeof(T) == 4 ? "float" : "double", c.paths, c.contacts, c.rejected, c.nan, c.inf,
      c.energy_created, c.energy_checked, c.worst_energy, c.plastic_pair_energy_created, c.plastic_pair_checked,
      c.worst_plastic_pair, seconds, c.first_failure.empty() ? "" : "; first: ", c.first_failure.c_str());
  std::fflush(stdout);
  CHECK(c.nan == 0);
  CHECK(c.inf == 0);
  CHECK(c.energy_created == 0);
}
constexpr long kCiPaths = 5000;  // each a wall and a pair path: 1e4 contact paths per law and precision
}  // namespace

TEMPLATE_TEST_CASE("fuzz: random pair and wall paths stay finite and create no energy", "[stability][fuzz]", double,
                   float) {
  SECTION("hertz_mindlin") { check_law<MakeHM, TestType>(kCiPaths, 1); }
  SECTION("hertz_jkr") { check_law<MakeJkr, TestType>(kCiPaths, 2); }
  SECTION("nan2022") { check_law<MakeNan, TestType>(kCiPaths, 3); }
  SECTION("mdr") { check_law<MakeMdr, TestType>(kCiPaths, 4); }
  SECTION("mdr+growth") { check_law<MakeMdrGrowth, TestType>(kCiPaths, 5); }
}

TEST_CASE("fuzz, long: EPAC_FUZZ_PATHS random paths per law and precision (default 5e5)", "[.long]") {
  const char* env = std::getenv("EPAC_FUZZ_PATHS");
  const long n = env ? std::atol(env) : 500000;  // each a wall and a pair path: 1e6 contact paths
  const std::uint64_t seed = 1000;
  report_law<MakeHM, double>(n, seed + 1);
  report_law<MakeHM, float>(n, seed + 2);
  report_law<MakeJkr, double>(n, seed + 3);
  report_law<MakeJkr, float>(n, seed + 4);
  report_law<MakeNan, double>(n, seed + 5);
  report_law<MakeNan, float>(n, seed + 6);
  report_law<MakeMdr, double>(n, seed + 7);
  report_law<MakeMdr, float>(n, seed + 8);
  report_law<MakeMdrGrowth, double>(n, seed + 9);
  report_law<MakeMdrGrowth, float>(n, seed + 10);
}
