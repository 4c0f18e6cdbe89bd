# epac_relocatable_rpath(<target>...): the installed executable looks for shared libraries
# (Kokkos's, when Kokkos is a shared build) next to itself, in <prefix>/lib, and then where the
# system looks (ld.so.conf, LD_LIBRARY_PATH); it carries no path of the build machine, so the
# install can move. The build-tree executable keeps its full build RPATH.
function(epac_relocatable_rpath)
  foreach(_t ${ARGN})
    set_target_properties(${_t} PROPERTIES
      INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}"
      INSTALL_RPATH_USE_LINK_PATH FALSE)
  endforeach()
endfunction()
