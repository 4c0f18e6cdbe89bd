#pragma once
// The material pairs of a scene that can meet (particle-particle and particle-wall), with the
// range of radii involved: what a model's scene check needs to bound its adhesive range before
// any device state exists (host only, no Kokkos).
#include "driver/scene.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <vector>

namespace epac {
namespace driver {

struct MeetingPair {
  int a = 0, b = 0;                       // a: a particle material; b: a particle material or a wall material
  bool wall = false;                      // b is a wall
  double ra_max = 0;                      // largest radius of the particles of material a
  double rb_max = 0;                      // largest radius of the particles of material b (0 for a wall)
  double R_star_min = 0, R_star_max = 0;  // range of R* = R_a R_b / (R_a + R_b) (wall: R_a)
};

inline std::vector<MeetingPair> meeting_pairs(const Scene& s) {
  std::map<int, std::pair<double, double>> r;  // particle material -> (min, max radius)
  std::map<int, int> count;                    // particle material -> number of particles
  for (const auto& p : s.particles) {
    auto it = r.find(p.material);
    if (it == r.end())
      r[p.material] = {p.radius, p.radius};
    else
      it->second = {std::min(it->second.first, p.radius), std::max(it->second.second, p.radius)};
    ++count[p.material];
  }
  std::vector<int> wall_mats;
  for (const auto& w : s.walls)
    if (std::find(wall_mats.begin(), wall_mats.end(), w.material) == wall_mats.end()) wall_mats.push_back(w.material);
  auto rstar = [](double x, double y) { return x * y / (x + y); };
  std::vector<MeetingPair> out;
  for (const auto& A : r) {
    for (const auto& B : r) {
      if (B.first < A.first) continue;                         // each unordered pair once
      if (B.first == A.first && count[A.first] < 2) continue;  // a lone particle meets no twin
      MeetingPair m;
      m.a = A.first;
      m.b = B.first;
      m.ra_max = A.second.second;
      m.rb_max = B.second.second;
      m.R_star_min = rstar(A.second.first, B.second.first);
      m.R_star_max = rstar(A.second.second, B.second.second);
      out.push_back(m);
    }
    for (int w : wall_mats) {
      MeetingPair m;
      m.a = A.first;
      m.b = w;
      m.wall = true;
      m.ra_max = A.second.second;
      m.R_star_min = A.second.first;
      m.R_star_max = A.second.second;
      out.push_back(m);
    }
  }
  return out;
}

// Particle materials (sorted, unique).
inline std::vector<int> particle_materials(const Scene& s) {
  std::vector<int> m;
  for (const auto& p : s.particles) m.push_back(p.material);
  std::sort(m.begin(), m.end());
  m.erase(std::unique(m.begin(), m.end()), m.end());
  return m;
}

}  // namespace driver
}  // namespace epac
