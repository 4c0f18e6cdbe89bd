// validate(particles, walls, model) (params/state_validation.hpp): every field a law reads, checked
// on the host with a message naming the field, the index, the value and the valid range; a valid
// state passes. The out-of-range material index used to read past the pair table silently.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/params/state_validation.hpp>

#include <cmath>
#include <functional>
#include <limits>

using namespace epac;

namespace {

template <class D>
struct State {
  Particles<double, D> p{3};
  Walls<double, D> w{1};
};

template <class D>
State<D> valid_state() {
  State<D> s;
  Kokkos::deep_copy(s.p.radius, 1e-3);
  Kokkos::deep_copy(s.p.radius0, 1e-3);
  Kokkos::deep_copy(s.p.mass, 1e-5);
  Kokkos::deep_copy(s.p.inertia, 4e-12);
  Kokkos::deep_copy(s.p.material, 0);
  auto p = s.p;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 3), KOKKOS_LAMBDA(int i) {
        p.gid(i) = 7 * i;
        p.x(i, 0) = 3e-3 * i;
      });
  auto n = Kokkos::create_mirror_view(s.w.normal);
  auto m = Kokkos::create_mirror_view(s.w.material);
  n(0, 2) = 1.0;
  m(0) = 1;
  Kokkos::deep_copy(s.w.normal, n);
  Kokkos::deep_copy(s.w.material, m);
  return s;
}

// Sets one host-side entry of a device view.
template <class View, class V>
void set(const View& v, int i, V value) {
  auto h = Kokkos::create_mirror_view(v);
  Kokkos::deep_copy(h, v);
  h(i) = value;
  Kokkos::deep_copy(v, h);
}
template <class View, class V>
void set(const View& v, int i, int d, V value) {
  auto h = Kokkos::create_mirror_view(v);
  Kokkos::deep_copy(h, v);
  h(i, d) = value;
  Kokkos::deep_copy(v, h);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("validate(particles, walls, model) names the field, index, value and range", "[validation]",
                        test::Backends) {
  using D = TestType;
  using Model = HertzMindlin<double, Effects<kFriction>, D>;
  Material glass{"glass", 70e9, 0.25, 2500, 0.5, 0.3};
  Material steel{"steel", 200e9, 0.3, 7800, 0.5, 0.3};
  steel.rigid = true;
  const Model model = Model::create({glass, steel});  // nmat = 2

  SECTION("a valid state passes") {
    auto s = valid_state<D>();
    CHECK_NOTHROW(validate(s.p, s.w, model));
    CHECK_NOTHROW(validate(s.p, model));
  }
  SECTION("particle material outside the model's materials") {
    auto s = valid_state<D>();
    set(s.p.material, 2, 2);
    CHECK_THROWS_AS(validate(s.p, model), ParameterError);
    CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains("particles.material[2] = 2") && Catch::Contains("[0, 1]"));
    set(s.p.material, 2, -1);
    CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains("particles.material[2] = -1"));
  }
  SECTION("wall material outside the model's materials (a wall needs its own entry)") {
    auto s = valid_state<D>();
    set(s.w.material, 0, 5);
    CHECK_THROWS_WITH(validate(s.p, s.w, model), Catch::Contains("walls.material[0] = 5") && Catch::Contains("[0, 1]"));
  }
  SECTION("a wall normal that is not a unit vector") {
    auto s = valid_state<D>();
    set(s.w.normal, 0, 2, 2.0);
    CHECK_THROWS_WITH(validate(s.p, s.w, model),
                      Catch::Contains("|walls.normal[0]| = 2") && Catch::Contains("unit normal"));
    set(s.w.normal, 0, 2, 0.0);  // the zero vector: never filled
    CHECK_THROWS_WITH(validate(s.p, s.w, model), Catch::Contains("|walls.normal[0]| = 0"));
    set(s.w.normal, 0, 2, 1.0 + 5e-7);  // within 1e-6: accepted
    CHECK_NOTHROW(validate(s.p, s.w, model));
  }
  SECTION("radius, radius0, mass, inertia must be positive and finite") {
    const std::vector<std::pair<const char*, std::function<void(State<D>&)>>> breakers = {
        {"particles.radius[1] = 0", [](State<D>& s) { set(s.p.radius, 1, 0.0); }},
        {"particles.radius0[0] = 0", [](State<D>& s) { set(s.p.radius0, 0, 0.0); }},
        {"particles.mass[2] = -1", [](State<D>& s) { set(s.p.mass, 2, -1.0); }},
        {"particles.inertia[1] = 0", [](State<D>& s) { set(s.p.inertia, 1, 0.0); }},
        {"particles.radius[0] = inf", [](State<D>& s) { set(s.p.radius, 0, std::numeric_limits<double>::infinity()); }},
    };
    for (const auto& b : breakers) {
      auto s = valid_state<D>();
      b.second(s);
      INFO(b.first);
      CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains(b.first) && Catch::Contains("(0, inf)"));
    }
  }
  SECTION("positions and velocities must be finite") {
    auto s = valid_state<D>();
    set(s.p.x, 1, 2, std::nan(""));
    CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains("particles.x[1] = nan") && Catch::Contains("finite"));
    s = valid_state<D>();
    set(s.p.v, 0, 0, std::numeric_limits<double>::infinity());
    CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains("particles.v[0] = inf"));
  }
  SECTION("global ids: non-negative, below 2^32 (history keys), unique") {
    auto s = valid_state<D>();
    set(s.p.gid, 1, std::int64_t(-3));
    CHECK_THROWS_WITH(validate(s.p, model),
                      Catch::Contains("particles.gid[1] = -3") && Catch::Contains("[0, 4294967295]"));
    s = valid_state<D>();
    set(s.p.gid, 1, std::int64_t(1) << 32);
    CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains("particles.gid[1] = 4294967296"));
    s = valid_state<D>();
    set(s.p.gid, 2, std::int64_t(0));  // particle 0 has gid 0
    CHECK_THROWS_WITH(validate(s.p, model), Catch::Contains("particles.gid[2] = 0") && Catch::Contains("unique") &&
                                                Catch::Contains("particle 0"));
  }
  SECTION("a freshly allocated state (nothing filled) is refused, not run") {
    Particles<double, D> p(2);
    CHECK_THROWS_AS(validate(p, model), ParameterError);
  }
}
