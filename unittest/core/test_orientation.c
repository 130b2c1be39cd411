/* Fracture energy across planes of any orientation from one family's
 * lattice sums (core/pd_orientation.c). */
#include "check.h"
#include "pd_influence.h"
#include "pd_law_stretch.h"
#include "pd_orientation.h"


/* The family of a simple-cubic (square, dim 2) site of spacing 1 within
 * delta = ratio, weights omega(|xi|) (kind >= 0) or 1. */
static pd_family cubic_family(int dim, double ratio, int kind)
{
  pd_lattice lat;
  pd_lattice_make(dim == 3 ? PD_LATTICE_SC : PD_LATTICE_SQ, 1.0, &lat);
  pd_influence_weight iw = {(pd_influence_kind) (kind >= 0 ? kind : 0), dim, ratio};
  pd_family f;
  pd_lattice_family(&lat, ratio, 1.0, kind >= 0 ? pd_influence_weight_fn : NULL, &iw, &f);
  return f;
}

static const char *kind_name(pd_release_kind kind)
{
  return kind == PD_RELEASE_ENERGY_OPENING   ? "energy law, opening"
         : kind == PD_RELEASE_ENERGY_UNIFORM ? "energy law, uniform"
                                             : "bond-based critical stretch";
}

static void one_pair(void)
{
  /* xi = +-a x: only +x crosses a plane of normal x. Energy law, opening
   * profile: (w / a) / (<cos+> 2 w / a) = 1 / (2 <cos+>): 2 in 3D, pi / 2
   * in 2D; uniform: (w a) / (<cos+> 2 w a), the same */
  pd_family_bond b[2] = {{{2.0, 0, 0}, 2.0, 0.7, {0}}, {{-2.0, 0, 0}, 2.0, 0.7, {0}}};
  pd_family f = {3, 2, 1.0, b};
  const double nx[3] = {1, 0, 0};
  check_rel("one pair, 3D, energy law: 1 / (2 <cos+>) = 2", pd_release(&f, PD_RELEASE_ENERGY_OPENING, nx), 2.0,
            1e-15);
  check_rel("one pair, 3D, energy law, uniform: 2", pd_release(&f, PD_RELEASE_ENERGY_UNIFORM, nx), 2.0, 1e-15);
  f.dim = 2;
  check_rel("one pair, 2D, energy law: pi / 2", pd_release(&f, PD_RELEASE_ENERGY_OPENING, nx), acos(-1.0) / 2,
            1e-15);
  /* bond-based, calibrated on the family: (xi.n)+ |xi| w over <cos+> sum |xi|^2 w
   * = 2 * 2 * 0.7 / (0.25 * 2 * 4 * 0.7) = 2 */
  f.dim = 3;
  check_rel("one pair, 3D, bond-based: 1 / (2 <cos+>) = 2", pd_release(&f, PD_RELEASE_BOND_BASED, nx), 2.0, 1e-15);
  const double n45[3] = {sqrt(0.5), sqrt(0.5), 0};
  check_rel("one pair, plane at 45 degrees: cos 45 of the release along x",
            pd_release(&f, PD_RELEASE_BOND_BASED, n45), sqrt(0.5) * 2.0, 1e-15);
}

/* The energy law is calibrated on the orientation average: the mean of
 * G(n) over evenly spread normals is G_c (to the spread's sampling error). */
static void average_is_calibrated(int dim, pd_release_kind kind)
{
  pd_family f = cubic_family(dim, 3.0, PD_INFLUENCE_INVERSE);
  const int count = dim == 3 ? 20000 : 3600;
  double mean = 0.0;
  for (int k = 0; k < count; k++) {
    double n[3];
    pd_spread_normal(dim, k, count, n);
    mean += pd_release(&f, kind, n) / count;
  }
  char what[120];
  snprintf(what, sizeof what, "%dD energy law, %s: mean over orientations is G_c (sampling 1e-4)", dim,
           kind_name(kind));
  check_rel(what, mean, 1.0, 1e-4);
  double lo, hi;
  pd_release_range(&f, kind, &lo, &hi);
  snprintf(what, sizeof what, "%dD energy law, %s, at 3 spacings: orientations spread (%.3f .. %.3f)", dim,
           kind_name(kind), lo, hi);
  check_true(what, lo < 0.99 && hi > 1.01 && lo > 0.8 && hi < 1.2);
  pd_family_free(&f);
}

/* Both converge to G_c in every orientation as the family becomes a
 * continuum (delta = 16 spacings: within 2%). */
static void continuum_limit(int dim, pd_release_kind kind, int influence)
{
  pd_family f = cubic_family(dim, 16.0, influence);
  double lo, hi;
  pd_release_range(&f, kind, &lo, &hi);
  char what[160];
  snprintf(what, sizeof what, "%dD %s, 16 spacings: every orientation within 2%% of G_c (%.4f .. %.4f)", dim,
           kind_name(kind), lo, hi);
  check_true(what, lo > 0.98 && hi < 1.02);
  pd_family_free(&f);
}

/* Separating a 3D sc block along a lattice plane released 0.913 G_c (energy
 * law, inverse influence, calibrated on the family, opening profile; 0.972
 * with the uniform one, whose release leans less on the short bonds that
 * lie in the plane: 0.968 without the opening steps' bias of +0.4%, both
 * with directional_correction no) and 1.15 G_c (critical
 * stretch, pd/bond, calibrated in the continuum) at 3 spacings, each
 * within 0.1% of its lattice sum: the sum reproduces both. The critical
 * stretch calibrated on the family (pd_critical_stretch_factor) scales the
 * continuum's release by its factor squared times the stiffness scale:
 * integral of |xi|^2 over sum |xi|^2 w V. */
static void measured_separations(void)
{
  const double nx[3] = {1, 0, 0};
  pd_family f = cubic_family(3, 3.0, PD_INFLUENCE_INVERSE);
  check_rel("sc, 3 spacings, energy law, plane along the axes: 0.913 (measured by separation)",
            pd_release(&f, PD_RELEASE_ENERGY_OPENING, nx), 0.913, 2e-3);
  check_rel("sc, 3 spacings, energy law, uniform profile, plane along the axes: 0.972 / 1.004 (measured by "
            "separation)", pd_release(&f, PD_RELEASE_ENERGY_UNIFORM, nx), 0.972 / 1.004, 2e-3);
  pd_family_free(&f);
  f = cubic_family(3, 3.0, -1);
  const double calibrated = pd_release(&f, PD_RELEASE_BOND_BASED, nx);
  const double factor = pd_critical_stretch_factor(3, 3.0, 1.0, 1.0, pd_family_moment_sum(&f, 2));
  check_rel("sc, 3 spacings, pd/bond critical stretch in the continuum, along the axes: 1.15 (measured by "
            "separation)", calibrated / (factor * factor), 1.15, 5e-3);
  char what[160];
  snprintf(what, sizeof what, "sc, 3 spacings, calibrated on the family: along the axes %.3f, within 3%%", calibrated);
  check_true(what, fabs(calibrated - 1.0) < 0.03);
  pd_family_free(&f);
}

/* The dilatation share of an ordinary solid's release (kappa) on a family,
 * by another method: per normal of the same spread, depth by depth on a
 * grid, the end at depth z sums each crossing bond's dilatation over the
 * crossing bonds that still reach it (xi.n > z) and break no earlier. */
static double kappa_by_depths(const pd_family *f, int nz)
{
  const int count = PD_RELEASE_NORMALS(f->dim);
  double m = 0.0, pairs = 0.0, across = 0.0;
  for (int b = 0; b < f->n; b++) m += f->bond[b].w * f->volume;
  for (int k = 0; k < count; k++) {
    double n[3], normal[4096];
    pd_spread_normal(f->dim, k, count, n);
    for (int b = 0; b < f->n; b++) {
      const double *xi = f->bond[b].xi;
      normal[b] = xi[0] * n[0] + xi[1] * n[1] + xi[2] * n[2];
      if (normal[b] > 0.0) across += f->bond[b].w * f->volume * normal[b];
    }
    for (int q = 0; q < nz; q++) {
      const double z = (q + 0.5) / nz * f->bond[0].r * 4.0; /* (past the longest bond) */
      for (int b = 0; b < f->n; b++) {
        if (!(normal[b] > z)) continue;
        const double opening = f->bond[b].r * f->bond[b].r / normal[b];
        double later = 0.0;
        for (int e = 0; e < f->n; e++)
          if (normal[e] > z && f->bond[e].r * f->bond[e].r / normal[e] >= opening * (1.0 - 1e-12))
            later += f->bond[e].w * f->volume * normal[e] / (f->bond[e].r * f->bond[e].r);
        pairs += f->bond[b].w * f->volume * opening * later * f->dim / m * (f->bond[0].r * 4.0 / nz);
      }
    }
  }
  return pairs / across;
}

/* ... on the lattice families: by depths, and toward the continuum's
 * integral (pd_ordinary_dilatation_release) as the horizon grows in
 * spacings, from above (a coarse family's crossing bonds load each end's
 * dilatation more) */
static void ordinary_dilatation_share(int dim)
{
  const double ratios[] = {3.0, 4.0, 6.0, 12.0};
  const int nratio = dim == 3 ? 3 : 4;
  const double continuum = pd_ordinary_dilatation_release(PD_INFLUENCE_CONSTANT, dim);
  double previous = INFINITY;
  for (int q = 0; q < nratio; q++) {
    pd_family f = cubic_family(dim, ratios[q], PD_INFLUENCE_CONSTANT);
    f.volume = 0.7; /* (a partner volume: kappa does not depend on it) */
    double sums[2] = {0.0, 0.0};
    pd_ordinary_family_release(&f, sums);
    const double kappa = sums[0] / sums[1];
    char what[200];
    if (q == 0) {
      /* the grid's error: a step of 1/nz of 4 spacings at each bond's reach */
      snprintf(what, sizeof what, "%dD ordinary stretch law, 3 spacings: kappa of the family %.4f, by depths "
               "(1e-3)", dim, kappa);
      check_rel(what, kappa, kappa_by_depths(&f, dim == 3 ? 400 : 4000), 1e-3);
    }
    snprintf(what, sizeof what, "%dD, %g spacings: kappa %.4f above the continuum's %.4f and below the "
             "coarser family's", dim, ratios[q], kappa, continuum);
    check_true(what, kappa > continuum && kappa < previous);
    previous = kappa;
    pd_family_free(&f);
  }
  char what[160];
  snprintf(what, sizeof what, "%dD, %g spacings: kappa within 2%% of the continuum's", dim, ratios[nratio - 1]);
  check_rel(what, previous, continuum, 0.02);
  pd_family_bond none = {{1.0, 0.0, 0.0}, 1.0, 0.0, {0}};
  pd_family empty = {dim, 1, 1.0, &none};
  double sums[2] = {0.0, 0.0};
  pd_ordinary_family_release(&empty, sums);
  check_true("a family of zero weight adds nothing", sums[0] == 0.0 && sums[1] == 0.0);
}

/* The ordinary solid's stretch law with its dilatation part: without it
 * (lambda = 0) the bond part alone, pd_release's; on average over
 * orientations G_c, as calibrated; and across the square lattice's rows
 * at 3 spacings (constant influence) the rise from plane stress (lambda /
 * mu of the bond moduli 0.04 for PMMA) to plane strain (0.67) that the
 * separation measured: 0.978 -> 0.995 (accuracy report). */
static void ordinary_release(void)
{
  pd_family f = cubic_family(2, 3.0, PD_INFLUENCE_CONSTANT);
  const double nx[3] = {1, 0, 0};
  check_rel("ordinary stretch law, lambda = 0: the bond part (pd_release)", pd_release_ordinary(&f, 0.0, nx),
            pd_release(&f, PD_RELEASE_ORDINARY_STRETCH, nx), 1e-12);
  double mean = 0.0;
  for (int k = 0; k < 360; k++) {
    double n[3];
    pd_spread_normal(2, k, 360, n);
    mean += pd_release_ordinary(&f, 0.67, n) / 360;
  }
  check_rel("ordinary stretch law, plane strain: G_c on average over orientations (the spread's sampling, "
            "1e-3)", mean, 1.0, 1e-3);
  const double rise = pd_release_ordinary(&f, 0.67, nx) - pd_release_ordinary(&f, 0.04, nx);
  char what[160];
  snprintf(what, sizeof what, "square, 3 spacings, along the rows: plane strain releases %.4f G_c more than "
           "plane stress, as measured (0.017, 5e-3)", rise);
  check_true(what, fabs(rise - 0.017) < 5e-3);
  pd_family_free(&f);
}

int main(void)
{
  one_pair();
  for (int k = PD_RELEASE_ENERGY_UNIFORM; k <= PD_RELEASE_ENERGY_OPENING; k++) {
    average_is_calibrated(3, (pd_release_kind) k);
    average_is_calibrated(2, (pd_release_kind) k);
    continuum_limit(3, (pd_release_kind) k, PD_INFLUENCE_INVERSE);
    continuum_limit(2, (pd_release_kind) k, PD_INFLUENCE_CONSTANT);
  }
  continuum_limit(3, PD_RELEASE_BOND_BASED, -1);
  continuum_limit(2, PD_RELEASE_BOND_BASED, -1);
  measured_separations();
  ordinary_dilatation_share(2);
  ordinary_dilatation_share(3);
  ordinary_release();
  return check_summary();
}
