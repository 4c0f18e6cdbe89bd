#pragma once
// Drives one contact of a model through a prescribed sequence of overlaps on the device (one
// thread, in order, history carried between evaluations) and returns what the law reported.
#include <backends.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/state/contact_history.hpp>

#include <vector>

namespace epac {
namespace test {

struct OverlapTrace {
  std::vector<double> alpha, f, k_n, damping, k_t;
  std::vector<int> active;
  std::vector<double> history0, history1;  // first two normal history fields (if any)
  std::size_t size() const { return alpha.size(); }
};

template <class Model>
OverlapTrace drive_overlap(const Model& model, const std::vector<double>& alphas, double R_eff, int pair = 0,
                           double m_eff = 1.0) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  const int n = static_cast<int>(alphas.size());
  Kokkos::View<T*, D> a("alpha", n), f("f", n), kn("kn", n), damp("damp", n), kt("kt", n), h0("h0", n), h1("h1", n);
  Kokkos::View<int*, D> act("active", n);
  {
    auto ah = Kokkos::create_mirror_view(a);
    for (int k = 0; k < n; ++k) ah(k) = T(alphas[k]);
    Kokkos::deep_copy(a, ah);
  }
  ContactHistory<T, D> hist(1, Model::history_size > 0 ? Model::history_size : 1);
  const T R = T(R_eff), m = T(m_eff);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        const HistoryRow<T, D> row{hist.data, 0, 0};
        for (int k = 0; k < n; ++k) {
          ContactGeometry<T> g;
          g.pair = pair;
          g.delta = a(k);
          g.R_i = R;
          g.R_eff = R;
          g.m_eff = m;
          const NormalForce<T> nf = model.normal(g, row);
          f(k) = nf.f;
          kn(k) = nf.k_n;
          damp(k) = nf.damping;
          kt(k) = nf.k_t;
          act(k) = nf.active ? 1 : 0;
          h0(k) = Model::normal_history_size > 0 ? row(0) : T(0);
          h1(k) = Model::normal_history_size > 1 ? row(1) : T(0);
        }
      });
  auto fh = to_host(f);
  auto knh = to_host(kn);
  auto dh = to_host(damp);
  auto kth = to_host(kt);
  auto acth = to_host(act);
  auto h0h = to_host(h0);
  auto h1h = to_host(h1);
  OverlapTrace t;
  for (int k = 0; k < n; ++k) {
    t.alpha.push_back(alphas[k]);
    t.f.push_back(fh(k));
    t.k_n.push_back(knh(k));
    t.damping.push_back(dh(k));
    t.k_t.push_back(kth(k));
    t.active.push_back(acth(k));
    t.history0.push_back(h0h(k));
    t.history1.push_back(h1h(k));
  }
  return t;
}

// Appends a straight ramp from the last value (exclusive) to `to` (inclusive) in steps <= step.
inline void ramp(std::vector<double>& a, double to, double step) {
  const double from = a.empty() ? to : a.back();
  const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(to - from) / step)));
  for (int k = 1; k <= n; ++k) a.push_back(from + (to - from) * k / n);
}

// Work put into the contact, sum of f d(alpha) (trapezoid, force 0 when inactive).
inline double work_in(const OverlapTrace& t, std::size_t from = 0, std::size_t to = ~std::size_t(0)) {
  double w = 0;
  to = std::min(to, t.size() - 1);
  for (std::size_t k = from; k < to; ++k) w += 0.5 * (t.f[k] + t.f[k + 1]) * (t.alpha[k + 1] - t.alpha[k]);
  return w;
}

}  // namespace test
}  // namespace epac
