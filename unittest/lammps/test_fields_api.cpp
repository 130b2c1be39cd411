/* The declared per-atom fields of fix pd/bonds through their C++ API, with
 * a field as wide as the tensors of a correspondence material (width 9),
 * on the ranks it is started with (mpirun -np 2): forward to ghosts,
 * reverse sum and max onto owners, migration with atoms that drift across
 * the processor boundary, a restart file (the field comes back by name,
 * before anyone declares it again), and compute pd/atom's 9 columns.
 * Each value is a function of the atom's ID and the column, so every check
 * is exact. Prints PASS/FAIL lines (rank 0) and exits 1 on a failure. */

#include "atom.h"
#include "comm.h"
#include "fix_pd_bonds.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"
#include "pd_compat.h"
#include "utils.h"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

constexpr int WIDTH = 9;
const PDField TENSOR = {"test_tensor", WIDTH,
                        PDField::FORWARD | PDField::MIGRATE | PDField::RESTART | PDField::OUTPUT};
int failures = 0;

double value(tagint tag, int w)
{
  return 1000.0 * (double) tag + w + 0.25;
}

// a check that holds on every rank
void check(const char *what, bool mine, const std::string &detail = "")
{
  int ok = mine ? 1 : 0, all = 0, me = 0;
  MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (!all) failures++;
  if (me == 0) printf("%s %s%s\n", all ? "PASS" : "FAIL", what, detail.empty() ? "" : ("  (" + detail + ")").c_str());
}

LAMMPS *start()
{
  const char *args[] = {"test_fields_api", "-log", "none", "-screen", "none", "-nocite"};
  return new LAMMPS(6, (char **) args, MPI_COMM_WORLD);
}

FixPDBonds *store(LAMMPS *lmp)
{
  return dynamic_cast<FixPDBonds *>(PDCompat::fix_by_id(lmp->modify, "PD_BONDS"));
}

// every owned (and, with ghosts, every ghost) atom holds value(tag, w)
bool holds_values(LAMMPS *lmp, const double *f, bool ghosts)
{
  const int n = lmp->atom->nlocal + (ghosts ? lmp->atom->nghost : 0);
  for (int i = 0; i < n; i++)
    for (int w = 0; w < WIDTH; w++)
      if (f[i * WIDTH + w] != value(lmp->atom->tag[i], w)) return false;
  return true;
}

// the rank + 1 owning each atom ID (0: none)
std::vector<int> owners(LAMMPS *lmp)
{
  std::vector<int> mine((size_t) lmp->atom->natoms + 1, 0), all(mine.size());
  for (int i = 0; i < lmp->atom->nlocal; i++) mine[lmp->atom->tag[i]] = lmp->comm->me + 1;
  MPI_Allreduce(mine.data(), all.data(), (int) mine.size(), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return all;
}

const char *DECK = R"(units si
boundary p p p
atom_style peri
atom_modify map array
lattice sc 0.0005
region box block 0 8 0 8 0 8
create_box 1 box
create_atoms 1 box
set group all density 2200
set group all volume 1.25e-10
neighbor 1e-4 bin
pair_style pd/bond
pair_coeff * * pmb K 14.9e9 horizon 0.0015001
velocity all set 0.0 0.0 40.0 units box
fix 1 all nve
timestep 1.0e-7
run 0
)";

}    // namespace

// Declaring the field with another width is an ERROR that names it: the
// refusal ends the run (error->all exits where LAMMPS is built without
// exceptions, as this package builds 29Sep2021), so it runs on its own and
// ctest reads its message. 'again': after a restart ("in the restart
// file"); else in the same run ("as first declared").
int refusal(const std::string &restart_file, bool again)
{
  const char *args[] = {"test_fields_api", "-log", "none", "-nocite"};
  LAMMPS *lmp = new LAMMPS(4, (char **) args, MPI_COMM_WORLD);
  lammps_commands_string(lmp, DECK);
  store(lmp)->add_field(TENSOR);
  if (again) {
    lmp->input->one("write_restart " + restart_file);
    delete lmp;
    lmp = new LAMMPS(4, (char **) args, MPI_COMM_WORLD);
    lmp->input->one("read_restart " + restart_file);
    lmp->input->one("fix PD_BONDS all pd/bonds weights history 0");
  }
  try {
    store(lmp)->add_field({"test_tensor", 6, TENSOR.flags});
  } catch (std::exception &e) {    // LAMMPS with exceptions: the message is here
    printf("ERROR: %s\n", e.what());
    return 0;
  }
  printf("NOT REFUSED: a width-6 declaration of a width-9 field was accepted\n");
  return 1;
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  if (argc > 2) {
    const int rc = refusal(argv[1], std::string(argv[2]) == "refuse-after-restart");
    MPI_Finalize();
    return rc;
  }
  const std::string restart_file = argc > 1 ? argv[1] : "fields_api.restart";
  LAMMPS *lmp = start();
  lammps_commands_string(lmp, DECK);
  FixPDBonds *bonds = store(lmp);
  check("the pair style created the bond store", bonds != nullptr);
  if (!bonds) MPI_Abort(MPI_COMM_WORLD, 1);

  const int id = bonds->add_field(TENSOR);
  check("declaring a field again returns the same field", bonds->add_field(TENSOR) == id);
  double *f = bonds->field(id);
  for (int i = 0; i < lmp->atom->nlocal; i++)
    for (int w = 0; w < WIDTH; w++) f[i * WIDTH + w] = value(lmp->atom->tag[i], w);

  // the next run sizes the communication for 9 values per atom; its set-up
  // re-sorts and exchanges atoms, which the field follows
  lmp->input->one("run 0");
  f = bonds->field(id);
  check("the owners' values follow their atoms through the set-up of a run", holds_values(lmp, f, false));
  bonds->forward(id);
  check("forward: every ghost holds its owner's 9 values", holds_values(lmp, f, true),
        fmt::format("{} ghosts on rank 0", lmp->atom->nghost));

  // reverse sum: each ghost adds (w + 1); an owner then holds (w + 1) x the
  // number of its ghost images on all ranks, counted here independently
  const int nlocal = lmp->atom->nlocal, nall = nlocal + lmp->atom->nghost;
  std::vector<int> mine((size_t) lmp->atom->natoms + 1, 0), images(mine.size());
  for (int i = nlocal; i < nall; i++) mine[lmp->atom->tag[i]]++;
  MPI_Allreduce(mine.data(), images.data(), (int) mine.size(), MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < nall; i++)
    for (int w = 0; w < WIDTH; w++) f[i * WIDTH + w] = i < nlocal ? 0.0 : w + 1.0;
  bonds->sum_to_owners(id);
  bool summed = true;
  int with_images = 0;
  for (int i = 0; i < nlocal; i++) {
    with_images += images[lmp->atom->tag[i]] > 0;
    for (int w = 0; w < WIDTH; w++) summed = summed && f[i * WIDTH + w] == (w + 1.0) * images[lmp->atom->tag[i]];
  }
  check("reverse sum: each owner holds the sum over its ghost images, in all 9 columns", summed && with_images > 0,
        fmt::format("{} of {} atoms on rank 0 have ghost images", with_images, nlocal));
  // reverse max: ghosts carry their owner's value, owners start below it
  for (int i = 0; i < nall; i++)
    for (int w = 0; w < WIDTH; w++) f[i * WIDTH + w] = i < nlocal ? -1.0 : value(lmp->atom->tag[i], w);
  bonds->max_to_owners(id);
  bool maxed = true;
  for (int i = 0; i < nlocal; i++)
    for (int w = 0; w < WIDTH; w++)
      maxed = maxed && f[i * WIDTH + w] == (images[lmp->atom->tag[i]] ? value(lmp->atom->tag[i], w) : -1.0);
  check("reverse max: each owner with ghost images takes their max", maxed);

  // migration: the block drifts along z, across the boundary of the two
  // processors and the periodic boundary, for 1.6 particle spacings
  for (int i = 0; i < nlocal; i++)
    for (int w = 0; w < WIDTH; w++) f[i * WIDTH + w] = value(lmp->atom->tag[i], w);
  const std::vector<int> before = owners(lmp);
  lmp->input->one("run 200");
  const std::vector<int> after = owners(lmp);
  int moved = 0;
  for (size_t t = 1; t < before.size(); t++) moved += before[t] != after[t];
  check("atoms changed processor", lmp->comm->nprocs == 1 || moved > 0, fmt::format("{} atoms", moved));
  check("migration: every atom keeps its 9 values", holds_values(lmp, bonds->field(id), false));

  // compute pd/atom: 9 columns of the field, then a width-1 field
  lmp->input->one("compute t all pd/atom test_tensor dissipated");
  lmp->input->one("run 0");
  auto **cols = (double **) lammps_extract_compute(lmp, "t", LMP_STYLE_ATOM, LMP_TYPE_ARRAY);
  bool output = cols != nullptr;
  for (int i = 0; output && i < lmp->atom->nlocal; i++) {
    for (int w = 0; w < WIDTH; w++) output = output && cols[i][w] == value(lmp->atom->tag[i], w);
    output = output && cols[i][WIDTH] == bonds->dissipated_atom()[i];
  }
  check("compute pd/atom gives the 9 columns of the field and then the next field", output);
  lmp->input->one("write_restart " + restart_file);
  delete lmp;

  // a new simulation from the file: the field comes back by name when the
  // store is re-created (here by hand, as pd/bond with partial volumes
  // creates it at its init), before anyone declares it again; its owner
  // declares it before the run, as a fix does at its init (a field still
  // unclaimed at the run's set-up is an ERROR)
  lmp = start();
  lmp->input->one("read_restart " + restart_file);
  lmp->input->one("fix PD_BONDS all pd/bonds weights history 0");
  bonds = store(lmp);
  const int back = bonds ? bonds->find_field("test_tensor") : -1;
  check("after read_restart the field is back, by name, with its width",
        back >= 0 && bonds->field_info(back).width == WIDTH);
  if (back >= 0) {
    check("declaring it as written returns it", bonds->add_field(TENSOR) == back);
    lmp->input->one("neighbor 1e-4 bin");
    lmp->input->one("fix 1 all nve");
    lmp->input->one("run 0");
    check("with every atom's 9 values", holds_values(lmp, bonds->field(back), false));
  }
  delete lmp;

  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) printf("%d failed\n", failures);
  MPI_Finalize();
  return failures ? 1 : 0;
}
