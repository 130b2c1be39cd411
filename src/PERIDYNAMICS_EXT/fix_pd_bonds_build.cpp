/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: building the bond families of fix pd/bonds.

   Once, on the first run, from the reference positions x0, without a
   LAMMPS neighbor list: owned and ghost atoms are sorted into cells by
   their reference position (core/pd_cell_bins.h), taken in the periodic
   image of their current position, and each owned atom looks at the atoms
   of the cells within reach of it. Its candidates are kept in a list per
   atom (the tables are rectangular: their row length, the longest list
   over all ranks, must be known before they are filled); the cells are
   freed, and the tables filled from the lists, storing each far end as the
   image it found, before the far ends are checked (map_partners). The
   lists give their memory back as they are read, so the build's peak is
   the tables' (the lists are about 4 bytes a bond).

   Which candidates become bonds, and what they store, is decided exactly
   as before the cells existed: the minimum image of x0_j - x0_i, the
   family spec's test and weight. A periodic box is longer than twice the
   reach in every direction (PairPD::check_box), so at most one image of a
   partner lies within reach: the pair is stored once (owns_bond), with
   that image. The ghost atoms of LAMMPS (horizon + skin around the
   subdomain, in current positions) hold every partner as long as atoms
   have moved less than the skin from their reference positions.
------------------------------------------------------------------------- */

#include "fix_pd_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "pd_compat.h"
#include "pd_table_memory.h"

#include <cmath>
#include <ctime>
#include <vector>

extern "C" {
#include "pd_cell_bins.h"
}

using namespace LAMMPS_NS;

namespace {

// The reference bond vector x0_j - x0_i, minimum image. From j it is
// exactly the negative: a difference and the image's period shifts are
// exact under negation.
inline void reference_bond(Domain *domain, double **x0, int i, int j, double xi[3])
{
  for (int c = 0; c < 3; c++) xi[c] = x0[j][c] - x0[i][c];
  PDCompat::minimum_image(domain, xi);
}

// Which end stores a bond: the one from which its reference vector points
// up (z > 0; on a plane of z, y > 0; on a line, x > 0); for coincident
// atoms (refused later) the smaller tag. Exactly one end, since the other
// sees -xi. Every atom of a lattice then stores the same number of bonds
// (the tables are padded to the longest row), and they reach the atoms
// after it in LAMMPS's order (create_atoms and atom sorting number atoms
// along z last): the force loop's far ends are the next planes only.
inline bool owns_bond(const double xi[3], tagint me, tagint other)
{
  for (int c = 2; c >= 0; c--)
    if (xi[c] != 0.0) return xi[c] > 0.0;
  return me < other;
}

// Cells of a third of the reach: a query scans about 2.3 times the atoms
// within reach (cells of the whole reach: 6 times).
constexpr double CELLS_PER_REACH = 3.0;

// Owned and ghost atoms at their reference positions, each moved by whole
// box periods to the image nearest its current position: a ghost carries
// its owner's x0 unshifted, and an owned atom's x0 lies outside the box once
// the atom has crossed a periodic boundary. Periods are counted in box
// units (lamda), so tilted boxes work too.
void reference_images(Atom *atom, Domain *domain, double *y)
{
  const int nall = atom->nlocal + atom->nghost;
  double **x = atom->x, **x0 = atom->x0;
  const double *h = domain->h, *hinv = domain->h_inv;
  const bool tilted = domain->triclinic;
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  for (int i = 0; i < nall; i++) {
    const double d[3] = {x[i][0] - x0[i][0], x[i][1] - x0[i][1], x[i][2] - x0[i][2]};
    double n[3] = {hinv[0] * d[0], hinv[1] * d[1], hinv[2] * d[2]};
    if (tilted) {
      n[0] += hinv[5] * d[1] + hinv[4] * d[2];
      n[1] += hinv[3] * d[2];
    }
    for (int k = 0; k < 3; k++) n[k] = periodic[k] ? std::nearbyint(n[k]) : 0.0;
    double shift[3] = {h[0] * n[0], h[1] * n[1], h[2] * n[2]};
    if (tilted) {
      shift[0] += h[5] * n[1] + h[4] * n[2];
      shift[1] += h[3] * n[2];
    }
    for (int k = 0; k < 3; k++) y[3 * i + k] = x0[i][k] + shift[k];
  }
}

// The atoms whose reference image lies within reach of an owned atom's
// (and a little farther: round-off; the caller's tests are exact).
class Neighbourhood {
 public:
  Neighbourhood(LAMMPS *lmp, double reach) :
      domain(lmp->domain), x0(lmp->atom->x0), flat(lmp->domain->dimension == 2),
      tie(margin(lmp->domain, reach)), cut(reach + tie)
  {
    Atom *atom = lmp->atom;
    const int nall = atom->nlocal + atom->nghost;
    {
      PDTableMemory::Block<double> y(3 * (size_t) nall + 3);
      if (y.data) reference_images(atom, lmp->domain, y.data);
      const double side = reach > 0.0 ? reach / CELLS_PER_REACH : 1.0;    // (no reach: no bonds)
      const int status = y.data ? pd_cell_bins_build(&bins, y.data, nall, side, 2L * nall + 64) : -2;
      if (status)
        lmp->error->one(FLERR, "Fix pd/bonds: cannot sort the atoms into cells to build the bond "
                        "families ({})", status == -1 ? "a reference position is not finite" : "out of memory");
    }
    runs.resize(2 * (size_t) pd_cell_bins_max_runs(&bins, cut));
    slot.resize(atom->nlocal);
    tags.resize(nall);
    for (int s = 0; s < nall; s++) {
      if (bins.index[s] < atom->nlocal) slot[bins.index[s]] = s;
      tags[s] = atom->tag[bins.index[s]];
    }
  }
  ~Neighbourhood() { pd_cell_bins_free(&bins); }
  Neighbourhood(const Neighbourhood &) = delete;
  Neighbourhood &operator=(const Neighbourhood &) = delete;

  // y_j - y_i differs from the minimum image of x0_j - x0_i by round-off
  static double margin(const Domain *domain, double reach)
  {
    double scale = 0.0;
    for (int d = 0; d < 3; d++) scale += fabs(domain->boxlo[d]) + fabs(domain->boxhi[d]);
    if (domain->triclinic) scale += fabs(domain->xy) + fabs(domain->xz) + fabs(domain->yz);
    return 1e-9 * reach + 1e-12 * scale;
  }

  // The atoms j near owned atom i that i would store (owns_bond), in the
  // order of the cells: atom(c) and its squared distance (reference
  // images) d2(c) for c below the count returned. The reference images'
  // z (2D: y) decides who stores a bond unless it is within round-off of
  // zero: then the exact reference vector does.
  int gather(int i)
  {
    const int me = slot[i];
    const double *p = bins.pos + 3 * (size_t) me;
    const tagint mytag = tags[me];
    const double cutsq = cut * cut;
    int(*run)[2] = reinterpret_cast<int(*)[2]>(runs.data());
    // only the cells that can hold a partner above (up >= -tie below;
    // twice that margin for the round-off of p - tie)
    const int axis = flat ? 1 : 2;
    const int nrun = pd_cell_bins_runs(&bins, p, cut, axis, p[axis] - 2.0 * tie, run);
    size_t scanned = 0;
    for (int q = 0; q < nrun; q++) scanned += run[q][1] - run[q][0];
    if (scanned > js.size()) {
      js.resize(scanned);
      d2s.resize(scanned);
    }
    int n = 0;
    for (int q = 0; q < nrun; q++)
      for (int s = run[q][0]; s < run[q][1]; s++) {
        const double *o = bins.pos + 3 * (size_t) s;
        const double dx = o[0] - p[0], dy = o[1] - p[1], dz = o[2] - p[2];
        const double d2 = dx * dx + dy * dy + dz * dz;
        // (written always, kept if near and stored here)
        const int j = bins.index[s];
        js[n] = j;
        d2s[n] = d2;
        const double up = flat ? dy : dz;
        if (!(d2 <= cutsq) || up < -tie) continue;
        if (up <= tie) {
          double xi[3];
          reference_bond(domain, x0, i, j, xi);
          if (!owns_bond(xi, mytag, tags[s])) continue;
        }
        n++;
      }
    return n;
  }
  int atom(int c) const { return js[c]; }
  double d2(int c) const { return d2s[c]; }

 private:
  Domain *domain;
  double **x0;
  bool flat;     // 2D: every z is 0
  double tie;    // the round-off of the reference images' differences
  double cut;
  pd_cell_bins bins;
  std::vector<int> runs;    // pairs: begin, end of a run of sorted atoms
  std::vector<int> slot;    // an owned atom's place among the sorted atoms
  std::vector<tagint> tags; // the sorted atoms' tags
  std::vector<int> js;      // the last gather's atoms
  std::vector<double> d2s;  // and their squared distances
};

// Lists of atoms, one per owned atom, one after another (the family
// build's candidates: about as many as the bonds).
class CandidateLists {
 public:
  CandidateLists(LAMMPS *lmp, int nrows) : error(lmp->error), start(nrows + 1, 0), items(0) {}

  // room for n atoms in the next list
  int *room(int n)
  {
    const size_t end = start[filled], need = end + n;
    if (need > capacity) {
      // the lists so far, projected over all rows, and a margin
      const size_t rows = start.size() - 1;
      const size_t projected = need + need / (filled + 1) * (rows - filled) / 16 * 17 + 1024;
      capacity = MAX(projected, capacity + capacity / 2);
      if (!items.resize(capacity, end))
        error->one(FLERR, "Fix pd/bonds: out of memory for the candidate bonds ({} atoms)", capacity);
    }
    return items.data + end;
  }
  // the next list holds the first n atoms of its room
  void close(int n)
  {
    start[filled + 1] = start[filled] + n;
    filled++;
  }
  const int *list(int i) const { return items.data + start[i]; }
  int length(int i) const { return (int) (start[i + 1] - start[i]); }
  // the lists before list i are read: their memory goes back (the tables
  // they fill grow as they shrink)
  void read_before(int i) { pd_pages_release(items.data, start[i] * sizeof(int)); }

 private:
  Error *error;
  std::vector<size_t> start;
  PDTableMemory::Block<int> items;
  size_t capacity = 0;
  int filled = 0;
};

}    // namespace

// The longest reach of a bond between two types of this style (types of
// another hybrid sub-style have no horizon: NaN).
static double longest_reach(const PDFamilySpec &spec)
{
  double reach = 0.0;
  for (int a = 1; a <= spec.ntypes; a++)
    for (int b = 1; b <= spec.ntypes; b++)
      if (spec.reach(a, b) > reach) reach = spec.reach(a, b);
  return reach;
}

void FixPDBonds::build_families()
{
  const double wall0 = MPI_Wtime(), cpu0 = (double) std::clock() / CLOCKS_PER_SEC;
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  const int *type = atom->type;
  double **x0 = atom->x0;

  // a candidate becomes a bond if the family spec says so (its reference
  // distance within the horizon, or with partial volumes a share of its
  // cell inside it). g: the candidate's geometry, for its weight.
  const double *vol = atom->vfrac;
  PDBondGeometry g;
  auto candidate = [&](int i, int j) {
    reference_bond(domain, x0, i, j, g.xi);
    g.r = sqrt(g.xi[0] * g.xi[0] + g.xi[1] * g.xi[1] + g.xi[2] * g.xi[2]);
    g.vi = vol[i];
    g.vj = vol[j];
    g.horizon = spec.horizon(type[i], type[j]);
    // a weight of zero (tupek's influence at the horizon, a partial cell
    // beyond it) is no bond: it would carry nothing, and a failure law
    // would see its zero threshold reached and "break" it at once
    return spec.is_bond(g) && (!use_weights || spec.bond_weight(g) > 0.0);
  };

  // the squared reach of each type pair, with the round-off margin of the
  // reference images (-1: no bonds)
  const int nt = atom->ntypes + 1;
  std::vector<double> reachsq(nt * nt, -1.0);
  for (int a = 1; a < nt; a++)
    for (int b = 1; b < nt; b++) {
      const double r = spec.reach(a, b);
      if (r > 0.0) reachsq[a * nt + b] = std::pow(r + Neighbourhood::margin(domain, r), 2);
    }
  std::vector<bigint> touching(nt * nt, 0);
  int differs = 0, mylongest = 0, coincident = 0;
  // the candidates each atom would store (its bonds and a few more, before
  // the exact test), to size the tables (their rows are as long as the
  // longest list); and the type pairs whose atoms come within one of the
  // two types' horizons (each pair is seen at the end that would store it)
  {
    CandidateLists candidates(lmp, nlocal);
    int mymax = 0;
    {
      Neighbourhood near(lmp, longest_reach(spec));
      for (int i = 0; i < nlocal; i++) {
        const int ncand = near.gather(i);
        const double *rsq = &reachsq[type[i] * nt];
        int *list = candidates.room(ncand), n = 0;
        for (int c = 0; c < ncand; c++) {
          list[n] = near.atom(c);
          n += near.d2(c) <= rsq[type[near.atom(c)]];
        }
        candidates.close(n);
        mymax = MAX(mymax, n);
        if (nt == 2) continue;
        for (int c = 0; c < ncand; c++) {
          const int j = near.atom(c);
          const int a = MIN(type[i], type[j]), b = MAX(type[i], type[j]);
          if (a == b || touching[a * nt + b]) continue;
          double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
          PDCompat::minimum_image(domain, d);
          const double reach = MAX(spec.horizon(a, a), spec.horizon(b, b));
          touching[a * nt + b] = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= reach * reach;
        }
      }
    }
    int longest;
    MPI_Allreduce(&mymax, &longest, 1, MPI_INT, MPI_MAX, world);
    resize_tables(MAX(longest, 1));

    // fill: the bonds among the candidates
    for (int i = 0; i < nlocal; i++) {
      if (i % 1024 == 0) candidates.read_before(i);
      npartner[i] = 0;
      built_tag[i] = tag[i];
      const int *list = candidates.list(i), ncand = candidates.length(i);
      const double coincident_length = 1e-12 * spec.horizon(type[i], type[i]);
      for (int c = 0; c < ncand; c++) {
        const int j = list[c];
        if (!candidate(i, j)) continue;
        const int k = npartner[i];
        if (k == maxpartner) {
          differs = 1;
          break;
        }
        npartner[i]++;
        partner[i][k] = tag[j];
        far[i][k] = j;
        r0[i][k] = g.r;
        coincident |= g.r <= coincident_length;
        if (use_weights) weight[i][k] = spec.bond_weight(g);
        for (int h = 0; h < nhistory; h++) history[i][k * nhistory + h] = 0.0;
      }
      mylongest = MAX(mylongest, npartner[i]);
    }
  }
  if (differs) error->one(FLERR, "Fix pd/bonds: a bond that was not counted (a bug in the family build)");
  // rows as long as the longest family, not its candidates
  int longest;
  MPI_Allreduce(&mylongest, &longest, 1, MPI_INT, MPI_MAX, world);
  shorten_rows(MAX(longest, 1));

  int any_coincident;
  MPI_Allreduce(&coincident, &any_coincident, 1, MPI_INT, MPI_MAX, world);
  if (any_coincident)
    error->all(FLERR, "Fix pd/bonds: two atoms share a reference position (x0); peridynamic "
               "bonds need distinct positions");
  built = 1;
  weights_fresh = use_weights != 0;
  map_partners(true, true);
  reference_sums();
  double *built_volume = field(ibuild_volume);
  for (int i = 0; i < nlocal; i++) built_volume[i] = atom->vfrac[i];
  // cracks of a restart file written before the first run (their fixes
  // need not exist any more); this run's pd/precrack fixes cut for themselves
  bigint precut = 0;
  for (const PendingCut &c : pending_cuts)
    if (c.fixid.empty()) precut += cut_crossing(c.crack, c.groupbit);
  pending_cuts.clear();

  bigint nbonds = 0, mybonds = 0;
  for (int i = 0; i < nlocal; i++) mybonds += npartner[i];
  MPI_Allreduce(&mybonds, &nbonds, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  // what the tables take per bond, with the rows' padding to the longest
  bigint slots = (bigint) nrows * maxpartner, allslots = 0;
  MPI_Allreduce(&slots, &allslots, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  report_bonds_by_type(touching);
  double took[2] = {MPI_Wtime() - wall0, (double) std::clock() / CLOCKS_PER_SEC - cpu0}, most[2];
  MPI_Allreduce(took, most, 2, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me == 0) {
    const double bytes = bytes_per_bond();
    utils::logmesg(lmp,
                   "pd/bonds: {} bonds, {:.2f} bonds per atom (each stored once), "
                   "up to {} owned per atom, {:.0f} bytes per bond ({:.1f} with the tables' padding)\n",
                   nbonds, 2.0 * nbonds / MAX(atom->natoms, 1), maxpartner, bytes,
                   bytes * allslots / MAX(nbonds, 1));
    utils::logmesg(lmp, "pd/bonds: families built in {:.3g} s ({:.3g} s CPU, slowest rank)\n",
                   most[0], most[1]);
    if (precut)
      utils::logmesg(lmp, "pd/bonds: {} bonds cut by the pre-cracks saved in the restart file\n", precut);
  }
}
