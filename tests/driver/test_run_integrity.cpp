// What a run leaves behind is honest: a folder holds one run's outputs (another run's are refused
// unless --overwrite, which removes them and nothing else), files are whole under their final
// names, summary.json says whether the run completed, diverged or was interrupted (SIGINT and
// SIGTERM sent to a running epac-run, once or to its process group too, or by coreutils
// `timeout`), the divergence watch stops a run whose time step is far
// too large, and no --threads value crashes.
#include <catch2/catch.hpp>

#include "driver/model_registry.hpp"
#include "driver/outputs.hpp"
#include "driver/scene.hpp"
#include "driver_test_util.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sched.h>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

extern char** environ;

using namespace epac;
using namespace epac::driver;
using namespace epac::test;
namespace fs = std::filesystem;

namespace {

// Two glass spheres (R = 1 mm, E = 1e7 Pa: smallest Rayleigh time 8.6e-5 s) closing at 0.2 m/s
// from a 0.02 mm gap; `dt` and `steps` vary.
std::string pair_scene(double dt, long steps, const std::string& run_extra = "") {
  std::ostringstream s;
  s << R"(
[materials.glass]
youngs_modulus = 1e7
poisson_ratio = 0.25
density = 2500
[[particles.list]]
position = [0, 0, 0]
radius = 0.001
material = "glass"
velocity = [0.1, 0, 0]
[[particles.list]]
position = [0.00202, 0, 0]
radius = 0.001
material = "glass"
velocity = [-0.1, 0, 0]
[run]
dt = )"
    << dt << "\nsteps = " << steps << "\n"
    << run_extra << "\n";
  return s.str();
}
constexpr double kRayleigh = 8.6e-5;  // pi R sqrt(rho/G) / (0.1631 nu + 0.8766) of pair_scene [s]

// 300 beads settling on a floor for a long time: a run to interrupt.
const std::string kLongScene = R"(
gravity = [0, 0, -9.81]
[materials.glass]
youngs_modulus = 1e7
poisson_ratio = 0.25
density = 2500
[materials.wall]
rigid = true
[particles.fill]
box_min = [0, 0, 0]
box_max = [0.02, 0.02, 0.03]
count = 300
radius_min = 0.0009
radius_max = 0.0011
material = "glass"
[[walls]]
point = [0, 0, 0]
normal = [0, 0, 1]
material = "wall"
[run]
dt = 1e-5
steps = 100000000
output_interval = 50
)";

RunOptions options(const fs::path& dir, bool overwrite = false) {
  RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.overwrite = overwrite;
  return o;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json summary_of(const fs::path& dir) { return nlohmann::json::parse(slurp(dir / "summary.json")); }

std::vector<std::string> partial_files(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == kPartialSuffix) found.push_back(e.path().string());
  return found;
}

// Every line of a CSV has the header's number of fields and ends with a newline; returns the
// data rows' first fields (the steps).
std::vector<long> whole_rows(const fs::path& csv) {
  const std::string text = slurp(csv);
  REQUIRE(!text.empty());
  CHECK(text.back() == '\n');
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  const auto fields = std::count(line.begin(), line.end(), ',');
  std::vector<long> steps;
  while (std::getline(in, line)) {
    CHECK(std::count(line.begin(), line.end(), ',') == fields);
    steps.push_back(std::stol(line.substr(0, line.find(','))));
  }
  return steps;
}

// epac-run as a child process (stdout and stderr to files in `dir`).
struct Child {
  pid_t pid = -1;
  fs::path out, err;
};
// `program` with `args`; with `own_group` the child leads a new process group (pgid = pid), as a
// batch scheduler's job or a shell's pipeline does.
Child spawn_program(const std::string& program, const std::vector<std::string>& args, const fs::path& dir,
                    bool own_group = false) {
  fs::create_directories(dir);
  Child c;
  c.out = dir / "stdout.txt";
  c.err = dir / "stderr.txt";
  std::vector<std::string> all = {program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, c.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, c.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  if (own_group) {
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
  }
  const int rc = posix_spawnp(&c.pid, program.c_str(), &fa, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&fa);
  REQUIRE(rc == 0);
  return c;
}
Child spawn_epac_run(const std::vector<std::string>& args, const fs::path& dir, bool own_group = false) {
  return spawn_program(EPAC_RUN_EXE, args, dir, own_group);
}
// Exit status, or 1000 + signal when the child died of a signal; -1 on timeout (then killed).
int wait_for(const Child& c, double timeout_s = 120) {
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(c.pid, &status, WNOHANG) == 0) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout_s) {
      kill(c.pid, SIGKILL);
      waitpid(c.pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}
int run_cli(const std::vector<std::string>& args, const fs::path& dir) { return wait_for(spawn_epac_run(args, dir)); }

fs::path write_scene(const fs::path& dir, const std::string& text) {
  fs::create_directories(dir);
  const fs::path p = dir / "scene.toml";
  std::ofstream(p) << text;
  return p;
}

}  // namespace

TEST_CASE("a folder with another run's outputs is refused, and keeps them", "[driver][outputs][integrity]") {
  const fs::path dir = fresh_out_dir("used");
  run(parse_scene_string(pair_scene(1e-6, 20)), options(dir));
  const std::string before = slurp(dir / "summary.json");
  std::string message;
  try {
    run(parse_scene_string(pair_scene(1e-6, 30)), options(dir));
  } catch (const OutputFolderInUse& e) { message = e.what(); }
  INFO(message);
  CHECK(message.find(dir.string()) != std::string::npos);
  CHECK(message.find("summary.json") != std::string::npos);
  CHECK(message.find("--overwrite") != std::string::npos);
  CHECK(slurp(dir / "summary.json") == before);  // untouched
  CHECK(summary_of(dir)["steps"] == 20);

  SECTION("a .partial file of a killed run counts as an output") {
    const fs::path d2 = fresh_out_dir("partial");
    fs::create_directories(d2);
    std::ofstream(d2 / "timeseries.csv.partial") << "step,time [s]\n0,0";
    CHECK_THROWS_AS(run(parse_scene_string(pair_scene(1e-6, 20)), options(d2)), OutputFolderInUse);
  }
  SECTION("other files do not make a folder used") {
    const fs::path d3 = fresh_out_dir("foreign");
    fs::create_directories(d3);
    std::ofstream(d3 / "notes.txt") << "mine";
    run(parse_scene_string(pair_scene(1e-6, 20)), options(d3));
    CHECK(slurp(d3 / "notes.txt") == "mine");
    CHECK(fs::exists(d3 / "summary.json"));
  }
}

TEST_CASE("option overwrite removes the earlier run's outputs, and only those", "[driver][outputs][integrity]") {
  const fs::path dir = fresh_out_dir("overwrite");
  // first run: contacts, particles and snapshots besides the timeseries
  run(parse_scene_string(
          pair_scene(1e-6, 20, "contact_output = true\nparticle_output = true\nsnapshot_format = \"vtp\"")),
      options(dir));
  REQUIRE(fs::exists(dir / "contacts.csv"));
  REQUIRE(fs::exists(dir / "snapshots"));
  std::ofstream(dir / "notes.txt") << "mine";
  fs::create_directories(dir / "snapshots");
  std::ofstream(dir / "snapshots" / "mine.txt") << "mine too";
  // second run writes only timeseries.csv and summary.json
  run(parse_scene_string(pair_scene(1e-6, 30)), options(dir, true));
  CHECK(summary_of(dir)["steps"] == 30);
  CHECK(summary_of(dir)["status"] == "completed");
  CHECK_FALSE(fs::exists(dir / "contacts.csv"));
  CHECK_FALSE(fs::exists(dir / "particles.csv"));
  CHECK_FALSE(fs::exists(dir / "particles.pvd"));
  CHECK(slurp(dir / "notes.txt") == "mine");
  CHECK(slurp(dir / "snapshots" / "mine.txt") == "mine too");
  for (const auto& e : fs::directory_iterator(dir / "snapshots")) CHECK(e.path().extension() != ".vtp");
  const auto steps = whole_rows(dir / "timeseries.csv");
  CHECK(steps.back() == 30);
}

TEST_CASE("a completed run leaves whole files under their names and status completed", "[driver][outputs][integrity]") {
  const fs::path dir = fresh_out_dir("completed");
  // 200 steps close the 0.02 mm gap at 0.2 m/s after 100: contacts.csv has rows
  run(parse_scene_string(
          pair_scene(1e-6, 200, "contact_output = true\nsnapshot_format = \"vtp\"\noutput_interval = 50")),
      options(dir));
  CHECK(partial_files(dir).empty());
  const auto j = summary_of(dir);
  CHECK(j["status"] == "completed");
  CHECK(j["steps_completed"] == 200);
  CHECK_FALSE(j.contains("status_reason"));
  CHECK(whole_rows(dir / "timeseries.csv") == std::vector<long>{0, 50, 100, 150, 200});
  const auto contact_steps = whole_rows(dir / "contacts.csv");
  REQUIRE_FALSE(contact_steps.empty());
  CHECK(contact_steps.back() == 200);
  CHECK(fs::exists(dir / "snapshots" / "particles_000000000200.vtp"));
}

TEST_CASE("a time step far too large is stopped by the divergence watch", "[driver][divergence][integrity]") {
  SECTION("the same scene with a sane step completes (the watch does not trip)") {
    const fs::path dir = fresh_out_dir("sane");
    const RunSummary s = run(parse_scene_string(pair_scene(0.1 * kRayleigh, 3000)), options(dir));
    CHECK(s.status == "completed");
    CHECK(summary_of(dir)["status"] == "completed");
  }
  SECTION("20 Rayleigh times: the spheres fly apart after one contact step") {
    // One step of overlap 0.17 R gives a Hertz force of about 0.35 N on 1e-5 kg for 1.7e-3 s:
    // 57 m/s, i.e. |v| dt = 97 R. Without the watch this ran to the end with exit 0.
    const fs::path dir = fresh_out_dir("huge_dt");
    std::string message;
    try {
      run(parse_scene_string(pair_scene(20 * kRayleigh, 200)), options(dir));
    } catch (const DivergedError& e) { message = e.what(); }
    INFO(message);
    REQUIRE_FALSE(message.empty());
    const auto j = summary_of(dir);
    CHECK(j["status"] == "diverged");
    const std::string reason = j["status_reason"];
    for (const char* part :
         {"particle ", "global id", "particles.list[", "|v| dt = ", "above the bound 0.5 R", "Rayleigh"})
      CHECK(reason.find(part) != std::string::npos);
    CHECK(message.find(reason) != std::string::npos);
    const long done = j["steps_completed"];
    CHECK(done < 10);  // stopped within a few steps of the first contact, not at step 200
    CHECK(partial_files(dir).empty());
    CHECK(whole_rows(dir / "timeseries.csv").back() <= done);
  }
}

TEST_CASE("the divergence watch names a non-finite particle", "[driver][divergence][integrity]") {
  // A particle launched at 1e4 m/s (the largest speed a scene accepts) with a step that lets it
  // cross its radius 10 times per step: the watch trips at step 0, before anything moves.
  const fs::path dir = fresh_out_dir("fast");
  std::string text = pair_scene(1e-6, 100);
  text.replace(text.find("velocity = [0.1, 0, 0]"), 22, "velocity = [10000, 0, 0]");
  CHECK_THROWS_WITH(run(parse_scene_string(text), options(dir)),
                    Catch::Contains("step 0: particle 0 (global id 0, particles.list[0]): |v| dt = 0.01 m"));
  CHECK(summary_of(dir)["steps_completed"] == 0);
}

// The outputs of a run that a stop request ended: whole files, status interrupted by `sig`.
void check_interrupted_outputs(const fs::path& out, int sig) {
  const auto j = summary_of(out);
  CHECK(j["status"] == "interrupted");
  CHECK(std::string(j["status_reason"]).find(sig == SIGINT ? "SIGINT" : "SIGTERM") != std::string::npos);
  const long done = j["steps_completed"];
  CHECK(done > 0);
  const auto steps = whole_rows(out / "timeseries.csv");
  CHECK(steps.back() == done);  // the stop step writes its row
  CHECK(partial_files(out).empty());
}

// Waits until a run streams timeseries rows (it is stepping); false after 60 s.
bool wait_until_stepping(const fs::path& out) {
  const fs::path partial = out / "timeseries.csv.partial";
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 60) {
    if (fs::exists(partial) && fs::file_size(partial) > 4000) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST_CASE("SIGINT and SIGTERM stop epac-run after a whole step with status interrupted",
          "[driver][signals][integrity]") {
  for (const int sig : {SIGINT, SIGTERM}) {
    SECTION(sig == SIGINT ? "SIGINT" : "SIGTERM") {
      const fs::path dir = fresh_out_dir(sig == SIGINT ? "sigint" : "sigterm");
      const fs::path scene = write_scene(dir, kLongScene);
      const fs::path out = dir / "out";
      Child c = spawn_epac_run({scene.string(), "--out", out.string(), "--threads", "1", "--quiet"}, dir);
      if (!wait_until_stepping(out)) {  // no run to interrupt: end the child, then fail
        kill(c.pid, SIGKILL);
        wait_for(c);
        FAIL("epac-run did not start stepping; stderr: " << slurp(c.err));
      }
      REQUIRE(kill(c.pid, sig) == 0);
      const int rc = wait_for(c);
      INFO("stderr: " << slurp(c.err));
      CHECK(rc == 128 + sig);  // 130 / 143
      CHECK(slurp(c.err).find("interrupted") != std::string::npos);
      check_interrupted_outputs(out, sig);
      CHECK(long(summary_of(out)["steps_completed"]) < 100000000);  // stopped, not run to the end
    }
  }
}

TEST_CASE("one stop request delivered twice (process, then its process group) ends the run cleanly",
          "[driver][signals][integrity]") {
  // What coreutils `timeout` and batch schedulers do: the signal reaches the process and then, a
  // few microseconds later, its whole process group. It is one request, not "end now".
  for (const int sig : {SIGINT, SIGTERM}) {
    SECTION(sig == SIGINT ? "SIGINT twice" : "SIGTERM twice") {
      const fs::path dir = fresh_out_dir(sig == SIGINT ? "sigint_group" : "sigterm_group");
      const fs::path scene = write_scene(dir, kLongScene);
      const fs::path out = dir / "out";
      Child c = spawn_epac_run({scene.string(), "--out", out.string(), "--threads", "1", "--quiet"}, dir, true);
      if (!wait_until_stepping(out)) {
        kill(c.pid, SIGKILL);
        wait_for(c);
        FAIL("epac-run did not start stepping; stderr: " << slurp(c.err));
      }
      REQUIRE(kill(c.pid, sig) == 0);
      REQUIRE(kill(-c.pid, sig) == 0);  // the process group the child leads
      const int rc = wait_for(c);
      INFO("stderr: " << slurp(c.err));
      CHECK(rc == 128 + sig);
      check_interrupted_outputs(out, sig);
    }
  }
}

TEST_CASE("a run under coreutils timeout ends with whole outputs", "[driver][signals][integrity]") {
  for (const int sig : {SIGINT, SIGTERM}) {
    SECTION(sig == SIGINT ? "timeout -s INT" : "timeout -s TERM") {
      const fs::path dir = fresh_out_dir(sig == SIGINT ? "timeout_int" : "timeout_term");
      const fs::path scene = write_scene(dir, kLongScene);
      const fs::path out = dir / "out";
      // 10 s: long enough for the run to be stepping on a loaded 2-core machine, far shorter
      // than kLongScene. timeout itself leads a process group, as it does from a shell.
      Child c = spawn_program("timeout",
                              {"-s", sig == SIGINT ? "INT" : "TERM", "10", EPAC_RUN_EXE, scene.string(), "--out",
                               out.string(), "--threads", "1", "--quiet"},
                              dir, true);
      const int rc = wait_for(c);
      INFO("stderr: " << slurp(c.err));
      CHECK(rc == 124);  // timeout's status when it had to stop the command
      CHECK(slurp(c.err).find("interrupted") != std::string::npos);
      check_interrupted_outputs(out, sig);
    }
  }
}

TEST_CASE("epac-run exit statuses: used folder 2, --overwrite 0, diverged 3", "[driver][cli][integrity]") {
  const fs::path dir = fresh_out_dir("cli");
  const fs::path scene = write_scene(dir, pair_scene(1e-6, 10));
  const fs::path out = dir / "out";
  CHECK(run_cli({scene.string(), "--out", out.string(), "--quiet"}, dir / "a") == 0);
  CHECK(run_cli({scene.string(), "--out", out.string(), "--quiet"}, dir / "b") == 2);
  CHECK(slurp(dir / "b" / "stderr.txt").find("holds outputs of another run") != std::string::npos);
  CHECK(run_cli({scene.string(), "--out", out.string(), "--quiet", "--overwrite"}, dir / "c") == 0);
  const fs::path huge = write_scene(dir / "huge", pair_scene(20 * kRayleigh, 200));
  CHECK(run_cli({huge.string(), "--out", (dir / "out_huge").string(), "--quiet"}, dir / "d") == 3);
  CHECK(slurp(dir / "d" / "stderr.txt").find("diverged") != std::string::npos);
  CHECK(summary_of(dir / "out_huge")["status"] == "diverged");
}

TEST_CASE("option threads above the machine's CPUs is clamped with a warning and does not crash",
          "[driver][cli][threads]") {
  cpu_set_t set;
  REQUIRE(sched_getaffinity(0, sizeof set, &set) == 0);
  const int cpus = CPU_COUNT(&set);
  const fs::path dir = fresh_out_dir("threads");
  const fs::path scene = write_scene(dir, pair_scene(1e-6, 10));
  for (const char* n : {"100000", "600"}) {  // 520-4096 crashed inside Kokkos' thread-data resize
    SECTION(std::string("--threads ") + n) {
      const fs::path out = dir / (std::string("out") + n);
      const int rc = run_cli({scene.string(), "--out", out.string(), "--quiet", "--threads", n}, dir / n);
      const std::string err = slurp(dir / n / "stderr.txt");
      INFO(err);
      CHECK(rc == 0);
      CHECK(err.find(std::string("--threads = ") + n + " is more than") != std::string::npos);
      const int threads = summary_of(out)["threads"];
      CHECK(threads >= 1);
      CHECK(threads <= cpus);
    }
  }
  SECTION("--threads up to the CPUs is honoured with OMP_PROC_BIND set") {
    // libgomp binds the initial thread to its first place before main when OMP_PROC_BIND is set,
    // so the child's own mask holds one CPU: it must still run the threads it was asked for (it
    // ran 1 before epac-run counted CPUs with omp_get_num_procs()).
    const int want = std::min(cpus, 2);
    const char* old_bind = std::getenv("OMP_PROC_BIND");
    const char* old_places = std::getenv("OMP_PLACES");
    const std::string keep_bind = old_bind ? old_bind : "", keep_places = old_places ? old_places : "";
    setenv("OMP_PROC_BIND", "spread", 1);
    setenv("OMP_PLACES", "threads", 1);
    const fs::path out = dir / "out_bound";
    const int rc =
        run_cli({scene.string(), "--out", out.string(), "--quiet", "--threads", std::to_string(want)}, dir / "bound");
    old_bind ? setenv("OMP_PROC_BIND", keep_bind.c_str(), 1) : unsetenv("OMP_PROC_BIND");
    old_places ? setenv("OMP_PLACES", keep_places.c_str(), 1) : unsetenv("OMP_PLACES");
    const std::string err = slurp(dir / "bound" / "stderr.txt");
    INFO(err);
    REQUIRE(rc == 0);
    CHECK(err.find("is more than") == std::string::npos);
    CHECK(static_cast<int>(summary_of(out)["threads"]) == want);
  }
  SECTION("--threads 0 is refused") {
    CHECK(run_cli({scene.string(), "--out", (dir / "out0").string(), "--quiet", "--threads", "0"}, dir / "zero") != 0);
    CHECK_FALSE(fs::exists(dir / "out0"));
  }
}
