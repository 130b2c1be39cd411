/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: errors that one rank finds.

   error->one's message is lost when the abort comes before the output is
   flushed (LAMMPS 29Sep2021 with exceptions: an empty log.lammps), and a
   rank other than 0 never writes log.lammps. So a check that runs on each
   rank is followed by this collective call: the message of the lowest rank
   that has one is sent to all and raised with error->all, which reaches
   the log and the screen on any rank count.

   error->all alone does not guarantee that either: rank 0 writes the
   message to the log's buffer and throws, and LAMMPS's main() flushes it
   only in exit(). On 2 or more ranks mpirun kills rank 0 as soon as
   another rank has exited with status 1, sometimes before that flush, and
   log.lammps ends empty (29Sep2021, 2Aug2023, 19Nov2024 alike: about 1 run
   in 40 on a loaded machine). pd_error_all flushes on the way out, before
   rank 0 reaches the barrier in main() that the other ranks wait at.
------------------------------------------------------------------------- */

#ifndef LMP_PD_ERROR_H
#define LMP_PD_ERROR_H

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include <cstdio>
#include <mpi.h>
#include <string>

namespace LAMMPS_NS {

// error->all(file, line, msg), with the screen and the log flushed as the
// error leaves (see above).
[[noreturn]] inline void pd_error_all(LAMMPS *lmp, const std::string &file, int line,
                                      const std::string &msg)
{
  try {
    lmp->error->all(file, line, msg);
  } catch (...) {
    if (lmp->screen) fflush(lmp->screen);
    if (lmp->logfile) fflush(lmp->logfile);
    throw;
  }
}

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
  pd_error_all(lmp, FLERR, msg);
}

}    // namespace LAMMPS_NS

#endif
