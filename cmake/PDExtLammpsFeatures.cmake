# Which LAMMPS API a source tree offers, read off its headers rather than
# its version number (the compat wrappers in src/PERIDYNAMICS_EXT/pd_compat.h
# switch on these definitions). Each entry: header, pattern, definition.
set(PDEXT_FEATURE_TESTS
  "comm.h"     "forward_comm_fix"               PDEXT_COMM_FIX_NAMED
  "neighbor.h" "add_request\\("                 PDEXT_NEIGH_ADD_REQUEST
  "domain.h"   "minimum_image\\(const (std::string ?&|char ?\\*)" PDEXT_MINIMUM_IMAGE_FLERR
  "modify.h"   "get_fix_by_id"                  PDEXT_GET_FIX_BY_ID
  "output.h"   "reset_dt\\("                     PDEXT_OUTPUT_RESET_DT)

function(pdext_lammps_features lammps_src out_var)
  set(found "")
  set(tests ${PDEXT_FEATURE_TESTS})
  while(tests)
    list(POP_FRONT tests header pattern definition)
    file(READ ${lammps_src}/src/${header} text)
    if(text MATCHES "${pattern}")
      list(APPEND found ${definition})
    endif()
  endwhile()
  file(STRINGS ${lammps_src}/src/version.h version REGEX "LAMMPS_VERSION")
  message(STATUS "PERIDYNAMICS_EXT: ${version}; API features: ${found}")
  set(${out_var} ${found} PARENT_SCOPE)
endfunction()
