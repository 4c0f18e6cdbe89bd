#pragma once
// What a binary was built with: epac's version, Kokkos's version and the Kokkos backends compiled
// in (host side; for --version lines, logs and run summaries).
#include <epac/version.hpp>

#include <Kokkos_Core.hpp>

#include <string>

namespace epac {

// "3.4.1" from KOKKOS_VERSION (major * 10000 + minor * 100 + patch).
inline std::string kokkos_version_string() {  // host
  const int v = KOKKOS_VERSION;
  return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." + std::to_string(v % 100);
}

// The enabled backends, space separated, host first: e.g. "Serial OpenMP" or "Serial OpenMP Cuda".
inline std::string kokkos_backends() {  // host
  std::string s;
  auto add = [&s](const char* name) { s += (s.empty() ? "" : " ") + std::string(name); };
#ifdef KOKKOS_ENABLE_SERIAL
  add("Serial");
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  add("OpenMP");
#endif
#ifdef KOKKOS_ENABLE_THREADS
  add("Threads");
#endif
#ifdef KOKKOS_ENABLE_HPX
  add("HPX");
#endif
#ifdef KOKKOS_ENABLE_CUDA
  add("Cuda");
#endif
#ifdef KOKKOS_ENABLE_HIP
  add("HIP");
#endif
#ifdef KOKKOS_ENABLE_SYCL
  add("SYCL");
#endif
#ifdef KOKKOS_ENABLE_OPENMPTARGET
  add("OpenMPTarget");
#endif
  return s;
}

// One line: "epac 0.1.0 (Kokkos 3.4.1: Serial OpenMP)".
inline std::string build_info() {  // host
  return std::string("epac ") + version_string + " (Kokkos " + kokkos_version_string() + ": " + kokkos_backends() + ")";
}

}  // namespace epac
