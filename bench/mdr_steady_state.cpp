// Steady-state cost of one MDR force pass (+ the radius update with growth) on the dense packing
// of bench_model_cost.cpp, for instruction counts on a shared machine (wall times there are
// noise): three warm passes (the first one switches every contact to plastic), then `passes`
// measured passes in measured_passes<1>, the callgrind toggle:
//   OMP_NUM_THREADS=1 valgrind --tool=callgrind --toggle-collect='*measured_passes<1*'
//       ./build/bench/epac-mdr-steady noadh 3   (one command line)
// Instructions per contact-step = the callgrind total / (passes x contacts). Without valgrind it
// prints the wall time per contact-step. Variants: all, nogrowth, noadh (no adhesion, no growth),
// noadhgrowth (no adhesion, growth), float (all effects).
#include <epac/compute/contact_forces.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <support/benchmark_powder.hpp>
#include <support/dense_packing.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace epac;

namespace {

constexpr unsigned FD = kFriction | kDamping;
constexpr unsigned ALL = FD | kAdhesion | kPlasticity | kRadiusGrowth;

template <int Tag, class Model, class P, class H>
__attribute__((noinline)) void measured_passes(Model& model, P& pk, H& h, int passes) {
  using T = typename Model::scalar_type;
  ForceSums<T, typename Model::device_type> sums(pk.particles);
  for (int k = 0; k < passes; ++k) {
    zero_forces(pk.particles);
    sums.begin();
    compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-9), sums);
    sums.end();
    if constexpr (Model::effects::radius_growth) model.update_radii();
    Kokkos::fence();
  }
}

template <class Model>
void run(Model model, int passes) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  auto pk = bench::make_dense_packing<T, D>(33);
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  if constexpr (Model::effects::radius_growth) model.bind(pk.particles);
  measured_passes<0>(model, pk, h, 3);
  Kokkos::Timer t;
  measured_passes<1>(model, pk, h, passes);
  const double s = t.seconds();
  std::printf("contacts %d passes %d ns/contact-step %.1f\n", pk.contacts.count, passes,
              s * 1e9 / passes / pk.contacts.count);
}
}  // namespace

int main(int argc, char** argv) {
  Kokkos::initialize(argc, argv);
  {
    const char* v = argc > 1 ? argv[1] : "all";
    const int passes = argc > 2 ? std::atoi(argv[2]) : 20;
    if (!std::strcmp(v, "all")) run(Mdr<double, Effects<ALL>>::create({bench::benchmark_powder()}), passes);
    if (!std::strcmp(v, "nogrowth"))
      run(Mdr<double, Effects<ALL & ~kRadiusGrowth>>::create({bench::benchmark_powder()}), passes);
    if (!std::strcmp(v, "noadh"))
      run(Mdr<double, Effects<FD | kPlasticity>>::create({bench::benchmark_powder_no_adhesion()}), passes);
    if (!std::strcmp(v, "noadhgrowth"))
      run(Mdr<double, Effects<FD | kPlasticity | kRadiusGrowth>>::create({bench::benchmark_powder_no_adhesion()}),
          passes);
    if (!std::strcmp(v, "float")) run(Mdr<float, Effects<ALL>>::create({bench::benchmark_powder()}), passes);
  }
  Kokkos::finalize();
}
