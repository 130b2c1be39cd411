/* Partial-volume quadrature (pd_quadrature.h): the share of a neighbour's
 * cell inside the horizon. The cells of a lattice tile space, so their
 * shares must add up to the disk or ball exactly; single cut cells are
 * compared with an independent integration. */
#include "check.h"
#include "pd_macros.h"
#include "pd_orientation.h"
#include "pd_quadrature.h"

#include <stdlib.h>
#include <string.h>

/* PDEXT_QUAD_BREAK=<name> perturbs one check so that it must fail:
 * tiling, independent, fracture */
static int broken(const char *name)
{
  const char *b = getenv("PDEXT_QUAD_BREAK");
  return b && strcmp(b, name) == 0;
}

/* sum of fraction * a^d over every lattice cell (side a, sites at
 * integer multiples of a) for a horizon centred at 'centre', skipping the
 * cell of site 0 when skip_own */
static double lattice_sum(int dim, double a, double delta, const double centre[3], int skip_own)
{
  const int n = (int) (delta / a) + 2;
  double sum = 0.0;
  for (int i = -n; i <= n; i++)
    for (int j = -n; j <= n; j++)
      for (int k = (dim == 3 ? -n : 0); k <= (dim == 3 ? n : 0); k++) {
        if (skip_own && i == 0 && j == 0 && k == 0) continue;
        const double c[3] = {i * a - centre[0], j * a - centre[1], k * a - centre[2]};
        /* (broken: the shares of cells 1e-9 larger, as a slip in the cell
         * side would give) */
        const double side = broken("tiling") ? a * (1.0 + 1e-9) : a;
        sum += pd_cell_fraction(dim, c, side, delta) * (dim == 3 ? a * a * a : a * a);
      }
  return sum;
}

static double ball(int dim, double delta)
{
  return dim == 3 ? 4.0 / 3.0 * PD_PI * delta * delta * delta : PD_PI * delta * delta;
}

/* The tiling: at a site, all cells but the own one make the ball minus
 * a^d; from an offset centre all cells make the ball. Each cut cell is
 * exact to ~1e-13 of a^d (3D) and the sums hold ~10^2 of them: 1e-10
 * relative leaves room for round-off only. */
static void tiling(void)
{
  const double ratios[] = {2.5, 3.0, 3.0002, 3.5, 4.0, 4.7, 6.0};
  const double a = 0.37;    /* not 1: the fractions must scale with a */
  char what[160];
  for (int dim = 2; dim <= 3; dim++)
    for (size_t r = 0; r < sizeof ratios / sizeof ratios[0]; r++) {
      const double delta = ratios[r] * a;
      const double zero[3] = {0.0, 0.0, 0.0};
      const double own = dim == 3 ? a * a * a : a * a;
      snprintf(what, sizeof what, "%dD delta = %g a: cells tile the %s minus the own cell", dim, ratios[r],
               dim == 3 ? "ball" : "disk");
      check_rel(what, lattice_sum(dim, a, delta, zero, 1), ball(dim, delta) - own, 1e-10);
      const double offsets[2][3] = {{0.31 * a, 0.17 * a, 0.43 * a}, {0.5 * a, 0.5 * a, 0.5 * a}};
      for (int o = 0; o < 2; o++) {
        snprintf(what, sizeof what, "%dD delta = %g a, centre off the site by (%g, %g, %g) a: the whole %s",
                 dim, ratios[r], offsets[o][0] / a, offsets[o][1] / a, dim == 3 ? offsets[o][2] / a : 0.0,
                 dim == 3 ? "ball" : "disk");
        check_rel(what, lattice_sum(dim, a, delta, offsets[o], 0), ball(dim, delta), 1e-10);
      }
    }
}

/* Whole cells: the quick tests and the slices must agree on the obvious. */
static void whole_cells(void)
{
  const double inside[3] = {1.0, 1.0, 1.0}, outside[3] = {3.6, 0.0, 0.0}, touching[3] = {2.5, 2.5, 2.5};
  check_rel("3D: a cell well inside has fraction 1", pd_cell_fraction_3d(inside, 1.0, 3.0), 1.0, 0.0);
  check_rel("2D: a cell well inside has fraction 1", pd_cell_fraction_2d(inside, 1.0, 3.0), 1.0, 0.0);
  check_rel("3D: a cell beyond the horizon has fraction 0", pd_cell_fraction_3d(outside, 1.0, 3.0), 0.0, 0.0);
  check_rel("2D: a cell beyond the horizon has fraction 0", pd_cell_fraction_2d(outside, 1.0, 3.0), 0.0, 0.0);
  /* nearest corner at distance 2 sqrt(3) = 3.46 > 3: outside */
  check_rel("3D: a cell whose nearest corner is beyond the horizon has 0",
            pd_cell_fraction_3d(touching, 1.0, 3.0), 0.0, 0.0);
  /* the cell of the centre itself is inside any horizon past its corners */
  const double own[3] = {0.0, 0.0, 0.0};
  check_rel("3D: the own cell (delta = 1 a) is whole", pd_cell_fraction_3d(own, 1.0, 1.0), 1.0, 0.0);
  /* a ball inside the cell: the ball's volume over a^3 */
  check_rel("3D: a small ball inside the cell gives its own volume / a^3", pd_cell_fraction_3d(own, 1.0, 0.3),
            ball(3, 0.3), 1e-13);
  check_rel("2D: a small disk inside the cell gives its own area / a^2", pd_cell_fraction_2d(own, 1.0, 0.3),
            ball(2, 0.3), 1e-14);
  /* reach: the farthest centre with a share is delta + half the diagonal */
  const double d3 = (3.0 + pd_cell_reach(3, 1.0)) / sqrt(3.0);
  const double diag_in[3] = {d3 - 1e-3, d3 - 1e-3, d3 - 1e-3}, diag_out[3] = {d3 + 1e-9, d3 + 1e-9, d3 + 1e-9};
  check_true("3D: a cell just within delta + a sqrt(3)/2 along the diagonal has a share",
             pd_cell_fraction_3d(diag_in, 1.0, 3.0) > 0.0);
  check_true("3D: ... and just beyond it none", pd_cell_fraction_3d(diag_out, 1.0, 3.0) == 0.0);
}

/* Cells that are mirror images or permutations of each other: the same
 * share (the slices run along z, so a permutation is a different sum:
 * equal to round-off, 1e-13). */
static void symmetry(void)
{
  const double c[3] = {1.3, 2.2, 1.7};
  const double f = pd_cell_fraction_3d(c, 1.0, 3.0);
  const double perms[5][3] = {{-1.3, 2.2, -1.7}, {2.2, 1.3, 1.7}, {1.7, 2.2, 1.3}, {-2.2, -1.7, 1.3}, {1.3, -1.7, 2.2}};
  char what[160];
  check_true("3D: the symmetry case is cut (0 < f < 1)", f > 0.0 && f < 1.0);
  for (int p = 0; p < 5; p++) {
    snprintf(what, sizeof what, "3D: cell at (%g, %g, %g) has the share of (1.3, 2.2, 1.7)", perms[p][0],
             perms[p][1], perms[p][2]);
    check_rel(what, pd_cell_fraction_3d(perms[p], 1.0, 3.0), f, 1e-13);
  }
  const double c2[2] = {2.4, 1.6}, m2[3][2] = {{-2.4, 1.6}, {1.6, 2.4}, {-1.6, -2.4}};
  const double f2 = pd_cell_fraction_2d(c2, 1.0, 3.0);
  for (int p = 0; p < 3; p++) {
    snprintf(what, sizeof what, "2D: cell at (%g, %g) has the share of (2.4, 1.6)", m2[p][0], m2[p][1]);
    check_rel(what, pd_cell_fraction_2d(m2[p], 1.0, 3.0), f2, 1e-14);
  }
}

/* length of [lo, hi] inside [-h, h] */
static double clip(double lo, double hi, double h)
{
  const double l = fmin(hi, h) - fmax(lo, -h);
  return l > 0.0 ? l : 0.0;
}

/* Independent integrations of cut cells: 2D, the chord length over x by
 * the midpoint rule on 10^6 strips (error O(h^1.5) at the kinks: ~1e-9);
 * 3D, the chord length along z over a 1500^2 midpoint grid in (x, y)
 * (error ~ (1/1500)^1.5 ~ 2e-5 at the kinks: tolerance 1e-4). */
static void independent(void)
{
  const double a = 1.0, delta = 3.0;
  const double c2[2] = {2.6, 1.3};
  const int n2 = 1000000;
  double area = 0.0;
  for (int k = 0; k < n2; k++) {
    const double x = c2[0] - 0.5 * a + (k + 0.5) * a / n2;
    if (fabs(x) < delta) area += clip(c2[1] - 0.5 * a, c2[1] + 0.5 * a, sqrt(delta * delta - x * x)) * a / n2;
  }
  const double f2 = pd_cell_fraction_2d(c2, a, delta);
  check_true("2D: the cell at (2.6, 1.3) is cut", f2 > 0.0 && f2 < 1.0);
  check_rel("2D: cut cell (2.6, 1.3), delta 3: against 10^6 midpoint strips", f2, area / (a * a), 1e-8);

  const double c3[3] = {1.9, 1.4, 1.7};
  const int n3 = 1500;
  double vol = 0.0;
  for (int i = 0; i < n3; i++)
    for (int j = 0; j < n3; j++) {
      const double x = c3[0] - 0.5 * a + (i + 0.5) * a / n3, y = c3[1] - 0.5 * a + (j + 0.5) * a / n3;
      const double s = delta * delta - x * x - y * y;
      if (s > 0.0) vol += clip(c3[2] - 0.5 * a, c3[2] + 0.5 * a, sqrt(s));
    }
  vol *= (a / n3) * (a / n3);
  double f3 = pd_cell_fraction_3d(c3, a, delta);
  if (broken("independent")) f3 *= 1.001;
  check_true("3D: the cell at (1.9, 1.4, 1.7) is cut", f3 > 0.0 && f3 < 1.0);
  check_rel("3D: cut cell (1.9, 1.4, 1.7), delta 3: against a 1500^2 midpoint grid", f3, vol / (a * a * a), 1e-4);
}

/* Bond-based weights on a unit lattice: the cell's share (partial) or 1. */
static double share(const double xi[3], double r, void *ctx)
{
  const double *delta = (const double *) ctx;
  return delta[1] > 0.0 ? pd_cell_fraction((int) delta[2], xi, 1.0, delta[0]) : r <= delta[0];
}

/* The fracture energy a bond-based body releases across a plane
 * (pd_orientation.h) with the critical stretch calibrated on the family
 * (pd_critical_stretch_factor): its mean over orientations is G_c, and
 * what is left is the family's spread over orientations. Measured worst
 * |G/G_c - 1| over orientations, point / partial: 3D 2.8% / 3.1% (3
 * spacings), 1.6% / 1.7% (4); 2D 4.0% / 2.0%, 2.7% / 1.1%. With the
 * continuum calibration (MS07 eq. 28-29), point quadrature was 18.3% off
 * in 3D at 3 spacings (partial 5.2%). Checked: both within 4.5%. */
static void fracture_energy(void)
{
  char what[160];
  for (int dim = 3; dim >= 2; dim--)
    for (int m = 3; m <= 4; m++)
      for (int partial = 0; partial < 2; partial++) {
        pd_lattice lat;
        pd_lattice_make(dim == 3 ? PD_LATTICE_SC : PD_LATTICE_SQ, 1.0, &lat);
        double ctx[3] = {m + 0.0002, partial, dim};
        const double cutoff = ctx[0] + (partial ? pd_cell_reach(dim, 1.0) : 0.0);
        pd_family f;
        pd_lattice_family(&lat, cutoff, 1.0, share, ctx, &f);
        double lo, hi;
        pd_release_range(&f, PD_RELEASE_BOND_BASED, &lo, &hi);
        double worst = fmax(fabs(lo - 1.0), fabs(hi - 1.0));
        pd_family_free(&f);
        if (broken("fracture")) worst += 0.1;
        snprintf(what, sizeof what, "%dD, %d spacings, %s quadrature: bond-based G/G_c within 4.5%% at every "
                 "orientation (%.4f .. %.4f)", dim, m, partial ? "partial" : "point", lo, hi);
        check_rel(what, 1.0 + worst, 1.0, 0.045);
      }
}

int main(void)
{
  tiling();
  whole_cells();
  symmetry();
  independent();
  fracture_energy();
  return check_summary();
}
