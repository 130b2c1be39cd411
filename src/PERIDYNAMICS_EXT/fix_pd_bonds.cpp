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
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "pd_bonds_record.h"
#include "pd_compat.h"
#include "pd_error.h"
#include "pd_table_memory.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// The global restart record and its version: pd_bonds_record.h, written
// and read in fix_pd_bonds_restart.cpp. The version covers the per-atom
// layout (pack_exchange) too.
static constexpr int PER_ATOM_FIXED = 2;    // count, own tag (then the fields, then the bonds)
static constexpr double MAX_INTACT_LENGTH = 11.0;    // stretch 10: no material survives it

FixPDBonds::FixPDBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), serving(false), built_tag(nullptr), use_weights(0), nhistory(0), built(0),
    weights_fresh(false), maxpartner(1), nrows(0), nowned(0), npartner(nullptr), partner(nullptr), r0(nullptr),
    weight(nullptr), history(nullptr), far(nullptr), nlost_local(0), intact_at_map(-1), stored_total(0),
    nlost_reported(0), warned_images(0), family_key(0.0), record(lmp), stable_dt(0.0), comm_array(nullptr),
    comm_width(1), comm_max(0), idissipated(-1), ifamily_volume(-1), iweighted_volume(-1), ibuild_volume(-1),
    fields_from_file(false), guard_step(INFINITY), guard_ke(0.0), guard_ke_step(0), guard_window(0), guard_streak(0), guard_relaxing(false), damaged(0), damaged_example(0)
{
  if (strcmp(id, "PD_BONDS") != 0)
    error->all(FLERR, "Fix pd/bonds is created by the pd/ pair styles (as PD_BONDS); do not define it by hand");
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
  wd_header = 1;    // to warn when write_data runs (write_data_header)
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 0;
  stores_ids = 1;
  create_attribute = 1;
  comm_forward = 3;    // MIN_COMM_WIDTH of fix_pd_bonds_fields.cpp
  comm_reverse = 3;
  maxexchange_dynamic = 1;    // the exchange size follows the longest family
  maxexchange = per_atom_max(PDField::MIGRATE);

  grow_arrays(atom->nmax);
  grow_rows(atom->nlocal + 1);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) set_arrays(i);
  const std::vector<PDField> own = own_fields();
  idissipated = add_field(own[0]);
  ifamily_volume = add_field(own[1]);
  iweighted_volume = add_field(own[2]);
  ibuild_volume = add_field(own[3]);
}

FixPDBonds::~FixPDBonds()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  destroy_tables();
  memory->destroy(built_tag);
  for (Field &f : fields) memory->destroy(f.data);
}

int FixPDBonds::setmask()
{
  return PRE_EXCHANGE | POST_NEIGHBOR | MIN_POST_NEIGHBOR | POST_RUN | END_OF_STEP;
}

// The atoms are about to change ranks and indices: the pair style settles
// what it keeps by index (PERI's rule, guarded: the s0 it deferred).
void FixPDBonds::pre_exchange()
{
  if (PDFamilySource *source = serving ? pd_family_source(force) : nullptr) source->catch_up(false);
}

// Lost partners are counted all along; say so once per run when there are new ones.
void FixPDBonds::post_run()
{
  if (PDFamilySource *source = serving ? pd_family_source(force) : nullptr) source->catch_up(true);
  const bigint total = (bigint) compute_scalar();
  if (total > nlost_reported && comm->me == 0)
    error->warning(FLERR, "Fix pd/bonds: {} intact bonds lost so far (an end moved beyond the "
                   "ghost cutoff, horizon + skin, or left the box or was deleted); f_{} counts "
                   "them; 'comm_modify cutoff' reaches further", total, id);
  nlost_reported = total;
}

// The families serve the pd/ material style of the current pair style. A run
// without one (pair_style none, or another style between runs) keeps them
// as they are: not mapped, not used, nothing dropped, until it returns.
void FixPDBonds::init()
{
  take_family_spec();
  if (!serving && built && comm->me == 0)
    utils::logmesg(lmp, "pd/bonds: no pd/ material pair style in this run; the bond families "
                   "are kept unchanged until one returns\n");
}

// The family spec of the pair style that provides one now, alone or as a
// hybrid sub-style (pair styles initialize before fixes, so it is this
// run's), copied: the store keeps no pointer to a pair style, which the
// next 'pair_style' command may delete. Families are built once: later
// runs must ask for the same ones.
void FixPDBonds::take_family_spec()
{
  const PDFamilySource *source = pd_family_source(force);
  serving = source != nullptr;
  spec = serving ? source->family_spec() : PDFamilySpec();
  stable_dt = 0.0;
  warned_images = 0;
  if (!serving) return;
  if (!built) family_key = spec.key;
  else if (family_key != spec.key)
    error->all(FLERR, "Pair {}: the bond families were built for other pair settings (style, horizons, "
               "influence, quadrature, directional_correction, legacy or dimension changed after the first "
               "run); they are built once: start the simulation again with the new settings", spec.style);
}

void FixPDBonds::setup_post_neighbor()
{
  if (!serving) nowned = 0;
  else if (!built) build_families();
  else {
    map_partners(true);
    check_identities();
    check_volumes();
    check_fields_claimed();
    // kept families (an earlier run, or a restart file): the log shows
    // that they were not rebuilt, and how many bonds they hold
    if (comm->me == 0)
      utils::logmesg(lmp, "pd/bonds: {} bonds kept, {} of them broken (families from an earlier run or "
                     "the restart file, not rebuilt)\n", stored_total, stored_total - intact_at_map);
  }
}

// The bonds' weights, the families' volumes and every material's
// calibration are of the volumes at the build: a volume set since (the
// 'set' command between runs) would change the stiffness and make energy.
void FixPDBonds::check_volumes()
{
  const double *built_volume = field(ibuild_volume), *vfrac = atom->vfrac;
  bigint changed = 0;
  tagint example = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (vfrac[i] != built_volume[i] && built_tag[i] != 0) {
      changed++;
      example = MAX(example, atom->tag[i]);
    }
  bigint total;
  MPI_Allreduce(&changed, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (!total) return;
  tagint who;
  MPI_Allreduce(&example, &who, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  error->all(FLERR, "Fix pd/bonds: the volume of {} atom{} changed since the bond families were built "
             "(e.g. atom {}: 'set ... volume' after the first run); the bonds, their weights and the "
             "materials' calibration are of the volumes at the build: set volumes before the first run",
             total, total > 1 ? "s" : "", who);
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
  if (serving) map_partners(false);
}

/* ---------------------------------------------------------------------- */

// Bonds per atom of each type and between each pair of types, as built. A
// type whose atoms have almost no bonds would run as free particles (a
// horizon below the real spacing: wrong units, volume or lattice), so it is
// an error; two types that touch but share no bonds get a warning unless
// the user said so ('nobond'), and so do a type that fails and one that
// does not when only the mixing rules bond them (an impactor glued to its
// target).
void FixPDBonds::report_bonds_by_type(const std::vector<bigint> &touching_mine)
{
  static constexpr double MIN_BONDS_PER_ATOM = 3.0;
  const int nt = atom->ntypes + 1;
  const int *type = atom->type;
  // counts[a * nt + b]: bonds between types a <= b; counts[t * nt]: atoms of type t
  std::vector<bigint> mine(nt * nt, 0), counts(nt * nt), touching(nt * nt);
  for (int i = 0; i < atom->nlocal; i++) {
    mine[type[i] * nt]++;
    for (int k = 0; k < npartner[i]; k++) {
      const int a = type[i], b = type[far[i][k]];
      mine[MIN(a, b) * nt + MAX(a, b)]++;
    }
  }
  MPI_Allreduce(mine.data(), counts.data(), nt * nt, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(touching_mine.data(), touching.data(), nt * nt, MPI_LMP_BIGINT, MPI_MAX, world);
  std::string per_type, between;
  for (int t = 1; t < nt; t++) {
    if (!counts[t * nt]) continue;
    bigint ends = 2 * counts[t * nt + t];
    for (int u = 1; u < nt; u++)
      if (u != t) ends += counts[MIN(t, u) * nt + MAX(t, u)];
    const double per_atom = (double) ends / counts[t * nt];
    per_type += fmt::format(" type {} {:.2f};", t, per_atom);
    // (a type left to another sub-style of a hybrid has no horizon here)
    if (per_atom < MIN_BONDS_PER_ATOM && !std::isnan(spec.horizon(t, t)))
      error->all(FLERR, "Fix pd/bonds: atoms of type {} have {:.2f} bonds on average (horizon {}): "
                 "they would move as free particles. The horizon must span several particle "
                 "spacings: check the lattice spacing, 'set volume' and the units", t, per_atom,
                 spec.horizon(t, t));
    for (int u = t + 1; u < nt; u++) {
      if (!counts[u * nt]) continue;
      between += fmt::format(" {}-{} {};", t, u, counts[t * nt + u]);
      if (touching[t * nt + u] && !counts[t * nt + u] && spec.horizon(t, u) > 0.0 && comm->me == 0)
        error->warning(FLERR, "Fix pd/bonds: types {} and {} touch (atoms within each other's "
                       "horizon) but share no bonds (their horizon {} is below the spacing); to "
                       "keep them unbonded write 'pair_coeff {} {} nobond'", t, u,
                       spec.horizon(t, u), t, u);
      if (counts[t * nt + u] && spec.is_unnamed_mixed(t, u) && comm->me == 0)
        error->warning(FLERR, "Fix pd/bonds: types {} and {} share {} bonds that no 'pair_coeff {} {}' line "
                       "names, one type failing and the other not: the mixing rules join them into one "
                       "body. For bodies that only touch write 'pair_coeff {} {} nobond'; to keep the bonds, "
                       "name their interface ('pair_coeff {} {} horizon H', and 'fail ...' for how they "
                       "break; under pair_style hybrid the style's name follows the types)",
                       t, u, counts[t * nt + u], t, u, t, u, t, u);
    }
  }
  if (comm->me == 0)
    utils::logmesg(lmp, "pd/bonds: bonds per atom by type:{}{}{}\n", per_type,
                   between.empty() ? "" : " bonds between types:", between);
}

// Local indices of the far ends: the image closest to the owner, valid until
// the next reneighboring (atoms move less than half the skin meanwhile).
// 'built': the family build has just stored each far end (the one image
// within reach of the owner in the reference configuration: the closest
// one unless atoms moved by half a box since), so only the checks run.
// A partner beyond the ghost cutoff is lost even when this rank happens to
// own it, so that the same bonds are lost on any number of ranks.
void FixPDBonds::map_partners(bool setup, bool built)
{
  if (setup) check_stored_partners(!built);    // (bonds just built name existing atoms)
  nowned = atom->nlocal;
  const double cut = comm->get_comm_cutoff(), cutsq = cut * cut;
  const int nall = atom->nlocal + atom->nghost;
  double **x = atom->x;
  std::string overstretched;
  bigint kept[2] = {0, 0};    // bonds kept, and how many of them intact (count_lost)
  // a bond within half the skin of half a periodic box side may reach
  // past it before the next reneighboring: its closest image is then
  // another one, and the bond jumps there
  double ambiguous[3];
  // (a lattice bond exactly there is not warned about; a 2D model's bonds
  // lie in the plane, whatever the thin periodic z period and the skin)
  for (int c = 0; c < 3; c++)
    ambiguous[c] = domain->periodicity[c] && c < domain->dimension
        ? (0.5 * domain->prd[c] - 0.5 * neighbor->skin) * (1.0 + 1e-9)
        : INFINITY;
  bigint nambiguous = 0;
  for (int i = 0; i < nowned; i++) {
    for (int k = 0; k < npartner[i]; k++) {
      int j = built ? far[i][k] : atom->map(partner[i][k]);
      if (j >= nall) j = -1;    // a stale map entry of a deleted atom
      if (j >= 0 && !built) j = domain->closest_image(i, j);
      if (j >= 0) {
        const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
        const double len2 = dx * dx + dy * dy + dz * dz;
        nambiguous += fabs(dx) > ambiguous[0] || fabs(dy) > ambiguous[1] || fabs(dz) > ambiguous[2];
        if (len2 > cutsq) j = -1;
        // an intact bond eleven times its length: the run has blown up
        else if (len2 > MAX_INTACT_LENGTH * MAX_INTACT_LENGTH * r0[i][k] * r0[i][k] && r0[i][k] > 0.0 &&
                 overstretched.empty())
          overstretched = fmt::format("Fix pd/bonds: the run is unstable at step {}: intact bond {}-{} "
                                      "is stretched to {:.3g} times its length; likely cause: the time "
                                      "step {:.6g} is too large (see the stable estimate in the log)",
                                      update->ntimestep, atom->tag[i], partner[i][k],
                                      sqrt(len2) / r0[i][k], update->dt);
      }
      if (j < 0) {
        remove_bond(i, k--);    // counted below, if intact
        continue;
      }
      far[i][k] = j;
      kept[1] += r0[i][k] > 0.0;
    }
    kept[0] += npartner[i];
  }
  pd_error_collective(lmp, overstretched);
  warn_ambiguous_images(nambiguous);
  const bigint lost = count_lost(kept[0], kept[1]);
  // minimize's line search moves atoms by up to 'min_modify dmax' (0.1
  // length units by default: 10 cm in SI), which tears bonds that physics
  // would keep
  if (update->whichflag == 2 && !setup && lost > 0)
    error->all(FLERR, "Fix pd/bonds: bond partners moved beyond the ghost cutoff during "
               "minimize; limit the line search step with 'min_modify dmax' (a small "
               "fraction of the particle spacing)");
}

// Bonds that reach near half a periodic box side (map_partners): warned
// about once per run, with their count.
void FixPDBonds::warn_ambiguous_images(bigint mine)
{
  bigint all;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all == 0 || warned_images) return;
  warned_images = 1;
  if (comm->me == 0)
    error->warning(FLERR, "Fix pd/bonds: at step {} {} bonds span nearly half the periodic box (within half "
                   "the skin): a bond that reaches past half the box jumps to another periodic image "
                   "and its energy with it; make the periodic box longer (twice the longest bond and "
                   "more)", update->ntimestep, all);
}

// Intact bonds lost since the last mapping, over all ranks: those that
// vanished without breaking, whichever end stored them (a partner beyond
// the ghost cutoff, an atom deleted or lost from the box with the bonds it
// stored). Counting from both ends makes the count independent of which
// end stores a bond, and so of the rank count (atom IDs, and so storage,
// depend on it). A broken bond that vanishes is not counted.
bigint FixPDBonds::count_lost(bigint stored, bigint intact)
{
  bigint mine[3] = {intact, record.take_breaks_since_map(), stored}, sums[3];
  MPI_Allreduce(mine, sums, 3, MPI_LMP_BIGINT, MPI_SUM, world);
  const bigint lost = intact_at_map < 0 ? 0 : intact_at_map - sums[1] - sums[0];
  intact_at_map = sums[0];
  stored_total = sums[2];
  if (comm->me == 0) nlost_local += lost;
  return lost;
}

// What a restart file or a migration delivered must name real atoms and
// real lengths before it is used to index anything (a damaged file); the
// bonds themselves are not scanned right after the build made them.
void FixPDBonds::check_stored_partners(bool scan_bonds)
{
  bigint total_damaged, claimed = damaged ? damaged_example : 0, bad_count;
  MPI_Allreduce(&damaged, &total_damaged, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&claimed, &bad_count, 1, MPI_LMP_BIGINT, MPI_MAX, world);
  if (total_damaged)
    error->all(FLERR, "Fix pd/bonds: {} atoms arrived with a bond record that fails its checksum, a "
               "bond count outside 0 to {} (largest seen: {}) or a record longer or shorter than its "
               "count and the listed per-atom fields make: the restart file is damaged",
               total_damaged, maxpartner, bad_count);
  if (!scan_bonds) return;
  bigint bad = 0;
  tagint example = 0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < npartner[i]; k++)
      if (partner[i][k] <= 0 || partner[i][k] > atom->map_tag_max || !std::isfinite(r0[i][k]) ||
          r0[i][k] == 0.0) {
        bad++;
        example = atom->tag[i];
      }
  bigint anybad;
  MPI_Allreduce(&bad, &anybad, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (anybad) {
    tagint who;
    MPI_Allreduce(&example, &who, 1, MPI_LMP_TAGINT, MPI_MAX, world);
    error->all(FLERR, "Fix pd/bonds: {} stored bonds name no existing atom or have no valid "
               "length (e.g. atom {}'s): atom IDs changed since the bond families were built "
               "('delete_atoms ... compress yes', reset_atom_ids), or the restart file is damaged",
               anybad, who);
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
  double *family = family_volume(), *weighted = weighted_volume();
  for (int i = 0; i < nall; i++) family[i] = weighted[i] = 0.0;
  const pd_bond_view v = view();
  pd_reference_volumes(&v, atom->vfrac, family, weighted);
  sum_to_owners(iweighted_volume);
  sum_to_owners(ifamily_volume);
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
  v.weight_horizon = 0.0;    // (the pair style knows when it may be set)
  return v;
}

// The rows of view(), with the partner tags and writable lengths the
// fracture record needs.
PDBondTable FixPDBonds::table() const
{
  const pd_bond_view v = view();
  return {v.nowner, v.stride, v.count, partner ? partner[0] : nullptr, r0 ? r0[0] : nullptr, v.far};
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

// the bond tables (owned rows, padded to the longest) and the per-atom
// arrays (owned and ghost atoms)
double FixPDBonds::memory_usage()
{
  int per_atom_fields = 0;
  for (const Field &f : fields) per_atom_fields += f.decl.width;
  const double tables = (double) nrows * (maxpartner * bytes_per_bond() + 5 * sizeof(void *));
  return tables + (double) atom->nmax * (sizeof(int) + sizeof(tagint) + per_atom_fields * sizeof(double));
}

/* ---------------------------------------------------------------------- */

// The loops of the four exchanges, with the width a constant where it is
// small (1: sums and notes, 2: a pair of per-atom values) and the reverse
// exchange's rule chosen outside them: per atom, generic loops cost about
// twice as much (PERI's rule: 2.8% of a step at 16^3).
namespace {
// W: the width, or 0 for w
template <int W> int pack_listed(const double *a, int width, int n, const int *list, double *buf)
{
  const int w = W ? W : width;
  for (int i = 0; i < n; i++)
    for (int c = 0; c < w; c++) buf[i * w + c] = a[list[i] * w + c];
  return n * w;
}

template <int W>
void unpack_listed(double *a, int width, int n, const int *list, const double *buf, bool max)
{
  const int w = W ? W : width;
  if (max) {
    for (int i = 0; i < n; i++)
      for (int c = 0; c < w; c++) a[list[i] * w + c] = MAX(a[list[i] * w + c], buf[i * w + c]);
  } else {
    for (int i = 0; i < n; i++)
      for (int c = 0; c < w; c++) a[list[i] * w + c] += buf[i * w + c];
  }
}
}    // namespace

int FixPDBonds::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  if (comm_width == 1) return pack_listed<1>(comm_array, 1, n, list, buf);
  if (comm_width == 2) return pack_listed<2>(comm_array, 2, n, list, buf);
  return pack_listed<0>(comm_array, comm_width, n, list, buf);
}

void FixPDBonds::unpack_forward_comm(int n, int first, double *buf)
{
  std::copy(buf, buf + (size_t) n * comm_width, comm_array + (size_t) first * comm_width);
}

int FixPDBonds::pack_reverse_comm(int n, int first, double *buf)
{
  const double *from = comm_array + (size_t) first * comm_width;
  std::copy(from, from + (size_t) n * comm_width, buf);
  return n * comm_width;
}

void FixPDBonds::unpack_reverse_comm(int n, int *list, double *buf)
{
  if (comm_width == 1) unpack_listed<1>(comm_array, 1, n, list, buf, comm_max);
  else if (comm_width == 2) unpack_listed<2>(comm_array, 2, n, list, buf, comm_max);
  else unpack_listed<0>(comm_array, comm_width, n, list, buf, comm_max);
}

/* ---------------------------------------------------------------------- */

// LAMMPS grows the per-atom arrays for owned and ghost atoms; the bond
// tables only hold owned atoms (grow_rows).
void FixPDBonds::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "pd/bonds:npartner");
  memory->grow(built_tag, nmax, "pd/bonds:built_tag");
  grow_fields(nmax);
}

// The bond tables have rows for owned atoms only: ghosts never own bonds
// here, and the kernels walk owned rows. A row is written only where an
// owned atom gets bonds: the build (rows 0 .. nlocal-1), an atom arriving
// (unpack_exchange, unpack_restart: row nlocal) and copy_arrays (an atom
// moved to another index, up to nlocal when LAMMPS sorts the atoms), each
// of which makes sure the row exists. So an atom with bonds always has
// its row (npartner[i] > 0 only for i < nrows); growth is geometric.
void FixPDBonds::grow_rows(int n)
{
  if (n <= nrows) return;
  if (nrows > 0) n = MAX(n, nrows + nrows / 8 + 64);
  const int kept = nrows;
  nrows = n;
  PDTableMemory::grow(error, partner, nrows, maxpartner, kept, "partner");
  PDTableMemory::grow(error, r0, nrows, maxpartner, kept, "r0");
  PDTableMemory::grow(error, far, nrows, maxpartner, kept, "far");
  if (use_weights) PDTableMemory::grow(error, weight, nrows, maxpartner, kept, "weight");
  if (nhistory) PDTableMemory::grow(error, history, nrows, maxpartner * nhistory, kept, "history");
}

void FixPDBonds::destroy_tables()
{
  PDTableMemory::destroy(partner);
  PDTableMemory::destroy(r0);
  PDTableMemory::destroy(weight);
  PDTableMemory::destroy(history);
  PDTableMemory::destroy(far);
  nrows = 0;
}

void FixPDBonds::copy_arrays(int i, int j, int)
{
  if (npartner[i] > 0) ensure_row(j);
  npartner[j] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) {
    partner[j][k] = partner[i][k];
    r0[j][k] = r0[i][k];
    if (use_weights) weight[j][k] = weight[i][k];
  }
  for (int h = 0; h < npartner[i] * nhistory; h++) history[j][h] = history[i][h];
  built_tag[j] = built_tag[i];
  for (Field &f : fields)
    for (int w = 0; w < f.decl.width; w++) f.data[j * f.decl.width + w] = f.data[i * f.decl.width + w];
}

// Atoms created after the families were built join without bonds.
void FixPDBonds::set_arrays(int i)
{
  npartner[i] = 0;
  built_tag[i] = 0;
  for (Field &f : fields)
    for (int w = 0; w < f.decl.width; w++) f.data[i * f.decl.width + w] = 0.0;
}

// doubles of one atom's exchange (flag MIGRATE) or restart (RESTART) record
int FixPDBonds::per_atom_doubles(int i, int flag) const
{
  return PER_ATOM_FIXED + field_doubles(flag) + npartner[i] * (2 + use_weights + nhistory);
}

// Layout shared by exchange and restart: count, own tag at build, the
// fields flagged MIGRATE (exchange) or RESTART (restart, in the order the
// global record lists them), then per bond: tag, r0 (its sign: broken)
// [, weight] [, history].
int FixPDBonds::pack_exchange(int i, double *buf)
{
  return pack_atom(i, buf, PDField::MIGRATE);
}

int FixPDBonds::unpack_exchange(int i, double *buf)
{
  return unpack_atom(i, buf, PDField::MIGRATE);
}

int FixPDBonds::pack_atom(int i, double *buf, int flag) const
{
  int m = 0;
  buf[m++] = ubuf(npartner[i]).d;
  buf[m++] = ubuf(built_tag[i]).d;
  m += pack_fields(i, buf + m, flag);
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    buf[m++] = r0[i][k];
    if (use_weights) buf[m++] = weight[i][k];
    for (int h = 0; h < nhistory; h++) buf[m++] = history[i][k * nhistory + h];
  }
  return m;
}

int FixPDBonds::unpack_atom(int i, const double *buf, int flag)
{
  int m = 0;
  const bigint count = ubuf(buf[m++]).i;
  if (count < 0 || count > maxpartner) {
    // a damaged record: said collectively at the next mapping (check_stored_partners)
    if (!damaged) damaged_example = count;
    damaged++;
    npartner[i] = 0;
    return m;
  }
  npartner[i] = (int) count;
  if (count > 0) ensure_row(i);
  built_tag[i] = (tagint) ubuf(buf[m++]).i;
  m += unpack_fields(i, buf + m, flag);
  for (int k = 0; k < npartner[i]; k++) {
    partner[i][k] = (tagint) ubuf(buf[m++]).i;
    r0[i][k] = buf[m++];
    if (use_weights) weight[i][k] = buf[m++];
    for (int h = 0; h < nhistory; h++) history[i][k * nhistory + h] = buf[m++];
  }
  return m;
}

// write_data calls this on rank 0 while it writes the header: the one hook
// LAMMPS gives a fix there. A data file keeps positions, not the bonds, the
// reference shape or the damage; say so on the screen, and in the file as a
// comment (read_data skips it).
void FixPDBonds::write_data_header(FILE *fp, int)
{
  if (!built) return;
  error->warning(FLERR, "Fix pd/bonds: write_data does not store the bond families (reference "
                 "positions, broken bonds, damage): read_data makes an intact body in its current "
                 "shape; continue a cracked body from a restart file (write_restart)");
  fputs("# PERIDYNAMICS_EXT: no bond families, reference positions or damage in data files; "
        "continue a cracked body from a restart file\n", fp);
}

// New row length of the per-atom bond tables (their contents are dropped:
// memory->grow cannot change the row length of a 2D array in place), with
// rows for the owned atoms.
void FixPDBonds::resize_tables(int rowlength)
{
  maxpartner = rowlength;
  maxexchange = per_atom_max(PDField::MIGRATE);
  destroy_tables();
  grow_rows(atom->nlocal + 1);
}

// Shorter rows for the bond tables, keeping the first 'rowlength' slots
// of each (in place).
void FixPDBonds::shorten_rows(int rowlength)
{
  if (rowlength >= maxpartner) return;
  PDTableMemory::narrow(partner, nrows, maxpartner, rowlength);
  PDTableMemory::narrow(r0, nrows, maxpartner, rowlength);
  PDTableMemory::narrow(far, nrows, maxpartner, rowlength);
  if (use_weights) PDTableMemory::narrow(weight, nrows, maxpartner, rowlength);
  if (nhistory) PDTableMemory::narrow(history, nrows, maxpartner * nhistory, rowlength * nhistory);
  maxpartner = rowlength;
  maxexchange = per_atom_max(PDField::MIGRATE);
}

// An atom's restart record: its length, the exchange layout with the
// RESTART fields, and the checksum of those values.
int FixPDBonds::pack_restart(int i, double *buf)
{
  const int n = pack_atom(i, buf + 1, PDField::RESTART);
  buf[n + 1] = pd_record_checksum_value(buf + 1, n);
  buf[0] = n + 2;
  return n + 2;
}

// A record whose length is not what its bond count and the global record's
// field list make, or whose values fail their checksum, is damaged (said
// collectively at the first mapping).
void FixPDBonds::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const double *record = &extra[nlocal][m];
  const double length = record[0];
  if (!(length >= 2 && length <= maxsize_restart()) ||
      pd_record_checksum_value(record + 1, (int) length - 2) != record[(int) length - 1]) {
    if (!damaged) damaged_example = -1;
    damaged++;
    npartner[nlocal] = 0;
    return;
  }
  const bigint before = damaged;
  const int used = unpack_atom(nlocal, record + 1, PDField::RESTART);
  if (damaged == before && used + 2 != (int) length) {
    if (!damaged) damaged_example = npartner[nlocal];
    damaged++;
    npartner[nlocal] = 0;
  }
}

int FixPDBonds::size_restart(int i)
{
  return per_atom_doubles(i, PDField::RESTART) + 2;
}

int FixPDBonds::per_atom_max(int flag) const
{
  return PER_ATOM_FIXED + field_doubles(flag) + maxpartner * (2 + use_weights + nhistory);
}

int FixPDBonds::maxsize_restart()
{
  return per_atom_max(PDField::RESTART) + 2;
}

// bond k of atom i in the reference configuration (minimum image)
void FixPDBonds::reference_vector(int i, int k, double xi[3]) const
{
  double **x0 = atom->x0;
  const int j = far[i][k];
  for (int d = 0; d < 3; d++) xi[d] = x0[j][d] - x0[i][d];
  PDCompat::minimum_image(domain, xi);
}

void FixPDBonds::each_reference_bond(const std::function<void(int, int, const double *, double)> &visit) const
{
  for (int i = 0; i < nowned; i++)
    for (int k = 0; k < npartner[i]; k++) {
      double xi[3];
      reference_vector(i, k, xi);
      visit(i, far[i][k], xi, use_weights ? weight[i][k] : 1.0);
    }
}

void FixPDBonds::scale_weights(const std::function<double(int, int, const double *)> &factor)
{
  if (!use_weights || !weights_fresh)
    error->all(FLERR, "Fix pd/bonds: bond weights scaled twice or without weights (a bug)");
  for (int i = 0; i < nowned; i++)
    for (int k = 0; k < npartner[i]; k++) {
      double xi[3];
      reference_vector(i, k, xi);
      weight[i][k] *= factor(i, far[i][k], xi);
    }
  weights_fresh = false;
  reference_sums();
}

bigint FixPDBonds::cut_crossing(const pd_crack &crack, int groupbit)
{
  double **x0 = atom->x0;
  const int *mask = atom->mask;
  bigint mine = 0;
  for (int i = 0; i < nowned; i++)
    for (int k = 0; k < npartner[i]; k++) {
      const int j = far[i][k];
      if (r0[i][k] < 0.0 || !(mask[i] & groupbit) || !(mask[j] & groupbit)) continue;
      double d[3];
      reference_vector(i, k, d);
      const double q[3] = {x0[i][0] + d[0], x0[i][1] + d[1], x0[i][2] + d[2]};
      if (pd_crack_crosses(&crack, x0[i], q)) {
        r0[i][k] = -r0[i][k];
        mine++;
      }
    }
  record.add_cut(mine);
  bigint total = 0;
  MPI_Allreduce(&mine, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total > 0) record.set_has_broken();
  return total;
}

void FixPDBonds::remember_cut(const std::string &fixid, const pd_crack &crack, int groupbit)
{
  for (PendingCut &c : pending_cuts)
    if (c.fixid == fixid) {
      c.crack = crack;
      c.groupbit = groupbit;
      return;
    }
  pending_cuts.push_back({fixid, crack, groupbit});
}
