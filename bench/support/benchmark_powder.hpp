#pragma once
// The material of the contact-law benchmarks: a cohesive polymer powder (the Ning particle of
// Nan Table 2, at R = 1 mm). One definition, so every benchmark times the same contacts.
#include <epac/params/material.hpp>

namespace epac::bench {

inline Material benchmark_powder() {
  Material m;
  m.name = "powder";
  m.youngs_modulus = 1.2e9;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  m.restitution = 0.81;
  m.friction = 0.3;
  m.surface_energy = 0.2;
  m.yield_stress = 35.3e6;
  return m;
}

// The same powder without adhesion (the variants that compile adhesion out).
inline Material benchmark_powder_no_adhesion() {
  Material m = benchmark_powder();
  m.surface_energy = 0;
  return m;
}

}  // namespace epac::bench
