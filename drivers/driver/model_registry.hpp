#pragma once
// The models the driver can run, by name: their scene keys, the effects each implements, and
// the function that dispatches a scene to the compiled (model x effects x scalar) instance.
//
// To add a model (e.g. mdr):
//  1. driver/models/mdr.cpp: a factory template MdrFactory<T, Bits, Device> (see
//     driver/model_factory.hpp) whose create(scene) builds the model from scene.materials and
//     scene.model.params, and `RunSummary run_mdr(const Scene&, const RunOptions&)` that calls
//     dispatch_run<MdrFactory, kSupportedMask>(scene, options) (driver/dispatch.hpp).
//  2. Declare run_mdr below and add one entry to model_registry() in model_registry.cpp
//     (keys, effects, and a scene check that validates the options and gives the adhesive range).
//  3. Add the .cpp to drivers/CMakeLists.txt.
#include "driver/run_options.hpp"
#include "driver/scene.hpp"

#include <epac/models/effects.hpp>

#include <string>
#include <vector>

namespace epac {
namespace driver {

// A model-specific key in [model]: a number, range-checked on parse (required if has_default is
// false), or, when `choices` is not empty, a string that must be one of them, stored in
// ModelSpec::params as its index (default_value is then the index of the default).
struct ModelKey {
  std::string name;
  double lo;
  Bound lo_kind;
  double hi;
  Bound hi_kind;
  bool has_default;
  double default_value;
  std::vector<std::string> choices = {};
};

// A string key with the given choices; `def` is the default's index.
inline ModelKey choice_key(const std::string& name, std::vector<std::string> choices, int def) {
  return {name, 0.0, Bound::closed, 0.0, Bound::closed, true, static_cast<double>(def), std::move(choices)};
}

// Parse-time check of a model against a whole scene (materials, radii, active effects, its keys):
// throws ParameterError for what the model cannot run, and returns the largest separation
// (negative overlap, m) at which one of the scene's contacts can stay active (adhesion), 0 if
// none. The contact list must keep such pairs, so the skin must exceed it (scene.cpp enforces it).
using ModelSceneCheck = double (*)(const Scene&);

using ModelRunner = RunSummary (*)(const Scene&, const RunOptions&);

struct ModelEntry {
  std::string name;
  unsigned supported_effects;  // the effect bits this model has code for
  unsigned implied_effects;    // bits always on for this model (e.g. radius growth for mdr)
  std::vector<ModelKey> keys;
  ModelRunner run;
  unsigned implied_with_plasticity = 0u;  // bits on whenever plasticity is (mdr: radius growth),
                                          // unless [model] effects sets the list
  ModelSceneCheck scene_check = nullptr;
};

const std::vector<ModelEntry>& model_registry();
// Throws SceneError listing the known names.
const ModelEntry& find_model(const std::string& name);

// Runs a parsed scene: the registry entry of scene.model.name, instantiated for the active
// effects and options.precision.
RunSummary run(const Scene& scene, const RunOptions& options);

// parse_scene_file + run: bad input throws before anything is written or run.
RunSummary run_scene_file(const std::string& path, const RunOptions& options);

// One runner per model (driver/models/<name>.cpp).
RunSummary run_hertz_mindlin(const Scene&, const RunOptions&);
RunSummary run_linear_spring(const Scene&, const RunOptions&);
RunSummary run_mdr(const Scene&, const RunOptions&);
RunSummary run_nan2022(const Scene&, const RunOptions&);
RunSummary run_jkr(const Scene&, const RunOptions&);
double mdr_scene_check(const Scene&);
double nan2022_scene_check(const Scene&);
double jkr_scene_check(const Scene&);

// [model] key values (ModelSpec::params) for a choice key: the index as an int.
inline int choice_of(const Scene& s, const std::string& key) { return static_cast<int>(s.model.params.at(key)); }

}  // namespace driver
}  // namespace epac
