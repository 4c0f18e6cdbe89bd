// Per-particle sums of a force pass (compute/particle_sums.hpp): end() adds the pass's sums to
// the forces, end(true) sets the forces to them where the sums are per-thread copies (the
// driver then skips zeroing the forces before each pass), and leaves the adds in place where
// they went straight into the forces (plain and atomic sums, whose forces must be zeroed).
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/particle_sums.hpp>

#include <utility>

using namespace epac;

namespace {
using HostVec = Kokkos::View<double* [3], Kokkos::LayoutLeft, Kokkos::HostSpace>;

// One pass through `sums`: particle i gets (i + 1) (1, 2, 3) three times in force and the
// negative in torque, between begin(overwrite) and end(overwrite). A named function: nvcc's
// extended lambdas cannot be defined inside another lambda.
template <class D>
void add_pass(ForceSums<double, D>& sums, int n, bool overwrite) {
  sums.begin(overwrite);
  const auto fs = sums.force.scatter;
  const auto ts = sums.torque.scatter;
  Kokkos::parallel_for(
      "test::sums_pass", Kokkos::RangePolicy<typename D::execution_space>(0, 3 * n), KOKKOS_LAMBDA(int k) {
        const int i = k % n;
        const Vec3<double> v(i + 1.0, 2.0 * (i + 1), 3.0 * (i + 1));
        scatter_add3(fs.access(), i, v);
        scatter_add3(ts.access(), i, -1.0 * v);
      });
  sums.end(overwrite);
}

// Forces and torques preset to `before`, then one add_pass; returns both.
template <class D>
std::pair<HostVec, HostVec> pass(int n, double before, bool overwrite) {
  Particles<double, D> p(n);
  Kokkos::deep_copy(p.force, before);
  Kokkos::deep_copy(p.torque, before);
  ForceSums<double, D> sums(p);
  add_pass(sums, n, overwrite);
  return {Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.force),
          Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.torque)};
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("particle sums: end() adds the pass to the forces, end(true) sets them (per-thread sums only)",
                        "[foundation][sums]", test::Backends) {
  using D = TestType;
  const int n = 257;  // not a multiple of a thread count or vector width
  const bool duplicated = sums_are_duplicated<D>();
  for (const bool overwrite : {false, true}) {
    CAPTURE(overwrite, duplicated);
    const auto ft = pass<D>(n, 5.0, overwrite);
    // Set where the sums were per-thread copies; elsewhere the pass added into the forces, so the
    // preset stays (those strategies need forces zeroed before the pass, which end(true) cannot do).
    const double base = overwrite && duplicated ? 0.0 : 5.0;
    int wrong = 0;
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {  // small integers: exact in any order of the adds
        if (ft.first(i, d) != base + 3.0 * (d + 1) * (i + 1)) ++wrong;
        if (ft.second(i, d) != base - 3.0 * (d + 1) * (i + 1)) ++wrong;
      }
    CHECK(wrong == 0);
  }
  // From zeroed forces both give the same bits.
  const auto a = pass<D>(n, 0.0, false), b = pass<D>(n, 0.0, true);
  int differ = 0;
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) differ += (a.first(i, d) != b.first(i, d)) + (a.second(i, d) != b.second(i, d));
  CHECK(differ == 0);
}

// One thread (the ctest particle_sums_one_thread runs this file's [sums] cases with
// OMP_NUM_THREADS=1): the per-thread sums have a single copy, and begin(true) lets the pass add
// into the forces themselves (no copy to clear or to add up). The same ForceSums then runs an
// adding pass, which must use its own copy again.
TEMPLATE_LIST_TEST_CASE("particle sums: a single copy's overwrite pass adds into the forces, the next pass adds",
                        "[foundation][sums]", test::Backends) {
  using D = TestType;
  using exec = typename D::execution_space;
  const int n = 257;
  const bool duplicated = sums_are_duplicated<D>();
  Particles<double, D> p(n);
  Kokkos::deep_copy(p.force, 5.0);
  Kokkos::deep_copy(p.torque, 5.0);
  ForceSums<double, D> sums(p);
  auto one_pass = [&](bool overwrite) { add_pass(sums, n, overwrite); };
  auto wrong = [&](double base, double times) {
    auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.force);
    auto t = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.torque);
    int bad = 0;
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        bad += f(i, d) != base + times * 3.0 * (d + 1) * (i + 1);
        bad += t(i, d) != base - times * 3.0 * (d + 1) * (i + 1);
      }
    return bad;
  };
  one_pass(true);
  CAPTURE(duplicated, exec().concurrency());
  CHECK(sums.force.direct == (duplicated && exec().concurrency() == 1));
  CHECK(wrong(duplicated ? 0.0 : 5.0, 1.0) == 0);
  one_pass(false);  // adds the same again
  CHECK_FALSE(sums.force.direct);
  CHECK(wrong(duplicated ? 0.0 : 5.0, 2.0) == 0);
  one_pass(true);  // and sets it again
  CHECK(wrong(duplicated ? 0.0 : 5.0, duplicated ? 1.0 : 3.0) == 0);
}
