// Accuracy versus cost (docs/performance.md): for every model, precision and time step we offer, the
// measured error of an impact next to the measured cost of the force kernel, in one run.
//   error: a sphere (the Ning particle of Nan Table 2: R = 2.45 um, E = 1.2 GPa, nu = 0.3,
//          Gamma = 0.2 J/m^2, sigma_y = 35.3 MPa) hits a rigid wall at 5 m/s; rebound
//          restitution and peak force at dt = t_c/N, against the same law in double at t_c/2000.
//          The wall is 1000 R from the origin (a box 1000 particles wide) for the time-step scan;
//          at dt = t_c/20 the same impact also runs 1, 10, 100 and 1000 m from the origin (the
//          offset scan: positions are double for any T, mixed precision, so what float keeps far
//          out shows next to what double keeps). The reference is at the origin.
//   cost:  ns per contact per force pass (median of repeated passes) on a dense packing of the
//          same particles (1.0e5 contacts, ~6 per particle), and the cost of simulating one
//          contact duration t_c (cost per pass x N).
// Output: two markdown tables on stdout (time steps, distances) and CSV (--csv FILE).
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>
#include <support/dense_packing.hpp>
#include <support/wall_impact.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

using namespace epac;

namespace {
constexpr double kR = 2.45e-6, kOffset = 1000 * kR, kV0 = 5.0, kE = 1.2e9, kNu = 0.3, kRho = 1000;
constexpr double kOffsets[] = {0.0, 1.0, 10.0, 100.0, 1000.0};  // m, the offset scan at t_c/20

Material particle() {
  Material m;
  m.name = "ning";
  m.youngs_modulus = kE;
  m.poisson_ratio = kNu;
  m.density = kRho;
  m.restitution = 0.81;
  m.friction = 0.3;
  m.surface_energy = 0.2;
  m.yield_stress = 35.3e6;
  return m;
}
Material wall() {
  Material m;
  m.name = "wall";
  m.rigid = true;
  m.poisson_ratio = 0.3;
  return m;
}

template <class Model>
double ns_per_contact(const Model& model) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  auto pk = bench::make_dense_packing<T, D>(33, kR);
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  std::vector<double> t;  // host
  for (int rep = 0; rep < 15; ++rep) {
    zero_forces(pk.particles);
    Kokkos::fence();
    const auto t0 = std::chrono::steady_clock::now();
    compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-10));
    Kokkos::fence();
    t.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2] / pk.contacts.count;
}

struct Row {
  std::string model, precision;
  int n_per_tc;
  double offset, dt, e, e_err, f_err, ns, ns_per_tc;
  bool finite;
};

template <template <class> class Make>
void evaluate(const std::string& name, std::vector<Row>& rows) {  // host
  const double m = kRho * 4.0 / 3.0 * M_PI * kR * kR * kR;
  const double tc = bench::hertz_contact_time(m, kR, kE / (1 - kNu * kNu), kV0);
  const auto ref = bench::wall_impact(Make<double>::make(), kR, m, kV0, tc / 2000, 200 * tc, 0.0);
  const double cost_d = ns_per_contact(Make<double>::make());
  const double cost_f = ns_per_contact(Make<float>::make());
  const auto add = [&](int prec, int n, double offset) {
    const double dt = tc / n;
    const auto r = prec == 0 ? bench::wall_impact(Make<double>::make(), kR, m, kV0, dt, 200 * tc, offset)
                             : bench::wall_impact(Make<float>::make(), kR, m, kV0, dt, 200 * tc, offset);
    const double ns = prec == 0 ? cost_d : cost_f;
    rows.push_back({name, prec == 0 ? "double" : "float", n, offset, dt, r.restitution,
                    std::abs(r.restitution - ref.restitution), std::abs(r.peak_force - ref.peak_force) / ref.peak_force,
                    ns, ns * n, r.finite});
  };
  for (int prec = 0; prec < 2; ++prec) {
    for (int n : {10, 20, 50, 100, 200}) add(prec, n, kOffset);
    for (double offset : kOffsets) add(prec, 20, offset);
  }
}

constexpr unsigned FD = kFriction | kDamping;
template <class T>
struct MakeHertzMindlin {
  static auto make() { return HertzMindlin<T, Effects<FD>>::create({particle(), wall()}); }
};
template <class T>
struct MakeJkr {
  static auto make() { return Jkr<T, Effects<FD | kAdhesion>>::create({particle(), wall()}); }
};
template <class T>
struct MakeNan {
  static auto make() { return Nan2022<T, Effects<FD | kAdhesion | kPlasticity>>::create({particle(), wall()}); }
};
template <class T>
struct MakeMdr {  // radius growth off: a single impact does not grow R measurably
  static auto make() { return Mdr<T, Effects<FD | kAdhesion | kPlasticity>>::create({particle(), wall()}); }
};
}  // namespace

int main(int argc, char* argv[]) {
  Kokkos::ScopeGuard guard(argc, argv);
  std::string csv;
  for (int a = 1; a < argc; ++a)
    if (!std::strcmp(argv[a], "--csv") && a + 1 < argc) csv = argv[++a];
  std::vector<Row> rows;  // host
  evaluate<MakeHertzMindlin>("hertz_mindlin", rows);
  evaluate<MakeJkr>("hertz_jkr", rows);
  evaluate<MakeNan>("nan2022", rows);
  evaluate<MakeMdr>("mdr", rows);
  std::printf("backend %s, %d threads; impact at %.1f m/s; errors against the same law in double at t_c/2000\n\n",
              Kokkos::DefaultExecutionSpace::name(), Kokkos::DefaultExecutionSpace().concurrency(), kV0);
  std::printf("Time steps (the wall %.3g m from the origin):\n\n", kOffset);
  std::printf(
      "| model | precision | dt = t_c/N | restitution | abs. error e | rel. error F_max | ns per contact per pass | ns "
      "per contact per t_c simulated |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : rows)
    if (r.offset == kOffset)
      std::printf("| %s | %s | %d | %.4f | %.2e | %.2e | %.1f | %.0f |%s\n", r.model.c_str(), r.precision.c_str(),
                  r.n_per_tc, r.e, r.e_err, r.f_err, r.ns, r.ns_per_tc, r.finite ? "" : " NON-FINITE");
  std::printf("\nDistance from the origin (dt = t_c/20): abs. error e / rel. error F_max at 0, 1, 10, 100, 1000 m\n\n");
  std::printf("| model | precision | 0 m | 1 m | 10 m | 100 m | 1000 m |\n|---|---|---|---|---|---|---|\n");
  for (std::size_t a = 0; a < rows.size(); ++a) {
    if (rows[a].offset != kOffsets[0] || rows[a].n_per_tc != 20) continue;
    std::printf("| %s | %s |", rows[a].model.c_str(), rows[a].precision.c_str());
    for (std::size_t b = a; b < rows.size() && b < a + std::size(kOffsets); ++b)
      std::printf(" %.2e / %.2e |%s", rows[b].e_err, rows[b].f_err, rows[b].finite ? "" : " NON-FINITE");
    std::printf("\n");
  }
  if (!csv.empty()) {
    FILE* f = std::fopen(csv.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(f,
                 "model,precision,n_per_tc,offset [m],dt [s],restitution [-],abs_error_restitution [-],"
                 "rel_error_peak_force [-],ns_per_contact [ns],ns_per_contact_per_tc [ns]\n");
    for (const auto& r : rows)
      std::fprintf(f, "%s,%s,%d,%.6e,%.6e,%.6f,%.6e,%.6e,%.3f,%.3f\n", r.model.c_str(), r.precision.c_str(), r.n_per_tc,
                   r.offset, r.dt, r.e, r.e_err, r.f_err, r.ns, r.ns_per_tc);
    std::fclose(f);
  }
  for (const auto& r : rows)
    if (!r.finite) return 1;
  return 0;
}
