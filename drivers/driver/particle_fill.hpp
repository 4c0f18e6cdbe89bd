#pragma once
// Host-side placement of particles: the overlap check of an explicit list, and the random
// non-overlapping fill of a box (random sequential addition on a hashed grid: O(N)), the fcc
// lattice fill, and wrapping into a periodic box.
#include "driver/scene.hpp"

#include <vector>

namespace epac {
namespace driver {

// Throws SceneError naming the first two particles found overlapping (distance < R_i + R_j by
// more than 1e-12 (R_i + R_j), so exactly touching particles written with rounded coordinates
// pass), the overlap and the distance.
// With a box (periodic axes), distances are minimum-image ones: images across the faces count.
void check_no_overlap(const std::vector<ParticleSpec>& particles, const BoxSpec* box = nullptr);

// Wraps every position into [lo, hi) along the box's periodic axes.
void wrap_into_box(const BoxSpec& box, std::vector<ParticleSpec>& particles);

// Appends the fcc lattice (LatticeSpec). Deterministic for a given seed on every platform. Does
// not check overlaps (check_no_overlap does, unless particles.allow_overlap).
void fill_lattice(const LatticeSpec& lattice, std::vector<ParticleSpec>& particles);

// Appends fill.count particles, none overlapping each other or the particles already present,
// each wholly inside the box. Deterministic for a given seed. Throws SceneError when the box
// cannot hold them (the random-sequential-addition jamming limit is about 0.38 solid fraction).
void fill_box(const FillSpec& fill, std::vector<ParticleSpec>& particles);

// Puts the particles in a random order (Fisher-Yates on a seeded mt19937_64 with the bounded
// draws made from 53-bit uniforms: the same order for a given seed on every platform).
void shuffle_order(std::uint64_t seed, std::vector<ParticleSpec>& particles);

}  // namespace driver
}  // namespace epac
