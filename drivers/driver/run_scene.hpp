#pragma once
// One run of a scene with one compiled (model, effects, scalar) instance: device state, contact
// detection with a skin, velocity-Verlet steps, outputs (docs/design.md section 4).
#include "driver/box_motion.hpp"
#include "driver/contact_detection.hpp"
#include "driver/contact_sampling.hpp"
#include "driver/diagnostics.hpp"
#include "driver/driven_motion.hpp"
#include "driver/effect_selection.hpp"
#include "driver/guard_warning.hpp"
#include "driver/initial_history.hpp"
#include "driver/integrator.hpp"
#include "driver/model_factory.hpp"
#include "driver/outputs.hpp"
#include "driver/particle_state.hpp"
#include "driver/phase_times.hpp"
#include "driver/run_options.hpp"
#include "driver/run_stats.hpp"
#include "driver/scene.hpp"
#include "driver/snapshot_capture.hpp"
#include "driver/snapshot_writer.hpp"
#include "driver/spatial_sort.hpp"
#include "driver/stop_signal.hpp"
#include "driver/wall_driver.hpp"

#include <epac/compute/contact_forces.hpp>
#include <epac/compute/deterministic_pass.hpp>
#include <epac/compute/particle_sums.hpp>
#include <epac/params/state_validation.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace epac {
namespace driver {

// One run: run() calls the phases in the order of the step. The members are what the phases
// share; the run is built once and run once.
template <template <class, unsigned, class> class Factory, class T, unsigned Bits>
class SceneRun {
 public:
  using Device = DefaultDevice;
  using F = Factory<T, Bits, Device>;
  using Model = typename F::model_type;
  static_assert(Model::effects::bits == Bits, "the factory must build the model with the dispatched effects");

  // The model's host validation throws here, before anything is written.
  SceneRun(const Scene& scene, const RunOptions& opt)
      : scene_(scene),
        opt_(opt),
        setup_start_(clock::now()),
        model_(F::create(scene)),
        g_(T(scene.gravity[0]), T(scene.gravity[1]), T(scene.gravity[2])),
        dt_(T(scene.run.dt)),
        half_dt_(T(0.5 * scene.run.dt)),
        box_(scene.box),
        det_(T(scene.run.skin), F::pair_history_fields, F::wall_history_fields),
        phases_(opt.phase_times) {}
  SceneRun(const SceneRun&) = delete;  // the sort callback and the wall driver point into it
  SceneRun& operator=(const SceneRun&) = delete;

  RunSummary run() {
    describe();
    build_state();
    build_contacts();
    open_outputs();
    first_pass();
    step_loop();
    finish();
    return sum_;
  }

 private:
  using exec = typename Device::execution_space;
  using clock = std::chrono::steady_clock;

  // The summary's description of the run, the output folder, the opening lines.
  void describe() {
    sum_.scene = scene_.source;
    sum_.model = scene_.model.name;
    sum_.effects = effect_names(Bits);
    sum_.scalar = std::is_same<T, float>::value ? "float" : "double";
    sum_.backend = exec::name();
    sum_.threads = exec().concurrency();
    sum_.particles = static_cast<std::int64_t>(scene_.particles.size());
    sum_.walls = static_cast<std::int64_t>(scene_.walls.size());
    sum_.steps = opt_.steps >= 0 ? opt_.steps : scene_.run.steps;
    sum_.dt = scene_.run.dt;
    sum_.history_fields = F::pair_history_fields;
    sum_.bytes_per_contact = bytes_per_contact(F::pair_history_fields, sizeof(T));

    prepare_output_dir(opt_.out_dir, opt_.overwrite);  // refuses another run's outputs (or removes them)
    sum_.timeseries_path = opt_.out_dir + "/timeseries.csv";
    sum_.summary_path = opt_.out_dir + "/summary.json";

    info_ = !opt_.quiet;
    if (info_) print_description();
    check_time_step();
  }

  void print_description() const {
    std::printf("epac-run: %s: %lld particles, %lld walls, %zu materials\n", scene_.source.c_str(),
                static_cast<long long>(sum_.particles), static_cast<long long>(sum_.walls), scene_.materials.size());
    std::printf("model %s, scalar %s, backend %s, %d threads\n", sum_.model.c_str(), sum_.scalar.c_str(),
                sum_.backend.c_str(), sum_.threads);
    std::printf("effects: %s (%s)\n", sum_.effects.c_str(),
                scene_.model.effects_overridden ? "set in [model] effects" : "derived from the materials");
    for (const auto& note : scene_.model.notes) std::printf("note: %s\n", note.c_str());
    std::printf("storage: pairs %s; walls %s\n", bytes_per_contact_text(F::pair_history_fields, sizeof(T)).c_str(),
                bytes_per_contact_text(F::wall_history_fields, sizeof(T)).c_str());
    std::printf("dt = %g s (%.3g of the smallest Rayleigh time), %lld steps, skin %g m, output every %lld steps\n",
                scene_.run.dt, scene_.run.dt / rayleigh_time(scene_), static_cast<long long>(sum_.steps),
                scene_.run.skin, static_cast<long long>(scene_.run.output_interval));
    std::fflush(stdout);
  }

  // dt / T_R matters for Hertz-type laws acting on integrated particles (not for linear_spring,
  // whose stiffness is its own, nor for a scene of driven particles only).
  void check_time_step() {
    const bool all_driven =
        std::all_of(scene_.particles.begin(), scene_.particles.end(), [](const ParticleSpec& q) { return q.driven; });
    dt_ratio_ = scene_.model.name == "linear_spring" || all_driven ? 0.0 : scene_.run.dt / rayleigh_time(scene_);
    if (dt_ratio_ > 1.0)  // a warning, not only information: printed with --quiet too
      std::fprintf(stderr,
                   "epac-run: warning: run.dt = %g s is %.3g smallest Rayleigh times (explicit DEM needs "
                   "about 0.1-0.3); the divergence watch stops the run if particles start to fly apart\n",
                   scene_.run.dt, dt_ratio_);
  }

  // Particles, walls and their motions, and the periodic box on the device.
  void build_state() {
    p_ = make_particles<T, Device>(scene_, driven_);
    F::bind(model_, p_);
    any_driven_ = scene_.any_driven();
    wall_driver_.emplace(scene_, walls_);
    validate(p_, walls_, model_);  // host: material indices, radii, ids, unit normals (params/state_validation.hpp)
    driven_motion_.emplace(scene_);
    nw_ = walls_.n;
    box_.apply(p_);  // the host wrapped the positions into the box (finish_scene)
  }

  // The first contact lists, the initial history, and the force pass's accumulators.
  void build_contacts() {
    on_sort_ = [this](const Kokkos::View<int*, Device>& perm) { sort_particles(perm); };
    detect(0);
    det_.remap(p_);
    // [run] initial_history: contacts overlapping at step 0 start from a quasi-static load
    if (start_history(scene_, model_, p_, walls_, det_, sum_, info_)) {
      detect(0);  // the load grew radii past the skin rule
      det_.remap(p_);
    }
    wall_driver_->mark_build();
    // Deterministic mode ([run] deterministic, --deterministic): per-contact buffers summed per
    // particle in key order (compute/deterministic_pass.hpp); its incidences follow every rebuild.
    deterministic_ = opt_.deterministic || scene_.run.deterministic;
    if (deterministic_) det_pass_.rebuild(p_, det_.pairs, det_.walls);
    if (info_ && deterministic_) std::printf("deterministic mode: the same bits on any thread count\n");
    // Per-thread sums (host backends) set the forces at the end of a pass, so kick_drift need not
    // zero them (a write of 48 B per particle and step); atomic and plain sums and the
    // deterministic pass add into them.
    overwrite_forces_ = sums_are_duplicated<Device, typename ForceSums<T, Device>::policy>() && !deterministic_;
    // One accumulator for all passes (its per-thread copies are allocated once); rebound if the
    // particle views are ever reallocated.
    sums_ = ForceSums<T, Device>(p_);
  }

  // The lists at `step` ([run] spatial_sort decides whether the detection reorders the particles).
  // auto: a scene of at least kAutoSortMinParticles particles is sorted at its first build, at
  // the first rebuild sort_interval steps after the last sort, and at a rebuild whose cell grid
  // has other dimensions than at the last sort (a deforming box, a spreading bed: the order no
  // longer follows the cells, and the pair search pays for it).
  void detect(std::int64_t step) {
    using Sort = RunSpec::Sort;
    using When = typename ContactDetector<T, Device>::SortWhen;
    const Sort mode = scene_.run.spatial_sort;
    const typename ContactDetector<T, Device>::sort_callback* sort = nullptr;
    When when = When::now;
    if (mode == Sort::always) sort = &on_sort_;
    if (mode == Sort::automatic && p_.n >= kAutoSortMinParticles) {
      sort = &on_sort_;
      if (last_sort_step_ >= 0 && step - last_sort_step_ < scene_.run.sort_interval) when = When::if_grid_changed;
    }
    if (det_.detect(p_, walls_, sort, when)) {
      last_sort_step_ = step;
      ++sorts_;
    }
    edge_at_build_ = box_.edge();
  }

  // Every per-particle array follows the cell order (a sorting detection).
  void sort_particles(const Kokkos::View<int*, Device>& perm) {
    const Permuter<T, Device> permute(perm);
    permute.particles(p_);
    permute(driven_);
    F::reorder(model_, permute);
    driven_motion_->reindex(permute.inverse());
  }

  // Every output file opens under its .partial name; each gets its final name in finish().
  void open_outputs() {
    std::vector<std::string> wall_names;
    for (const auto& w : scene_.walls) wall_names.push_back(w.name);
    if (scene_.run.contact_output)
      contacts_csv_ =
          std::make_unique<ContactsWriter>(opt_.out_dir + "/contacts.csv", F::contact_extra_names(), wall_names);
    if (scene_.run.particle_output) particles_csv_ = std::make_unique<ParticlesWriter>(opt_.out_dir + "/particles.csv");
    // [run] snapshot_format = "vtp": particles.pvd + snapshots/*.vtp
    if (scene_.run.snapshot_format == "vtp") snapshots_ = std::make_unique<SnapshotWriter>(opt_.out_dir);
    csv_ = std::make_unique<TimeseriesWriter>(sum_.timeseries_path, wall_names, any_driven_, scene_.box.enabled);
  }

  // The force pass of step 0 with dt = 0 (forces for the opening half kick; no tangential
  // increment), its sample and divergence check: the end of the setup.
  void first_pass() {
    force_pass(T(0), true, 0);
    sample(0);
    diverged(0);
    Kokkos::fence();
    sum_.setup_time_s = std::chrono::duration<double>(clock::now() - setup_start_).count();
  }

  // Forces are zeroed by kick_drift or overwritten by sums_.end (overwrite_forces_), and are zero
  // on allocation before the first pass.
  // `step`: the step whose forces these are (for contacts.csv).
  // Phases (--phase-times): force (hooks, both lists, sums.end()), output (contacts.csv),
  // growth (after_forces).
  void force_pass(T step_dt, bool with_outputs, std::int64_t step) {
    F::before_forces(model_, p_, walls_, det_, step_dt);
    if (with_outputs) size_outputs();
    if (!sums_.bound_to(p_)) sums_ = ForceSums<T, Device>(p_);
    const ContactOutputs<T, Device> none{};
    if (deterministic_)
      det_pass_.begin(model_);
    else
      sums_.begin(overwrite_forces_);
    compute_pair_forces(model_, p_, det_.pairs, det_.pair_history, step_dt, sums_, with_outputs ? pair_out_ : none,
                        det_pass_.pair_buffer);
    if (nw_ > 0)
      compute_wall_forces(model_, p_, walls_, det_.walls, det_.wall_history, step_dt, sums_,
                          with_outputs ? wall_out_ : none, det_pass_.wall_buffer);
    if (deterministic_)
      det_pass_.end(model_, p_);
    else
      sums_.end(overwrite_forces_);
    phases_.lap(Phase::force);
    if (with_outputs && contacts_csv_) {  // before after_forces: the geometry the force pass saw
      contacts_csv_->write(step, step * scene_.run.dt,
                           collect_contacts<F>(model_, p_, walls_, det_.pairs, det_.pair_history, det_.walls,
                                               det_.wall_history, pair_out_, wall_out_));
      phases_.lap(Phase::output);
    }
    F::after_forces(model_, p_, step_dt);
    phases_.lap(Phase::growth);
  }

  // Room for the per-contact outputs of a sampled force pass (25% headroom on growth).
  void size_outputs() {
    auto fit = [](ContactOutputs<T, Device>& o, int count, const char* label) {
      if (static_cast<int>(o.overlap.extent(0)) >= count) return;
      const int cap = count + count / 4 + 16;
      o.normal_force = Kokkos::View<T*, Device>(std::string(label) + ".normal_force", cap);
      o.overlap = Kokkos::View<T*, Device>(std::string(label) + ".overlap", cap);
    };
    fit(pair_out_, det_.pairs.count, "pair_out");
    fit(wall_out_, det_.walls.count, "wall_out");
  }

  // One sample: a timeseries.csv row, particles.csv rows, a snapshot.
  void sample(std::int64_t step) {
    Sample s;
    s.step = step;
    s.time = step * scene_.run.dt;
    sample_state(p_, driven_, any_driven_, g_, det_.pairs, det_.walls, pair_out_, wall_out_, nw_, s);
    s.wall_displacement.resize(nw_);
    for (int k = 0; k < nw_; ++k) s.wall_displacement[k] = wall_driver_->normal_displacement(k);
    for (int d = 0; d < 3; ++d) s.box_edge[d] = box_.edge()[d];
    csv_->write(s);
    if (particles_csv_) write_particles(step);
    if (snapshots_) snapshots_->write(capture_snapshot<F>(model_, p_, step, s.time));
    stats_.add_sample(s.pair_contacts + s.wall_contacts, in_window(step));
  }

  void write_particles(std::int64_t step) {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.x);
    auto R = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.radius);
    auto R0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.radius0);
    const auto vol = F::template particle_volume<T, Device>(model_);
    auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), vol);
    auto gid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.gid);
    const int n = p_.n;
    std::vector<double> xs(n), ys(n), zs(n), Rs(n), R0s(n), Vs(n);
    for (int i = 0; i < n; ++i) {  // rows in global-id order (the arrays may be spatially sorted)
      const std::size_t k = static_cast<std::size_t>(gid(i));
      xs[k] = x(i, 0);
      ys[k] = x(i, 1);
      zs[k] = x(i, 2);
      Rs[k] = R(i);
      R0s[k] = R0(i);
      Vs[k] = static_cast<int>(V.extent(0)) == n ? double(V(i)) : 4.0 / 3.0 * M_PI * Rs[k] * Rs[k] * Rs[k];
    }
    particles_csv_->write(step, step * scene_.run.dt, xs, ys, zs, Rs, R0s, Vs);
  }

  // Divergence watch (diagnostics.hpp), at step 0, before every rebuild (a non-finite or runaway
  // particle forces one) and at every output step: sets the status; the loop then stops.
  bool diverged(std::int64_t step) {
    const std::string why = divergence_check(p_, driven_, scene_.run.dt, scene_);
    if (why.empty()) return false;
    sum_.status = "diverged";
    char where[160];
    std::snprintf(where, sizeof where, "step %lld: ", static_cast<long long>(step));
    sum_.status_reason = where + why;
    if (dt_ratio_ > 0.3) {
      std::snprintf(where, sizeof where, "; run.dt is %.3g smallest Rayleigh times: reduce it", dt_ratio_);
      sum_.status_reason += where;
    }
    return true;
  }

  // The steps, until the last, a divergence or a stop signal.
  void step_loop() {
    const std::int64_t steps = sum_.steps;
    const std::int64_t every = scene_.run.output_interval;
    ProgressLine progress(opt_.progress && !opt_.quiet, steps);
    stats_.builds0 = det_.builds;
    loop_start_ = clock::now();
    phases_.start();
    window_start_ = loop_start_;
    for (std::int64_t step = 1; step <= steps && sum_.status == "completed"; ++step) {
      if (step == opt_.time_after + 1) {
        Kokkos::fence();
        phases_.mark_window(Phase::output);  // the window's own phase seconds (summary "timed")
        window_start_ = clock::now();
      }
      const T shift = advance(step);
      if (det_.needs_rebuild(shift, T(wall_driver_->max_shift_since_build()), lambda_since_build_)) {
        if (diverged(step)) break;  // before the cell list meets a non-finite coordinate
        rebuild_contacts(step);
      }
      // SIGINT/SIGTERM: this step is the last; it writes its sample like the final step.
      const int signal = stop_signal();
      const bool output = step % every == 0 || step == steps || signal != 0;
      force_pass(dt_, output, step);
      full_step_velocities_ = output;
      if (output) close_step(step);
      stats_.done = step;
      if (output && diverged(step)) break;
      if (signal != 0) interrupt(signal, step);
      stats_.add_step(det_.pairs.count + det_.walls.count, in_window(step));
      progress.update(step, stats_.list_steps);
      phases_.lap(Phase::output);
    }
    Kokkos::fence();
    loop_end_ = clock::now();
    progress.finish();
  }

  // Driven velocities, box deformation, kicks, drift and wall motion of `step`; returns the
  // particles' shift for the rebuild rule.
  T advance(std::int64_t step) {
    driven_motion_->advance(p_, (step - 1) * scene_.run.dt, scene_.run.dt);
    // [box.deform] remap x, before the drift (in kick_drift's pass)
    const auto remap = box_.deform_to(p_, step);
    // The rebuild rule counts only the motion beyond the deformation since the last build
    // (ContactDetector::shift_allowance): in an isotropic compression the lists then last until
    // the compression, not each particle's affine drift, uses up the skin. Walls too: the scene
    // deforms only periodic axes and a wall's normal has no component along one (both validated,
    // scene.cpp), so the deformation leaves every particle's distance to every wall unchanged,
    // and a wall contact missing from the list stays at least R + skin - s - w away (s: the shift
    // beyond the deformation, at most the allowance <= skin/2; w: the wall's, <= skin/2).
    const auto since = box_.map_since(edge_at_build_);
    lambda_since_build_ = 1.0;
    if (since.active)
      for (int d = 0; d < 3; ++d) lambda_since_build_ = std::min(lambda_since_build_, double(since.ratio[d]));
    // closing half kick of the previous step (if deferred) + opening half kick + drift
    // the drift in double with the scene's dt (positions are double, state/particles.hpp)
    const T shift = kick_drift(p_, driven_, g_, full_step_velocities_ ? half_dt_ : dt_, scene_.run.dt,
                               det_.reference_positions(), det_.reference_radii(), remap, since, !overwrite_forces_);
    wall_driver_->advance((step - 1) * scene_.run.dt, scene_.run.dt);
    phases_.lap(Phase::integration);
    return shift;
  }

  // The skin is used up: new lists, their history, the deterministic incidences.
  void rebuild_contacts(std::int64_t step) {
    box_.wrap(p_);  // then detect() records the wrapped positions as the reference: a wrap is no motion
    detect(step);
    wall_driver_->mark_build();
    phases_.lap(Phase::detection);
    det_.remap(p_);
    if (deterministic_) det_pass_.rebuild(p_, det_.pairs, det_.walls);
    phases_.lap(Phase::remap);
  }

  // An output step: the closing half kick now (samples need whole-step velocities), the sample.
  void close_step(std::int64_t step) {
    half_kick(p_, driven_, g_, half_dt_);
    phases_.lap(Phase::integration);
    sample(step);
  }

  void interrupt(int signal, std::int64_t step) {
    sum_.status = "interrupted";
    sum_.stop_signal = signal;
    sum_.status_reason = std::string(signal == SIGINT    ? "SIGINT"
                                     : signal == SIGTERM ? "SIGTERM"
                                                         : "signal") +
                         " after step " + std::to_string(step);
  }

  // The step is in the --time-after window.
  bool in_window(std::int64_t step) const { return opt_.time_after >= 0 && step > opt_.time_after; }

  // The summary, the outputs under their final names, the closing lines.
  void finish() {
    summarize();
    F::report(model_, sum_);
    warn_on_guard_hits(sum_);
    // Every file gets its final name, whole rows only; summary.json last: its presence says the
    // folder holds one run's complete outputs, its status whether the run completed.
    csv_->commit();
    if (contacts_csv_) contacts_csv_->commit();
    if (particles_csv_) particles_csv_->commit();
    write_summary_json(sum_.summary_path, sum_);
    if (sum_.status == "diverged")
      throw DivergedError("the simulation diverged at " + sum_.status_reason + " (outputs up to step " +
                          std::to_string(stats_.done) + " and summary.json with status \"diverged\" in " +
                          opt_.out_dir + ")");
    if (info_) print_results();
  }

  // Timings, means and rates of the loop (and of the --time-after window).
  void summarize() {
    const std::int64_t done = stats_.done;
    sum_.wall_time_s = std::chrono::duration<double>(loop_end_ - loop_start_).count();
    sum_.steps_completed = done;
    if (opt_.time_after >= 0 && opt_.time_after < done) {
      sum_.timed.enabled = true;
      sum_.timed.first_step = opt_.time_after + 1;
      sum_.timed.steps = done - opt_.time_after;
      sum_.timed.wall_s = std::chrono::duration<double>(loop_end_ - window_start_).count();
      sum_.timed.list_contacts_mean = stats_.window_list_steps / static_cast<double>(sum_.timed.steps);
      sum_.timed.active_contacts_mean =
          stats_.window_samples > 0 ? stats_.window_active_sum / stats_.window_samples : 0.0;
      sum_.timed.phases = phases_.window_results();
    }
    sum_.rebuilds = det_.builds - stats_.builds0;
    sum_.sorts = sorts_;
    sum_.simulated_time = done * scene_.run.dt;
    sum_.contacts_mean = stats_.samples > 0 ? stats_.active_sum / stats_.samples : 0.0;
    sum_.contact_list_mean =
        done > 0 ? stats_.list_steps / done : static_cast<double>(det_.pairs.count + det_.walls.count);
    if (sum_.wall_time_s > 0) {
      sum_.contact_steps_per_second = stats_.list_steps / sum_.wall_time_s;
      sum_.active_contact_steps_per_second = sum_.contacts_mean * done / sum_.wall_time_s;
      sum_.particle_steps_per_second =
          static_cast<double>(sum_.particles) * static_cast<double>(done) / sum_.wall_time_s;
    }
    if (phases_.enabled()) sum_.phases = phases_.results();
    if (scene_.box.enabled) sum_.box_edge.assign(box_.edge().begin(), box_.edge().end());
  }

  void print_results() const {
    for (const auto& kv : sum_.model_counters) std::printf("%s = %.10g\n", kv.first.c_str(), kv.second);
    std::printf(
        "%lld steps in %.3f s (setup %.3f s): %.3g contact-steps/s (list entries), %.1f contacts (mean, "
        "active), %lld rebuilds, %lld spatial sorts\n",
        static_cast<long long>(stats_.done), sum_.wall_time_s, sum_.setup_time_s, sum_.contact_steps_per_second,
        sum_.contacts_mean, static_cast<long long>(sum_.rebuilds), static_cast<long long>(sum_.sorts));
    if (phases_.enabled()) {
      std::printf("phases [s]:");
      for (const auto& kv : sum_.phases) std::printf(" %s %.3f", kv.first.c_str(), kv.second);
      std::printf("\n");
    }
    std::printf("wrote %s and %s\n", sum_.timeseries_path.c_str(), sum_.summary_path.c_str());
  }

  const Scene& scene_;
  const RunOptions& opt_;
  const clock::time_point setup_start_;
  Model model_;
  RunSummary sum_;
  bool info_ = false;    // informational lines (not --quiet)
  double dt_ratio_ = 0;  // run.dt / smallest Rayleigh time; 0 where it does not apply
  // device state (build_state)
  Kokkos::View<unsigned char*, Device> driven_;
  Particles<T, Device> p_;
  bool any_driven_ = false;
  Walls<T, Device> walls_;
  std::optional<WallDriver<T, Device>> wall_driver_;
  std::optional<DrivenMotion<T, Device>> driven_motion_;
  const Vec3<T> g_;
  const T dt_, half_dt_;
  int nw_ = 0;
  BoxMotion<T, Device> box_;
  std::array<double, 3> edge_at_build_{0, 0, 0};  // the box at the last build (the rebuild rule)
  double lambda_since_build_ = 1.0;               // the least edge ratio since then
  // contacts and forces (build_contacts)
  ContactDetector<T, Device> det_;
  typename ContactDetector<T, Device>::sort_callback on_sort_;
  std::int64_t last_sort_step_ = -1;  // [run] spatial_sort = "auto"
  std::int64_t sorts_ = 0;            // detections that reordered the particles (setup included)
  bool deterministic_ = false;
  bool overwrite_forces_ = false;  // sums_.end sets the forces: kick_drift does not zero them
  DeterministicPass<T, Device> det_pass_;
  ForceSums<T, Device> sums_;
  PhaseTimer phases_;
  // outputs (open_outputs)
  ContactOutputs<T, Device> pair_out_, wall_out_;
  std::unique_ptr<ContactsWriter> contacts_csv_;
  std::unique_ptr<ParticlesWriter> particles_csv_;
  std::unique_ptr<SnapshotWriter> snapshots_;
  std::unique_ptr<TimeseriesWriter> csv_;
  // the loop
  RunStats stats_;
  bool full_step_velocities_ = true;  // v is at a whole step (after a closing half kick)
  clock::time_point loop_start_{}, window_start_{}, loop_end_{};
};

template <template <class, unsigned, class> class Factory, class T, unsigned Bits>
RunSummary run_scene(const Scene& scene, const RunOptions& opt) {
  return SceneRun<Factory, T, Bits>(scene, opt).run();
}

}  // namespace driver
}  // namespace epac
