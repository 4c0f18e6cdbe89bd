#pragma once
// Umbrella header: every public epac header (convenience; include the ones you use for faster
// builds). Not included: params/nan2022/nan2022_calibration.hpp, the host-side calibration,
// which needs Eigen 3, and the laws' internals under */detail/ (included by the laws' headers).
#include <epac/version.hpp>

#include <epac/compute/contact_forces.hpp>
#include <epac/compute/contact_side_sums.hpp>
#include <epac/compute/deterministic_pass.hpp>
#include <epac/compute/deterministic_reduce.hpp>
#include <epac/compute/history_from_overlaps.hpp>
#include <epac/compute/history_remap.hpp>
#include <epac/compute/ordered_sum.hpp>
#include <epac/core/build_info.hpp>
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/root_solve.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/linear_spring.hpp>
#include <epac/models/mdr/mdr_history_layout.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>
#include <epac/models/mdr/mdr_radius_growth.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/models/nan2022/nan2022.hpp>
#include <epac/models/nan2022/nan2022_pair.hpp>
#include <epac/models/tangential_spring.hpp>
#include <epac/params/material.hpp>
#include <epac/params/nan2022/nan2022_parameters.hpp>
#include <epac/params/nan2022/nan2022_sticking_velocity.hpp>
#include <epac/params/nan2022/nan2022_time_step.hpp>
#include <epac/params/restitution_damping.hpp>
#include <epac/params/state_validation.hpp>
#include <epac/params/validation.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>
