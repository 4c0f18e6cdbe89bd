#pragma once
// The models the driver can run, by name: their scene keys, the effects each implements, and
// the function that dispatches a scene to the compiled (model x effects x scalar) instance.
//
// To add a model (e.g. mdr):
//  1. driver/models/mdr.cpp: a factory template MdrFactory<T, Bits, Device> (see
//     driver/model_factory.hpp) whose create(scene) builds the model from scene.materials and
//     scene.model.params, and `RunSummary run_mdr(const Scene&, const RunOptions&)` that calls
//     dispatch_run<MdrFactory, kSupportedMask>(scene, options) (driver/dispatch.hpp).
//  2. Declare run_mdr below and add one entry to model_registry() in model_registry.cpp.
//  3. Add the .cpp to drivers/CMakeLists.txt.
#include "driver/run_options.hpp"
#include "driver/scene.hpp"

#include <epac/models/effects.hpp>

#include <string>
#include <vector>

namespace epac {
namespace driver {

// A model-specific number in [model]: range-checked on parse; required if has_default is false.
struct ModelKey {
  std::string name;
  double lo;
  Bound lo_kind;
  double hi;
  Bound hi_kind;
  bool has_default;
  double default_value;
};

using ModelRunner = RunSummary (*)(const Scene&, const RunOptions&);

struct ModelEntry {
  std::string name;
  unsigned supported_effects;  // the effect bits this model has code for
  unsigned implied_effects;    // bits always on for this model (e.g. radius growth for mdr)
  std::vector<ModelKey> keys;
  ModelRunner run;
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

}  // namespace driver
}  // namespace epac
