#pragma once
// Random contact paths for every law (docs/stability.md): mixed materials and size ratios to 100,
// driven through the contact kernels in batches (one model per group of paths, one kernel launch
// per step for the whole group). Two kinds of path, alternating:
//   - finite paths: random overlaps from a gap to 1.2 R (jumps and small increments), random
//     velocities to 100 m/s, spins, dt from 1e-12 s to 10 contact times; every force, torque,
//     normal force and radius must stay finite;
//   - energy paths: quasi-static (no velocity: no damping, no sliding) closed walks on a grid of
//     overlaps, one node per step, load / unload / reload, starting and ending at a gap, with
//     non-adhesive materials. Each grid segment is crossed as often up as down, so for a law
//     whose force is a function of the overlap (elastic) the trapezoid sums telescope: the work
//     returned equals the work put in to round-off, and any hysteresis that returns more (energy
//     created) shows; dissipative laws must return less.
// Every contact (each path's wall contact and its pair) sits at its own random offset from the
// origin (0, or 1e-3 to 1e3 m log-uniformly, along a random direction) with a random wall normal
// or pair axis, its positions written in double (Particles::x is double for every T): at 1e3 m
// float's spacing of a coordinate (6e-5 m) is far coarser than most overlaps, double's (1.1e-13 m)
// is not. The energy sums take the overlap the kernel computes from those positions (the same
// double expression as contact_forces.hpp), not the overlap the path asked for: far from the
// origin the two differ by the coordinates' rounding, and the test must weigh the forces with
// the overlaps they were computed at. (Positions rounded to float, as this test wrote them before,
// move the overlap the law sees in steps of the coordinates' float spacing, not along the path's
// grid: at size ratios near 100 that spacing is up to 1e-5 R_min at the origin, and hysteretic
// cycles of small amplitude then appear to create energy. docs/stability.md has the measurements.)
// Parameters that `create` rejects are drawn again and counted.
// first > 0 (the long test's EPAC_FUZZ_FIRST): the groups of paths before the one that holds path
// `first` are drawn (every random draw, in the same order) but not run or checked, so a run can
// start near a path index a longer run reported, with the same paths from there on; the counts
// then cover the paths from the group that holds `first` (paths still counts all, skipped too).
#include "stability_helpers.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace epac {
namespace test {

struct FuzzCounts {
  long paths = 0, contacts = 0, rejected = 0, nan = 0, inf = 0, energy_checked = 0, energy_created = 0;
  // MDR pairs with a yielding side: a subset of the counts above, also reported on their own (the
  // case a geometric split with the mean force got wrong on ~1% of cycles; the balanced split of
  // mdr_pair_balance.hpp is passive by construction)
  long plastic_pair_checked = 0, plastic_pair_energy_created = 0;
  double worst_plastic_pair = -1;  // largest (returned - put in) / put in over those pairs
  double worst_energy = -1;        // largest (returned - put in) / put in over the energy paths
  std::string first_failure;
  FuzzCounts& operator+=(const FuzzCounts& o) {
    paths += o.paths;
    contacts += o.contacts;
    rejected += o.rejected;
    nan += o.nan;
    inf += o.inf;
    energy_checked += o.energy_checked;
    energy_created += o.energy_created;
    plastic_pair_checked += o.plastic_pair_checked;
    plastic_pair_energy_created += o.plastic_pair_energy_created;
    worst_energy = std::max(worst_energy, o.worst_energy);
    worst_plastic_pair = std::max(worst_plastic_pair, o.worst_plastic_pair);
    if (first_failure.empty()) first_failure = o.first_failure;
    return *this;
  }
};

struct FuzzRng {
  std::mt19937_64 g;
  explicit FuzzRng(std::uint64_t s) : g(s) {}
  double u(double a = 0, double b = 1) { return std::uniform_real_distribution<double>(a, b)(g); }
  double log_u(double a, double b) { return std::pow(10.0, u(std::log10(a), std::log10(b))); }
  int i(int a, int b) { return std::uniform_int_distribution<int>(a, b)(g); }
  Vec3<double> unit() {  // uniform on the sphere
    const double z = u(-1, 1), phi = u(0, 6.283185307179586), s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }
  // Distance of a contact from the origin: 0 (one draw in 7) or 1e-3 to 1e3 m log-uniformly,
  // along a random direction.
  Vec3<double> offset() {
    const double d = i(0, 6) == 0 ? 0.0 : log_u(1e-3, 1e3);
    return d * unit();
  }
};

// The contact geometry as the kernels compute it from double positions (contact_forces.hpp,
// pair_geometry_exact and wall_geometry_exact), for the energy sums.
inline double fuzz_pair_overlap(double Ri, double Rj, const Vec3<double>& xi, const Vec3<double>& xj) {
  return Ri + Rj - norm(xi - xj);
}
inline double fuzz_wall_overlap(double Ri, const Vec3<double>& xi, const Vec3<double>& point,
                                const Vec3<double>& normal) {
  return Ri - dot(xi - point, normal);
}

// A random material of the ranges: E 1e5-1e12 Pa, nu -0.5-0.49, E/Y 1.5-1e5 (or no
// yield), surface energy up to E R (0 when !adhesive).
inline Material fuzz_material(FuzzRng& r, double R, bool adhesive, bool may_not_yield) {
  Material m;
  m.name = "fuzz";
  m.youngs_modulus = r.log_u(1e5, 1e12);
  m.poisson_ratio = r.u(-0.5, 0.49);
  m.density = r.log_u(300, 2e4);
  m.restitution = r.u();
  m.friction = r.u();
  m.yield_stress =
      (may_not_yield && r.u() < 0.2) ? std::numeric_limits<double>::infinity() : m.youngs_modulus / r.log_u(1.5, 1e5);
  m.surface_energy = adhesive ? m.youngs_modulus * R * r.log_u(1e-10, 1.0) : 0.0;
  return m;
}

// Grid walk for an energy path: node indices, +-1 per step, from 0 up and down through random
// turning points back to 0.
inline std::vector<int> fuzz_grid_walk(FuzzRng& r, int N) {
  std::vector<int> w{0};
  int pos = 0;
  const int turns = r.i(1, 3);
  for (int t = 0; t < turns; ++t) {
    const int up = r.i(std::max(pos + 1, 1), N);
    while (pos < up) w.push_back(++pos);
    const int down = (t + 1 == turns) ? 0 : r.i(0, pos - 1);
    while (pos > down) w.push_back(--pos);
  }
  return w;
}

// refine > 1 (the long test's EPAC_FUZZ_REFINE): every grid step of an energy path is cut into
// `refine` steps (the same paths, a finer quasi-static walk: discretisation error shows as a
// decrease with refine); the finite paths hold each node `refine` steps, and the random draws
// per step happen once per `refine` steps, so the paths drawn are those of refine = 1.
template <class Make, class T, class D = DefaultDevice>
FuzzCounts fuzz_paths(long n_paths, std::uint64_t seed, int group = 512, int refine = 1, long first = 0) {
  using Model = typename Make::M;
  FuzzCounts c;
  FuzzRng r(seed);
  FuzzRng rg(seed ^ 0x6a09e667f3bcc909ULL);                  // geometry: offsets and directions
  const bool is_nan = std::string(Make::name) == "nan2022";  // Nan 2022 needs a yield pressure (k_el)
  const bool is_mdr = std::string(Make::name).rfind("mdr", 0) == 0;
  const double tol_energy = 1e-9;
  while (c.paths < n_paths) {
    const int G = static_cast<int>(std::min<long>(group, n_paths - c.paths));
    // materials: K non-adhesive and K adhesive, each accepted by create alone against a wall
    const int K = 4;
    const double Rg = r.log_u(1e-7, 1e-1);
    std::vector<Material> mats;
    for (int k = 0; k < 2 * K; ++k) {
      for (;;) {  // until create accepts the material
        const Material m = fuzz_material(r, Rg, k >= K, !is_nan);
        try {
          (void)Make::make({m, stability_wall()});
          mats.push_back(m);
          break;
        } catch (const ParameterError&) { ++c.rejected; }
      }
    }
    mats.push_back(stability_wall());
    const int wall_mat = 2 * K;
    Model model;
    try {
      model = Make::make(mats);
    } catch (const ParameterError&) {
      ++c.rejected;  // a pair of two accepted materials rejected: draw the group again
      continue;
    }
    // paths
    Particles<T, D> p(3 * G, "fuzz");
    Walls<T, D> w(G, "fuzz_wall");  // one per path, at the wall contact's offset
    ContactList<D> wc(G, "fuzz_wc"), pc(G, "fuzz_pc");
    ContactHistory<T, D> wh(G, Model::history_size), ph(G, Model::history_size);
    ContactOutputs<T, D> ow, op;
    ow.normal_force = Kokkos::View<T*, D>("fuzz.fw", G);
    op.normal_force = Kokkos::View<T*, D>("fuzz.fp", G);
    std::vector<double> Ra(G), Rb(G), rho(G), Eg(G);
    std::vector<int> energy(G), plastic_pair(G, 0), mA(G), mB(G);
    std::vector<std::vector<double>> Fp(G);
    std::vector<std::vector<double>> dw(G), dp(G);  // overlap per step asked for, wall and pair
    std::vector<std::vector<double>> rp(G);         // pair overlap per step as the kernel computes it
    // geometry: wall point and normal (normal as the kernel reads it: T, then double), pair
    // position and axis; drawn from their own generator, so that materials, radii, paths,
    // velocities and steps are those the same seed drew before the offsets existed
    std::vector<Vec3<double>> w_point(G), w_normal(G), p_point(G), p_axis(G);
    std::vector<double> Ra_T(G), Rb_T(G);  // radii as stored (T)
    int S = 0;
    {
      auto R0 = Kokkos::create_mirror_view(p.radius0);
      auto mass = Kokkos::create_mirror_view(p.mass);
      auto inertia = Kokkos::create_mirror_view(p.inertia);
      auto mat = Kokkos::create_mirror_view(p.material);
      auto gid = Kokkos::create_mirror_view(p.gid);
      auto wf = Kokkos::create_mirror_view(wc.first), ws = Kokkos::create_mirror_view(wc.second);
      auto pf = Kokkos::create_mirror_view(pc.first), ps = Kokkos::create_mirror_view(pc.second);
      for (int i = 0; i < G; ++i) {
        energy[i] = (c.paths + i) % 2 == 0;
        const int ma = energy[i] ? r.i(0, K - 1) : r.i(0, 2 * K - 1);
        const int mb = energy[i] ? r.i(0, K - 1) : r.i(0, 2 * K - 1);
        Ra[i] = std::min(std::max(Rg * r.log_u(0.1, 10), 1e-7), 1e-1);
        Rb[i] = std::min(std::max(Ra[i] * r.log_u(1e-2, 1e2), 1e-7), 1e-1);
        const double rs[3] = {Ra[i], Ra[i], Rb[i]};
        const int ms[3] = {ma, ma, mb};
        for (int q = 0; q < 3; ++q) {
          const int k = 3 * i + q;
          R0(k) = T(rs[q]);
          mass(k) = T(mats[ms[q]].density * 4.18879 * rs[q] * rs[q] * rs[q]);
          inertia(k) = T(0.4 * double(mass(k)) * rs[q] * rs[q]);
          mat(k) = ms[q];
          gid(k) = k;
        }
        rho[i] = mats[ma].density;
        mA[i] = ma;
        mB[i] = mb;
        plastic_pair[i] = std::isfinite(mats[ma].yield_stress) || std::isfinite(mats[mb].yield_stress);
        Eg[i] = std::min(mats[ma].youngs_modulus, mats[mb].youngs_modulus);
        wf(i) = 3 * i;
        ws(i) = i;
        Ra_T[i] = double(T(Ra[i]));
        Rb_T[i] = double(T(Rb[i]));
        w_point[i] = rg.offset();
        w_normal[i] = vec_cast<double>(vec_cast<T>(rg.unit()));
        p_point[i] = rg.offset();
        p_axis[i] = rg.unit();
        pf(i) = 3 * i + 1;
        ps(i) = 3 * i + 2;
        const double Rmin = std::min(Ra[i], Rb[i]);
        if (energy[i]) {
          const int N = r.i(4, 25);
          const std::vector<int> walk = fuzz_grid_walk(r, N);
          const double pw = Ra[i] * r.log_u(1e-4, 1.2), pp = Rmin * r.log_u(1e-4, 1.2);
          for (std::size_t q = 0; q < walk.size(); ++q)
            for (int j = (q == 0 ? refine : 1); j <= refine; ++j) {
              const double kk = q == 0 ? walk[0] : walk[q - 1] + (walk[q] - walk[q - 1]) * double(j) / refine;
              dw[i].push_back(pw * (-0.05 + 1.05 * kk / N));
              dp[i].push_back(pp * (-0.05 + 1.05 * kk / N));
            }
        } else {
          const int n = r.i(5, 60);
          double a = 0, b = 0;
          for (int k = 0; k < n; ++k) {
            if (r.u() < 0.5) {
              a = Ra[i] * r.u(-0.3, 1.2);
              b = Rmin * r.u(-0.3, 1.2);
            } else {
              a += Ra[i] * r.u(-0.05, 0.05);
              b += Rmin * r.u(-0.05, 0.05);
            }
            dw[i].push_back(a);
            dp[i].push_back(b);
          }
        }
        S = std::max(S, static_cast<int>(dw[i].size()) * (energy[i] ? 1 : refine));
      }
      Kokkos::deep_copy(p.radius0, R0);
      Kokkos::deep_copy(p.radius, R0);
      Kokkos::deep_copy(p.mass, mass);
      Kokkos::deep_copy(p.inertia, inertia);
      Kokkos::deep_copy(p.material, mat);
      Kokkos::deep_copy(p.gid, gid);
      Kokkos::deep_copy(wc.first, wf);
      Kokkos::deep_copy(wc.second, ws);
      Kokkos::deep_copy(pc.first, pf);
      Kokkos::deep_copy(pc.second, ps);
      auto wn = Kokkos::create_mirror_view(w.normal);
      auto wp = Kokkos::create_mirror_view(w.point);
      for (int i = 0; i < G; ++i)
        for (int d = 0; d < 3; ++d) {
          wp(i, d) = w_point[i][d];
          wn(i, d) = T(w_normal[i][d]);  // exact: w_normal holds T values
        }
      Kokkos::deep_copy(w.normal, wn);
      Kokkos::deep_copy(w.point, wp);
      Kokkos::deep_copy(w.material, wall_mat);
    }
    if constexpr (Model::effects::radius_growth) model.bind(p);
    auto x = Kokkos::create_mirror_view(p.x);
    auto v = Kokkos::create_mirror_view(p.v);
    auto om = Kokkos::create_mirror_view(p.omega);
    std::vector<double> Win(2 * G, 0.0), Wout(2 * G, 0.0), Fprev(2 * G, 0.0);
    std::vector<double> delta(2 * G, 0.0), delta_prev(2 * G, 0.0);  // kernel's overlaps, wall and pair
    std::vector<int> bad(G, 0);                                     // 1 NaN, 2 Inf
    const double tc_min = 3.0 * Rg * std::sqrt(2500.0 / 1e12);
    double dt_held = 0;
    const bool skip = c.paths + G <= first;  // drawn, not run (EPAC_FUZZ_FIRST)
    for (int s = 0; s < S; ++s) {
      const bool draw = s % refine == 0;
      if (skip) {  // the draws of the step below, in its order, and nothing else
        if (draw) {
          for (int i = 0; i < G; ++i)
            if (!energy[i])
              for (int q = 0; q < 3; ++q)
                for (int d = 0; d < 3; ++d) {
                  (void)r.u(-100, 100);
                  (void)r.u(-100, 100);
                }
          const double tc = 3.0 * std::max(Rg, 1e-7) * std::sqrt(2500.0 / 1e5);
          dt_held = r.log_u(1e-12, std::max(10.0 * tc, 1e-11));
        }
        continue;
      }
      if (draw) {
        Kokkos::deep_copy(v, T(0));
        Kokkos::deep_copy(om, T(0));
      }
      for (int i = 0; i < G; ++i) {
        const int k =
            std::min<int>(energy[i] ? s : s / refine, static_cast<int>(dw[i].size()) - 1);  // shorter paths hold
        // only listed contacts act: contacts of different paths may overlap in space
        const Vec3<double> xw = w_point[i] + (Ra_T[i] - dw[i][k]) * w_normal[i];
        const Vec3<double> xa = p_point[i];
        const Vec3<double> xb = p_point[i] + (Ra_T[i] + Rb_T[i] - dp[i][k]) * p_axis[i];
        for (int d = 0; d < 3; ++d) {
          x(3 * i, d) = xw[d];
          x(3 * i + 1, d) = xa[d];
          x(3 * i + 2, d) = xb[d];
        }
        // radii: R0 (a cycle during which a radius grew is not checked)
        delta[2 * i] = fuzz_wall_overlap(Ra_T[i], xw, w_point[i], w_normal[i]);
        delta[2 * i + 1] = fuzz_pair_overlap(Ra_T[i], Rb_T[i], xa, xb);
        if (!energy[i] && draw)
          for (int q = 0; q < 3; ++q)
            for (int d = 0; d < 3; ++d) {
              v(3 * i + q, d) = T(r.u(-100, 100));
              om(3 * i + q, d) = T(r.u(-100, 100) / (q == 2 ? Rb[i] : Ra[i]));
            }
      }
      Kokkos::deep_copy(p.x, x);
      Kokkos::deep_copy(p.v, v);
      Kokkos::deep_copy(p.omega, om);
      const double tc = 3.0 * std::max(Rg, 1e-7) * std::sqrt(2500.0 / 1e5);  // up to the softest
      if (draw) dt_held = r.log_u(1e-12, std::max(10.0 * tc, 1e-11));
      const double dt = dt_held;
      (void)tc_min;
      zero_forces(p);
      compute_wall_forces(model, p, w, wc, wh, T(dt), ow);
      compute_pair_forces(model, p, pc, ph, T(dt), op);
      if constexpr (Model::effects::radius_growth) model.update_radii();
      auto F = to_host(p.force);
      auto Tq = to_host(p.torque);
      auto R = to_host(p.radius);
      auto fw = to_host(ow.normal_force);
      auto fp = to_host(op.normal_force);
      c.contacts += 2 * G;
      for (int i = 0; i < G; ++i) {
        auto check = [&](double val) {
          if (std::isnan(val))
            bad[i] = bad[i] ? bad[i] : 1;
          else if (std::isinf(val))
            bad[i] = bad[i] ? bad[i] : 2;
        };
        check(fw(i));
        check(fp(i));
        for (int q = 0; q < 3; ++q) {
          check(R(3 * i + q));
          for (int d = 0; d < 3; ++d) {
            check(F(3 * i + q, d));
            check(Tq(3 * i + q, d));
          }
        }
        if (energy[i] && s > 0 && s < static_cast<int>(dw[i].size())) {
          const double f[2] = {double(fw(i)), double(fp(i))};
          const double dd[2] = {delta[2 * i] - delta_prev[2 * i], delta[2 * i + 1] - delta_prev[2 * i + 1]};
          for (int e = 0; e < 2; ++e) {
            const double work = 0.5 * (f[e] + Fprev[2 * i + e]) * dd[e];
            (work > 0 ? Win : Wout)[2 * i + e] += std::fabs(work);
          }
        }
        if (energy[i] && s < static_cast<int>(dw[i].size())) {
          Fp[i].push_back(fp(i));
          rp[i].push_back(delta[2 * i + 1]);
        }
        if (energy[i]) {
          Fprev[2 * i] = fw(i);
          Fprev[2 * i + 1] = fp(i);
          delta_prev[2 * i] = delta[2 * i];
          delta_prev[2 * i + 1] = delta[2 * i + 1];
        }
      }
    }
    if (skip) {
      c.paths += G;
      continue;
    }
    auto Rstart = to_host(p.radius0);
    auto Rend = to_host(p.radius);
    for (int i = 0; i < G; ++i) {
      if (bad[i] == 1) ++c.nan;
      if (bad[i] == 2) ++c.inf;
      if (bad[i] && c.first_failure.empty())
        c.first_failure = std::string(Make::name) + (bad[i] == 1 ? ": NaN" : ": Inf") + " in path " +
                          std::to_string(c.paths + i) + " (seed " + std::to_string(seed) + ")";
      if (!energy[i]) continue;
      for (int e = 0; e < 2; ++e) {
        // with radius growth a cycle is closed only if the radii came back (none grew): a grown
        // particle is another body, and its larger apparent overlap legitimately returns more
        const bool grew = e == 0 ? Rend(3 * i) != Rstart(3 * i)
                                 : (Rend(3 * i + 1) != Rstart(3 * i + 1) || Rend(3 * i + 2) != Rstart(3 * i + 2));
        if (Model::effects::radius_growth && grew) continue;
        const double in = Win[2 * i + e], out = Wout[2 * i + e];
        if (!(in > 0)) continue;
        const double rel = (out - in) / in;
        if (const char* dp = std::getenv("EPAC_FUZZ_DUMP_PATH"))  // one path's cycles, whatever they gave
          if (std::atol(dp) == c.paths + i)
            std::printf("PATH %ld %s rel %.6g in %.9g out %.9g\n", c.paths + i, e ? "pair" : "wall", rel, in, out);
        if (is_mdr && e == 1 && plastic_pair[i]) {
          ++c.plastic_pair_checked;
          c.worst_plastic_pair = std::max(c.worst_plastic_pair, rel);
          if (out > in * (1 + tol_energy)) {
            ++c.plastic_pair_energy_created;
            if (std::getenv("EPAC_FUZZ_DUMP")) {
              std::printf("PAIR path %ld at %.4g m rel %.4g in %.6g out %.6g\n", c.paths + i, norm(p_point[i]), rel, in,
                          out);
              std::printf("PAIR rel %.4g Ra %.4g Rb %.4g EA %.4g nuA %.3g YA %.4g EB %.4g nuB %.3g YB %.4g\n", rel,
                          Ra[i], Rb[i], mats[mA[i]].youngs_modulus, mats[mA[i]].poisson_ratio, mats[mA[i]].yield_stress,
                          mats[mB[i]].youngs_modulus, mats[mB[i]].poisson_ratio, mats[mB[i]].yield_stress);
              for (std::size_t q = 0; q < Fp[i].size(); ++q) std::printf("  %.6g %.6g\n", rp[i][q], Fp[i][q]);
            }
          }
        }
        ++c.energy_checked;
        c.worst_energy = std::max(c.worst_energy, rel);
        if (out > in * (1 + tol_energy)) {
          ++c.energy_created;
          if (c.first_failure.empty())
            c.first_failure = std::string(Make::name) + ": energy created " + std::to_string(rel) + " on the " +
                              (e ? "pair" : "wall") + " of path " + std::to_string(c.paths + i) + ", E_min " +
                              std::to_string(Eg[i]) + ", Ra " + std::to_string(Ra[i]) + ", Rb " +
                              std::to_string(Rb[i]) + ", at " + std::to_string(norm(e ? p_point[i] : w_point[i])) +
                              " m from the origin";
        }
      }
    }
    c.paths += G;
  }
  return c;
}

}  // namespace test
}  // namespace epac
