/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/contact (MS07 eq. 32-34).
     pair_style pd/contact [friction <mu>] [legacy] [skin <s>]
     pair_coeff I J [stiffness <c_s>] [distance <d>]
   Used next to a pd/ material style with pair_style hybrid/overlay, or
   alone with explicit stiffness. Pairs of atoms that were bond partners in
   the reference configuration never get contact forces: the material
   pushes them (broken bonds resist compression, T14 6.1.3), so no pair is
   pushed twice.
------------------------------------------------------------------------- */

#include "pair_pd_contact.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_pd.h"
#include "pd_compat.h"
#include "pd_contact_cache.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

extern "C" {
#include "pd_contact.h"
#include "pd_tangent.h"
}

using namespace LAMMPS_NS;

// default skin of the short list, in contact distances (doc/pair_pd_contact.md)
static constexpr double SHORT_SKIN = 0.25;

PairPDContact::PairPDContact(LAMMPS *lmp) :
    Pair(lmp), stiffness(nullptr), distance(nullptr), cutmax_contact(0.0), material(nullptr),
    friction(0.0), legacy(0), dim(3), thickness(0.0), skin_short(NAN), skin_used(0.0), report(0),
    cache(new PDContactCache(lmp)), cache_build(-1), legacy_c(nullptr), legacy_delta(nullptr)
{
  restartinfo = 1;
  single_enable = 0;
  no_virial_fdotr_compute = 1;
}

PairPDContact::~PairPDContact()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(stiffness);
    memory->destroy(distance);
    memory->destroy(legacy_c);
    memory->destroy(legacy_delta);
  }
  delete cache;
}

void PairPDContact::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(stiffness, n + 1, n + 1, "pair:stiffness");
  memory->create(distance, n + 1, n + 1, "pair:distance");
  memory->create(legacy_c, n + 1, n + 1, "pair:legacy_c");
  memory->create(legacy_delta, n + 1, n + 1, "pair:legacy_delta");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) {
      setflag[i][j] = 0;
      stiffness[i][j] = distance[i][j] = NAN;
    }
}

void PairPDContact::settings(int narg, char **arg)
{
  friction = 0.0;
  legacy = 0;
  skin_short = NAN;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (strcmp(arg[iarg], "legacy") == 0) {
      legacy = 1;
      iarg--;
      continue;
    }
    if (strcmp(arg[iarg], "friction") != 0 && strcmp(arg[iarg], "skin") != 0)
      error->all(FLERR, "Pair style pd/contact: unknown keyword '{}' (friction, legacy, skin)", arg[iarg]);
    if (iarg + 1 >= narg) error->all(FLERR, "Pair style pd/contact: '{}' needs a value", arg[iarg]);
    const double v = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (!(v >= 0.0) || !std::isfinite(v))
      error->all(FLERR, "Pair style pd/contact: {} must be a finite number >= 0, got '{}'",
                 strcmp(arg[iarg], "skin") == 0 ? "skin" : "friction coefficient", arg[iarg + 1]);
    if (strcmp(arg[iarg], "skin") == 0) skin_short = v;
    else friction = v;
  }
}

void PairPDContact::coeff(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "Incorrect args for pair coefficients");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  double cs = NAN, d = NAN;
  for (int iarg = 2; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) error->all(FLERR, "Pair pd/contact coeff: '{}' needs a value", arg[iarg]);
    const double v = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (strcmp(arg[iarg], "stiffness") == 0) cs = v;
    else if (strcmp(arg[iarg], "distance") == 0) d = v;
    else error->all(FLERR, "Pair pd/contact coeff: unknown keyword '{}' (stiffness, distance)", arg[iarg]);
    if (!(v > 0.0) || !std::isfinite(v))
      error->all(FLERR, "Pair pd/contact coeff: {} must be a positive finite number, got '{}'",
                 arg[iarg], arg[iarg + 1]);
  }
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      stiffness[i][j] = cs;
      distance[i][j] = d;
      setflag[i][j] = 1;
    }
}

void PairPDContact::init_style()
{
  if (!atom->vfrac_flag || !atom->x0)
    error->all(FLERR, "Pair pd/contact requires atom_style peri (volumes and reference positions)");
  if (!force->newton_pair) error->all(FLERR, "Pair pd/contact needs 'newton on'");
  if (friction > 0.0 && !comm->ghost_velocity)
    error->all(FLERR, "Pair pd/contact with friction needs the ghosts' velocities: 'comm_modify vel yes'");
  material = PairPD::active(force);
  dim = domain->dimension;
  thickness = material ? material->plate_thickness() : 0.0;
  if (dim == 2 && !(thickness > 0.0))
    error->all(FLERR, "Pair pd/contact in 2D takes the plate thickness from the pd/ material style");

  // the list's cutoff: the largest contact distance, from the largest volume
  double vmax = 0.0, v;
  for (int i = 0; i < atom->nlocal; i++) vmax = MAX(vmax, atom->vfrac[i]);
  MPI_Allreduce(&vmax, &v, 1, MPI_DOUBLE, MPI_MAX, world);
  cutmax_contact = 2.0 * pd_contact_radius(dim, v, thickness);
  if (legacy) {
    if (!material || !(material->legacy_spacing() > 0.0))
      error->all(FLERR, "Pair pd/contact legacy needs a pd/ material style in legacy mode "
                 "(hybrid/overlay), whose lattice spacing sets the contact distance");
    if (friction > 0.0) error->all(FLERR, "Pair pd/contact legacy has no friction (PERI has none)");
    cutmax_contact = 1.35 * material->legacy_spacing();
  }
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (!std::isnan(distance[i][j])) cutmax_contact = MAX(cutmax_contact, distance[i][j]);

  // a half list of its own, with its own short cutoff: not the horizon
  PDCompat::request_pair_with_cutoff(neighbor, this, instance_me, cutmax_contact);
  report = 1;
  cache_build = -1;
  // the short list's skin: by default a quarter of the contact distance; no
  // use beyond the neighbor skin, within which LAMMPS's list is valid
  skin_used = MIN(std::isnan(skin_short) ? SHORT_SKIN * cutmax_contact : skin_short, neighbor->skin);
}

double PairPDContact::init_one(int i, int j)
{
  if (!setflag[i][j]) {
    stiffness[i][j] = 0.5 * (stiffness[i][i] + stiffness[j][j]);
    distance[i][j] = 0.5 * (distance[i][i] + distance[j][j]);
  }
  // default stiffness: 15 times the material's micromodulus (MS07). Two
  // types take the harmonic mean of their own values: the softer body sets
  // it (twice the two springs in series, so a type with itself keeps its
  // own). Not a value from the interface's horizon, which is often set
  // below the spacing to keep bodies unbonded.
  if (std::isnan(stiffness[i][j]) && material) {
    const double ci = material->contact_micromodulus(i, i), cj = material->contact_micromodulus(j, j);
    stiffness[i][j] = 15.0 * 2.0 * ci * cj / (ci + cj);
  }
  if (std::isnan(stiffness[i][j]))
    error->all(FLERR, "Pair pd/contact coeff {} {}: without a pd/ material style (hybrid/overlay) "
               "give 'stiffness <c_s>'", i, j);
  stiffness[j][i] = stiffness[i][j];
  distance[j][i] = distance[i][j];
  return cutmax_contact;
}

// Keep the candidates that were not bond partners: reference distance
// beyond the material's horizon (all of them without a material style),
// each with its contact distance; then the short list.
void PairPDContact::filter_pairs()
{
  double **x0 = atom->x0;
  const int *type = atom->type;
  const double *vol = atom->vfrac;
  cache->clear();
  bigint candidates = 0;
  const double lc = legacy ? material->legacy_spacing() : 0.0;
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  if (legacy)
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = 1; j <= atom->ntypes; j++) {
        legacy_c[i][j] = material->contact_micromodulus(i, j);
        legacy_delta[i][j] = material->horizon(i, j);
      }
  // which reference pairs are bonds: the material's rule (with partial
  // volumes some reach past the horizon)
  const PDFamilySpec spec = material && !legacy ? material->family_spec() : PDFamilySpec();
  PDBondGeometry g;
  // the list's own cutoff, applied here too: newer LAMMPS serves a
  // request whose cutoff is below every pair cutoff with the full list
  double **x = atom->x;
  const double cut = cutmax_contact + neighbor->skin, cut2 = cut * cut;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
      if (dx * dx + dy * dy + dz * dz > cut2) continue;
      candidates++;
      if (legacy) {
        // PERI: every neighbour pair, bonded or not, at min(0.9 |xi|, 1.35 lc)
        double d0[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
        if (periodic) PDCompat::minimum_image(domain, d0);
        cache->add(i, j, MIN(0.9 * sqrt(d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2]), 1.35 * lc));
        continue;
      }
      if (material) {
        double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
        if (periodic) PDCompat::minimum_image(domain, d);
        const double reach = spec.reach(type[i], type[j]), d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (d2 <= reach * reach) {
          if (!spec.fraction) continue;    // point quadrature: every pair within the horizon
          for (int c = 0; c < 3; c++) g.xi[c] = d[c];
          g.r = sqrt(d2);
          g.vi = atom->vfrac[i];
          g.vj = atom->vfrac[j];
          g.horizon = spec.horizon(type[i], type[j]);
          if (spec.is_bond(g)) continue;
        }
      }
      const int ti = type[i], tj = type[j];
      cache->add(i, j, std::isnan(distance[ti][tj])
                 ? pd_contact_radius(dim, vol[i], thickness) + pd_contact_radius(dim, vol[j], thickness)
                 : distance[ti][tj]);
    }
  }
  cache->settle(skin_used);
  if (report) {
    report = 0;
    report_stable_dt();
    bigint mine[3] = {candidates, cache->ncandidates(), cache->npairs()}, all[3];
    MPI_Allreduce(mine, all, 3, MPI_LMP_BIGINT, MPI_SUM, world);
    const double per_atom = 2.0 / MAX(atom->natoms, 1);
    if (comm->me == 0)
      utils::logmesg(lmp, "pd/contact: list cutoff {:.6g} (contact distance {:.6g} + skin): {:.2f} "
                     "neighbours per atom, {:.2f} of them candidates for contact{}; {}\n",
                     cutmax_contact + neighbor->skin, cutmax_contact, per_atom * all[0], per_atom * all[1],
                     legacy ? " (legacy: all pairs)" : " (never bond partners)",
                     skin_used > 0.0 ? fmt::format("short list (skin {:.6g}): {:.2f} neighbours per atom",
                                                   skin_used, per_atom * all[2])
                                     : std::string("no short list (skin 0)"));
    if (comm->me == 0 && !legacy) {
      std::string line = "pd/contact: stiffness c_s";
      for (int i = 1; i <= atom->ntypes; i++)
        for (int j = i; j <= atom->ntypes; j++) line += fmt::format(" {}-{} {:.6g}", i, j, stiffness[i][j]);
      utils::logmesg(lmp, line + "\n");
    }
  }
}

// The contact springs have their own stable step, which the material's
// estimate does not include: a particle pressed by its 2d nearest
// neighbours (d = dimension) at the contact distance, linearized,
// dt = sqrt(2 rho dist / (2d c_s V)), the smallest over the atoms.
void PairPDContact::report_stable_dt()
{
  double mine = INFINITY;
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const int ti = type[i];
    for (int tj = 1; tj <= atom->ntypes; tj++) {
      const double dist = legacy ? 0.9 * 2.0 * pd_contact_radius(dim, atom->vfrac[i], thickness)
          : (std::isnan(distance[ti][tj]) ? 2.0 * pd_contact_radius(dim, atom->vfrac[i], thickness)
                                          : distance[ti][tj]);
      const double cs = legacy ? 15.0 * material->contact_micromodulus(ti, tj) * dist /
                                     material->horizon(ti, tj)
                               : stiffness[ti][tj];
      // a = ftm2v f / m in every unit system
      const double dt = sqrt(2.0 * atom->rmass[i] * dist / (2.0 * dim * force->ftm2v * cs * atom->vfrac[i]));
      mine = MIN(mine, dt);
    }
  }
  double dt;
  MPI_Allreduce(&mine, &dt, 1, MPI_DOUBLE, MPI_MIN, world);
  if (comm->me == 0)
    utils::logmesg(lmp, "pd/contact: stable time step estimate of the contact springs {:.6g}, "
                   "timestep {:.6g} is {:.3f} of it\n", dt, update->dt, update->dt / dt);
  if (update->dt > dt)
    error->warning(FLERR, "Pair pd/contact: timestep {} exceeds the contact springs' stable "
                   "estimate {}", update->dt, dt);
}

// The spring constant of a pair as pd_contact_pair's c_s: PERI's force
// 15 c V_j (r - d) / delta is c_s (r/d - 1) with c_s = 15 c d / delta.
void PairPDContact::tangent_sum(double *sum, double *closing, double reach) const
{
  double **x = atom->x, **v = atom->v;
  const double *vol = atom->vfrac;
  const int *type = atom->type;
  const pd_contact_cand *pairs = cache->candidates();
  for (int p = 0; p < cache->ncandidates(); p++) {
    const int i = pairs[p].i, j = pairs[p].j, ti = type[i], tj = type[j];
    const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), dist = pairs[p].dist;
    const double cs = legacy ? 15.0 * legacy_c[ti][tj] * dist / legacy_delta[ti][tj] : stiffness[ti][tj];
    const double c = pd_contact_tangent(cs, dist, len, reach);
    sum[i] += c * vol[j];
    sum[j] += c * vol[i];
    if (c > 0.0) {
      const double r = pd_closing_rate(d, len, v[i], v[j]);
      closing[i] = std::max(closing[i], r);
      closing[j] = std::max(closing[j], r);
    }
  }
}

void PairPDContact::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (neighbor->ago == 0 || neighbor->ncalls != cache_build) {
    filter_pairs();
    cache_build = neighbor->ncalls;
  } else
    cache->refresh();
  double **x = atom->x, **f = atom->f, **v = atom->v;
  const double *vol = atom->vfrac;
  const int *type = atom->type;
  pd_tally t = {};
  t.eatom = eflag_atom ? eatom : nullptr;
  t.skip_virial = !vflag_global;
  t.vatom = vflag_atom && vatom ? vatom[0] : nullptr;
  pd_tally *tp = evflag ? &t : nullptr;
  const pd_contact_cand *pairs = cache->pairs();
  const int npairs = cache->npairs();
  // most pairs of the list are not in contact: the coefficients are
  // looked up for those that are
  if (legacy) {
    // PERI: every neighbour pair, bonded or not
    for (int p = 0; p < npairs; p++) {
      const int i = pairs[p].i, j = pairs[p].j;
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= pairs[p].dist * pairs[p].dist) continue;
      const int ti = type[i], tj = type[j];
      pd_contact_legacy_pair(legacy_c[ti][tj], legacy_delta[ti][tj], pairs[p].dist, vol[i], vol[j], d, f[i],
                             f[j], tp, i, j);
    }
  } else {
    for (int p = 0; p < npairs; p++) {
      const int i = pairs[p].i, j = pairs[p].j;
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= pairs[p].dist * pairs[p].dist) continue;
      const double dv[3] = {v[j][0] - v[i][0], v[j][1] - v[i][1], v[j][2] - v[i][2]};
      pd_contact_pair(stiffness[type[i]][type[j]], pairs[p].dist, friction, vol[i], vol[j], d, dv, f[i], f[j],
                      tp, i, j);
    }
  }
  if (evflag) {
    if (eflag_global) eng_vdwl += t.energy;
    if (vflag_global)
      for (int k = 0; k < 6; k++) virial[k] += t.virial[k];
  }
}

double PairPDContact::memory_usage()
{
  return Pair::memory_usage() + cache->memory_usage();
}

void PairPDContact::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        fwrite(&stiffness[i][j], sizeof(double), 1, fp);
        fwrite(&distance[i][j], sizeof(double), 1, fp);
      }
    }
}

void PairPDContact::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        if (comm->me == 0) {
          utils::sfread(FLERR, &stiffness[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &distance[i][j], sizeof(double), 1, fp, nullptr, error);
        }
        MPI_Bcast(&stiffness[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&distance[i][j], 1, MPI_DOUBLE, 0, world);
      }
    }
}

void PairPDContact::write_restart_settings(FILE *fp)
{
  fwrite(&friction, sizeof(double), 1, fp);
  fwrite(&legacy, sizeof(int), 1, fp);
}

void PairPDContact::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &friction, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &legacy, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&friction, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&legacy, 1, MPI_INT, 0, world);
}
