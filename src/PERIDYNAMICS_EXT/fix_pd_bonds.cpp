/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: bond families of the pd/ pair styles.

   Families are built once, from the reference positions x0, on the first
   run. Each bond is stored at one end (owns_bond) and visited once.
   Partners are kept as tags (for migration and restart) and turned into
   local indices after every reneighboring, never per bond per step.
------------------------------------------------------------------------- */

#include "fix_pd_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair_pd.h"
#include "pd_compat.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// Tag of the global restart record: bump it whenever the layout of the
// record or of the per-atom restart data changes.
static constexpr double RESTART_FORMAT = 20261122.2;
static constexpr int PER_ATOM_FIXED = 5;    // count, own tag, family and weighted volume, dissipated

// Which end stores a bond: the smaller tag when the tags' sum is even, the
// larger when odd. Either rule stores each bond once; alternating keeps the
// per-atom tables (padded to the longest row) about half full rather than
// giving the first atom of a periodic lattice every one of its bonds.
static inline bool owns_bond(tagint me, tagint other)
{
  return ((me + other) & 1) ? me > other : me < other;
}

FixPDBonds::FixPDBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), family_volume(nullptr), weighted_volume(nullptr), dissipated_atom(nullptr), owner(nullptr), built_tag(nullptr),
    use_weights(0), nhistory(0), built(0), maxpartner(1), nowned(0), npartner(nullptr), partner(nullptr),
    r0(nullptr), weight(nullptr), history(nullptr), far(nullptr), nlost_local(0), nlost_reported(0), dissipated(0.0), dissipated_joule(0.0), nbroken_local(0), any_broken(0),
    family_key(0.0), fresh_step(-1), list(nullptr),
    comm_array(nullptr), comm_width(1), comm_max(0)
{
  if (narg != 6 || strcmp(arg[4], "history") != 0)
    error->all(FLERR, "Illegal fix pd/bonds command: expected 'weights|noweights history N' "
               "(it is created by the pd/ pair styles)");
  if (strcmp(arg[3], "weights") == 0) use_weights = 1;
  else if (strcmp(arg[3], "noweights") == 0) use_weights = 0;
  else error->all(FLERR, "Illegal fix pd/bonds argument '{}': expected weights or noweights", arg[3]);
  nhistory = utils::inumeric(FLERR, arg[5], false, lmp);
  if (nhistory < 0) error->all(FLERR, "Illegal fix pd/bonds history count {}", nhistory);

  restart_global = 1;
  restart_peratom = 1;
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 0;
  stores_ids = 1;
  create_attribute = 1;
  comm_forward = 2;
  comm_reverse = 2;
  maxexchange_dynamic = 1;    // the exchange size follows the longest family
  maxexchange = per_atom_max();

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) set_arrays(i);
}

FixPDBonds::~FixPDBonds()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  memory->destroy(partner);
  memory->destroy(r0);
  memory->destroy(weight);
  memory->destroy(history);
  memory->destroy(far);
  memory->destroy(family_volume);
  memory->destroy(weighted_volume);
  memory->destroy(built_tag);
  memory->destroy(dissipated_atom);
}

int FixPDBonds::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR | POST_RUN;
}

// Lost partners are counted all along; say so once per run when there are new ones.
void FixPDBonds::post_run()
{
  const bigint total = (bigint) compute_scalar();
  if (total > nlost_reported && comm->me == 0)
    error->warning(FLERR, "Fix pd/bonds: {} bond partners lost so far (moved beyond the ghost "
                   "cutoff, horizon + skin); f_{} counts them; 'comm_modify cutoff' reaches further",
                   total, id);
  nlost_reported = total;
}

void FixPDBonds::init()
{
  if (!owner) error->all(FLERR, "Fix pd/bonds is created by a pd/ pair style; do not define it by hand");
  if (!built) PDCompat::request_occasional_full(neighbor, this, instance_me);
}

void FixPDBonds::init_list(int, NeighList *ptr)
{
  list = ptr;
}

void FixPDBonds::setup_post_neighbor()
{
  if (!built) build_families();
  else {
    map_partners(true);
    check_identities();
  }
}

// Between runs, commands can renumber atoms (delete_atoms with compress
// yes, reset_atom_ids) or give a new atom a deleted atom's ID: the stored
// partner tags would then name other atoms. Each atom carries the tag it had
// when the families were built; every bond's far end must still carry the
// partner's.
void FixPDBonds::check_identities()
{
  const int nall = atom->nlocal + atom->nghost;
  double *who = new double[nall];
  for (int i = 0; i < nall; i++) who[i] = i < atom->nlocal ? (double) built_tag[i] : -1.0;
  copy_to_ghosts(who);
  int bad = 0;
  for (int i = 0; i < nowned && !bad; i++) {
    if (built_tag[i] && built_tag[i] != atom->tag[i]) bad = 1;
    for (int k = 0; k < npartner[i]; k++)
      if (who[far[i][k]] != (double) partner[i][k]) bad = 1;
  }
  delete[] who;
  int anybad;
  MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, world);
  if (anybad)
    error->all(FLERR, "Fix pd/bonds: atom IDs changed since the bond families were built "
               "(e.g. by 'delete_atoms ... compress yes', reset_atom_ids, or new atoms taking a "
               "deleted atom's ID), so stored partners would name other atoms; use "
               "'delete_atoms ... compress no' and create new atoms before the first run");
}

void FixPDBonds::post_neighbor()
{
  map_partners(false);
}

/* ---------------------------------------------------------------------- */

void FixPDBonds::build_families()
{
  neighbor->build_one(list);
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  const int *type = atom->type;
  double **x0 = atom->x0;

  // a candidate becomes a bond if its reference distance is within the
  // horizon; the pair is stored once (at its owner) and with one image only
  // (closest_image walks the image chain from its head, the mapped atom)
  auto reference_length = [&](int i, int j) {
    if (!owns_bond(tag[i], tag[j]) || domain->closest_image(i, atom->map(tag[j])) != j) return -1.0;
    double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
    domain->minimum_image(d[0], d[1], d[2]);
    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return r <= owner->horizon(type[i], type[j]) ? r : -1.0;
  };

  int mymax = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int n = 0;
    for (int jj = 0; jj < list->numneigh[i]; jj++)
      if (reference_length(i, list->firstneigh[i][jj] & NEIGHMASK) >= 0.0) n++;
    mymax = MAX(mymax, n);
  }
  int longest;
  MPI_Allreduce(&mymax, &longest, 1, MPI_INT, MPI_MAX, world);
  resize_tables(MAX(longest, 1));

  for (int i = 0; i < nlocal; i++) {
    npartner[i] = 0;
    built_tag[i] = tag[i];
  }
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      const double r = reference_length(i, j);
      if (r < 0.0) continue;
      const int k = npartner[i]++;
      partner[i][k] = tag[j];
      r0[i][k] = r;
      if (use_weights) weight[i][k] = owner->bond_weight(type[i], type[j], r);
      for (int h = 0; h < nhistory; h++) history[i][k * nhistory + h] = 0.0;
    }
  }
  int coincident = 0, any_coincident;
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < npartner[i]; k++)
      if (r0[i][k] <= 1e-12 * owner->horizon(type[i], type[i])) coincident = 1;
  MPI_Allreduce(&coincident, &any_coincident, 1, MPI_INT, MPI_MAX, world);
  if (any_coincident)
    error->all(FLERR, "Fix pd/bonds: two atoms share a reference position (x0); peridynamic "
               "bonds need distinct positions");
  built = 1;
  map_partners(true);
  reference_sums();

  bigint nbonds = 0, mybonds = 0;
  for (int i = 0; i < nlocal; i++) mybonds += npartner[i];
  MPI_Allreduce(&mybonds, &nbonds, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0) {
    const double bytes = bytes_per_bond();
    utils::logmesg(lmp,
                   "pd/bonds: {} bonds, {:.2f} bonds per atom (each stored once), "
                   "up to {} owned per atom, {:.0f} bytes per bond\n",
                   nbonds, 2.0 * nbonds / MAX(atom->natoms, 1), maxpartner, bytes);
  }
}

// Local indices of the far ends: the image closest to the owner, valid until
// the next reneighboring (atoms move less than half the skin meanwhile).
// A partner beyond the ghost cutoff is lost even when this rank happens to
// own it, so that the same bonds are lost on any number of ranks.
void FixPDBonds::map_partners(bool setup)
{
  nowned = atom->nlocal;
  const double cut = comm->get_comm_cutoff(), cutsq = cut * cut;
  const int nall = atom->nlocal + atom->nghost;
  double **x = atom->x;
  const bigint lost_before = nlost_local;    // intact bonds lost so far
  for (int i = 0; i < nowned; i++)
    for (int k = 0; k < npartner[i]; k++) {
      int j = atom->map(partner[i][k]);
      if (j >= nall) j = -1;    // a stale map entry of a deleted atom
      if (j >= 0) j = domain->closest_image(i, j);
      if (j >= 0) {
        const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
        if (dx * dx + dy * dy + dz * dz > cutsq) j = -1;
      }
      if (j < 0) {
        // a broken bond whose ends drifted apart is simply gone; an intact one is lost
        if (r0[i][k] > 0.0) nlost_local++;
        remove_bond(i, k--);
        continue;
      }
      far[i][k] = j;
    }
  // minimize's line search moves atoms by up to 'min_modify dmax' (0.1
  // length units by default: 10 cm in SI), which tears bonds that physics
  // would keep; every rank is here at once, so the check is collective
  if (update->whichflag == 2 && !setup) {
    const int mine = nlost_local > lost_before;
    int any;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      error->all(FLERR, "Fix pd/bonds: bond partners moved beyond the ghost cutoff during "
                 "minimize; limit the line search step with 'min_modify dmax' (a small "
                 "fraction of the particle spacing)");
  }
}

void FixPDBonds::remove_bond(int i, int k)
{
  const int last = --npartner[i];
  partner[i][k] = partner[i][last];
  r0[i][k] = r0[i][last];
  far[i][k] = far[i][last];
  if (use_weights) weight[i][k] = weight[i][last];
  for (int h = 0; h < nhistory; h++) history[i][k * nhistory + h] = history[i][last * nhistory + h];
}

// Family volume and weighted volume of every atom, over both ends of each bond.
void FixPDBonds::reference_sums()
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) family_volume[i] = weighted_volume[i] = 0.0;
  pd_bond_view v = view();
  pd_weighted_volume(&v, atom->vfrac, weighted_volume);
  v.weight = nullptr;
  pd_weighted_volume(&v, atom->vfrac, family_volume);
  sum_to_owners(weighted_volume);
  sum_to_owners(family_volume);
}

pd_bond_view FixPDBonds::view() const
{
  pd_bond_view v;
  v.nowner = nowned;
  v.stride = maxpartner;
  v.count = npartner;
  v.far = far ? far[0] : nullptr;
  v.len0 = r0 ? r0[0] : nullptr;
  v.weight = use_weights && weight ? weight[0] : nullptr;
  return v;
}

double FixPDBonds::compute_scalar()
{
  bigint total = 0;
  MPI_Allreduce(&nlost_local, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return (double) total;
}

// tag, reference length, local index, then what the material asked for
double FixPDBonds::bytes_per_bond() const
{
  return sizeof(tagint) + sizeof(double) + sizeof(int) + (use_weights + nhistory) * sizeof(double);
}

double FixPDBonds::memory_usage()
{
  const double per_bond = bytes_per_bond();
  return (double) atom->nmax * (maxpartner * per_bond + sizeof(int) + sizeof(tagint) + 2 * sizeof(double));
}

/* ---------------------------------------------------------------------- */

void FixPDBonds::sum_to_owners(double *a, int width)
{
  comm_array = a;
  comm_width = width;
  PDCompat::reverse_comm(comm, this, width);
}

void FixPDBonds::max_to_owners(double *a)
{
  comm_max = 1;
  sum_to_owners(a, 1);
  comm_max = 0;
}

void FixPDBonds::copy_to_ghosts(double *a, int width)
{
  comm_array = a;
  comm_width = width;
  PDCompat::forward_comm(comm, this, width);
}

int FixPDBonds::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int w = 0; w < comm_width; w++) buf[m++] = comm_array[list[i] * comm_width + w];
  return m;
}

void FixPDBonds::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int w = 0; w < comm_width; w++) comm_array[i * comm_width + w] = buf[m++];
}

int FixPDBonds::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int w = 0; w < comm_width; w++) buf[m++] = comm_array[i * comm_width + w];
  return m;
}

void FixPDBonds::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int w = 0; w < comm_width; w++, m++) {
      double &a = comm_array[list[i] * comm_width + w];
      a = comm_max ? MAX(a, buf[m]) : a + buf[m];
    }
}

/* ---------------------------------------------------------------------- */

void FixPDBonds::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "pd/bonds:npartner");
  memory->grow(partner, nmax, maxpartner, "pd/bonds:partner");
  memory->grow(r0, nmax, maxpartner, "pd/bonds:r0");
  memory->grow(far, nmax, maxpartner, "pd/bonds:far");
  if (use_weights) memory->grow(weight, nmax, maxpartner, "pd/bonds:weight");
  if (nhistory) memory->grow(history, nmax, maxpartner * nhistory, "pd/bonds:history");
  memory->grow(family_volume, nmax, "pd/bonds:family_volume");
  memory->grow(weighted_volume, nmax, "pd/bonds:weighted_volume");
  memory->grow(built_tag, nmax, "pd/bonds:built_tag");
  memory->grow(dissipated_atom, nmax, "pd/bonds:dissipated_atom");
}

void FixPDBonds::copy_arrays(int i, int j, int)
{
  npartner[j] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) {
    partner[j][k] = partner[i][k];
    r0[j][k] = r0[i][k];
    if (use_weights) weight[j][k] = weight[i][k];
  }
  for (int h = 0; h < npartner[i] * nhistory; h++) history[j][h] = history[i][h];
  family_volume[j] = family_volume[i];
  weighted_volume[j] = weighted_volume[i];
  built_tag[j] = built_tag[i];
  dissipated_atom[j] = dissipated_atom[i];
}

// Atoms created after the families were built join without bonds.
void FixPDBonds::set_arrays(int i)
{
  npartner[i] = 0;
  built_tag[i] = 0;
  family_volume[i] = weighted_volume[i] = dissipated_atom[i] = 0.0;
}

int FixPDBonds::per_atom_doubles(int i) const
{
  return PER_ATOM_FIXED + npartner[i] * (2 + use_weights + nhistory);
}

// Layout shared by exchange and restart: count, own tag at build, family
// volume, weighted volume, dissipated energy, then per bond: tag, r0 (its
// sign: broken) [, weight] [, history].
int FixPDBonds::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = ubuf(npartner[i]).d;
  buf[m++] = ubuf(built_tag[i]).d;
  buf[m++] = family_volume[i];
  buf[m++] = weighted_volume[i];
  buf[m++] = dissipated_atom[i];
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    buf[m++] = r0[i][k];
    if (use_weights) buf[m++] = weight[i][k];
    for (int h = 0; h < nhistory; h++) buf[m++] = history[i][k * nhistory + h];
  }
  return m;
}

int FixPDBonds::unpack_exchange(int i, double *buf)
{
  int m = 0;
  npartner[i] = (int) ubuf(buf[m++]).i;
  if (npartner[i] > maxpartner) error->one(FLERR, "Fix pd/bonds: atom arrived with more bonds than the tables hold");
  built_tag[i] = (tagint) ubuf(buf[m++]).i;
  family_volume[i] = buf[m++];
  weighted_volume[i] = buf[m++];
  dissipated_atom[i] = buf[m++];
  for (int k = 0; k < npartner[i]; k++) {
    partner[i][k] = (tagint) ubuf(buf[m++]).i;
    r0[i][k] = buf[m++];
    if (use_weights) weight[i][k] = buf[m++];
    for (int h = 0; h < nhistory; h++) history[i][k * nhistory + h] = buf[m++];
  }
  return m;
}

void FixPDBonds::write_restart(FILE *fp)
{
  double total_lost = compute_scalar(), sums[2], mine[2] = {dissipated, dissipated_joule};
  MPI_Allreduce(mine, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  bigint total_broken = 0;
  MPI_Allreduce(&nbroken_local, &total_broken, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0) {
    // the record, then the bonds broken at the last evaluation (every rank
    // has them all) with its step, so that a restart replays that step
    std::vector<double> list = {RESTART_FORMAT, (double) built, (double) maxpartner, (double) use_weights,
                                total_lost, (double) nhistory, sums[0], family_key, sums[1],
                                (double) total_broken, (double) any_broken, (double) fresh_step,
                                (double) fresh_pairs.size()};
    for (tagint t : fresh_pairs) list.push_back((double) t);
    int size = list.size() * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

void FixPDBonds::restart(char *buf)
{
  if (((double *) buf)[0] != RESTART_FORMAT)
    error->all(FLERR, "Fix pd/bonds: the restart file's bonds are in another format than this build "
               "reads (format {}; written by an older or newer PERIDYNAMICS_EXT)", RESTART_FORMAT);
  double *list = (double *) buf + 1;
  if ((int) list[2] != use_weights)
    error->all(FLERR, "Fix pd/bonds: restart file bonds {} weights, the pair style now {}",
               list[2] ? "carry" : "carry no", use_weights ? "needs them" : "does not");
  if ((int) list[4] != nhistory)
    error->all(FLERR, "Fix pd/bonds: restart file bonds carry {} history values, the pair style "
               "now needs {}", (int) list[4], nhistory);
  built = (int) list[0];
  resize_tables((int) list[1]);
  // totals are kept once, on rank 0, so the global sums carry over
  nlost_local = comm->me == 0 ? (bigint) list[3] : 0;
  dissipated = comm->me == 0 ? list[5] : 0.0;
  family_key = list[6];
  dissipated_joule = comm->me == 0 ? list[7] : 0.0;
  nbroken_local = comm->me == 0 ? (bigint) list[8] : 0;
  any_broken = (int) list[9];
  fresh_step = (bigint) list[10];
  fresh_pairs.resize((size_t) list[11]);
  for (size_t p = 0; p < fresh_pairs.size(); p++) fresh_pairs[p] = (tagint) list[12 + p];
}

// New row length of the per-atom bond tables (their contents are dropped:
// memory->grow cannot change the row length of a 2D array in place).
void FixPDBonds::resize_tables(int rowlength)
{
  maxpartner = rowlength;
  maxexchange = per_atom_max();
  memory->destroy(partner);
  memory->destroy(r0);
  memory->destroy(weight);
  memory->destroy(history);
  memory->destroy(far);
  grow_arrays(atom->nmax);
}

int FixPDBonds::pack_restart(int i, double *buf)
{
  buf[0] = per_atom_doubles(i) + 1;
  return pack_exchange(i, buf + 1) + 1;
}

void FixPDBonds::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  unpack_exchange(nlocal, &extra[nlocal][m + 1]);
}

int FixPDBonds::size_restart(int i)
{
  return per_atom_doubles(i) + 1;
}

int FixPDBonds::per_atom_max() const
{
  return PER_ATOM_FIXED + maxpartner * (2 + use_weights + nhistory);
}

int FixPDBonds::maxsize_restart()
{
  return per_atom_max() + 1;
}

bool FixPDBonds::unbreak_fresh(bigint step)
{
  if (step != fresh_step || fresh_pairs.empty()) return false;
  sign_fresh(1.0);
  return true;
}

void FixPDBonds::rebreak_fresh()
{
  sign_fresh(-1.0);
}

// Set the sign of the listed bonds' reference lengths (on their owners).
void FixPDBonds::sign_fresh(double sign)
{
  for (size_t p = 0; p < fresh_pairs.size(); p += 2) {
    const int i = atom->map(fresh_pairs[p]);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int k = 0; k < npartner[i]; k++)
      if (partner[i][k] == fresh_pairs[p + 1]) r0[i][k] = sign * fabs(r0[i][k]);
  }
}

void FixPDBonds::note_fresh(const int *idx, int n, bigint step, bool any)
{
  fresh_step = step;
  fresh_pairs.clear();
  if (!any) return;
  std::vector<tagint> mine(2 * (size_t) n);
  for (int q = 0; q < n; q++) {
    const int i = idx[q] / maxpartner, k = idx[q] % maxpartner;
    mine[2 * q] = atom->tag[i];
    mine[2 * q + 1] = partner[i][k];
  }
  int count = 2 * n;
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int r = 1; r < comm->nprocs; r++) displs[r] = displs[r - 1] + counts[r - 1];
  fresh_pairs.resize(displs.back() + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_LMP_TAGINT, fresh_pairs.data(), counts.data(), displs.data(),
                 MPI_LMP_TAGINT, world);
}
