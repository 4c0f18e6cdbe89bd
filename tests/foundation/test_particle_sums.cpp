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

// Forces and torques preset to `before`; then one pass of 3 n contributions: particle i gets
// (i + 1) (1, 2, 3) three times in force and the negative in torque. Returns both after
// end(overwrite).
template <class D>
std::pair<HostVec, HostVec> pass(int n, double before, bool overwrite) {
  Particles<double, D> p(n);
  Kokkos::deep_copy(p.force, before);
  Kokkos::deep_copy(p.torque, before);
  ForceSums<double, D> sums(p);
  sums.begin();
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
