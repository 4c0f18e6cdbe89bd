#pragma once
// Rolling resistance: a spring-dashpot-slider on the relative rolling displacement (the effect
// kRolling, models/effects.hpp), for every law. It is LAMMPS's `rolling sds`
// (GRANULAR/gran_sub_mod_rolling.cpp, the MDR authors' examples use it), after Luding (2008,
// Granular Matter 10:235) and Marshall (2009, J. Comput. Phys. 228:1541):
//   v_rl = R* (omega_i - omega_j) x n                 rolling velocity (Wang et al. 2015, eq. 31)
//   xi_r += dt v_rl                                    after rotating xi_r into the contact plane
//   F_r  = -k_r xi_r - gamma_r v_rl, |F_r| <= mu_r F_c   (F_c: the tangential spring's normal force)
//   torque R* n x F_r on i, the opposite on j (torque only: no force on the centres)
// v_rl is the same for (i, j) and (j, i) (omega_i - omega_j and n both change sign), so the
// history needs no orientation, unlike the tangential spring's.
// Host: the per-pair table (k_r, gamma_r, mu_r) from the materials' rolling_* keys
// (params/material.hpp: geometric mean for two particles, as LAMMPS mixes them).
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/vec3.hpp>
#include <epac/params/material.hpp>

#include <string>
#include <vector>

namespace epac {

template <class T>
struct RollingPair {
  T k = 0;      // k_r [N/m]
  T gamma = 0;  // gamma_r [N s/m]
  T mu = 0;     // mu_r: |F_r| <= mu_r F_c
};

// A law's rolling table: empty (no view, nothing allocated) unless the effect is on.
template <class T, class Device, bool Enabled>
struct RollingTable {
  static RollingTable create(const std::vector<Material>&) { return {}; }  // host
};

template <class T, class Device>
struct RollingTable<T, Device, true> {
  Kokkos::View<RollingPair<T>*, Device> pairs;  // nmat x nmat, row-major (the law's pair index)

  static RollingTable create(const std::vector<Material>& materials) {  // host
    const int nmat = static_cast<int>(materials.size());
    RollingTable t;
    t.pairs = Kokkos::View<RollingPair<T>*, Device>("rolling.pairs", nmat * nmat);
    auto h = Kokkos::create_mirror_view(t.pairs);
    for (int a = 0; a < nmat; ++a)
      for (int b = 0; b < nmat; ++b) {
        const Material& A = materials[a];
        const Material& B = materials[b];
        if (A.rigid && B.rigid) continue;  // never meet (the row stays zero)
        const PairProperties pp = pair_properties(A, B);
        const std::string from = "the rolling keys of '" + A.name + "' and '" + B.name + "'";  // host
        require_representable<T>("rolling: rolling_stiffness", pp.rolling_stiffness, from);
        require_representable<T>("rolling: rolling_damping", pp.rolling_damping, from);
        require_representable<T>("rolling: rolling_friction", pp.rolling_friction, from);
        h(a * nmat + b) = {T(pp.rolling_stiffness), T(pp.rolling_damping), T(pp.rolling_friction)};
      }
    Kokkos::deep_copy(t.pairs, h);
    return t;
  }

  // Host, before a kernel reads it: a law built without materials (Nan2022::create_from_pairs)
  // must be given its table (RollingTable::create) before rolling can run.
  void require_bound(int nmat) const {
    if (static_cast<long>(pairs.extent(0)) < static_cast<long>(nmat) * nmat)
      throw ParameterError("rolling resistance: the model's rolling table has " + std::to_string(pairs.extent(0)) +
                           " pair entries, needs nmat^2 = " + std::to_string(nmat * nmat) +
                           " (set model.rolling = RollingTable<...>::create(materials))");  // host
  }
};

// Returns F_r, the rolling resistance "force" of i (its torque is R* n x F_r). f_c: the normal
// force the tangential spring's Coulomb bound uses (the law's f, or f + F_d under the MDR
// authors' convention); the bound is mu_r |f_c|. h: the 3 history fields xi_r.
// Domains: the rescale sqrt(len2_old / len2_new) runs only for len2_new > 0 (the quotient is then
// >= 1 and finite); the slider divides by k_r only when k_r > 0 and by |F_r| only when
// |F_r| > mu_r |f_c| >= 0.
template <class T, class Row>
KOKKOS_FORCEINLINE_FUNCTION Vec3<T> rolling_sds_force(const RollingPair<T>& rp, const Vec3<T>& n, const Vec3<T>& v_rl,
                                                      T f_c, T dt, const Row& h) {
  Vec3<T> xi(h(0), h(1), h(2));
  // Into the current contact plane, keeping |xi| (as the tangential spring; LAMMPS skips this
  // when |xi.n| k_r <= 1e-10 mu_r |f_c|, a difference of that relative size).
  const T xn = dot(xi, n);
  if (xn != T(0)) {
    const T len2_old = dot(xi, xi);
    xi -= xn * n;
    const T len2_new = dot(xi, xi);
    xi = len2_new > T(0) ? math::sqrt(len2_old / len2_new) * xi : Vec3<T>();
  }
  xi += dt * v_rl;
  Vec3<T> fr = T(-1) * rp.k * xi - rp.gamma * v_rl;
  const T f_lim = rp.mu * math::fabs(f_c);
  const T fr2 = dot(fr, fr);
  if (fr2 > f_lim * f_lim) {
    // Slipping: F_r along itself with |F_r| = mu_r |f_c|, and the spring set so that
    // -k_r xi - gamma_r v_rl is exactly that (LAMMPS; it also keeps the damping part).
    const Vec3<T> fr_lim = (f_lim / math::sqrt(fr2)) * fr;  // fr2 > f_lim^2 >= 0
    if (rp.k > T(0)) {
      // xi == 0 here only in a pass with dt = 0 (a run's first): LAMMPS then drops F_r, and so
      // does epac, so that the two agree from the first step.
      const bool unloaded = xi.x == T(0) && xi.y == T(0) && xi.z == T(0);
      if (!unloaded) xi = (T(-1) / rp.k) * (fr_lim + rp.gamma * v_rl);
      fr = unloaded ? Vec3<T>() : fr_lim;
    } else {
      fr = fr_lim;  // k_r == 0: a dashpot held at the bound (LAMMPS would divide by k_r)
    }
  }
  h(0) = xi.x;
  h(1) = xi.y;
  h(2) = xi.z;
  return fr;
}

template <class Row>
KOKKOS_INLINE_FUNCTION void reset_rolling(const Row& h) {
  h(0) = 0;
  h(1) = 0;
  h(2) = 0;
}

}  // namespace epac
