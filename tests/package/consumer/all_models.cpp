// Instantiates every contact law's kernel in double and float through the installed package,
// so the consumer build (C++20, see CMakeLists.txt) compiles all device code paths.
#include <epac/epac.hpp>

namespace {
template <class Model>
void force_pass(const Model& model, int n) {
  using T = typename Model::scalar_type;
  epac::Particles<T> p(n);
  epac::ContactList<> c(0);
  epac::ContactHistory<T> h(0, Model::history_size);
  epac::Walls<T> w(0);
  epac::compute_pair_forces(model, p, c, h, T(1e-7));
  epac::compute_wall_forces(model, p, w, c, h, T(1e-7));
}
template <class T>
void all_models() {
  constexpr unsigned all = epac::kAllEffects;
  epac::Material m{"m", 1e9, 0.3, 1000, 0.5, 0.3, 0.1, 1e7};
  force_pass(epac::HertzMindlin<T, epac::Effects<all>>::create({m}), 2);
  force_pass(epac::LinearSpring<T, epac::Effects<all>>::create({m}, 1e3), 2);
  force_pass(epac::Jkr<T, epac::Effects<all>>::create({m}), 2);
  force_pass(epac::Nan2022<T, epac::Effects<all>>::create({m}), 2);
  force_pass(epac::Mdr<T, epac::Effects<all>>::create({m}), 2);
}
}  // namespace

void instantiate_all_models() {
  all_models<double>();
  all_models<float>();
}
