// Bad parameters are rejected on the host, before anything runs, with a message naming the
// parameter, the value and the valid range; a rejected input leaves existing state unchanged.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include <limits>
#include <string>

using namespace epac;

namespace {
Material good() {
  Material m;
  m.name = "glass";
  m.youngs_modulus = 70e9;
  m.poisson_ratio = 0.25;
  m.density = 2500;
  return m;
}
std::string message_of(const Material& m) {
  try {
    m.validate();
  } catch (const ParameterError& e) { return e.what(); }
  return "";
}
}  // namespace

TEST_CASE("material validation names key, value and range", "[validation]") {
  Material m = good();
  m.youngs_modulus = -1;
  auto msg = message_of(m);
  CHECK_THAT(msg, Catch::Contains("youngs_modulus") && Catch::Contains("-1") && Catch::Contains("(0, inf)") &&
                      Catch::Contains("glass"));
  m = good();
  m.poisson_ratio = 0.5;
  CHECK_THAT(message_of(m), Catch::Contains("poisson_ratio = 0.5") && Catch::Contains("(-1, 0.5)"));
  m = good();
  m.poisson_ratio = 0.7;
  CHECK_THAT(message_of(m), Catch::Contains("poisson_ratio = 0.7"));
  m = good();
  m.density = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(message_of(m), Catch::Contains("density = nan"));
  m = good();
  m.restitution = 1.2;
  CHECK_THAT(message_of(m), Catch::Contains("restitution = 1.2") && Catch::Contains("[0, 1]"));
  m = good();
  m.youngs_modulus = std::numeric_limits<double>::infinity();
  CHECK_THAT(message_of(m), Catch::Contains("youngs_modulus = inf"));
  m = good();
  m.yield_stress = std::numeric_limits<double>::infinity();  // "no yield" is valid
  CHECK(message_of(m).empty());
  m = good();
  m.yield_stress = 0;
  CHECK_THAT(message_of(m), Catch::Contains("yield_stress = 0"));
  CHECK(message_of(good()).empty());
}

TEST_CASE("a rejected material leaves an existing model unchanged", "[validation]") {
  using Model = HertzMindlin<double, Effects<kFriction | kDamping>>;
  Model model = Model::create({good()});
  auto before = test::to_host(model.pairs);
  Material bad = good();
  bad.poisson_ratio = 0.5;
  CHECK_THROWS_AS(model = Model::create({good(), bad}), ParameterError);
  CHECK(model.nmat == 1);
  auto after = test::to_host(model.pairs);
  CHECK(after(0).E_star == before(0).E_star);
  CHECK(after(0).mu == before(0).mu);
}
