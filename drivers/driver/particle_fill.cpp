#include "driver/particle_fill.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <unordered_map>

namespace epac {
namespace driver {
namespace {

// A uniform draw in [0, 1) from 53 random bits: the same on every platform (std's distributions
// are not). Every seeded stream of the scene (fill, lattice, order) draws through it.
double unit_draw(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0); }

// Hashed uniform grid of cell size h >= 2 R_max: overlapping spheres lie in neighbouring cells.
// Distinct cells may share a hash bucket; that only adds candidates, never loses one.
class HostGrid {
 public:
  explicit HostGrid(double h) : h_(h) {}
  void insert(const Vec3d& x, int id) { cells_[key(cell(x[0]), cell(x[1]), cell(x[2]))].push_back(id); }
  // Calls f(id) for every particle in the 27 cells around x; stops when f returns true.
  template <class F>
  bool any_near(const Vec3d& x, F&& f) const {
    const std::int64_t c[3] = {cell(x[0]), cell(x[1]), cell(x[2])};
    for (std::int64_t a = -1; a <= 1; ++a)
      for (std::int64_t b = -1; b <= 1; ++b)
        for (std::int64_t d = -1; d <= 1; ++d) {
          auto it = cells_.find(key(c[0] + a, c[1] + b, c[2] + d));
          if (it == cells_.end()) continue;
          for (int id : it->second)
            if (f(id)) return true;
        }
    return false;
  }

 private:
  std::int64_t cell(double v) const { return static_cast<std::int64_t>(std::floor(v / h_)); }
  static std::uint64_t key(std::int64_t a, std::int64_t b, std::int64_t c) {
    return static_cast<std::uint64_t>(a) * 73856093ULL ^ static_cast<std::uint64_t>(b) * 19349663ULL ^
           static_cast<std::uint64_t>(c) * 83492791ULL;
  }
  double h_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

double distance(const Vec3d& a, const Vec3d& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double max_radius(const std::vector<ParticleSpec>& ps, double r) {
  for (const auto& p : ps) r = std::max(r, p.radius);
  return r;
}

}  // namespace

void check_no_overlap(const std::vector<ParticleSpec>& ps, const BoxSpec* box) {
  if (ps.size() < 2) return;
  const double reach = 2.0 * max_radius(ps, 0.0);
  HostGrid grid(reach);
  // Periodic axes: a particle within `reach` of a face is also looked up at its image on the
  // other side (positions are wrapped into the box, and the box edge is > 2 reach).
  const bool periodic = box && box->any_periodic();
  for (int i = 0; i < static_cast<int>(ps.size()); ++i) {
    int hit = -1;
    double hit_d = 0;
    std::vector<double> shifts[3];
    for (int d = 0; d < 3; ++d) {
      shifts[d].push_back(0.0);
      if (!periodic || !box->periodic[d]) continue;
      const double L = box->edge0(d);
      if (ps[i].position[d] < box->lo[d] + reach) shifts[d].push_back(L);
      if (ps[i].position[d] > box->hi[d] - reach) shifts[d].push_back(-L);
    }
    for (double sx : shifts[0])
      for (double sy : shifts[1])
        for (double sz : shifts[2]) {
          if (hit >= 0) break;
          const Vec3d xi{ps[i].position[0] + sx, ps[i].position[1] + sy, ps[i].position[2] + sz};
          grid.any_near(xi, [&](int j) {
            const double d = distance(xi, ps[j].position);
            const double sum = ps[i].radius + ps[j].radius;
            if (sum - d > 1e-12 * sum) {
              hit = j;
              hit_d = d;
              return true;
            }
            return false;
          });
        }
    if (hit >= 0) {
      const auto& a = ps[hit];
      const auto& b = ps[i];
      const double d = hit_d;
      std::ostringstream s;
      s << a.origin << " and " << b.origin << " overlap by " << (a.radius + b.radius - d) << " m (centre distance " << d
        << " m < R_i + R_j = " << (a.radius + b.radius)
        << " m; valid: distance >= R_i + R_j); set particles.allow_overlap = true to allow it";
      throw SceneError(s.str());
    }
    grid.insert(ps[i].position, i);
  }
}

void fill_box(const FillSpec& f, std::vector<ParticleSpec>& ps) {
  if (!f.enabled || f.count == 0) return;
  for (int d = 0; d < 3; ++d) {
    if (f.box_max[d] - f.box_min[d] <= 2.0 * f.radius_max) {
      std::ostringstream s;
      s << "particles.fill.box_max[" << d << "] - box_min[" << d << "] = " << (f.box_max[d] - f.box_min[d])
        << " m is outside the valid range (2 radius_max = " << 2.0 * f.radius_max << ", inf)";
      throw SceneError(s.str());
    }
  }
  // Solid fraction the fill asks for: count x E[4/3 pi R^3], R uniform in [rmin, rmax].
  const double r0 = f.radius_min, r1 = f.radius_max;
  const double mean_r3 = r1 > r0 ? (r1 * r1 * r1 * r1 - r0 * r0 * r0 * r0) / (4.0 * (r1 - r0)) : r0 * r0 * r0;
  const double box = (f.box_max[0] - f.box_min[0]) * (f.box_max[1] - f.box_min[1]) * (f.box_max[2] - f.box_min[2]);
  const double fraction = static_cast<double>(f.count) * 4.0 / 3.0 * M_PI * mean_r3 / box;
  if (fraction > 0.38) {
    std::ostringstream s;
    s << "particles.fill.count = " << f.count << " asks for a solid volume fraction " << fraction
      << " of the box, outside the valid range (0, 0.38] of a random non-overlapping fill "
         "(the random-sequential-addition jamming limit); enlarge the box or lower the count";
    throw SceneError(s.str());
  }

  std::mt19937_64 rng(f.seed);
  auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * unit_draw(rng); };
  HostGrid grid(2.0 * max_radius(ps, f.radius_max));
  for (int i = 0; i < static_cast<int>(ps.size()); ++i) grid.insert(ps[i].position, i);

  const std::int64_t max_attempts = 500 * f.count + 10000;
  std::int64_t attempts = 0, placed = 0;
  while (placed < f.count) {
    if (++attempts > max_attempts) {
      std::ostringstream s;
      s << "particles.fill: placed only " << placed << " of count = " << f.count << " particles after " << max_attempts
        << " attempts (solid fraction " << fraction << "); enlarge the box or lower the count";
      throw SceneError(s.str());
    }
    ParticleSpec p;
    p.radius = r1 > r0 ? uniform(r0, r1) : r0;
    for (int d = 0; d < 3; ++d) p.position[d] = uniform(f.box_min[d] + p.radius, f.box_max[d] - p.radius);
    const bool blocked = grid.any_near(
        p.position, [&](int j) { return distance(p.position, ps[j].position) < p.radius + ps[j].radius; });
    if (blocked) continue;
    p.material = f.material;
    p.velocity = f.velocity;
    p.origin = "particles.fill[" + std::to_string(placed) + "]";
    grid.insert(p.position, static_cast<int>(ps.size()));
    ps.push_back(p);
    ++placed;
  }
}

void wrap_into_box(const BoxSpec& box, std::vector<ParticleSpec>& ps) {
  for (auto& p : ps)
    for (int d = 0; d < 3; ++d) {
      if (!box.periodic[d]) continue;
      const double L = box.edge0(d);
      double x = p.position[d] - L * std::floor((p.position[d] - box.lo[d]) / L);
      if (x >= box.hi[d]) x = box.lo[d];  // round-off at the upper face
      p.position[d] = x;
    }
}

void fill_lattice(const LatticeSpec& l, std::vector<ParticleSpec>& ps) {
  if (!l.enabled) return;
  static const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::mt19937_64 rng(l.seed);
  auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * unit_draw(rng); };
  std::int64_t k = 0;
  ps.reserve(ps.size() + static_cast<std::size_t>(l.count()));
  for (std::int64_t cz = 0; cz < l.cells[2]; ++cz)
    for (std::int64_t cy = 0; cy < l.cells[1]; ++cy)
      for (std::int64_t cx = 0; cx < l.cells[0]; ++cx)
        for (int b = 0; b < 4; ++b, ++k) {
          ParticleSpec p;
          // Evaluation order fixed: radius, then the jitter in x, y, z.
          p.radius = l.radius_max > l.radius_min ? uniform(l.radius_min, l.radius_max) : l.radius_min;
          const double cell[3] = {double(cx), double(cy), double(cz)};
          for (int d = 0; d < 3; ++d) {
            const double j = l.jitter > 0 ? uniform(-l.jitter, l.jitter) : 0.0;
            p.position[d] = l.origin[d] + l.a * (cell[d] + basis[b][d]) + j;
          }
          p.material = l.material;
          p.velocity = l.velocity;
          p.origin = "particles.lattice[" + std::to_string(k) + "]";
          ps.push_back(p);
        }
}

void shuffle_order(std::uint64_t seed, std::vector<ParticleSpec>& ps) {
  std::mt19937_64 rng(seed);
  for (std::size_t k = ps.size(); k > 1; --k) {
    std::size_t j = static_cast<std::size_t>(unit_draw(rng) * static_cast<double>(k));
    if (j >= k) j = k - 1;
    std::swap(ps[k - 1], ps[j]);
  }
}

}  // namespace driver
}  // namespace epac
