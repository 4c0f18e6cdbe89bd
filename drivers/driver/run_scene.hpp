#pragma once
// One run of a scene with one compiled (model, effects, scalar) instance: device state, contact
// detection with a skin, velocity-Verlet steps, outputs (docs/design.md section 4).
#include "driver/box_motion.hpp"
#include "driver/contact_detection.hpp"
#include "driver/contact_sampling.hpp"
#include "driver/diagnostics.hpp"
#include "driver/effect_selection.hpp"
#include "driver/guard_warning.hpp"
#include "driver/initial_history.hpp"
#include "driver/integrator.hpp"
#include "driver/model_factory.hpp"
#include "driver/outputs.hpp"
#include "driver/phase_times.hpp"
#include "driver/run_options.hpp"
#include "driver/scene.hpp"
#include "driver/snapshot_capture.hpp"
#include "driver/snapshot_writer.hpp"
#include "driver/spatial_sort.hpp"
#include "driver/stop_signal.hpp"

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
#include <type_traits>

namespace epac {
namespace driver {

// Device particle state from the scene's particles.
template <class T, class Device>
Particles<T, Device> make_particles(const Scene& s, Kokkos::View<unsigned char*, Device>& driven) {
  const int n = static_cast<int>(s.particles.size());
  Particles<T, Device> p(n);
  driven = Kokkos::View<unsigned char*, Device>("epac::driver::driven", n);
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto w = Kokkos::create_mirror_view(p.omega);
  auto m = Kokkos::create_mirror_view(p.mass);
  auto I = Kokkos::create_mirror_view(p.inertia);
  auto r0 = Kokkos::create_mirror_view(p.radius0);
  auto mat = Kokkos::create_mirror_view(p.material);
  auto gid = Kokkos::create_mirror_view(p.gid);
  auto dr = Kokkos::create_mirror_view(driven);
  for (int i = 0; i < n; ++i) {
    const ParticleSpec& q = s.particles[i];
    const double mass = sphere_mass(s.materials[q.material].density, q.radius);
    for (int d = 0; d < 3; ++d) {
      x(i, d) = T(q.position[d]);
      v(i, d) = T(q.velocity[d]);
      w(i, d) = T(q.angular_velocity[d]);
    }
    m(i) = T(mass);
    I(i) = T(0.4 * mass * q.radius * q.radius);
    r0(i) = T(q.radius);
    mat(i) = q.material;
    gid(i) = i;
    dr(i) = q.driven ? 1 : 0;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.omega, w);
  Kokkos::deep_copy(p.mass, m);
  Kokkos::deep_copy(p.inertia, I);
  Kokkos::deep_copy(p.radius0, r0);
  Kokkos::deep_copy(p.radius, r0);
  Kokkos::deep_copy(p.material, mat);
  Kokkos::deep_copy(p.gid, gid);
  Kokkos::deep_copy(driven, dr);
  return p;
}

// Wall positions are kept on the host in double (exact prescribed displacement, no drift in
// float) and copied to the device after each move; the velocity of a step is its displacement
// over dt, so damping and friction see the mean velocity of the step.
template <class T, class Device>
class WallDriver {
 public:
  WallDriver(const Scene& s, Walls<T, Device>& w) : specs_(s.walls), w_(w) {
    const int nw = static_cast<int>(specs_.size());
    w_ = Walls<T, Device>(nw);
    point_ = Kokkos::create_mirror_view(w_.point);
    vel_ = Kokkos::create_mirror_view(w_.velocity);
    auto nrm = Kokkos::create_mirror_view(w_.normal);
    auto mat = Kokkos::create_mirror_view(w_.material);
    pos_.resize(nw);
    at_build_.resize(nw);
    for (int k = 0; k < nw; ++k) {
      pos_[k] = specs_[k].point;
      for (int d = 0; d < 3; ++d) {
        point_(k, d) = T(pos_[k][d]);
        nrm(k, d) = T(specs_[k].normal[d]);
        vel_(k, d) = T(0);
      }
      mat(k) = specs_[k].material;
    }
    Kokkos::deep_copy(w_.point, point_);
    Kokkos::deep_copy(w_.normal, nrm);
    Kokkos::deep_copy(w_.velocity, vel_);
    Kokkos::deep_copy(w_.material, mat);
  }

  // Moves the walls over [t0, t0 + dt].
  void advance(double t0, double dt) {
    bool changed = false;
    for (std::size_t k = 0; k < specs_.size(); ++k) {
      const Vec3d d = specs_[k].displacement(t0, t0 + dt);
      for (int c = 0; c < 3; ++c) {
        const T vel = T(d[c] / dt);
        if (d[c] != 0.0 || vel_(k, c) != vel) changed = true;
        pos_[k][c] += d[c];
        point_(k, c) = T(pos_[k][c]);
        vel_(k, c) = vel;
      }
    }
    if (changed) {
      Kokkos::deep_copy(w_.point, point_);
      Kokkos::deep_copy(w_.velocity, vel_);
    }
  }

  // Displacement of wall k along its normal since t = 0.
  double normal_displacement(int k) const {
    double s = 0;
    for (int d = 0; d < 3; ++d) s += (pos_[k][d] - specs_[k].point[d]) * specs_[k].normal[d];
    return s;
  }

  // The rebuild rule's wall measure, on the host: max_w |normal displacement since mark_build()|.
  void mark_build() { at_build_ = pos_; }
  double max_shift_since_build() const {
    double m = 0;
    for (std::size_t k = 0; k < pos_.size(); ++k) {
      double s = 0;
      for (int d = 0; d < 3; ++d) s += (pos_[k][d] - at_build_[k][d]) * specs_[k].normal[d];
      m = std::max(m, std::fabs(s));
    }
    return m;
  }

 private:
  const std::vector<WallSpec>& specs_;
  Walls<T, Device>& w_;
  host_mirror_t<typename Walls<T, Device>::vec_view> point_, vel_;
  std::vector<Vec3d> pos_, at_build_;
};

// Driven particles with a motion (piecewise-constant velocity): the velocity of a step is the
// exact displacement of the step over dt (as for walls), written to the device when it changes.
template <class T, class Device>
class DrivenMotion {
 public:
  explicit DrivenMotion(const Scene& s) : specs_(s.particles) {
    for (std::size_t i = 0; i < specs_.size(); ++i)
      if (specs_[i].driven && !specs_[i].motion.empty()) idx_.push_back(static_cast<int>(i));
    const int n = static_cast<int>(idx_.size());
    d_idx_ = Kokkos::View<int*, Device>("epac::driver::moved", n);
    d_vel_ = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>("epac::driver::moved_velocity", n);
    h_vel_ = Kokkos::create_mirror_view(d_vel_);
    auto hi = Kokkos::create_mirror_view(d_idx_);
    for (int k = 0; k < n; ++k) hi(k) = idx_[k];
    Kokkos::deep_copy(d_idx_, hi);
    last_.assign(n, Vec3d{0, 0, 0});
  }
  bool empty() const { return idx_.empty(); }

  // After a spatial sort: the moved particles' device indices follow them (inv: old -> new).
  void reindex(const Kokkos::View<int*, Device>& inv) {
    if (idx_.empty()) return;
    const auto idx = d_idx_;
    Kokkos::parallel_for("epac::driver::driven_reindex",
                         Kokkos::RangePolicy<typename Device::execution_space>(0, static_cast<int>(idx_.size())),
                         KOKKOS_LAMBDA(int k) { idx(k) = inv(idx(k)); });
  }

  // Sets the driven velocities for the step [t0, t0 + dt].
  void advance(const Particles<T, Device>& p, double t0, double dt) {
    if (idx_.empty()) return;
    bool changed = first_;
    first_ = false;
    for (std::size_t k = 0; k < idx_.size(); ++k) {
      const Vec3d d = segments_displacement(specs_[idx_[k]].motion, t0, t0 + dt);
      for (int c = 0; c < 3; ++c) {
        const double v = d[c] / dt;
        if (v != last_[k][c]) changed = true;
        last_[k][c] = v;
        h_vel_(k, c) = T(v);
      }
    }
    if (!changed) return;
    Kokkos::deep_copy(d_vel_, h_vel_);
    const auto idx = d_idx_;
    const auto vel = d_vel_;
    const auto v = p.v;
    Kokkos::parallel_for("epac::driver::driven_motion",
                         Kokkos::RangePolicy<typename Device::execution_space>(0, static_cast<int>(idx_.size())),
                         KOKKOS_LAMBDA(int k) {
                           for (int c = 0; c < 3; ++c) v(idx(k), c) = vel(k, c);
                         });
  }

 private:
  const std::vector<ParticleSpec>& specs_;
  std::vector<int> idx_;
  Kokkos::View<int*, Device> d_idx_;
  Kokkos::View<T* [3], Kokkos::LayoutLeft, Device> d_vel_;
  typename Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>::HostMirror h_vel_;
  std::vector<Vec3d> last_;
  bool first_ = true;
};

template <template <class, unsigned, class> class Factory, class T, unsigned Bits>
RunSummary run_scene(const Scene& scene, const RunOptions& opt) {
  using Device = DefaultDevice;
  using exec = typename Device::execution_space;
  using F = Factory<T, Bits, Device>;
  using Model = typename F::model_type;
  using clock = std::chrono::steady_clock;
  static_assert(Model::effects::bits == Bits, "the factory must build the model with the dispatched effects");

  const auto setup_start = clock::now();
  Model model = F::create(scene);  // host validation: throws before anything is written

  RunSummary sum;
  sum.scene = scene.source;
  sum.model = scene.model.name;
  sum.effects = effect_names(Bits);
  sum.scalar = std::is_same<T, float>::value ? "float" : "double";
  sum.backend = exec::name();
  sum.threads = exec().concurrency();
  sum.particles = static_cast<std::int64_t>(scene.particles.size());
  sum.walls = static_cast<std::int64_t>(scene.walls.size());
  sum.steps = opt.steps >= 0 ? opt.steps : scene.run.steps;
  sum.dt = scene.run.dt;
  sum.history_fields = F::pair_history_fields;
  sum.bytes_per_contact = bytes_per_contact(F::pair_history_fields, sizeof(T));

  prepare_output_dir(opt.out_dir, opt.overwrite);  // refuses another run's outputs (or removes them)
  sum.timeseries_path = opt.out_dir + "/timeseries.csv";
  sum.summary_path = opt.out_dir + "/summary.json";

  const bool info = !opt.quiet;
  if (info) {
    std::printf("epac-run: %s: %lld particles, %lld walls, %zu materials\n", scene.source.c_str(),
                static_cast<long long>(sum.particles), static_cast<long long>(sum.walls), scene.materials.size());
    std::printf("model %s, scalar %s, backend %s, %d threads\n", sum.model.c_str(), sum.scalar.c_str(),
                sum.backend.c_str(), sum.threads);
    std::printf("effects: %s (%s)\n", sum.effects.c_str(),
                scene.model.effects_overridden ? "set in [model] effects" : "derived from the materials");
    for (const auto& note : scene.model.notes) std::printf("note: %s\n", note.c_str());
    std::printf("storage: pairs %s; walls %s\n", bytes_per_contact_text(F::pair_history_fields, sizeof(T)).c_str(),
                bytes_per_contact_text(F::wall_history_fields, sizeof(T)).c_str());
    std::printf("dt = %g s (%.3g of the smallest Rayleigh time), %lld steps, skin %g m, output every %lld steps\n",
                scene.run.dt, scene.run.dt / rayleigh_time(scene), static_cast<long long>(sum.steps),
                scene.run.skin, static_cast<long long>(scene.run.output_interval));
    std::fflush(stdout);
  }
  // dt / T_R matters for Hertz-type laws acting on integrated particles (not for linear_spring,
  // whose stiffness is its own, nor for a scene of driven particles only).
  const bool all_driven = std::all_of(scene.particles.begin(), scene.particles.end(),
                                      [](const ParticleSpec& q) { return q.driven; });
  const double dt_ratio =
      scene.model.name == "linear_spring" || all_driven ? 0.0 : scene.run.dt / rayleigh_time(scene);
  if (dt_ratio > 1.0)  // a warning, not only information: printed with --quiet too
    std::fprintf(stderr, "epac-run: warning: run.dt = %g s is %.3g smallest Rayleigh times (explicit DEM needs about "
                 "0.1-0.3); the divergence watch stops the run if particles start to fly apart\n",
                 scene.run.dt, dt_ratio);

  Kokkos::View<unsigned char*, Device> driven;
  Particles<T, Device> p = make_particles<T, Device>(scene, driven);
  F::bind(model, p);
  const bool any_driven = scene.any_driven();
  Walls<T, Device> walls;
  WallDriver<T, Device> wall_driver(scene, walls);
  validate(p, walls, model);  // host: material indices, radii, ids, unit normals (params/state_validation.hpp)
  DrivenMotion<T, Device> driven_motion(scene);
  const Vec3<T> g(T(scene.gravity[0]), T(scene.gravity[1]), T(scene.gravity[2]));
  const T dt = T(scene.run.dt);
  const T half_dt = T(0.5 * scene.run.dt);
  const int nw = walls.n;
  BoxMotion<T, Device> box(scene.box);
  box.apply(p);  // the host wrapped the positions into the box (finish_scene)

  ContactDetector<T, Device> det(T(scene.run.skin), F::pair_history_fields, F::wall_history_fields);
  // [run] spatial_sort: every per-particle array follows the cell order at each rebuild.
  typename ContactDetector<T, Device>::sort_callback on_sort;
  if (scene.run.spatial_sort)
    on_sort = [&](const Kokkos::View<int*, Device>& perm) {
      const Permuter<T, Device> permute(perm);
      permute.particles(p);
      permute(driven);
      F::reorder(model, permute);
      driven_motion.reindex(permute.inverse());
    };
  det.detect(p, walls, &on_sort);
  det.remap(p);
  // [run] initial_history: contacts overlapping at step 0 start from a quasi-static load
  if (start_history(scene, model, p, walls, det, sum, info)) {
    det.detect(p, walls, &on_sort);  // the load grew radii past the skin rule
    det.remap(p);
  }
  wall_driver.mark_build();
  // Deterministic mode ([run] deterministic, --deterministic): per-contact buffers summed per
  // particle in key order (compute/deterministic_pass.hpp); its incidences follow every rebuild.
  const bool deterministic = opt.deterministic || scene.run.deterministic;
  DeterministicPass<T, Device> det_pass;
  if (deterministic) det_pass.rebuild(p, det.pairs, det.walls);
  if (info && deterministic) std::printf("deterministic mode: the same bits on any thread count\n");
  // One accumulator for all passes (its per-thread copies are allocated once); rebound if the
  // particle views are ever reallocated.
  ForceSums<T, Device> sums(p);
  PhaseTimer phases(opt.phase_times);

  ContactOutputs<T, Device> pair_out, wall_out;
  auto size_outputs = [&]() {
    auto fit = [](ContactOutputs<T, Device>& o, int count, const char* label) {
      if (static_cast<int>(o.overlap.extent(0)) >= count) return;
      const int cap = count + count / 4 + 16;
      o.normal_force = Kokkos::View<T*, Device>(std::string(label) + ".normal_force", cap);
      o.overlap = Kokkos::View<T*, Device>(std::string(label) + ".overlap", cap);
    };
    fit(pair_out, det.pairs.count, "pair_out");
    fit(wall_out, det.walls.count, "wall_out");
  };
  std::vector<std::string> wall_names;
  for (const auto& w : scene.walls) wall_names.push_back(w.name);
  std::unique_ptr<ContactsWriter> contacts_csv;
  std::unique_ptr<ParticlesWriter> particles_csv;
  if (scene.run.contact_output)
    contacts_csv = std::make_unique<ContactsWriter>(opt.out_dir + "/contacts.csv", F::contact_extra_names(), wall_names);
  if (scene.run.particle_output) particles_csv = std::make_unique<ParticlesWriter>(opt.out_dir + "/particles.csv");
  std::unique_ptr<SnapshotWriter> snapshots;  // [run] snapshot_format = "vtp": particles.pvd + snapshots/*.vtp
  if (scene.run.snapshot_format == "vtp") snapshots = std::make_unique<SnapshotWriter>(opt.out_dir);

  // Forces are zeroed by kick_drift (and are zero on allocation before the first pass).
  // `step`: the step whose forces these are (for contacts.csv).
  // Phases (--phase-times): force (hooks, both lists, sums.end()), output (contacts.csv),
  // growth (after_forces).
  auto force_pass = [&](T step_dt, bool with_outputs, std::int64_t step) {
    F::before_forces(model, p, step_dt);
    if (with_outputs) size_outputs();
    if (!sums.bound_to(p)) sums = ForceSums<T, Device>(p);
    const ContactOutputs<T, Device> none{};
    if (deterministic) det_pass.begin(model);
    else sums.begin();
    compute_pair_forces(model, p, det.pairs, det.pair_history, step_dt, sums, with_outputs ? pair_out : none,
                        det_pass.pair_buffer);
    if (nw > 0)
      compute_wall_forces(model, p, walls, det.walls, det.wall_history, step_dt, sums, with_outputs ? wall_out : none,
                          det_pass.wall_buffer);
    if (deterministic) det_pass.end(model, p);
    else sums.end();
    phases.lap(Phase::force);
    if (with_outputs && contacts_csv) {  // before after_forces: the geometry the force pass saw
      contacts_csv->write(step, step * scene.run.dt,
                          collect_contacts<F>(model, p, walls, det.pairs, det.pair_history, det.walls,
                                              det.wall_history, pair_out, wall_out));
      phases.lap(Phase::output);
    }
    F::after_forces(model, p, step_dt);
    phases.lap(Phase::growth);
  };
  auto write_particles = [&](std::int64_t step) {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.x);
    auto R = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.radius);
    auto R0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.radius0);
    const auto vol = F::template particle_volume<T, Device>(model);
    auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), vol);
    auto gid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.gid);
    const int n = p.n;
    std::vector<double> xs(n), ys(n), zs(n), Rs(n), R0s(n), Vs(n);
    for (int i = 0; i < n; ++i) {  // rows in global-id order (the arrays may be spatially sorted)
      const std::size_t k = static_cast<std::size_t>(gid(i));
      xs[k] = x(i, 0); ys[k] = x(i, 1); zs[k] = x(i, 2);
      Rs[k] = R(i); R0s[k] = R0(i);
      Vs[k] = static_cast<int>(V.extent(0)) == n ? double(V(i)) : 4.0 / 3.0 * M_PI * Rs[k] * Rs[k] * Rs[k];
    }
    particles_csv->write(step, step * scene.run.dt, xs, ys, zs, Rs, R0s, Vs);
  };

  TimeseriesWriter csv(sum.timeseries_path, [&] {
    std::vector<std::string> names;
    for (const auto& w : scene.walls) names.push_back(w.name);
    return names;
  }(), any_driven, scene.box.enabled);
  double active_sum = 0;
  std::int64_t samples = 0;
  double window_active_sum = 0, window_list_steps = 0;  // --time-after window
  std::int64_t window_samples = 0;
  auto write_sample = [&](std::int64_t step) {
    Sample s;
    s.step = step;
    s.time = step * scene.run.dt;
    sample_state(p, driven, any_driven, g, det.pairs, det.walls, pair_out, wall_out, nw, s);
    s.wall_displacement.resize(nw);
    for (int k = 0; k < nw; ++k) s.wall_displacement[k] = wall_driver.normal_displacement(k);
    for (int d = 0; d < 3; ++d) s.box_edge[d] = box.edge()[d];
    csv.write(s);
    if (particles_csv) write_particles(step);
    if (snapshots) snapshots->write(capture_snapshot<F>(model, p, step, s.time));
    active_sum += static_cast<double>(s.pair_contacts + s.wall_contacts);
    ++samples;
    if (opt.time_after >= 0 && step > opt.time_after) {
      window_active_sum += static_cast<double>(s.pair_contacts + s.wall_contacts);
      ++window_samples;
    }
  };

  // Divergence watch (diagnostics.hpp), at step 0, before every rebuild (a non-finite or runaway
  // particle forces one) and at every output step: sets the status; the loop then stops.
  auto diverged = [&](std::int64_t step) {
    const std::string why = divergence_check(p, driven, scene.run.dt, scene);
    if (why.empty()) return false;
    sum.status = "diverged";
    char where[160];
    std::snprintf(where, sizeof where, "step %lld: ", static_cast<long long>(step));
    sum.status_reason = where + why;
    if (dt_ratio > 0.3) {
      std::snprintf(where, sizeof where, "; run.dt is %.3g smallest Rayleigh times: reduce it", dt_ratio);
      sum.status_reason += where;
    }
    return true;
  };

  // First force pass with dt = 0: forces for the opening half kick; no tangential increment.
  force_pass(T(0), true, 0);
  write_sample(0);
  diverged(0);
  Kokkos::fence();
  sum.setup_time_s = std::chrono::duration<double>(clock::now() - setup_start).count();

  const std::int64_t steps = sum.steps;
  const std::int64_t every = scene.run.output_interval;
  ProgressLine progress(opt.progress && !opt.quiet, steps);
  double list_steps = 0;
  const std::int64_t builds0 = det.builds;
  const auto loop_start = clock::now();
  phases.start();
  bool full_step_velocities = true;  // v is at a whole step (after a closing half kick)
  auto window_start = loop_start;
  std::int64_t done = 0;  // steps completed (their forces and outputs written)
  for (std::int64_t step = 1; step <= steps && sum.status == "completed"; ++step) {
    if (step == opt.time_after + 1) {
      Kokkos::fence();
      window_start = clock::now();
    }
    driven_motion.advance(p, (step - 1) * scene.run.dt, scene.run.dt);
    // [box.deform] remap x, before the drift: the rebuild measure below sees it as displacement
    box.deform_to(p, step);
    // closing half kick of the previous step (if deferred) + opening half kick + drift
    const T shift = kick_drift(p, driven, g, full_step_velocities ? half_dt : dt, dt, det.reference_positions(),
                               det.reference_radii());
    wall_driver.advance((step - 1) * scene.run.dt, scene.run.dt);
    phases.lap(Phase::integration);
    if (det.needs_rebuild(shift, T(wall_driver.max_shift_since_build()))) {
      if (diverged(step)) break;  // before the cell list meets a non-finite coordinate
      box.wrap(p);  // then detect() records the wrapped positions as the reference: a wrap is no motion
      det.detect(p, walls, &on_sort);
      wall_driver.mark_build();
      phases.lap(Phase::detection);
      det.remap(p);
      if (deterministic) det_pass.rebuild(p, det.pairs, det.walls);
      phases.lap(Phase::remap);
    }
    // SIGINT/SIGTERM: this step is the last; it writes its sample like the final step.
    const int signal = stop_signal();
    const bool output = step % every == 0 || step == steps || signal != 0;
    force_pass(dt, output, step);
    full_step_velocities = output;
    if (output) {
      half_kick(p, driven, g, half_dt);  // closing half kick now: samples need whole-step velocities
      phases.lap(Phase::integration);
      write_sample(step);
    }
    done = step;
    if (output && diverged(step)) break;
    if (signal != 0) {
      sum.status = "interrupted";
      sum.stop_signal = signal;
      sum.status_reason = std::string(signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "signal") +
                          " after step " + std::to_string(step);
    }
    list_steps += det.pairs.count + det.walls.count;
    if (opt.time_after >= 0 && step > opt.time_after) window_list_steps += det.pairs.count + det.walls.count;
    progress.update(step, list_steps);
    phases.lap(Phase::output);
  }
  Kokkos::fence();
  const auto loop_end = clock::now();
  sum.wall_time_s = std::chrono::duration<double>(loop_end - loop_start).count();
  sum.steps_completed = done;
  if (opt.time_after >= 0 && opt.time_after < done) {
    sum.timed.enabled = true;
    sum.timed.first_step = opt.time_after + 1;
    sum.timed.steps = done - opt.time_after;
    sum.timed.wall_s = std::chrono::duration<double>(loop_end - window_start).count();
    sum.timed.list_contacts_mean = window_list_steps / static_cast<double>(sum.timed.steps);
    sum.timed.active_contacts_mean = window_samples > 0 ? window_active_sum / window_samples : 0.0;
  }
  progress.finish();

  sum.rebuilds = det.builds - builds0;
  sum.simulated_time = done * scene.run.dt;
  sum.contacts_mean = samples > 0 ? active_sum / samples : 0.0;
  sum.contact_list_mean = done > 0 ? list_steps / done : static_cast<double>(det.pairs.count + det.walls.count);
  if (sum.wall_time_s > 0) {
    sum.contact_steps_per_second = list_steps / sum.wall_time_s;
    sum.active_contact_steps_per_second = sum.contacts_mean * done / sum.wall_time_s;
    sum.particle_steps_per_second = static_cast<double>(sum.particles) * static_cast<double>(done) / sum.wall_time_s;
  }
  if (phases.enabled()) sum.phases = phases.results();
  if (scene.box.enabled) sum.box_edge.assign(box.edge().begin(), box.edge().end());
  F::report(model, sum);
  warn_on_guard_hits(sum);
  // Every file gets its final name, whole rows only; summary.json last: its presence says the
  // folder holds one run's complete outputs, its status whether the run completed.
  csv.commit();
  if (contacts_csv) contacts_csv->commit();
  if (particles_csv) particles_csv->commit();
  write_summary_json(sum.summary_path, sum);
  if (sum.status == "diverged")
    throw DivergedError("the simulation diverged at " + sum.status_reason + " (outputs up to step " +
                        std::to_string(done) + " and summary.json with status \"diverged\" in " + opt.out_dir + ")");
  if (info) {
    for (const auto& kv : sum.model_counters) std::printf("%s = %.10g\n", kv.first.c_str(), kv.second);
    std::printf("%lld steps in %.3f s (setup %.3f s): %.3g contact-steps/s (list entries), %.1f contacts (mean, "
                "active), %lld rebuilds\n",
                static_cast<long long>(done), sum.wall_time_s, sum.setup_time_s, sum.contact_steps_per_second,
                sum.contacts_mean, static_cast<long long>(sum.rebuilds));
    if (phases.enabled()) {
      std::printf("phases [s]:");
      for (const auto& kv : sum.phases) std::printf(" %s %.3f", kv.first.c_str(), kv.second);
      std::printf("\n");
    }
    std::printf("wrote %s and %s\n", sum.timeseries_path.c_str(), sum.summary_path.c_str());
  }
  return sum;
}

}  // namespace driver
}  // namespace epac
