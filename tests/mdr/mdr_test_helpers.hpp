#pragma once
// Helpers of the MDR tests: a single side driven along a prescribed overlap path on the device,
// the two-flat / die-compaction scene (one sphere between rigid flats moved by prescribed
// displacement, through the generic wall kernel), and JKR theory for comparison.
#include <backends.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/mdr/mdr_model.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace epac {
namespace test {

// The Poisson ratio of the MDR tests' materials, and an infinite yield stress (elastic).
constexpr double kNu = 0.3;
constexpr double kInf = std::numeric_limits<double>::infinity();

// For ContactStepper::evaluate on an MDR contact: one field of the stored contact's outputs
// (m.outputs), as a functor the device can call (a test's lambda is host code).
struct MdrOutputField {
  enum Field { side_force, side_overlap, yielded };
  Field field;
  int side;  // 0 or 1 (ignored for yielded)
  template <class M, class G, class Row>
  KOKKOS_INLINE_FUNCTION typename M::scalar_type operator()(const M& m, const G& g, const Row& row) const {
    using T = typename M::scalar_type;
    const auto o = m.outputs(g, row);
    return field == side_force ? o.side_force[side] : field == side_overlap ? o.side_overlap[side] : T(o.yielded);
  }
};

// A deformable material with E, nu, Y (Y = inf: elastic), surface energy gamma.
inline Material mdr_material(double E, double nu, double Y, double gamma = 0.0, double restitution = 1.0) {
  Material m;
  m.name = "mdr";
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.density = 1000.0;
  m.yield_stress = Y;
  m.surface_energy = gamma;
  m.restitution = restitution;
  return m;
}

inline Material rigid_wall_material() {
  Material w;
  w.name = "wall";
  w.rigid = true;
  return w;
}

template <class T>
MdrSideConstants<T> side_constants(double E, double nu, double Y, MdrYieldOnset onset = MdrYieldOnset::elastic_law) {
  return mdr_side_constants<T>(mdr_material(E, nu, Y), onset);
}

// One side driven through overlaps path[k] (one device thread, in order).
struct SideTrace {
  std::vector<double> delta, F, area, a, d1De, delta_p, delta_max, A, B;
  std::vector<int> yielded, state, floored;
  int size() const { return static_cast<int>(F.size()); }
};

template <class D, class T, bool Plastic, bool Adhesive>
SideTrace run_side_path(const MdrSideConstants<T>& c, double gamma, double xi, double R,
                        const std::vector<double>& path) {
  const int n = static_cast<int>(path.size());
  Kokkos::View<T*, D> dv("path", n);
  auto hd = Kokkos::create_mirror_view(dv);
  for (int k = 0; k < n; ++k) hd(k) = T(path[k]);
  Kokkos::deep_copy(dv, hd);
  Kokkos::View<double**, Kokkos::LayoutRight, D> out("out", n, 12);
  const T g = T(gamma), x = T(xi), Rt = T(R);
  Kokkos::parallel_for(
      "mdr_test::side_path", Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        MdrSideState<T> s;
        for (int k = 0; k < n; ++k) {
          const MdrSideResult<T> r = mdr_side_force<Plastic, Adhesive>(c, g, x, dv(k), Rt, T(0), s);
          out(k, 0) = r.F;
          out(k, 1) = r.area;
          out(k, 2) = r.a;
          out(k, 3) = r.d1De;
          out(k, 4) = s.delta_p;
          out(k, 5) = r.delta_max;
          out(k, 6) = r.A;
          out(k, 7) = r.B;
          out(k, 8) = s.yielded;
          out(k, 9) = r.adhesion_state;
          out(k, 10) = r.ratio_floored ? 1 : 0;
          out(k, 11) = dv(k);
        }
      });
  auto h = to_host(out);
  SideTrace t;
  for (int k = 0; k < n; ++k) {
    t.F.push_back(h(k, 0));
    t.area.push_back(h(k, 1));
    t.a.push_back(h(k, 2));
    t.d1De.push_back(h(k, 3));
    t.delta_p.push_back(h(k, 4));
    t.delta_max.push_back(h(k, 5));
    t.A.push_back(h(k, 6));
    t.B.push_back(h(k, 7));
    t.yielded.push_back(static_cast<int>(h(k, 8)));
    t.state.push_back(static_cast<int>(h(k, 9)));
    t.floored.push_back(static_cast<int>(h(k, 10)));
    t.delta.push_back(h(k, 11));
  }
  return t;
}

// Linear ramp from a to b in n steps (excluding a, including b).
inline void append_ramp(std::vector<double>& p, double a, double b, int n) {
  for (int k = 1; k <= n; ++k) p.push_back(a + (b - a) * double(k) / double(n));
}

// --- JKR theory (sphere R on a rigid flat, modulus E = E_eff, work of adhesion gamma) ---
struct Jkr {
  double E, R, gamma;
  double delta_of_a(double a) const { return a * a / R - std::sqrt(2.0 * M_PI * gamma * a / E); }
  double force_of_a(double a) const {
    return 4.0 * E * a * a * a / (3.0 * R) - std::sqrt(8.0 * M_PI * gamma * E * a * a * a);
  }
  // displacement-control critical radius: d(delta)/da = 0
  double a_critical_displacement() const { return std::cbrt(M_PI * gamma * R * R / (8.0 * E)); }
  double pull_off() const { return 1.5 * M_PI * gamma * R; }  // largest tension
  double pull_off_displacement_control() const { return 5.0 / 6.0 * M_PI * gamma * R; }
  // force at overlap delta on the stable branch a >= a_critical_displacement (bisection)
  double force_of_delta(double delta) const {
    double lo = a_critical_displacement(), hi = R;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (delta_of_a(mid) < delta ? lo : hi) = mid;
    }
    return force_of_a(0.5 * (lo + hi));
  }
};

// --- one sphere between rigid flats (the setting of Part I Figs 8-12) ---
// Two flats move along x towards the sphere at the origin, each by delta_o (so delta_o is the
// displacement per contact, measured against R_o); `lateral` adds four fixed flats at +-R_o in y
// and z that initially just touch the sphere (die compaction, Fig. 12).
struct FlatTrace {
  std::vector<double> delta_o, F_primary, F_secondary, area, pressure, R, V, delta_max;
  std::vector<int> yielded;
};

template <class Model, class D, class T = typename Model::scalar_type>
FlatTrace run_flats(Model model, double R0, const std::vector<double>& delta_o_path, bool lateral,
                    std::array<int, kMdrGuardCount>* guards = nullptr) {
  const int nw = lateral ? 6 : 2;
  Particles<T, D> p(1);
  {
    auto r0 = Kokkos::create_mirror_view(p.radius0);
    auto m = Kokkos::create_mirror_view(p.mass);
    r0(0) = T(R0);
    m(0) = T(1);
    Kokkos::deep_copy(p.radius0, r0);
    Kokkos::deep_copy(p.radius, r0);
    Kokkos::deep_copy(p.mass, m);
    // material 0 (the sphere), gid 0, at the origin: the views are zero-initialised
  }
  model.bind(p);
  Walls<T, D> w(nw);
  auto wp = Kokkos::create_mirror_view(w.point);
  auto wn = Kokkos::create_mirror_view(w.normal);
  auto wm = Kokkos::create_mirror_view(w.material);
  for (int k = 0; k < nw; ++k) {
    wm(k) = 1;
    const int axis = k / 2;
    const double sgn = (k % 2 == 0) ? 1.0 : -1.0;
    for (int d = 0; d < 3; ++d) {
      wp(k, d) = T(0);
      wn(k, d) = T(0);
    }
    wp(k, axis) = T(sgn * R0);
    wn(k, axis) = T(-sgn);
  }
  Kokkos::deep_copy(w.normal, wn);
  Kokkos::deep_copy(w.material, wm);
  ContactList<D> c(nw);
  {
    auto f = Kokkos::create_mirror_view(c.first);
    auto s = Kokkos::create_mirror_view(c.second);
    for (int k = 0; k < nw; ++k) {
      f(k) = 0;
      s(k) = k;
    }
    Kokkos::deep_copy(c.first, f);
    Kokkos::deep_copy(c.second, s);
  }
  ContactHistory<T, D> h(nw, Model::history_size);
  ContactOutputs<T, D> out;
  out.normal_force = Kokkos::View<T*, D>("fn", nw);
  Kokkos::View<double*, D> extra("extra", 4);
  FlatTrace tr;
  for (double d_o : delta_o_path) {
    for (int k = 0; k < 2; ++k) wp(k, 0) = T((k == 0 ? 1.0 : -1.0) * (R0 - d_o));
    Kokkos::deep_copy(w.point, wp);
    zero_forces(p);
    compute_wall_forces(model, p, w, c, h, T(0), out);
    // outputs of the first flat's contact (read-only re-evaluation, before the radius update)
    {
      const Model mm = model;
      const auto hp = h;
      const auto pp = p;
      const auto ww = w;
      const int nmat = model.nmat;
      Kokkos::parallel_for(
          "mdr_test::flat_outputs", Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
            const ContactGeometry<T> g = wall_geometry(pp, ww, 0, 0, nmat);  // the kernel's geometry
            const MdrContactOutput<T> o = mm.outputs(g, HistoryRow<T, D>{hp.data, 0, 0});
            extra(0) = o.area;
            extra(1) = o.mean_pressure;
            extra(2) = o.delta_max;
            extra(3) = o.yielded;
          });
    }
    auto fn = to_host(out.normal_force);
    auto ex = to_host(extra);
    model.update_radii();
    auto R = to_host(p.radius);
    tr.delta_o.push_back(d_o);
    tr.F_primary.push_back(fn(0));
    tr.F_secondary.push_back(lateral ? double(fn(2)) : 0.0);
    tr.area.push_back(ex(0));
    tr.pressure.push_back(ex(1));
    tr.delta_max.push_back(ex(2));
    tr.yielded.push_back(static_cast<int>(ex(3)));
    tr.R.push_back(R(0));
    if (Model::effects::radius_growth) {
      auto V = to_host(model.growth.volume);
      tr.V.push_back(V(0));
    } else {
      tr.V.push_back(4.0 / 3.0 * M_PI * R0 * R0 * R0);
    }
  }
  if (guards) *guards = model.guard_hits();
  return tr;
}

// --- two particles on the x axis pressed through a sequence of total overlaps ---
// Particle 0 (radius R0, material 0, gid 0) at the origin, particle 1 (radius R1, material m1,
// gid 1) on +x at centre distance R0_o + R1_o - delta (measured with the initial radii, so a
// growing radius adds to the apparent overlap as in a packing). Radius growth is applied after
// every pass (update_radii) when the model has it. Records the normal force on particle 0 along n
// (law output), both radii and the largest |force component|.
struct PairTrace {
  std::vector<double> delta, F, R0, R1;
  bool finite = true;
  int first_non_finite = -1;
};

template <class Model, class D, class T = typename Model::scalar_type>
PairTrace run_pair_path(Model model, double R0, double R1, int m1, const std::vector<double>& overlaps) {
  Particles<T, D> p(2);
  {
    auto r = Kokkos::create_mirror_view(p.radius);
    auto m = Kokkos::create_mirror_view(p.mass);
    auto g = Kokkos::create_mirror_view(p.gid);
    auto mat = Kokkos::create_mirror_view(p.material);
    r(0) = T(R0);
    r(1) = T(R1);
    m(0) = T(1);
    m(1) = T(1);
    g(0) = 0;
    g(1) = 1;
    mat(0) = 0;
    mat(1) = m1;
    Kokkos::deep_copy(p.radius, r);
    Kokkos::deep_copy(p.radius0, r);
    Kokkos::deep_copy(p.mass, m);
    Kokkos::deep_copy(p.gid, g);
    Kokkos::deep_copy(p.material, mat);
  }
  model.bind(p);
  ContactList<D> c(1);
  {
    auto f = Kokkos::create_mirror_view(c.first);
    auto s = Kokkos::create_mirror_view(c.second);
    f(0) = 0;
    s(0) = 1;
    Kokkos::deep_copy(c.first, f);
    Kokkos::deep_copy(c.second, s);
  }
  ContactHistory<T, D> h(1, Model::history_size);
  ContactOutputs<T, D> out;
  out.normal_force = Kokkos::View<T*, D>("fn", 1);
  auto x = Kokkos::create_mirror_view(p.x);
  PairTrace tr;
  for (double d : overlaps) {
    x(0, 0) = T(0);
    x(1, 0) = R0 + R1 - d;  // double whatever T (Particles::position_type)
    Kokkos::deep_copy(p.x, x);
    zero_forces(p);
    compute_pair_forces(model, p, c, h, T(0), out);
    model.update_radii();
    auto fn = to_host(out.normal_force);
    auto f = to_host(p.force);
    auto r = to_host(p.radius);
    tr.delta.push_back(d);
    tr.F.push_back(fn(0));
    tr.R0.push_back(r(0));
    tr.R1.push_back(r(1));
    const bool ok = std::isfinite(double(fn(0))) && std::isfinite(double(f(0, 0))) && std::isfinite(double(f(1, 0))) &&
                    std::isfinite(double(r(0))) && std::isfinite(double(r(1)));
    if (!ok && tr.finite) {
      tr.finite = false;
      tr.first_non_finite = static_cast<int>(tr.F.size()) - 1;
    }
  }
  return tr;
}

}  // namespace test
}  // namespace epac
