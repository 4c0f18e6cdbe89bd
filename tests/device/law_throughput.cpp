// Contacts per second of one force pass for each contact law (the laws and effects of
// bench/bench_model_cost.cpp: all effects on, friction and damping everywhere), double and float,
// on the dense packing of the benchmarks at the sizes asked for (default 1e5, 1e6 and 1e7
// contacts), on Kokkos' default execution space: the GPU in a CUDA build. cmake/device-run.sh
// runs it; on the host it runs too (small sizes). One force pass = zero forces, the force kernel
// with the backend's default particle sums (atomics on a GPU), the radius update for MDR growth.
//   epac-law-throughput [--contacts 1e5,1e6,1e7] [--seconds 0.5] [--passes N] [--laws a,b]
//                       [--scalars double,float] [--json FILE]
// --passes N times exactly N passes (after the two untimed ones) instead of --seconds: what
// bench/roofline/roofline.py needs to count instructions per contact under callgrind.
// --laws picks from hertz_mindlin, jkr, nan2022, mdr (default all); --scalars from double, float.
// The JSON is a list of {law, scalar, contacts, particles, passes, seconds, contacts_per_s}.
#include <Kokkos_Core.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>
#include <support/benchmark_powder.hpp>
#include <support/dense_packing.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace epac;

namespace {

struct Row {
  std::string law, scalar;
  long contacts, particles;
  int passes;
  double seconds, contacts_per_s;
};

// The packing's side for about `contacts` contacts: n^3 particles, 3 n^2 (n - 1) contacts.
int side_for(double contacts) {
  int n = 2;
  while (3.0 * n * n * (n - 1) < contacts) ++n;
  return n;
}

struct Options {
  std::vector<double> sizes{1e5, 1e6, 1e7};
  double seconds = 0.5;
  int passes = 0;  // 0: time for `seconds` (at least 3 passes)
  std::vector<std::string> laws{"hertz_mindlin", "jkr", "nan2022", "mdr"};
  std::vector<std::string> scalars{"double", "float"};
  std::string json;
  bool wants(const std::vector<std::string>& list, const std::string& name) const {
    for (const auto& x : list)
      if (x == name) return true;
    return false;
  }
};

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out;
  for (size_t p = 0; p < list.size();) {
    const size_t q = list.find(',', p);
    out.push_back(list.substr(p, q == std::string::npos ? std::string::npos : q - p));
    p = q == std::string::npos ? list.size() : q + 1;
  }
  return out;
}

template <class Model>
Row measure(const char* law, Model model, double contacts, const Options& opt) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  auto pk = bench::make_dense_packing<T, D>(side_for(contacts));
  ContactHistory<T, D> h(pk.contacts.count, Model::history_size);
  constexpr bool grows = Model::effects::radius_growth;
  if constexpr (grows) model.bind(pk.particles);
  ForceSums<T, D> sums(pk.particles);
  auto pass = [&] {
    zero_forces(pk.particles);
    sums.begin();
    compute_pair_forces(model, pk.particles, pk.contacts, h, T(1e-9), sums);
    sums.end();
    if constexpr (grows) model.update_radii();
  };
  for (int k = 0; k < 2; ++k) pass();  // first touch, history set up
  Kokkos::fence();
  Kokkos::Timer timer;
  int passes = 0;
  do {
    pass();
    Kokkos::fence();
    ++passes;
  } while (opt.passes > 0 ? passes < opt.passes : (timer.seconds() < opt.seconds || passes < 3));
  const double s = timer.seconds();
  return {law, sizeof(T) == 8 ? "double" : "float",   long(pk.contacts.count), long(pk.particles.n), passes,
          s,   double(pk.contacts.count) * passes / s};
}

constexpr unsigned FD = kFriction | kDamping;
constexpr unsigned ALL = FD | kAdhesion | kPlasticity | kRadiusGrowth;

template <class T>
void all_laws(std::vector<Row>& rows, double c, const Options& o) {
  if (!o.wants(o.scalars, sizeof(T) == 8 ? "double" : "float")) return;
  if (o.wants(o.laws, "hertz_mindlin"))
    rows.push_back(measure("hertz_mindlin", HertzMindlin<T, Effects<FD>>::create({bench::benchmark_powder()}), c, o));
  if (o.wants(o.laws, "jkr"))
    rows.push_back(measure("jkr", Jkr<T, Effects<FD | kAdhesion>>::create({bench::benchmark_powder()}), c, o));
  if (o.wants(o.laws, "nan2022"))
    rows.push_back(measure(
        "nan2022", Nan2022<T, Effects<FD | kAdhesion | kPlasticity>>::create({bench::benchmark_powder()}), c, o));
  if (o.wants(o.laws, "mdr"))
    rows.push_back(measure("mdr", Mdr<T, Effects<ALL>>::create({bench::benchmark_powder()}), c, o));
}
}  // namespace

int main(int argc, char** argv) {
  Kokkos::ScopeGuard guard(argc, argv);
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--contacts" && i + 1 < argc) {
      opt.sizes.clear();
      for (const auto& x : split_list(argv[++i])) opt.sizes.push_back(std::atof(x.c_str()));
    } else if (a == "--seconds" && i + 1 < argc) {
      opt.seconds = std::atof(argv[++i]);
    } else if (a == "--passes" && i + 1 < argc) {
      opt.passes = std::atoi(argv[++i]);
    } else if (a == "--laws" && i + 1 < argc) {
      opt.laws = split_list(argv[++i]);
    } else if (a == "--scalars" && i + 1 < argc) {
      opt.scalars = split_list(argv[++i]);
    } else if (a == "--json" && i + 1 < argc) {
      opt.json = argv[++i];
    } else {
      std::fprintf(
          stderr,
          "usage: %s [--contacts 1e5,1e6,1e7] [--seconds 0.5] [--passes N] [--laws hertz_mindlin,jkr,nan2022,mdr] "
          "[--scalars double,float] [--json FILE]\n",
          argv[0]);
      return 2;
    }
  }
  const Options all;
  for (const auto& l : opt.laws)
    if (!all.wants(all.laws, l)) {
      std::fprintf(stderr, "--laws: unknown law '%s' (hertz_mindlin, jkr, nan2022, mdr)\n", l.c_str());
      return 2;
    }
  for (const auto& s : opt.scalars)
    if (!all.wants(all.scalars, s)) {
      std::fprintf(stderr, "--scalars: unknown scalar '%s' (double, float)\n", s.c_str());
      return 2;
    }
  const std::string json = opt.json;
  std::vector<Row> rows;
  for (double c : opt.sizes) {
    all_laws<double>(rows, c, opt);
    all_laws<float>(rows, c, opt);
  }
  std::printf("| law | scalar | contacts | contacts/s |\n|---|---|---|---|\n");
  for (const Row& r : rows)
    std::printf("| %s | %s | %ld | %.3g |\n", r.law.c_str(), r.scalar.c_str(), r.contacts, r.contacts_per_s);
  if (!json.empty()) {
    FILE* f = std::fopen(json.c_str(), "w");
    if (!f) {
      std::perror(json.c_str());
      return 1;
    }
    std::fprintf(f, "{\"backend\": \"%s\", \"results\": [\n", Kokkos::DefaultExecutionSpace::name());
    for (size_t k = 0; k < rows.size(); ++k) {
      const Row& r = rows[k];
      std::fprintf(f,
                   "  {\"law\": \"%s\", \"scalar\": \"%s\", \"contacts\": %ld, \"particles\": %ld, \"passes\": %d, "
                   "\"seconds\": %.6g, \"contacts_per_s\": %.6g}%s\n",
                   r.law.c_str(), r.scalar.c_str(), r.contacts, r.particles, r.passes, r.seconds, r.contacts_per_s,
                   k + 1 < rows.size() ? "," : "");
    }
    std::fprintf(f, "]}\n");
    std::fclose(f);
  }
  return 0;
}
