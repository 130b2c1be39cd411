/* PMB bond-based material (MS07 eq. 14-18) on a simple-cubic lattice. */
#include "check.h"
#include "common.h"
#include "model.h"
#include "pd_bond_based.h"
#include "pd_params.h"

#include <stdlib.h>

static double eval_pmb(const lattice *l, const double *x, double *f, void *ctx)
{
  return pmb_eval(l, *(double *) ctx, x, f, NULL);
}


int main(void)
{
  const double K = 14.9e9, h = 5e-4;
  /* Uniform strain at the centre of a 13^3 block, delta = 5 h: the family of
   * the centre is complete. */
  {
    const double delta = 5.0001 * h;
    lattice l = lattice_make(3, 13, h, delta, -1);
    double c = pd_pmb_micromodulus_3d(K, delta);
    double *x = malloc(sizeof(double) * 3 * l.natoms), *f = malloc(sizeof(double) * 3 * l.natoms);
    double *psi = malloc(sizeof(double) * l.natoms);
    const int ctr = lattice_center(&l);
    const double s = 1e-4;
    double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
    lattice_strain(&l, dil, x);
    pmb_eval(&l, c, x, f, psi);
    /* Exact: psi = 1/4 c s^2 sum |xi| V over the family (stretch is s on
     * every bond under uniform dilatation). */
    double sum_r = 0.0;
    for (int a = 0; a < l.natoms; a++) {
      const double dx = l.x0[3 * a] - l.x0[3 * ctr], dy = l.x0[3 * a + 1] - l.x0[3 * ctr + 1],
                   dz = l.x0[3 * a + 2] - l.x0[3 * ctr + 2];
      const double r = sqrt(dx * dx + dy * dy + dz * dz);
      if (a != ctr && r <= delta) sum_r += r * l.vol[a];
    }
    check_rel("PMB dilatation: psi = c s^2/4 sum |xi| V (exact)", psi[ctr], 0.25 * c * s * s * sum_r, 1e-11);
    /* Continuum: c = 18K/(pi delta^4) gives 9/2 K s^2. The lattice sum of |xi| V
     * over a ball of radius 5h is 2.2% below its integral pi delta^4 (surface
     * quadrature error, O(h/delta)): tolerance 3%. */
    check_rel("PMB dilatation: psi = 9/2 K s^2 (lattice error 2.2%)", psi[ctr], 4.5 * K * s * s, 0.03);
    /* General small strain with nu = 1/4 (lambda = mu = 3K/5): the same
     * lattice error plus the lattice's 4th-moment anisotropy; tolerance 4%. */
    unsigned seed = 7;
    for (int trial = 0; trial < 3; trial++) {
      double e[3][3];
      for (int i = 0; i < 3; i++)
        for (int j = 0; j <= i; j++) e[i][j] = e[j][i] = 1e-4 * urand(&seed);
      lattice_strain(&l, e, x);
      pmb_eval(&l, c, x, f, psi);
      check_rel("PMB random strain: classical energy, nu = 1/4", psi[ctr],
                classical_energy(0.6 * K, 0.6 * K, e), 0.04);
    }
    lattice_free(&l);
    free(x);
    free(f);
    free(psi);
  }
  /* Energy-force consistency, objectivity and balance on a small block with
   * a finite random displacement (1% of the spacing) and legacy-like weights. */
  {
    lattice l = lattice_make(3, 5, h, 2.0001 * h, PD_INFLUENCE_GAUSS);
    double c = pd_pmb_micromodulus_3d(K, l.delta);
    double *x = malloc(sizeof(double) * 3 * l.natoms);
    random_displacement(&l, 0.01 * h, 3, x);
    /* Central differences with step 1e-6 h: truncation ~1e-12, round-off
     * ~1e-16 E / (1e-6 h F) ~ 1e-8 relative: tolerance 1e-6. */
    check_energy_gradient("PMB", &l, x, eval_pmb, &c, 1e-6);
    check_objectivity("PMB", &l, x, eval_pmb, &c);
    /* Unequal volumes: V_i f_i = -V_j f_j must still hold. */
    for (int a = 0; a < l.natoms; a++) l.vol[a] *= 1.0 + 0.3 * (a % 3);
    check_momentum("PMB, unequal volumes", &l, x, eval_pmb, &c);
    lattice_free(&l);
    free(x);
  }
  /* Microplastic bonds (MS07 eq. 19-21): one bond of two unit-volume points
   * stretched to 3 sy and released. The force saturates at c sy, the bond
   * keeps a permanent stretch of 2 sy, and the plastic work is c sy 2 sy |xi|
   * per unit volume pair (half attributed to each end). With a huge yield
   * stretch the kernel is the PMB kernel, bit for bit. */
  {
    lattice l = lattice_make(3, 2, h, 1.0001 * h, -1);
    l.natoms = 2; /* the first two points of the row: one bond */
    l.count[1] = 0;
    l.count[0] = 1;
    for (int a = 0; a < 2; a++) l.vol[a] = 1.0;
    const double c = 1e20, sy = 1e-3, big = 1e300;
    double plastic = 0.0, x[6] = {0, 0, 0, h, 0, 0}, f[6];
    pd_bond_view v = lattice_view(&l);
    pd_pmb mat = {&c};
    pd_microplastic mp = {.sy = &sy, .plastic = &plastic};
    const double stretches[] = {1e-3, 2e-3, 3e-3, 2e-3, 0.0};
    double force[5];
    for (int k = 0; k < 5; k++) {
      x[3] = h * (1.0 + stretches[k]);
      for (int q = 0; q < 6; q++) f[q] = 0.0;
      pd_microplastic_forces(&(pd_loop){&v, l.type, 1, x, l.vol, f, NULL, NULL, l.reaction, l.natoms, 0, NULL, 0}, &mat, &mp);
      force[k] = f[0];
    }
    check_rel("microplastic: force at yield is c sy", force[0], c * sy, 1e-9);
    check_rel("microplastic: force saturates at c sy beyond yield", force[2], c * sy, 1e-9);
    check_rel("microplastic: unloading by sy is elastic (force 0)", 1.0 + force[3] / (c * sy), 1.0, 1e-9);
    check_rel("microplastic: release leaves a compressive yield force", force[4], -c * sy, 1e-9);
    check_rel("microplastic: permanent stretch after the cycle", plastic, 1e-3, 1e-9);
    check_rel("microplastic: plastic work = c sy |total plastic flow| |xi|", mp.dissipated,
              c * sy * (2e-3 + 1e-3) * h, 1e-9);
    double plastic2 = 0.0, g[6] = {0}, f2[6] = {0};
    pd_microplastic mp2 = {.sy = &big, .plastic = &plastic2};
    x[3] = h * 1.01;
    pd_microplastic_forces(&(pd_loop){&v, l.type, 1, x, l.vol, g, NULL, NULL, l.reaction, l.natoms, 0, NULL, 0}, &mat, &mp2);
    pd_pmb_forces(&(pd_loop){&v, l.type, 1, x, l.vol, f2, NULL, NULL, l.reaction, l.natoms, 0, NULL, 0}, &mat);
    check_true("microplastic with an unreachable yield stretch is PMB exactly", g[0] == f2[0] && g[3] == f2[3]);
    l.natoms = 8;
    lattice_free(&l);
  }
  return check_summary();
}
