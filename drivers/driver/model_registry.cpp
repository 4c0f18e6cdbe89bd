#include "driver/model_registry.hpp"

#include <limits>

namespace epac {
namespace driver {

const std::vector<ModelEntry>& model_registry() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  static const std::vector<ModelEntry> entries = {
      {"hertz_mindlin", kFriction | kDamping, 0u, {}, &run_hertz_mindlin},
      {"linear_spring", kFriction | kDamping, 0u,
       {{"stiffness", 0.0, Bound::open, inf, Bound::open, false, 0.0}},  // k_n [N/m]
       &run_linear_spring},
      // Add models here, e.g.
      // {"mdr", kAdhesion | kPlasticity | kFriction | kDamping | kRadiusGrowth, kPlasticity | kRadiusGrowth,
      //  {...keys...}, &run_mdr},
  };
  return entries;
}

const ModelEntry& find_model(const std::string& name) {
  std::string known;
  for (const auto& e : model_registry()) {
    if (e.name == name) return e;
    known += (known.empty() ? "" : ", ") + e.name;
  }
  throw SceneError("model.name = \"" + name + "\" is not a known model (valid: " + known + ")");
}

RunSummary run(const Scene& scene, const RunOptions& options) {
  if (options.precision != "double" && options.precision != "float")
    throw ParameterError("--precision = " + options.precision + " is not valid (valid: double, float)");
  if (options.steps < -1) throw ParameterError("--steps must be >= 0");
  return find_model(scene.model.name).run(scene, options);
}

RunSummary run_scene_file(const std::string& path, const RunOptions& options) {
  return run(parse_scene_file(path), options);
}

}  // namespace driver
}  // namespace epac
