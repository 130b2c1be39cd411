/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: errors that one rank finds.

   error->one's message is lost when the abort comes before the output is
   flushed (LAMMPS 29Sep2021 with exceptions: an empty log.lammps), and a
   rank other than 0 never writes log.lammps. So a check that runs on each
   rank is followed by this collective call: the message of the lowest rank
   that has one is sent to all and raised with error->all, which reaches
   the log and the screen on any rank count.
------------------------------------------------------------------------- */

#ifndef LMP_PD_ERROR_H
#define LMP_PD_ERROR_H

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include <mpi.h>
#include <string>

namespace LAMMPS_NS {

// All ranks call it; 'mine' is empty where this rank found nothing.
inline void pd_error_collective(LAMMPS *lmp, const std::string &mine)
{
  const int nprocs = lmp->comm->nprocs;
  int who = mine.empty() ? nprocs : lmp->comm->me, first;
  MPI_Allreduce(&who, &first, 1, MPI_INT, MPI_MIN, lmp->world);
  if (first == nprocs) return;
  std::string msg = mine;
  int len = msg.size();
  MPI_Bcast(&len, 1, MPI_INT, first, lmp->world);
  msg.resize(len);
  MPI_Bcast(&msg[0], len, MPI_CHAR, first, lmp->world);
  lmp->error->all(FLERR, msg);
}

}    // namespace LAMMPS_NS

#endif
