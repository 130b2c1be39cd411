/* Ordinary state-based solid (T14 eq. 5.1): LPS at m = 1/2, nonlinear
 * orders, on a simple-cubic lattice. */
#include "check.h"
#include "common.h"
#include "model.h"
#include "pd_ordinary.h"
#include "pd_params.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
  double lambda, mu, order;
} material;

static double eval_ordinary(const lattice *l, const double *x, double *f, void *ctx)
{
  const material *m = ctx;
  return ordinary_eval(l, m->lambda, m->mu, m->order, x, f, NULL, NULL);
}


int main(void)
{
  const double K = 14.9e9, G = 7.0e9, h = 5e-4;
  const double lambda = K - 2.0 * G / 3.0;
  const pd_lame bar = pd_ordinary_lame_3d(K, G);
  check_rel("3D mu_bar = 5 mu / 2", bar.mu, 2.5 * G, 1e-15);
  check_rel("3D lambda_bar = lambda - mu", bar.lambda, lambda - G, 1e-15);
  /* LPS (m = 1/2, peri/lps influence, discrete normalization) at the centre
   * of a 9^3 block with delta = 3h: the centre's family is complete. */
  {
    lattice l = lattice_make(3, 9, h, 3.0001 * h, PD_INFLUENCE_LPS);
    const int n = l.natoms, ctr = lattice_center(&l);
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    double *psi = malloc(sizeof(double) * n), *theta = malloc(sizeof(double) * n);
    const double s = 1e-4;
    double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
    lattice_strain(&l, dil, x);
    ordinary_eval(&l, bar.lambda, bar.mu, 0.5, x, f, psi, theta);
    /* Every bond has stretch s, and the weighted volume normalizes the sum
     * exactly: theta = 3 s to round-off, at every atom, even at surfaces. */
    check_rel("LPS dilatation theta = 3 s at the centre", theta[ctr], 3 * s, 1e-12);
    check_rel("LPS dilatation theta = 3 s at a corner", theta[0], 3 * s, 1e-12);
    check_rel("LPS dilatation energy = K theta^2 / 2", psi[ctr], 0.5 * K * 9 * s * s, 1e-10);
    lattice_free(&l);
    free(x);
    free(f);
    free(psi);
    free(theta);
  }
  /* Deviatoric strains: on the lattice at delta = 3h the discrete 4th moment
   * of omega = 1/|xi| (discretely normalized) makes shear along the axes 1.5%
   * too stiff and shear off the axes 1.0% too soft (THEORY.md, discretization
   * facts; recomputed for this lattice), so the energy of any small strain is
   * within 1.5% of the classical one: tolerance 2%. (peri/lps's influence,
   * omega ~ |xi| here, is off by -13% and +8.6%: not a good default.) */
  {
    lattice l = lattice_make(3, 9, h, 3.0001 * h, PD_INFLUENCE_INVERSE);
    const int n = l.natoms, ctr = lattice_center(&l);
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    double *psi = malloc(sizeof(double) * n), *theta = malloc(sizeof(double) * n);
    unsigned seed = 11;
    for (int trial = 0; trial < 3; trial++) {
      double e[3][3];
      for (int i = 0; i < 3; i++)
        for (int j = 0; j <= i; j++) e[i][j] = e[j][i] = 1e-4 * urand(&seed);
      lattice_strain(&l, e, x);
      ordinary_eval(&l, bar.lambda, bar.mu, 0.5, x, f, psi, theta);
      check_rel("m = 1/2 random strain: classical energy", psi[ctr], classical_energy(lambda, G, e), 0.02);
      /* Small strain: every order m agrees with LPS to O(strain). */
      ordinary_eval(&l, bar.lambda, bar.mu, 0.0, x, f, psi, theta);
      check_rel("m = 0, random small strain: classical energy", psi[ctr], classical_energy(lambda, G, e), 0.02);
    }
    lattice_free(&l);
    free(x);
    free(f);
    free(psi);
    free(theta);
  }
  /* 2D plane stress and plane strain (THEORY.md: mu_bar = 2 mu, lambda_bar =
   * lambda_2D - mu, tr_omega(1) = 2): the energy density of a random in-plane
   * strain at the centre of a 17^2 square lattice. The square lattice is far
   * less isotropic than the cubic one: its 4th moment ratio M1111 / 3 M1122
   * (1 when isotropic) is 1.21 for omega = 1/|xi| and 1.09 for a constant
   * omega at delta = 3h, and 0.993 for a constant omega at delta = 6h, used
   * here: the deviatoric energy is then within 1% of the classical one;
   * tolerance 2%. PMMA plane stress (T14 6.2.1) checks the constants
   * themselves: mu_bar = 2.6 GPa, lambda_bar = 0.1 GPa. */
  {
    pd_elastic pmma;
    pd_elastic_from_E_nu(3.5e9, 0.35, &pmma);
    const pd_lame ps = pd_ordinary_lame(PD_PLANE_STRESS, &pmma);
    check_rel("PMMA plane stress mu_bar = 2.59 GPa (T14 6.2.1: 2.6)", ps.mu, 2.0 * 3.5e9 / 2.7, 1e-12);
    check_rel("PMMA plane stress lambda_bar = 0.1 GPa (T14 6.2.1)", ps.lambda, 0.1e9, 0.01);
    lattice l = lattice_make(2, 17, h, 6.0001 * h, PD_INFLUENCE_CONSTANT);
    const int n = l.natoms, ctr = lattice_center(&l);
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    double *psi = malloc(sizeof(double) * n);
    unsigned seed = 5;
    const pd_dimension dims[] = {PD_PLANE_STRESS, PD_PLANE_STRAIN};
    for (int k = 0; k < 2; k++) {
      const pd_lame b2 = pd_ordinary_lame(dims[k], &pmma);
      /* classical 2D energy: lambda_2D/2 tr^2 + mu e:e over in-plane strains */
      const double lambda2 = b2.lambda + pmma.G;
      for (int trial = 0; trial < 3; trial++) {
        double e[3][3] = {{0}};
        e[0][0] = 1e-4 * urand(&seed);
        e[1][1] = 1e-4 * urand(&seed);
        e[0][1] = e[1][0] = 1e-4 * urand(&seed);
        lattice_strain(&l, e, x);
        ordinary_eval(&l, b2.lambda, b2.mu, 0.5, x, f, psi, NULL);
        check_rel(k == 0 ? "2D plane stress random strain: classical energy"
                         : "2D plane strain random strain: classical energy",
                  psi[ctr], classical_energy(lambda2, pmma.G, e), 0.02);
      }
    }
    lattice_free(&l);
    free(x);
    free(f);
    free(psi);
  }
  /* lambda_bar = 0 is bond-based (T14 5.1): each bond's force then depends
   * on its own stretch only, so forces are linear in mu_bar and moving one
   * atom changes forces on its partners alone; with lambda_bar != 0 the
   * dilatation couples atoms up to two horizons apart. */
  {
    lattice l = lattice_make(3, 5, h, 2.0001 * h, PD_INFLUENCE_CONSTANT);
    double *x = malloc(sizeof(double) * 3 * l.natoms), *f = malloc(sizeof(double) * 3 * l.natoms);
    double *f2 = malloc(sizeof(double) * 3 * l.natoms);
    random_displacement(&l, 0.01 * h, 9, x);
    ordinary_eval(&l, 0.0, 3e9, 0.5, x, f, NULL, NULL);
    ordinary_eval(&l, 0.0, 1e9, 0.5, x, f2, NULL, NULL);
    double err = 0.0, scale = 0.0;
    for (int k = 0; k < 3 * l.natoms; k++) {
      err = fmax(err, fabs(f[k] - 3.0 * f2[k]));
      scale = fmax(scale, fabs(f[k]));
    }
    check_rel("lambda_bar = 0: forces linear in mu_bar (bond-based)", 1.0 + err / scale, 1.0, 1e-13);
    ordinary_eval(&l, 0.0, 1e9, 0.5, x, f, NULL, NULL);
    const int moved = lattice_center(&l);
    x[3 * moved] += 0.003 * h;
    ordinary_eval(&l, 0.0, 1e9, 0.5, x, f2, NULL, NULL);
    int far_changed = 0;
    for (int a = 0; a < l.natoms; a++) {
      const double dx = l.x0[3 * a] - l.x0[3 * moved], dy = l.x0[3 * a + 1] - l.x0[3 * moved + 1],
                   dz = l.x0[3 * a + 2] - l.x0[3 * moved + 2];
      if (sqrt(dx * dx + dy * dy + dz * dz) > l.delta && fabs(f[3 * a] - f2[3 * a]) > 1e-12 * scale)
        far_changed = 1;
    }
    check_true("lambda_bar = 0: a moved atom changes forces only within its horizon", !far_changed);
    ordinary_eval(&l, 1e9, 1e9, 0.5, x, f, NULL, NULL);
    x[3 * moved] -= 0.003 * h;
    ordinary_eval(&l, 1e9, 1e9, 0.5, x, f2, NULL, NULL);
    far_changed = 0;
    for (int a = 0; a < l.natoms; a++) {
      const double dx = l.x0[3 * a] - l.x0[3 * moved], dy = l.x0[3 * a + 1] - l.x0[3 * moved + 1],
                   dz = l.x0[3 * a + 2] - l.x0[3 * moved + 2];
      if (sqrt(dx * dx + dy * dy + dz * dz) > l.delta && fabs(f[3 * a] - f2[3 * a]) > 1e-12 * scale)
        far_changed = 1;
    }
    check_true("lambda_bar != 0: the dilatation couples atoms up to two horizons apart", far_changed);
    lattice_free(&l);
    free(x);
    free(f);
    free(f2);
  }
  /* Collapse of a sub-horizon region toward a point (T14 5.2.1-5.2.2): the
   * atoms within 1.5h of the centre are scaled toward it by alpha. For
   * m = 1/2 the bond strain is bounded below by -1, so the energy converges
   * as alpha -> 0; for m <= 0 it diverges (log^2 for m = 0, alpha^(4m) for
   * m < 0). */
  {
    lattice l = lattice_make(3, 9, h, 3.0001 * h, PD_INFLUENCE_TUPEK);
    const int n = l.natoms, ctr = lattice_center(&l);
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    const double orders[] = {0.5, 0.0, -1.0};
    double e[3][3];
    for (int k = 0; k < 3; k++) {
      for (int q = 0; q < 3; q++) {
        const double alpha = q == 0 ? 1e-2 : (q == 1 ? 1e-4 : 1e-6);
        for (int a = 0; a < n; a++)
          for (int c = 0; c < 3; c++) {
            const double rel = l.x0[3 * a + c] - l.x0[3 * ctr + c];
            x[3 * a + c] = l.x0[3 * a + c];
            double r2 = 0.0;
            for (int cc = 0; cc < 3; cc++) {
              const double dd = l.x0[3 * a + cc] - l.x0[3 * ctr + cc];
              r2 += dd * dd;
            }
            if (r2 <= 2.25 * h * h) x[3 * a + c] = l.x0[3 * ctr + c] + alpha * rel;
          }
        e[k][q] = ordinary_eval(&l, bar.lambda, bar.mu, orders[k], x, f, NULL, NULL);
      }
    }
    check_rel("m = 1/2 collapse energy converges (alpha 1e-4 -> 1e-6)", e[0][2], e[0][1], 1e-3);
    check_true("m = 0 collapse energy grows without bound (x1.5 per 1e-2 in alpha)",
               e[1][1] > 1.5 * e[1][0] && e[1][2] > 1.3 * e[1][1]);
    check_true("m = -1 collapse energy grows without bound (x1e6 per 1e-2 in alpha)",
               e[2][1] > 1e6 * e[2][0] && e[2][2] > 1e6 * e[2][1]);
    printf("collapse energies (J) alpha = 1e-2, 1e-4, 1e-6:\n");
    for (int k = 0; k < 3; k++) printf("  m = %4.1f: %.4g %.4g %.4g\n", orders[k], e[k][0], e[k][1], e[k][2]);
    lattice_free(&l);
    free(x);
    free(f);
  }
  /* Energy-force consistency for m = 1/2, 0, -1 on a small block with a
   * random displacement of 1% of the spacing and Tupek's weights. */
  {
    lattice l = lattice_make(3, 5, h, 2.0001 * h, PD_INFLUENCE_TUPEK);
    double *x = malloc(sizeof(double) * 3 * l.natoms);
    random_displacement(&l, 0.01 * h, 5, x);
    const double orders[] = {0.5, 0.0, -1.0};
    for (int k = 0; k < 3; k++) {
      material m = {bar.lambda, bar.mu, orders[k]};
      char name[32];
      snprintf(name, sizeof name, "ordinary m = %g", orders[k]);
      check_energy_gradient(name, &l, x, eval_ordinary, &m, 1e-6);
      check_objectivity(name, &l, x, eval_ordinary, &m);
      check_momentum(name, &l, x, eval_ordinary, &m);
    }
    lattice_free(&l);
    free(x);
  }
  /* The default 3D weight computed in the loops (pd_bond_view.weight_horizon:
   * the horizon over |xi|) is the table's number: the dilatation sums and
   * the forces are the same to the bit, in the vectorized passes (no
   * tally) and bond by bond (per-atom energy), on a randomly displaced
   * block. A horizon 1e-12 larger changes them: the loops take it. */
  {
    const double delta = 3.0001 * h;
    lattice l = lattice_make(3, 7, h, delta, PD_INFLUENCE_INVERSE);
    const int n = l.natoms;
    double *x = malloc(sizeof(double) * 3 * n), *ab = malloc(sizeof(double) * 2 * n);
    double *sum[3], *f[3];
    unsigned seed = 11;
    for (int a = 0; a < 3 * n; a++) x[a] = l.x0[a] + 1e-3 * h * urand(&seed);
    int same_sums = 1, same_forces = 1, moved = 1;
    for (int per_atom = 0; per_atom < 2; per_atom++) {
      const double horizons[3] = {0.0, delta, delta * (1.0 + 1e-12)};
      for (int w = 0; w < 3; w++) {
        sum[w] = calloc(n, sizeof(double));
        f[w] = calloc(3 * (size_t) n, sizeof(double));
        double *eatom = calloc(n, sizeof(double));
        pd_tally t = {0};
        t.eatom = eatom;
        pd_bond_view v = lattice_view(&l);
        v.weight_horizon = horizons[w];
        pd_ordinary_state st = {0.5, sum[w], ab, NULL, 0};
        const pd_loop L = {&v, l.type, 1, x, l.vol, f[w], per_atom ? &t : NULL, NULL, l.reaction, n, 0, NULL, 0};
        pd_ordinary_dilatation(&L, &st);
        for (int a = 0; a < n; a++) {
          ab[2 * a] = 1e22 * sum[w][a];
          ab[2 * a + 1] = 3e13;
        }
        pd_ordinary_forces(&L, &st);
        free(eatom);
      }
      same_sums &= memcmp(sum[0], sum[1], sizeof(double) * n) == 0;
      same_forces &= memcmp(f[0], f[1], sizeof(double) * 3 * n) == 0;
      moved &= memcmp(f[0], f[2], sizeof(double) * 3 * n) != 0 && memcmp(sum[0], sum[2], sizeof(double) * n) != 0;
      for (int w = 0; w < 3; w++) free(sum[w]), free(f[w]);
    }
    check_true("weight horizon / |xi| computed: dilatation sums equal the table's to the bit", same_sums);
    check_true("weight horizon / |xi| computed: forces equal the table's to the bit", same_forces);
    check_true("a horizon 1e-12 larger changes the sums and the forces (the loops use it)", moved);
    lattice_free(&l);
    free(x);
    free(ab);
  }
  /* The sums pass takes a row's chunk either in two passes (vectorized
   * values, scalar sums) or, when a bond in it is broken, bond by bond.
   * Both add in the same order onto the same two halves of the sum on i,
   * so the dilatation sums are the same to the bit: with every row's last
   * bond broken (adding nothing: no recontact), bond by bond, and with the
   * rows cut before it, in two passes. Rows of more than one chunk
   * (PD_CHUNK, 64 bonds) and odd lengths meet. */
  {
    lattice l = lattice_make(3, 9, h, 3.5001 * h, PD_INFLUENCE_INVERSE);
    const int n = l.natoms;
    double *x = malloc(sizeof(double) * 3 * n), *sum[2];
    int *cut = malloc(sizeof(int) * n), longest = 0, odd = 0;
    unsigned seed = 17;
    for (int a = 0; a < 3 * n; a++) x[a] = l.x0[a] + 1e-3 * h * urand(&seed);
    for (int a = 0; a < n; a++) {
      cut[a] = l.count[a] > 0 ? l.count[a] - 1 : 0;
      longest = cut[a] > longest ? cut[a] : longest;
      odd += cut[a] % 2;
    }
    for (int broken = 0; broken < 2; broken++) {
      sum[broken] = calloc(n, sizeof(double));
      pd_bond_view v = lattice_view(&l);
      if (!broken) v.count = cut;
      for (int a = 0; broken && a < n; a++)
        if (l.count[a]) l.len0[a * l.stride + l.count[a] - 1] *= -1.0;
      pd_failure fail = {.law = PD_FAIL_STRETCH, .recontact = 0, .len0 = l.len0};
      pd_ordinary_state st = {0.5, sum[broken], NULL, NULL, 0};
      const pd_loop L = {&v, l.type, 1, x, l.vol, NULL, NULL, broken ? &fail : NULL, l.reaction, n, 0, NULL, 0};
      pd_ordinary_dilatation(&L, &st);
      for (int a = 0; broken && a < n; a++)
        if (l.count[a]) l.len0[a * l.stride + l.count[a] - 1] *= -1.0;
    }
    /* (the last atom's bonds are each the last of their rows: its sum is 0) */
    int nonzero = 0;
    for (int a = 0; a < n; a++) nonzero += sum[0][a] != 0.0;
    check_true("sums pass: rows of 65 or more bonds and rows of odd length", longest > 64 && odd > 0);
    check_true("sums pass: dilatation sums bond by bond equal the two passes' to the bit",
               nonzero == n - 1 && memcmp(sum[0], sum[1], sizeof(double) * n) == 0);
    lattice_free(&l);
    free(x);
    free(cut);
    free(sum[0]);
    free(sum[1]);
  }
  /* One B for all atoms (pd_ordinary_state.uniform_b): the m = 1/2 force
   * pass takes the owner's B for the far end's. With every B equal the
   * forces are the same to the bit, vectorized and bond by bond; with B
   * varying they differ, so the pass does take the flag. */
  {
    lattice l = lattice_make(3, 7, h, 3.0001 * h, PD_INFLUENCE_INVERSE);
    const int n = l.natoms;
    double *x = malloc(sizeof(double) * 3 * n), *ab = malloc(sizeof(double) * 2 * n);
    double *sum = calloc(n, sizeof(double)), *f[2][2][2];
    unsigned seed = 5;
    for (int a = 0; a < 3 * n; a++) x[a] = l.x0[a] + 1e-3 * h * urand(&seed);
    for (int varying = 0; varying < 2; varying++)
      for (int per_atom = 0; per_atom < 2; per_atom++)
        for (int uniform = 0; uniform < 2; uniform++) {
          double *eatom = calloc(n, sizeof(double));
          pd_tally t = {0};
          t.eatom = eatom;
          pd_bond_view v = lattice_view(&l);
          f[varying][per_atom][uniform] = calloc(3 * (size_t) n, sizeof(double));
          memset(sum, 0, sizeof(double) * n);
          pd_ordinary_state st = {0.5, sum, ab, NULL, uniform};
          const pd_loop L = {&v, l.type, 1, x, l.vol, f[varying][per_atom][uniform],
                             per_atom ? &t : NULL, NULL, l.reaction, n, 0, NULL, 0};
          pd_ordinary_dilatation(&L, &st);
          for (int a = 0; a < n; a++) {
            ab[2 * a] = 1e22 * sum[a];
            ab[2 * a + 1] = 3e13 * (varying ? 1.0 + 0.1 * (a % 3) : 1.0);
          }
          pd_ordinary_forces(&L, &st);
          free(eatom);
        }
    const size_t bytes = sizeof(double) * 3 * n;
    check_true("one B for all atoms: forces equal the gathered B's to the bit (vectorized)",
               memcmp(f[0][0][0], f[0][0][1], bytes) == 0);
    check_true("one B for all atoms: forces equal the gathered B's to the bit (bond by bond)",
               memcmp(f[0][1][0], f[0][1][1], bytes) == 0);
    check_true("B varying: the flag changes the forces (the pass takes it)",
               memcmp(f[1][0][0], f[1][0][1], bytes) != 0 && memcmp(f[1][1][0], f[1][1][1], bytes) != 0);
    for (int varying = 0; varying < 2; varying++)
      for (int per_atom = 0; per_atom < 2; per_atom++)
        for (int uniform = 0; uniform < 2; uniform++) free(f[varying][per_atom][uniform]);
    lattice_free(&l);
    free(x);
    free(ab);
    free(sum);
  }
  return check_summary();
}
