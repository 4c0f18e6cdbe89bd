#pragma once
// Host-side checks of the state a host hands to the kernels: what the laws read but cannot check
// on the device without a cost per contact (a material index outside the pair table is an
// out-of-bounds read that returns a zero or garbage force, not an error). Call validate() once
// after filling the particles and walls (and after changing materials or ids); the driver does.
// Copies the views it reads to the host. Throws ParameterError naming the field, the index, the
// value and the valid range; the first failure wins.
#include <epac/params/validation.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace epac {

namespace state_detail {

[[noreturn]] inline void fail(const std::string& what, int index, const std::string& value,  // host
                              const std::string& range) {                                    // host
  std::ostringstream s;
  s << what << "[" << index << "] = " << value << " is outside the valid range " << range;
  throw ParameterError(s.str());  // host
}
template <class V>
std::string str(V v) {  // host
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}
template <class View>
auto host_copy(const View& v) {  // host
  auto h = Kokkos::create_mirror_view(v);
  Kokkos::deep_copy(h, v);
  return h;
}
inline void check_material(const std::string& what, int index, int m, int nmat) {  // host
  if (m < 0 || m >= nmat) fail(what, index, str(m), "[0, " + str(nmat - 1) + "] (the model's materials)");
}
template <class T>
void check_positive(const std::string& what, int index, T v) {  // host
  if (!(std::isfinite(static_cast<double>(v)) && v > T(0))) fail(what, index, str(v), "(0, inf)");
}
template <class T>
void check_finite(const std::string& what, int index, T v) {  // host
  if (!std::isfinite(static_cast<double>(v))) fail(what, index, str(v), "finite");
}

}  // namespace state_detail

// Particles against a model with `nmat` materials. Checks: material in [0, nmat); radius,
// radius0, mass, inertia finite and > 0; x, v, omega finite; gid in [0, 2^32) (history keys pack
// two ids into 64 bits, contact_list.hpp) and unique (keys and MDR's side order need it).
template <class T, class Device>
void validate(const Particles<T, Device>& p, int nmat) {  // host
  using namespace state_detail;
  if (nmat < 1) throw ParameterError("validate: the model has " + str(nmat) + " materials (valid: >= 1)");  // host
  const auto mat = host_copy(p.material);
  const auto r = host_copy(p.radius), r0 = host_copy(p.radius0);
  const auto m = host_copy(p.mass), inertia = host_copy(p.inertia);
  const auto x = host_copy(p.x);  // double positions: a declaration of its own (one `auto`, one type)
  const auto v = host_copy(p.v), w = host_copy(p.omega);
  const auto gid = host_copy(p.gid);
  for (int i = 0; i < p.n; ++i) {
    check_material("particles.material", i, mat(i), nmat);
    check_positive("particles.radius", i, r(i));
    check_positive("particles.radius0", i, r0(i));
    check_positive("particles.mass", i, m(i));
    check_positive("particles.inertia", i, inertia(i));
    for (int d = 0; d < 3; ++d) {
      check_finite("particles.x", i, x(i, d));
      check_finite("particles.v", i, v(i, d));
      check_finite("particles.omega", i, w(i, d));
    }
    if (gid(i) < 0 || gid(i) > std::int64_t(0xffffffffLL)) fail("particles.gid", i, str(gid(i)), "[0, 4294967295]");
  }
  std::vector<std::pair<std::int64_t, int>> ids(static_cast<std::size_t>(p.n));  // host
  for (int i = 0; i < p.n; ++i) ids[static_cast<std::size_t>(i)] = {gid(i), i};
  std::sort(ids.begin(), ids.end());
  for (std::size_t k = 1; k < ids.size(); ++k)
    if (ids[k].first == ids[k - 1].first)
      fail("particles.gid", ids[k].second, str(ids[k].first),
           "unique ids (particle " + str(ids[k - 1].second) + " has the same)");
}

// Walls against a model with `nmat` materials: material in [0, nmat) (a wall needs its own
// entry in the material list, usually rigid), unit normals (| |n| - 1 | <= 1e-6; the laws use n
// as given), finite point, velocity and curvature.
template <class T, class Device>
void validate(const Walls<T, Device>& w, int nmat) {  // host
  using namespace state_detail;
  const auto mat = host_copy(w.material);
  const auto pt = host_copy(w.point);  // double, the others T: declarations of their own
  const auto n = host_copy(w.normal), v = host_copy(w.velocity);
  const auto c = host_copy(w.curvature);  // T* (not T*[3]): a declaration of its own
  for (int k = 0; k < w.n; ++k) {
    check_material("walls.material", k, mat(k), nmat);
    check_finite("walls.curvature", k, c(k));
    for (int d = 0; d < 3; ++d) {
      check_finite("walls.point", k, pt(k, d));
      check_finite("walls.velocity", k, v(k, d));
    }
    const double len = std::sqrt(double(n(k, 0)) * n(k, 0) + double(n(k, 1)) * n(k, 1) + double(n(k, 2)) * n(k, 2));
    if (!(std::fabs(len - 1.0) <= 1e-6))
      throw ParameterError("|walls.normal[" + str(k) + "]| = " + str(len) +  // host
                           " is outside the valid range [1 - 1e-6, 1 + 1e-6] (a unit normal)");
  }
}

// The same against a model (any epac law: it has `nmat`).
template <class T, class Device, class Model>
void validate(const Particles<T, Device>& p, const Model& model) {  // host
  validate(p, model.nmat);
}
// With walls: a concave wall (curvature R_w < 0) needs -R_w >= 2 R_i for the largest particle
// (R* <= 2 R_i, the domain of the wall's R*: compute/contact_forces.hpp wall_effective_radius).
template <class T, class Device, class Model>
void validate(const Particles<T, Device>& p, const Walls<T, Device>& w, const Model& model) {  // host
  validate(p, model.nmat);
  validate(w, model.nmat);
  using namespace state_detail;
  const auto r = host_copy(p.radius);
  const auto c = host_copy(w.curvature);
  double r_max = 0;
  for (int i = 0; i < p.n; ++i) r_max = std::fmax(r_max, double(r(i)));
  for (int k = 0; k < w.n; ++k)
    if (c(k) < T(0) && !(-double(c(k)) >= 2.0 * r_max))
      fail("walls.curvature", k, str(c(k)),
           "(-inf, -2 R_max] U [0, inf) (R_max = " + str(r_max) +
               ", the largest particle radius: a concave wall's R* <= 2 R_i)");
}

}  // namespace epac
