// `create` of every law rejects, for float models, moduli, surface energies and yield stresses whose
// derived constants overflow or underflow in float (docs/stability.md), naming the constant, its
// value and the representable range; the same materials are accepted by the double models.
#include "stability_helpers.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace epac;
using namespace epac::test;

namespace {
Material base() { return stability_material(1e9, 1e7, 0.0, 1e-3); }

template <class Make>
std::string rejection(const Material& m) {
  try {
    (void)Make::make({m, stability_wall()});
  } catch (const ParameterError& e) { return e.what(); }
  return "";
}

// Float rejects with a message naming float and the range; double accepts.
template <template <class> class Make>
void float_rejects(const Material& m, const std::string& constant) {
  const std::string msg = rejection<Make<float>>(m);
  INFO(Make<float>::name << ": " << msg);
  CHECK(msg.find(constant) != std::string::npos);
  CHECK(msg.find("float") != std::string::npos);
  CHECK(msg.find("1.17549e-38") != std::string::npos);  // the range's lower end
  CHECK(rejection<Make<double>>(m).empty());
}
}  // namespace

TEST_CASE("create: float models reject inputs whose derived constants leave float's range", "[stability][create]") {
  // the base material is accepted everywhere
  CHECK(rejection<MakeHM<float>>(base()).empty());
  CHECK(rejection<MakeJkr<float>>(base()).empty());
  CHECK(rejection<MakeNan<float>>(base()).empty());
  CHECK(rejection<MakeMdr<float>>(base()).empty());

  Material huge_E = base();
  huge_E.youngs_modulus = 1e39;
  huge_E.yield_stress = 1e37;
  Material tiny_E = base();
  tiny_E.youngs_modulus = 1e-39;
  tiny_E.yield_stress = 1e-41;
  SECTION("moduli") {
    float_rejects<MakeHM>(huge_E, "E_star");
    float_rejects<MakeHM>(tiny_E, "E_star");
    float_rejects<MakeJkr>(huge_E, "E_star");
    float_rejects<MakeJkr>(tiny_E, "E_star");
    float_rejects<MakeNan>(huge_E, "E_star");
    float_rejects<MakeNan>(tiny_E, "E_star");
    float_rejects<MakeMdr>(huge_E, "E_eff");
    float_rejects<MakeMdr>(tiny_E, "E_eff");
  }
  SECTION("surface energies") {
    Material big = base();
    big.surface_energy = 1e39;
    Material small = base();
    small.surface_energy = 1e-40;  // nonzero, but a float denormal
    float_rejects<MakeJkr>(big, "surface_energy");
    float_rejects<MakeJkr>(small, "surface_energy");
    float_rejects<MakeNan>(big, "surface_energy");
    float_rejects<MakeNan>(small, "surface_energy");
    float_rejects<MakeMdr>(big, "surface_energy");
    float_rejects<MakeMdr>(small, "surface_energy");
  }
  SECTION("yield stresses") {
    Material soft = base();
    soft.yield_stress = 1e-39;
    float_rejects<MakeNan>(soft, "yield_pressure");
    float_rejects<MakeMdr>(soft, "yield_stress");
  }
  SECTION("double models reject what overflows double") {
    Material m = base();
    m.youngs_modulus = 1e300;
    m.poisson_ratio = 0.49;
    m.yield_stress = 1e299;
    // kappa = E / (3 (1 - 2 nu)) = 1.7e301 is fine; 4 / E_eff underflows nothing; so MDR accepts,
    // while a modulus of 1e-310 (a double denormal) is rejected
    Material d = base();
    d.youngs_modulus = 1e-310;
    d.yield_stress = 1e-312;
    const std::string msg = rejection<MakeMdr<double>>(d);
    INFO(msg);
    CHECK(msg.find("double") != std::string::npos);
    CHECK(rejection<MakeMdr<double>>(m).empty());
  }
}
