#pragma once
// Nan2022Options from a scene's [model] keys (defined in models/nan2022.cpp); shared by the
// driver's nan2022 factory and epac-sticking-velocity's analytic comparison.
#include "driver/scene.hpp"

#include <epac/params/nan2022/nan2022_parameters.hpp>

namespace epac {
namespace driver {
Nan2022Options nan2022_options(const Scene& s);
}  // namespace driver
}  // namespace epac
