// Cost of each contact law in one run (ratios are what to read: the machine is shared):
// contact-steps per second of one force pass on the same dense packing (about 6 contacts per
// particle, 1.0e5 and 1.0e6 contacts), for Hertz-Mindlin, Hertz-JKR, Nan et al. 2022 and MDR,
// with all their effects and with adhesion, plasticity or radius growth compiled out. Friction
// and damping are on everywhere. The packing's overlaps (about 0.1 R) put every Nan and MDR
// contact past yield. MDR with radius growth includes its per-particle update kernel. The rolling
// variants add rolling resistance (LAMMPS rolling sds) to the same set; the packing's particles
// spin (random omega), so the rolling spring and dashpot act. BM_Mdr_Penalty adds MDR's contact
// penalty (MdrOptions::contact_penalty): its weights every pass, the per-particle index of the
// list once (as between rebuilds).
#include <benchmark/benchmark.h>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>
#include <support/benchmark_powder.hpp>
#include <support/dense_packing.hpp>

using namespace epac;

namespace {

// MDR's contact penalty before each pass (a no-op unless the option is on); nothing for the others
template <class Model, class P, class C>
void prepare(Model&, const P&, const C&) {}
template <class T, class Eff, class D, class P, class C>
void prepare(Mdr<T, Eff, D>& m, const P& p, const C& c) {
  m.compute_contact_penalty(p, c, -1, 0);
}

template <class Model>
void run(benchmark::State& state, Model model) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  auto pk = bench::make_dense_packing<T, D>(static_cast<int>(state.range(0)));
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  constexpr bool grows = Model::effects::radius_growth;
  if constexpr (grows) model.bind(pk.particles);
  ForceSums<T, D> sums(pk.particles);  // per-thread copies allocated once, as in a simulation
  for (auto _ : state) {
    zero_forces(pk.particles);
    prepare(model, pk.particles, pk.contacts);
    sums.begin();
    compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-9), sums);
    sums.end();
    if constexpr (grows) model.update_radii();
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * pk.contacts.count);
  state.counters["contacts_per_s"] =
      benchmark::Counter(double(pk.contacts.count), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["history_bytes_per_contact"] = Model::history_size * sizeof(T);
}

constexpr unsigned FD = kFriction | kDamping;

template <class T>
void BM_HertzMindlin(benchmark::State& s) {
  run(s, HertzMindlin<T, Effects<FD>>::create({bench::benchmark_powder()}));
}
// the powder with rolling resistance: k_r 1e3 N/m, gamma_r 1e-4 N s/m, mu_r 0.1
Material rolling_powder(Material m) {
  m.rolling_stiffness = 1e3;
  m.rolling_damping = 1e-4;
  m.rolling_friction = 0.1;
  return m;
}
template <class T>
void BM_HertzMindlin_Rolling(benchmark::State& s) {
  run(s, HertzMindlin<T, Effects<FD | kRolling>>::create({rolling_powder(bench::benchmark_powder())}));
}
template <class T>
void BM_HertzJKR(benchmark::State& s) {
  run(s, Jkr<T, Effects<FD | kAdhesion>>::create({bench::benchmark_powder()}));
}
template <class T>
void BM_Nan2022(benchmark::State& s) {
  run(s, Nan2022<T, Effects<FD | kAdhesion | kPlasticity>>::create({bench::benchmark_powder()}));
}
template <class T>
void BM_Nan2022_NoAdhesion(benchmark::State& s) {
  run(s, Nan2022<T, Effects<FD | kPlasticity>>::create({bench::benchmark_powder_no_adhesion()}));
}

constexpr unsigned ALL = FD | kAdhesion | kPlasticity | kRadiusGrowth;
template <class T>
void BM_Mdr(benchmark::State& s) {
  run(s, Mdr<T, Effects<ALL>>::create({bench::benchmark_powder()}));
}
template <class T>
void BM_Mdr_Penalty(benchmark::State& s) {
  MdrOptions o;
  o.contact_penalty = true;
  run(s, Mdr<T, Effects<ALL>>::create({bench::benchmark_powder()}, o));
}
template <class T>
void BM_Mdr_Rolling(benchmark::State& s) {
  run(s, Mdr<T, Effects<ALL | kRolling>>::create({rolling_powder(bench::benchmark_powder())}));
}
template <class T>
void BM_Mdr_NoGrowth(benchmark::State& s) {
  run(s, Mdr<T, Effects<ALL & ~kRadiusGrowth>>::create({bench::benchmark_powder()}));
}
template <class T>
void BM_Mdr_NoAdhesionNoGrowth(benchmark::State& s) {
  run(s, Mdr<T, Effects<FD | kPlasticity>>::create({bench::benchmark_powder_no_adhesion()}));
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {33, 70}) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
}  // namespace

BENCHMARK_TEMPLATE(BM_HertzMindlin, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlin_Rolling, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_HertzJKR, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Nan2022, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Nan2022_NoAdhesion, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Mdr, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Mdr_Rolling, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Mdr_Penalty, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Mdr_NoGrowth, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Mdr_NoAdhesionNoGrowth, double)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlin, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_HertzJKR, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Nan2022, float)->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Mdr, float)->Apply(sizes);
