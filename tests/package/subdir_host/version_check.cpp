// Prints epac's version seen through add_subdirectory (the generated header is on the target's
// build-interface include path) and the Kokkos it was configured with.
#include <epac/core/build_info.hpp>
#include <epac/version.hpp>

#include <cstdio>

int main() {
  std::printf("%s\n", epac::build_info().c_str());
  return EPAC_VERSION == EPAC_VERSION_NUMBER(epac::version_major, epac::version_minor, epac::version_patch) ? 0 : 1;
}
