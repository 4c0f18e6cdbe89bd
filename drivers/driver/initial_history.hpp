#pragma once
// The history a run starts with ([run] initial_history): a scene whose contacts overlap at step 0
// (a packing made elsewhere) gets the history of a quasi-static load to those overlaps
// (epac::history_from_overlaps), unless the scene asks for a fresh one ("zero"). Without it, MDR
// with radius growth takes the whole overlap as one plastic increment and the radii run away.
#include "driver/contact_detection.hpp"
#include "driver/run_options.hpp"
#include "driver/scene.hpp"

#include <epac/compute/history_from_overlaps.hpp>

#include <cstdio>

namespace epac {
namespace driver {

// Call after the first detection and remap, before the first force pass. Returns true when the
// load grew radii past the contact detector's rule (the caller then rebuilds the lists, so the
// first pass sees every contact that growth closed).
template <class Model, class T, class Device>
bool start_history(const Scene& scene, const Model& model, const Particles<T, Device>& p, const Walls<T, Device>& w,
                   ContactDetector<T, Device>& det, RunSummary& sum, bool info) {
  InitialHistorySummary& ih = sum.initial_history;
  ih.mode = scene.run.initial_history;
  const OverlapCensus census = overlap_census(p, det.pairs, w, det.walls);
  ih.overlapping_contacts = census.contacts();
  ih.max_overlap_ratio = census.max_overlap_ratio;
  if (census.contacts() == 0) {
    ih.mode = "zero";  // nothing overlaps: a fresh history is the loaded one
    return false;
  }
  if (scene.run.initial_history == "zero") {
    if (info)
      std::printf(
          "initial history: zero (run.initial_history): %d contacts start overlapping (%d pairs, %d walls), "
          "largest overlap %.3g R, with fresh history\n",
          census.contacts(), census.pair_contacts, census.wall_contacts, census.max_overlap_ratio);
    return false;
  }
  const HistoryFromOverlapsReport rep =
      history_from_overlaps(model, p, det.pairs, det.pair_history, w, det.walls, det.wall_history);
  if (rep.increments == 0) {  // a law without contact history: its contacts start as they are
    if (info)
      std::printf(
          "initial history: %d contacts start overlapping (%d pairs, %d walls), largest overlap %.3g R; "
          "model %s keeps no contact history, so nothing is loaded\n",
          census.contacts(), census.pair_contacts, census.wall_contacts, census.max_overlap_ratio, Model::name);
    return false;
  }
  ih.applied = true;
  ih.increments = rep.increments;
  ih.max_radius_ratio = rep.max_radius_ratio;
  ih.guard_hits = rep.guard_hits;
  if (info) {
    std::printf(
        "initial history: from overlaps: %d contacts (%d pairs, %d walls), largest overlap %.3g R, "
        "quasi-static load in %d increments",
        census.contacts(), census.pair_contacts, census.wall_contacts, census.max_overlap_ratio, rep.increments);
    if (rep.max_radius_ratio > 1.0) std::printf("; largest R/R_o %.4g", rep.max_radius_ratio);
    if (rep.guard_hits > 0) std::printf("; growth guards acted %lld times", rep.guard_hits);
    std::printf("\n");
    std::fflush(stdout);
  }
  return rep.max_radius_ratio > 1.0 && det.needs_rebuild(p, w);
}

}  // namespace driver
}  // namespace epac
