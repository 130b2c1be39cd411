/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/fragments [min_atoms N] [bins N]
                     [range lo hi | range auto]
   Fragments are the connected components of the graph of intact bonds
   between atoms of the group (contact does not join). The graph logic is
   in core/pd_fragments.c; here: the labels' exchange between owners and
   ghosts until they settle, and the gathering of each fragment's pieces at
   one rank (the rank 'ID modulo ranks': no rank holds all fragments).
   Per atom: the fragment's ID, its smallest atom ID. Global vector: counts
   and masses; global array: the cumulative mass distribution.
------------------------------------------------------------------------- */

#include "compute_pd_fragments.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "memory.h"
#include "pd_compat.h"
#include "pd_modify_lookup.h"
#include "update.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;

static constexpr int NVALUES = 7;
static constexpr int MAX_BINS = 100000;

ComputePDFragments::ComputePDFragments(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), bonds(nullptr), min_atoms(2), nbins(20), auto_range(true), range_lo(0.0),
    range_hi(0.0), nmax(0), root(nullptr), slot(nullptr), label(nullptr), fragment_id(nullptr),
    mass(nullptr), reverse_lowered(0), labels_step(-1), totals_step(-1)
{
  parse(narg, arg);
  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 0;    // counts and masses of the whole group: never divided by the atom count
  array_flag = 1;
  size_array_rows = nbins;
  size_array_cols = 3;
  extarray = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
  comm_forward = 1;
  comm_reverse = 1;
  vector = new double[NVALUES]();
  memory->create(array, nbins, 3, "pd/fragments:array");
  for (int k = 0; k < nbins; k++) array[k][0] = array[k][1] = array[k][2] = 0.0;
}

ComputePDFragments::~ComputePDFragments()
{
  delete[] vector;
  memory->destroy(array);
  memory->destroy(root);
  memory->destroy(slot);
  memory->destroy(label);
  memory->destroy(fragment_id);
  memory->destroy(mass);
}

// Whole-word numbers only: utils::numeric's messages do not name the keyword.
static bool read_integer(const char *text, long long &value)
{
  char *end = nullptr;
  errno = 0;
  value = strtoll(text, &end, 10);
  return end != text && *end == '\0' && errno == 0;
}

static bool read_number(const char *text, double &value)
{
  char *end = nullptr;
  value = strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

void ComputePDFragments::parse(int narg, char **arg)
{
  for (int iarg = 3; iarg < narg;) {
    const char *key = arg[iarg];
    const int need = strcmp(key, "range") == 0 && iarg + 1 < narg && strcmp(arg[iarg + 1], "auto") != 0 ? 2 : 1;
    if (strcmp(key, "min_atoms") != 0 && strcmp(key, "bins") != 0 && strcmp(key, "range") != 0)
      error->all(FLERR, "Compute pd/fragments: unknown keyword '{}' (min_atoms, bins, range)", key);
    if (iarg + need >= narg)
      error->all(FLERR, "Compute pd/fragments: '{}' needs {}", key,
                 strcmp(key, "range") == 0 ? "two masses lo hi, or 'auto'" : "a value");
    long long n = 0;
    if (strcmp(key, "min_atoms") == 0) {
      if (!read_integer(arg[iarg + 1], n) || n < 1)
        error->all(FLERR, "Compute pd/fragments: min_atoms must be an integer >= 1 (the fewest atoms a "
                   "counted fragment has), got '{}'", arg[iarg + 1]);
      min_atoms = n;
    } else if (strcmp(key, "bins") == 0) {
      if (!read_integer(arg[iarg + 1], n) || n < 1 || n > MAX_BINS)
        error->all(FLERR, "Compute pd/fragments: bins must be an integer from 1 to {}, got '{}'", MAX_BINS,
                   arg[iarg + 1]);
      nbins = (int) n;
    } else if (need == 1) {
      auto_range = true;
    } else {
      double lo, hi;
      if (!read_number(arg[iarg + 1], lo) || !(lo > 0.0))
        error->all(FLERR, "Compute pd/fragments: range lo must be a finite mass > 0 (log-spaced bins), got "
                   "'{}'", arg[iarg + 1]);
      if (!read_number(arg[iarg + 2], hi) || !(hi > lo))
        error->all(FLERR, "Compute pd/fragments: range hi must be a finite mass > lo = {}, got '{}'", lo,
                   arg[iarg + 2]);
      auto_range = false;
      range_lo = lo;
      range_hi = hi;
    }
    iarg += need + 1;
  }
}

void ComputePDFragments::init()
{
  bonds = find_bond_store(lmp, "Compute pd/fragments");
  if (!atom->rmass_flag || !atom->vfrac_flag)
    error->all(FLERR, "Compute pd/fragments needs per-atom density and volume (atom_style peri)");
}

void ComputePDFragments::grow()
{
  if (atom->nmax <= nmax) return;
  nmax = atom->nmax;
  memory->destroy(root);
  memory->destroy(slot);
  memory->destroy(label);
  memory->destroy(fragment_id);
  memory->destroy(mass);
  memory->create(root, nmax, "pd/fragments:root");
  memory->create(slot, nmax, "pd/fragments:slot");
  memory->create(label, nmax, "pd/fragments:label");
  memory->create(fragment_id, nmax, "pd/fragments:fragment_id");
  memory->create(mass, nmax, "pd/fragments:mass");
  vector_atom = fragment_id;
}

// A caller that asks for another of the outputs in the same evaluation
// (LAMMPS sets invoked_flag there and clears it before the next) gets what
// was found then: nothing can have changed in between.
bool ComputePDFragments::reusable(int what, bigint step) const
{
  return (invoked_flag & what) && step == update->ntimestep;
}

// Labels: every atom of the group starts with its own ID; each round gives
// the ghosts their owners' labels, lowers each local tree's labels to its
// smallest, and gives each owner the smallest label of its ghosts. A bond
// is stored at one end only and ghosts store none, so a fragment that
// crosses ranks or a periodic boundary joins through the ghosts' labels.
// Labels only go down, so the rounds end; the last one changes nothing.
void ComputePDFragments::find_labels()
{
  if (!bonds->is_built())
    error->all(FLERR, "Compute pd/fragments: bond families are built by the first run");
  grow();
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *mask = atom->mask;
  for (int i = 0; i < nall; i++) label[i] = i < nlocal && (mask[i] & groupbit) ? (int64_t) atom->tag[i] : 0;
  pd_uf_init(root, nall);
  const pd_bond_view view = bonds->view();
  pd_fragments_join(&view, igroup == 0 ? nullptr : mask, groupbit, root);
  pd_uf_flatten(root, nall);
  int changed = 1;
  while (changed) {
    PDCompat::forward_comm(comm, this);
    int mine = pd_fragments_relax(root, label, nall, nlocal);
    reverse_lowered = 0;
    PDCompat::reverse_comm(comm, this);
    mine |= reverse_lowered;
    MPI_Allreduce(&mine, &changed, 1, MPI_INT, MPI_MAX, world);
  }
  labels_step = update->ntimestep;
}

// Each fragment's pieces (one per local tree) go to the rank 'ID modulo
// ranks', which adds them up: memory and messages scale with the pieces,
// not with the number of fragments times ranks.
void ComputePDFragments::gather_fragments()
{
  const int nlocal = atom->nlocal, nprocs = comm->nprocs;
  for (int i = 0; i < nlocal; i++) mass[i] = atom->rmass[i] * atom->vfrac[i];
  pieces.resize(nlocal);
  const int npieces = pd_fragments_pieces(root, label, mass, nlocal, slot, pieces.data());
  std::vector<int> send_count(nprocs, 0), send_start(nprocs + 1, 0), recv_count(nprocs), recv_start(nprocs + 1, 0);
  for (int k = 0; k < npieces; k++) send_count[pieces[k].id % nprocs]++;
  for (int p = 0; p < nprocs; p++) send_start[p + 1] = send_start[p] + send_count[p];
  std::vector<pd_fragment> outbox(npieces);
  std::vector<int> fill(send_start.begin(), send_start.end() - 1);
  for (int k = 0; k < npieces; k++) outbox[fill[pieces[k].id % nprocs]++] = pieces[k];
  MPI_Alltoall(send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, world);
  for (int p = 0; p < nprocs; p++) recv_start[p + 1] = recv_start[p] + recv_count[p];
  fragments.resize(recv_start[nprocs]);
  // as bytes (a pd_fragment is plain data)
  const int size = (int) sizeof(pd_fragment);
  for (int p = 0; p < nprocs; p++) {
    send_count[p] *= size;
    send_start[p] *= size;
    recv_count[p] *= size;
    recv_start[p] *= size;
  }
  MPI_Alltoallv(outbox.data(), send_count.data(), send_start.data(), MPI_BYTE, fragments.data(),
                recv_count.data(), recv_start.data(), MPI_BYTE, world);
  fragments.resize(pd_fragments_merge(fragments.data(), (int) fragments.size()));
}

// The global vector and array from the gathered fragments.
void ComputePDFragments::find_totals()
{
  gather_fragments();
  pd_fragment_tally t = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  pd_fragments_tally(fragments.data(), (int) fragments.size(), min_atoms, &t);
  double lightest = INFINITY;
  for (int i = 0; i < atom->nlocal; i++)
    if (label[i] > 0) lightest = std::min(lightest, mass[i]);
  double sums[4] = {t.counted, t.all, t.counted_mass, t.debris_mass}, total[4];
  MPI_Allreduce(sums, total, 4, MPI_DOUBLE, MPI_SUM, world);
  double maxes[2] = {t.largest, -lightest}, most[2];
  MPI_Allreduce(maxes, most, 2, MPI_DOUBLE, MPI_MAX, world);
  // the largest fragment's atoms, from the rank that holds it (the most,
  // should two weigh exactly the same)
  double atoms = t.largest == most[0] ? t.largest_atoms : 0.0, largest_atoms;
  MPI_Allreduce(&atoms, &largest_atoms, 1, MPI_DOUBLE, MPI_MAX, world);
  const double group_mass = total[2] + total[3];
  vector[0] = total[0];
  vector[1] = most[0];
  vector[2] = total[0] > 0.0 ? total[2] / total[0] : 0.0;
  vector[3] = group_mass;
  vector[4] = total[1];
  vector[5] = total[3];
  vector[6] = largest_atoms;

  const double lo = auto_range ? -most[1] : range_lo, hi = auto_range ? group_mass : range_hi;
  std::vector<double> edge(nbins, 0.0), bins(2 * nbins, 0.0), all(2 * nbins, 0.0);
  if (lo > 0.0 && std::isfinite(lo)) {    // (auto: the group has atoms of positive mass)
    pd_mass_edges(lo, hi, nbins, edge.data());
    pd_fragments_histogram(fragments.data(), (int) fragments.size(), min_atoms, lo, hi, nbins, bins.data(),
                           bins.data() + nbins);
  }
  MPI_Allreduce(bins.data(), all.data(), 2 * nbins, MPI_DOUBLE, MPI_SUM, world);
  pd_cumulate(all.data(), nbins);
  pd_cumulate(all.data() + nbins, nbins);
  for (int k = 0; k < nbins; k++) {
    array[k][0] = edge[k];
    array[k][1] = all[k];
    array[k][2] = total[2] > 0.0 ? all[nbins + k] / total[2] : 0.0;
  }
  totals_step = update->ntimestep;
}

void ComputePDFragments::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (reusable(INVOKED_ARRAY, totals_step)) return;
  if (!reusable(INVOKED_PERATOM, labels_step)) find_labels();
  find_totals();
}

void ComputePDFragments::compute_array()
{
  invoked_array = update->ntimestep;
  if (reusable(INVOKED_VECTOR, totals_step)) return;
  if (!reusable(INVOKED_PERATOM, labels_step)) find_labels();
  find_totals();
}

void ComputePDFragments::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (!reusable(INVOKED_VECTOR | INVOKED_ARRAY, labels_step)) find_labels();
  for (int i = 0; i < atom->nlocal; i++) fragment_id[i] = (double) label[i];
}

int ComputePDFragments::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = ubuf(label[list[k]]).d;
  return n;
}

void ComputePDFragments::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) label[first + k] = (int64_t) ubuf(buf[k]).i;
}

int ComputePDFragments::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = ubuf(label[first + k]).d;
  return n;
}

// Owners take the smallest label of their ghosts (0, outside the group,
// stays 0: an atom's ghosts share its group).
void ComputePDFragments::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) {
    const int64_t theirs = (int64_t) ubuf(buf[k]).i;
    int64_t &mine = label[list[k]];
    if (theirs < mine) {
      mine = theirs;
      reverse_lowered = 1;
    }
  }
}

double ComputePDFragments::memory_usage()
{
  return (double) nmax * (2 * sizeof(int) + sizeof(int64_t) + 2 * sizeof(double)) +
         (double) (pieces.capacity() + fragments.capacity()) * sizeof(pd_fragment);
}
