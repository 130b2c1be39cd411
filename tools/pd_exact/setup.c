#include "setup.h"

#include <math.h>
#include <string.h>

#include "pd_directional.h"
#include "pd_quadrature.h"

#define GIVEN(x) (!isnan(x))

static int fail(FILE *err, const char *msg)
{
  fprintf(err, "pd_exact: %s\n", msg);
  return -1;
}

/* The elastic constants: (K, G) or (E, nu); with K or E alone the PMB's
 * Poisson ratio (1/4, 1/3 in plane stress), as pd/bond's material. */
static int elastic(const exact_input *in, pd_dimension pdim, pd_elastic *e, FILE *err)
{
  if (GIVEN(in->K) && GIVEN(in->G)) return pd_elastic_from_K_G(in->K, in->G, e) ? fail(err, "K, G: not a stable material") : 0;
  const double nu = GIVEN(in->nu) ? in->nu : pd_pmb_poisson(pdim);
  if (GIVEN(in->E)) return pd_elastic_from_E_nu(in->E, nu, e) ? fail(err, "E, nu: not a stable material") : 0;
  if (GIVEN(in->K)) return pd_elastic_from_E_nu(3.0 * in->K * (1.0 - 2.0 * nu), nu, e) ? fail(err, "K: not a stable material") : 0;
  return fail(err, "give K and G, or E and nu (or K or E alone for the PMB's Poisson ratio)");
}

/* A bond's weight as the pair styles give it: pd/ordinary's influence at
 * min(r, horizon) (bonds past the horizon come only with partial cells),
 * times the share of the partner's cell inside the horizon with
 * 'quadrature partial' (a cube or square of the particle's volume, as the
 * styles take it; core/pd_quadrature). */
typedef struct weight_ctx {
  pd_influence_weight iw;
  int ordinary, partial, dim;
  double cell;
} weight_ctx;

static double bond_weight(const double xi[3], double r, void *ctx)
{
  const weight_ctx *c = (const weight_ctx *) ctx;
  double w = c->ordinary ? pd_influence_of_cell(c->iw.kind, c->iw.dim, r, c->iw.horizon) : 1.0;
  if (c->partial) w *= pd_cell_fraction(c->dim, xi, c->cell, c->iw.horizon);
  return w;
}

/* The pair styles' directional correction on a lattice family: every
 * site's family is the same, so each bond's weight takes that family's
 * factor (core/pd_directional.h); the stiffness share is w V |xi|^power. */
static int directional(pd_family *f, int power)
{
  double form[PD_DIRECTIONAL_MAX_TERMS];
  if (pd_family_directional_form(f, power, form)) return -1;
  for (int b = 0; b < f->n; b++) {
    pd_family_bond *bd = &f->bond[b];
    const double n[3] = {bd->xi[0] / bd->r, bd->xi[1] / bd->r, bd->xi[2] / bd->r};
    bd->w *= pd_directional_factor(f->dim, form, n);
  }
  return 0;
}

static int pmb(const exact_input *in, exact_problem *p, FILE *err)
{
  const int nstiff = GIVEN(in->c) + GIVEN(in->K) + GIVEN(in->E);
  if (nstiff != 1) return fail(err, "pmb: give exactly one of c, K (3D) or E");
  if (GIVEN(in->nu) && p->lat.dim > 1 && fabs(in->nu - pd_pmb_poisson(p->pdim)) > 1e-6)
    return fail(err, "pmb: bond-based elasticity fixes nu (1/4 in 3D and plane strain, 1/3 in plane stress)");
  const int d = p->lat.dim;
  if (GIVEN(in->c)) p->model = pd_linear_pmb_c(d, in->c);
  else if (d == 1) /* 1D analogue of MS07 eq. 18: E = c delta^2 / 2 per unit cross-section */
    p->model = pd_linear_pmb_c(1, GIVEN(in->E) ? 2.0 * in->E / (in->horizon * in->horizon) : NAN);
  else if (GIVEN(in->K)) {
    if (d != 3) return fail(err, "pmb: K is a 3D option; in 2D give E");
    p->model = pd_linear_pmb_K(in->K, in->horizon);
  } else p->model = pd_linear_pmb_E(p->pdim, in->E, in->horizon, in->thickness);
  if (!(p->model.c > 0.0)) return fail(err, "pmb: give E or c for a chain");
  return 0;
}

int exact_setup(const exact_input *in, exact_problem *p, FILE *err)
{
  memset(p, 0, sizeof(*p));
  const int kind = pd_lattice_from_name(in->lattice);
  if (kind < 0) return fail(err, "lattice: expected chain, sq, hex, sc or fcc");
  if (pd_lattice_make((pd_lattice_kind) kind, in->spacing, &p->lat)) return fail(err, "spacing must be positive");
  const int d = p->lat.dim;
  if (in->dim && in->dim != d) return fail(err, "dim does not match the lattice");
  for (int c = 0; c < 3; c++) {
    p->grid[c] = c < d ? in->n[c] * p->lat.sub[c] : 1;
    if (c < d && p->lat.parity && p->grid[c] % 2) return fail(err, "n: internal error (odd grid)");
  }
  if (d == 2) {
    if (strcmp(in->plane, "stress") == 0) p->pdim = PD_PLANE_STRESS;
    else if (strcmp(in->plane, "strain") == 0) p->pdim = PD_PLANE_STRAIN;
    else return fail(err, "2D needs 'plane stress' or 'plane strain'");
  } else p->pdim = PD_3D;
  if (!(in->density > 0.0)) return fail(err, "density must be positive");
  if (in->fields[0] && !(in->time >= 0.0)) return fail(err, "time must be >= 0");
  p->density = in->density;
  p->time = in->time;
  const int classical = strcmp(in->model, "classical") == 0;
  if (!classical && !(in->horizon > 0.0)) return fail(err, "horizon must be positive");

  /* influence: pd/ordinary's default, 1/|xi| in 3D and constant in 2D */
  weight_ctx wc = {{d == 3 ? PD_INFLUENCE_INVERSE : PD_INFLUENCE_CONSTANT, d == 3 ? 3 : 2, in->horizon},
                   strcmp(in->model, "ordinary") == 0, 0, d, 0.0};
  if (in->influence[0]) {
    const int k = pd_influence_from_name(in->influence);
    if (k < 0) return fail(err, "unknown influence function");
    wc.iw.kind = (pd_influence_kind) k;
  }
  double cutoff = in->horizon;
  if (in->quadrature[0] && strcmp(in->quadrature, "point") != 0) {
    if (strcmp(in->quadrature, "partial") != 0) return fail(err, "quadrature: expected point or partial");
    wc.partial = 1;
    wc.cell = d == 3 ? cbrt(p->lat.volume) : d == 2 ? sqrt(p->lat.volume) : p->lat.volume;
    cutoff += pd_cell_reach(d, wc.cell);
  }
  const int ordinary = wc.ordinary;
  if (!classical && pd_lattice_family(&p->lat, cutoff, in->thickness, bond_weight, &wc, &p->fam) < 1)
    return fail(err, "the horizon holds no bond");
  if (in->directional[0] && strcmp(in->directional, "yes") != 0 && strcmp(in->directional, "no") != 0)
    return fail(err, "directional_correction: expected yes or no");
  if (!classical && d >= 2 && strcmp(in->directional, "no") != 0 && directional(&p->fam, ordinary ? 0 : 1))
    return fail(err, "directional_correction: the family's eighth moments are singular");

  pd_elastic e;
  if (strcmp(in->model, "pmb") == 0) {
    if (pmb(in, p, err)) return -1;
    if (d == 1) p->classical = pd_linear_classical_1d(0.5 * p->model.c * in->horizon * in->horizon);
    else if (GIVEN(in->c)) {
      /* the material that c is calibrated to: invert c(K) in 3D, c(E) in 2D */
      const double nu = pd_pmb_poisson(p->pdim);
      const double E = p->pdim == PD_3D ? 3.0 * (1.0 - 2.0 * nu) * p->model.c / pd_linear_pmb_K(1.0, in->horizon).c
                                        : p->model.c / pd_linear_pmb_E(p->pdim, 1.0, in->horizon, in->thickness).c;
      pd_elastic_from_E_nu(E, nu, &e);
      p->classical = pd_linear_classical(p->pdim, &e);
    } else {
      if (elastic(in, p->pdim, &e, err)) return -1;
      p->classical = pd_linear_classical(p->pdim, &e);
      /* pd/bond calibrates a micromodulus from E or K on the family */
      p->model.c *= pd_pmb_moment_continuum(d, in->horizon, in->thickness) / pd_family_moment_sum(&p->fam, 1);
    }
  } else if (ordinary) {
    if (d == 1) return fail(err, "ordinary: 2D or 3D lattices only");
    if (elastic(in, p->pdim, &e, err)) return -1;
    p->model = pd_linear_ordinary(p->pdim, &e, &p->fam);
    p->classical = pd_linear_classical(p->pdim, &e);
  } else if (classical) {
    if (d == 1) {
      if (!GIVEN(in->E)) return fail(err, "classical chain: give E");
      p->classical = pd_linear_classical_1d(in->E);
    } else {
      if (elastic(in, p->pdim, &e, err)) return -1;
      p->classical = pd_linear_classical(p->pdim, &e);
    }
    p->model = p->classical;
  } else return fail(err, "model: expected pmb, ordinary or classical");
  return 0;
}

void exact_report(const exact_input *in, const exact_problem *p, FILE *out)
{
  fprintf(out, "pd_exact: %s lattice, %d x %d x %d grid points, model %s", pd_lattice_name(p->lat.kind),
          p->grid[0], p->grid[1], p->grid[2], in->model);
  if (p->model.kind == PD_LINEAR_CLASSICAL) {
    fprintf(out, "\n");
    return;
  }
  fprintf(out, ", %d bonds per site, horizon / spacing %.6g\n", p->fam.n, in->horizon / in->spacing);
  double C[PD_SYM4], Cref[PD_SYM4];
  pd_effective_tensor(&p->model, &p->fam, C);
  pd_effective_tensor(&p->classical, NULL, Cref);
  const pd_moduli_error me = pd_moduli_error_of(C, Cref, p->lat.dim);
  fprintf(out, "pd_exact: lattice error of the constants (energy): dilatation %+.5f shear_xx_yy %+.5f "
          "shear_xy %+.5f worst %.5f\n", me.dilatation, me.shear_xx_yy, me.shear_xy, me.worst);
}
