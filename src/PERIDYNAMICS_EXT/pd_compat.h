/* The LAMMPS calls whose names or signatures changed between releases, in
 * one place. Written against 29 Sep 2021; later releases renamed the comm
 * entry points (forward_comm(Fix *, int) ...) and the neighbor request API
 * (add_request(this, NeighConst::REQ_FULL | REQ_OCCASIONAL)). */
#ifndef LMP_PD_COMPAT_H
#define LMP_PD_COMPAT_H

#include "comm.h"
#include "neigh_request.h"
#include "neighbor.h"

namespace LAMMPS_NS {
namespace PDCompat {

  inline void forward_comm(Comm *comm, class Fix *fix, int size) { comm->forward_comm_fix(fix, size); }
  inline void reverse_comm(Comm *comm, class Fix *fix, int size) { comm->reverse_comm_fix(fix, size); }

  /* A full neighbor list for a fix, built only on demand. */
  inline void request_occasional_full(Neighbor *neighbor, class Fix *fix, int instance)
  {
    int irequest = neighbor->request(fix, instance);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->occasional = 1;
  }

  /* A half list for a pair style, built with its own cutoff. */
  inline void request_pair_with_cutoff(Neighbor *neighbor, class Pair *pair, int instance, double cutoff)
  {
    int irequest = neighbor->request(pair, instance);
    neighbor->requests[irequest]->cut = 1;
    neighbor->requests[irequest]->cutoff = cutoff;
  }

}    // namespace PDCompat
}    // namespace LAMMPS_NS

#endif
