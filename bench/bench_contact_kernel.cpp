// Contact-kernel throughput (contacts per second) on random dense packings with about 6 contacts
// per particle (support/dense_packing.hpp), 1e4 to 1e6 contacts, double and float.
// One iteration = one force pass: zero forces, then compute_pair_forces.
#include <benchmark/benchmark.h>
#include <epac/compute/contact_forces.hpp>
#include <epac/compute/deterministic_reduce.hpp>
#include <epac/compute/history_remap.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <support/dense_packing.hpp>

using namespace epac;

namespace {
Material glass() {
  Material m;
  m.name = "glass";
  m.youngs_modulus = 70e9;
  m.poisson_ratio = 0.25;
  m.density = 2500;
  m.restitution = 0.5;
  m.friction = 0.5;
  return m;
}

// Sums: the accumulation policy (compute/particle_sums.hpp). DefaultSums is what the backend
// gets (per-thread copies on OpenMP); AtomicSums forces atomics, to show what they cost.
// The pass as compute_pair_forces runs it.
struct DefaultForm {
  template <class... A>
  void operator()(const A&... a) const {
    compute_pair_forces(a...);
  }
};
// The one-contact kernel, which Hertz-Mindlin ran before contacts in lanes (and which the
// deterministic mode and the laws without a lane form run).
struct OneContactForm {
  template <class Model, class... A>
  void operator()(const Model& model, const A&... a) const {
    detail::pair_kernel<Model::effects::friction>(
        model, a..., ContactOutputs<typename Model::scalar_type, typename Model::device_type>{},
        ContactForceBuffer<typename Model::scalar_type, typename Model::device_type>{});
  }
};
// Contacts in lanes of width W (compute/pair_lanes.hpp): the width's effect.
template <int W>
struct LanesForm {
  template <class Model, class... A>
  void operator()(const Model& model, const A&... a) const {
    detail::pair_kernel_lanes<W>(model, a...,
                                 ContactOutputs<typename Model::scalar_type, typename Model::device_type>{});
  }
};

template <class Sums = DefaultSums, class Form = DefaultForm, class Model>
void run_contact_kernel(benchmark::State& state, const Model& model) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  auto pk = bench::make_dense_packing<T, D>(static_cast<int>(state.range(0)));
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  ForceSums<T, D, Sums> sums(pk.particles);
  for (auto _ : state) {
    zero_forces(pk.particles);
    sums.begin();
    Form{}(model, pk.particles, pk.contacts, h, T(1e-7), sums);
    sums.end();
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * pk.contacts.count);
  state.counters["contacts"] = pk.contacts.count;
  state.counters["contacts_per_s"] =
      benchmark::Counter(double(pk.contacts.count), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["history_bytes_per_contact"] = Model::history_size * sizeof(T);
}

template <class T>
void BM_HertzMindlin(benchmark::State& state) {
  run_contact_kernel(state, HertzMindlin<T, Effects<kFriction | kDamping>>::create({glass()}));
}
template <class T>
void BM_HertzMindlinAtomic(benchmark::State& state) {
  run_contact_kernel<AtomicSums>(state, HertzMindlin<T, Effects<kFriction | kDamping>>::create({glass()}));
}
template <class T>
void BM_HertzMindlinOneContact(benchmark::State& state) {
  run_contact_kernel<DefaultSums, OneContactForm>(state,
                                                  HertzMindlin<T, Effects<kFriction | kDamping>>::create({glass()}));
}
template <class T, int W>
void BM_HertzMindlinLanes(benchmark::State& state) {
  run_contact_kernel<DefaultSums, LanesForm<W>>(state,
                                                HertzMindlin<T, Effects<kFriction | kDamping>>::create({glass()}));
}
template <class T>
void BM_HertzOnly(benchmark::State& state) {  // no friction, no damping: what the effects cost
  run_contact_kernel(state, HertzMindlin<T, Effects<0>>::create({glass()}));
}

// Deterministic mode: per-contact buffer + per-particle sum in key order (docs/design.md section 6).
// The incidence is built once per list rebuild, outside the timed loop, as in a simulation.
template <class T>
void BM_HertzMindlinDeterministic(benchmark::State& state) {
  using Model = HertzMindlin<T, Effects<kFriction | kDamping>>;
  using D = typename Model::device_type;
  const Model model = Model::create({glass()});
  auto pk = bench::make_dense_packing<T, D>(static_cast<int>(state.range(0)));
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  ContactForceBuffer<T, D> buf(pk.contacts.count);
  auto inc = build_incidence(pk.particles.n, pk.contacts, pair_contact_keys(pk.particles, pk.contacts), true);
  for (auto _ : state) {
    zero_forces(pk.particles);
    compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-7), {}, buf);
    reduce_contact_forces(pk.particles, buf, inc);
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * pk.contacts.count);
  state.counters["contacts"] = pk.contacts.count;
  state.counters["contacts_per_s"] =
      benchmark::Counter(double(pk.contacts.count), benchmark::Counter::kIsIterationInvariantRate);
}

// n_side^3 particles, 3 n^2 (n-1) contacts: 16 -> 1.2e4, 33 -> 1.0e5, 47 -> 3.0e5, 70 -> 1.0e6
void packing_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {16, 33, 47, 70}) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
}  // namespace

BENCHMARK_TEMPLATE(BM_HertzMindlin, double)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlin, float)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlinOneContact, double)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlinOneContact, float)->Apply(packing_sizes);
#if !defined(KOKKOS_ENABLE_CUDA) && !defined(KOKKOS_ENABLE_HIP)  // the widths are a host question
BENCHMARK_TEMPLATE(BM_HertzMindlinLanes, double, 4)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlinLanes, double, 16)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlinLanes, float, 4)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlinLanes, float, 16)->Apply(packing_sizes);
#endif
BENCHMARK_TEMPLATE(BM_HertzMindlinAtomic, double)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzMindlinDeterministic, double)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzOnly, double)->Apply(packing_sizes);
BENCHMARK_TEMPLATE(BM_HertzOnly, float)->Apply(packing_sizes);
