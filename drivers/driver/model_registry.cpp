#include "driver/model_registry.hpp"

#include <limits>

namespace epac {
namespace driver {

const std::vector<ModelEntry>& model_registry() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  static const std::vector<ModelEntry> entries = {
      {"hertz_mindlin", kFriction | kDamping | kRolling, 0u, {}, &run_hertz_mindlin},
      {"linear_spring",
       kFriction | kDamping | kRolling,
       0u,
       {{"stiffness", 0.0, Bound::open, inf, Bound::open, false, 0.0}},  // k_n [N/m]
       &run_linear_spring},
      // MDR (Zunker & Kamrin Part I), driver/models/mdr.cpp. Radius growth is on whenever
      // plasticity is (unless [model] effects says otherwise).
      {"mdr",
       kAdhesion | kPlasticity | kFriction | kDamping | kRadiusGrowth | kRolling | kBulkResponse,
       0u,
       {{"xi", 1.0, Bound::closed, 3.0, Bound::closed, true, 1.0},  // MDR (15): 1 or 3 (checked)
        choice_key("growth_rule", {"plastic_loading", "yielded_contacts"}, 0),
        choice_key("yield_onset", {"elastic_law", "hertz_40"}, 0),
        choice_key("pair_split", {"equal_pair", "balanced", "geometric", "geometric_authors"}, 0),
        choice_key("delta_max", {"paper_19", "running_max"}, 0),
        choice_key("damping", {"restitution_exact", "authors"}, 0),
        choice_key("friction", {"mindlin", "authors"}, 0),
        choice_key("surface_energy_share", {"series", "each_side_full"}, 0),
        choice_key("adhesive_radius", {"paper", "authors"}, 0),
        choice_key("release", {"critical_overlap", "zero_overlap"}, 0),
        choice_key("contact_penalty", {"off", "on"}, 0),  // LAMMPS's MDR penalty (mdr_contact_penalty.hpp)
        {"tangential_stiffness", 0.0, Bound::closed, inf, Bound::open, true, 0.0},  // k_t [N/m] of friction "authors"
        {"radius_cap", 1.0, Bound::closed, 10.0, Bound::closed, true, 1.5},         // R <= cap R_o
        {"denominator_floor", 0.0, Bound::open, 1.0, Bound::open, true, 0.05},      // guard of (37)
        {"volume_floor", 0.0, Bound::open, 1.0, Bound::open, true, 0.1},            // V >= floor V_o
        {"psi_b", 0.0, Bound::closed, 1.0, Bound::closed, true, 0.0}},              // Part II; > 0: bulk response
       &run_mdr,
       kRadiusGrowth,
       &mdr_scene_check},
      // Nan et al. 2022 linear elasto-plastic adhesive model, driver/models/nan2022.cpp.
      {"nan2022",
       kAdhesion | kPlasticity | kFriction | kDamping | kRolling,
       0u,
       {choice_key("yield_pressure_from", {"jackson_green", "chang", "given_pressure"}, 0),
        {"strain_rate_Y", -inf, Bound::open, inf, Bound::open, true, 0.0},  // Nan (34), off when 0
        {"strain_rate_V_i", 0.0, Bound::open, inf, Bound::open, true, 1.0},
        {"strain_rate_V_0", 0.0, Bound::open, inf, Bound::open, true, 1.0},
        choice_key("k_el_from", {"yield_pressure", "stiffness_pressure", "fixed", "unloading_line"}, 0),
        {"stiffness_pressure", 0.0, Bound::closed, inf, Bound::open, true, 0.0},  // p_k [Pa]
        {"k_el", 0.0, Bound::closed, inf, Bound::open, true, 0.0},                // [N/m]
        {"k_e0", 0.0, Bound::closed, inf, Bound::open, true, 0.0},                // [N/m]
        {"alpha_max0", 0.0, Bound::closed, inf, Bound::open, true, 0.0},          // [m]
        {"reference_radius", 0.0, Bound::closed, inf, Bound::open, true, 0.0},    // [m]
        {"k_p_ratio", 0.0, Bound::open, 1.0, Bound::closed, true, 1.0},
        {"k_p", 0.0, Bound::closed, inf, Bound::open, true, 0.0},  // [N/m], > 0 overrides
        choice_key("unloading_law", {"sqrt_max_overlap", "plastic_offset"}, 0),
        choice_key("pull_off_law", {"work_balance", "effective_radius", "stiffness_power"}, 0),
        {"beta_yielded", 0.0, Bound::closed, 1.0, Bound::closed, true, 0.1}},
       &run_nan2022,
       0u,
       &nan2022_scene_check},
      // Hertz-JKR (Nan Appendix B), driver/models/jkr.cpp.
      {"jkr", kAdhesion | kFriction | kDamping | kRolling, 0u, {}, &run_jkr, 0u, &jkr_scene_check},
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
