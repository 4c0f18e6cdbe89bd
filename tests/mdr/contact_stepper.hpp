#pragma once
// One pair contact (two particles on the x axis) or one wall contact of any model, stepped through
// the generic kernels (compute_pair_forces / compute_wall_forces) one overlap at a time, with its
// history row readable: the detachment tests (single-step jumps) of every adhesive law use it.
#include <backends.hpp>
#include <epac/compute/contact_forces.hpp>

#include <cmath>
#include <vector>

namespace epac {
namespace test {

// For ContactStepper::evaluate: the model's critical overlap of the stored contact (adhesive laws).
struct CriticalOverlap {
  template <class M, class G, class Row>
  KOKKOS_INLINE_FUNCTION typename M::scalar_type operator()(const M& m, const G& g, const Row& row) const {
    return m.critical_overlap(g, row);
  }
};

// Growth = true (MDR with radius growth): the particles are bound to the model and their radii
// updated after every force pass.
template <class Model, bool Growth = false>
class ContactStepper {
 public:
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;

  // Pair: particles of radii R0, R1 and materials m0, m1. Wall (R1 <= 0): particle of radius R0
  // and material m0 against a wall of material m1 (normal -x, at x = R0 - delta).
  ContactStepper(const Model& model, double R0, double R1, int m0, int m1)
      : model_(model), pair_(R1 > 0), p_(pair_ ? 2 : 1), w_(pair_ ? 0 : 1), c_(1), h_(1, Model::history_size) {
    auto r = Kokkos::create_mirror_view(p_.radius);
    auto m = Kokkos::create_mirror_view(p_.mass);
    auto g = Kokkos::create_mirror_view(p_.gid);
    auto mat = Kokkos::create_mirror_view(p_.material);
    r(0) = T(R0);
    m(0) = T(1);
    g(0) = 0;
    mat(0) = m0;
    if (pair_) {
      r(1) = T(R1);
      m(1) = T(1);
      g(1) = 1;
      mat(1) = m1;
    }
    Kokkos::deep_copy(p_.radius, r);
    Kokkos::deep_copy(p_.radius0, r);
    Kokkos::deep_copy(p_.mass, m);
    Kokkos::deep_copy(p_.gid, g);
    Kokkos::deep_copy(p_.material, mat);
    auto f = Kokkos::create_mirror_view(c_.first);
    auto s = Kokkos::create_mirror_view(c_.second);
    f(0) = 0;
    s(0) = pair_ ? 1 : 0;
    Kokkos::deep_copy(c_.first, f);
    Kokkos::deep_copy(c_.second, s);
    if (!pair_) {
      auto wn = Kokkos::create_mirror_view(w_.normal);
      auto wm = Kokkos::create_mirror_view(w_.material);
      wn(0, 0) = T(-1);
      wn(0, 1) = T(0);
      wn(0, 2) = T(0);
      wm(0) = m1;
      Kokkos::deep_copy(w_.normal, wn);
      Kokkos::deep_copy(w_.material, wm);
    }
    out_.normal_force = Kokkos::View<T*, D>("fn", 1);
    out_.overlap = Kokkos::View<T*, D>("delta", 1);
    if constexpr (Growth) model_.bind(p_);
  }

  // One force pass at apparent overlap delta (negative: a gap); returns the normal force on the
  // particle along n (law + damping; 0 when inactive). overlap() is the delta the kernel saw.
  double step(double delta) {
    auto r = to_host(p_.radius);  // the current (grown) radii: delta is the apparent overlap
    if (pair_) {
      auto x = Kokkos::create_mirror_view(p_.x);
      // positions are double whatever T (Particles::position_type): the overlap is not rounded to T
      x(1, 0) = double(r(0)) + double(r(1)) - delta;
      Kokkos::deep_copy(p_.x, x);
    } else {
      auto wp = Kokkos::create_mirror_view(w_.point);
      wp(0, 0) = double(r(0)) - delta;
      Kokkos::deep_copy(w_.point, wp);
    }
    zero_forces(p_);
    if (pair_)
      compute_pair_forces(model_, p_, c_, h_, T(0), out_);
    else
      compute_wall_forces(model_, p_, w_, c_, h_, T(0), out_);
    const double f = to_host(out_.normal_force)(0);
    if constexpr (Growth) model_.update_radii();
    return f;
  }
  double overlap() const { return to_host(out_.overlap)(0); }
  double radius(int k) const { return double(to_host(p_.radius)(k)); }  // current (grown) radius
  bool radii_finite() const {
    auto r = to_host(p_.radius);
    for (int k = 0; k < p_.n; ++k)
      if (!std::isfinite(double(r(k)))) return false;
    return true;
  }

  std::vector<double> history() const {
    auto h = to_host(h_.data);
    std::vector<double> v;
    for (int k = 0; k < Model::history_size; ++k) v.push_back(h(0, k));
    return v;
  }

  // f(model, geometry, row) evaluated on the device at the current positions, as a double. f is a
  // functor at namespace scope with a KOKKOS_INLINE_FUNCTION operator() (e.g. CriticalOverlap): a
  // test's lambda is host code, which nvcc does not let a device kernel call.
  template <class F>
  double evaluate(F f) const {
    Kokkos::View<double*, D> r("r", 1);
    const Model m = model_;
    const auto p = p_;
    const auto w = w_;
    const auto h = h_;
    const bool pair = pair_;
    Kokkos::parallel_for(
        Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
          const ContactGeometry<T> g =
              pair ? pair_geometry<T, D>(p, 0, 1, m.nmat) : wall_geometry<T, D>(p, w, 0, 0, m.nmat);
          r(0) = double(f(m, g, HistoryRow<T, D>{h.data, 0, 0}));
        });
    return to_host(r)(0);
  }

 private:
  Model model_;
  bool pair_;
  Particles<T, D> p_;
  Walls<T, D> w_;
  ContactList<D> c_;
  ContactHistory<T, D> h_;
  ContactOutputs<T, D> out_;
};

}  // namespace test
}  // namespace epac
