/* PERI's rule, guarded (core/pd_law_legacy.h): the guarded kernels give the
 * exact kernels' forces, and the largest stretch they keep is the floor
 * the LAMMPS side tests against; pd_law_legacy_notes_at gives the exact
 * kernels' notes. All to the bit: a guarded run must equal an exact one. */
#include "check.h"
#include "lattice.h"
#include "pd_bond_loop.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static inline double linear_strain(void *mat, const pd_bond *bd)
{
  (void) mat;
  return pd_bond_stretch(bd);
}

static inline pd_bond_force linear_force(void *mat, const pd_bond *bd, double s)
{
  (void) mat;
  const pd_bond_force bf = {.tl = s * bd->w / bd->len, .stored = s * s};
  return bf;
}

PD_DEFINE_KERNELS(linear, linear_strain, linear_force)

typedef struct scene {
  lattice l;
  double *x, *f, *note, *s0, *len0;
  double s00[4], alpha[4];    /* (ntypes + 1)^2, one type */
} scene;

/* One evaluation of law 'law' (f zeroed first); returns bonds broken. */
static long evaluate(scene *sc, pd_fail_law law, pd_failure *fail)
{
  lattice *l = &sc->l;
  pd_bond_view v = lattice_view(l);
  v.len0 = sc->len0;
  memset(sc->f, 0, sizeof(double) * 3 * l->natoms);
  static pd_law_legacy params;
  params = (pd_law_legacy){sc->s00, sc->alpha, sc->s0, pd_failure_floor(sc->s0, l->natoms)};
  memset(fail, 0, sizeof *fail);
  fail->law = law;
  fail->params = law == PD_FAIL_LEGACY ? &params : NULL;
  fail->len0 = sc->len0;
  fail->note_atom = law == PD_FAIL_LEGACY ? sc->note : NULL;
  const pd_loop L = {&v, NULL, 2, sc->x, l->vol, sc->f, NULL, fail, l->reaction, l->natoms, 0, NULL, 0};
  pd_run_kernel(linear_kernels, &L, NULL);
  return fail->nbroken;
}

static int same(const double *a, const double *b, int n)
{
  int eq = 1;
  for (int k = 0; k < n; k++) eq &= a[k] == b[k] || (isinf(a[k]) && a[k] == b[k]);
  return eq;
}

int main(void)
{
  /* 9^3 points, horizon 3.0001 spacings: rows that are and are not whole
   * vectors; random displacements give stretches of both signs */
  const double h = 5e-4;
  scene sc = {.l = lattice_make(3, 9, h, 3.0001 * h, -1)};
  lattice *l = &sc.l;
  const int n = l->natoms, nslots = n * l->stride;
  sc.x = malloc(sizeof(double) * 3 * n);
  sc.f = malloc(sizeof(double) * 3 * n);
  sc.note = malloc(sizeof(double) * n);
  sc.s0 = malloc(sizeof(double) * n);
  sc.len0 = malloc(sizeof(double) * nslots);
  double *f_exact = malloc(sizeof(double) * 3 * n), *note_exact = malloc(sizeof(double) * n);
  double *note_at = malloc(sizeof(double) * n);
  for (int k = 0; k < 4; k++) sc.s00[k] = 5e-4, sc.alpha[k] = 0.25;
  unsigned seed = 11;
  for (int a = 0; a < 3 * n; a++) sc.x[a] = l->x0[a] + 2e-3 * h * urand(&seed);
  memcpy(sc.len0, l->len0, sizeof(double) * nslots);
  /* a few bonds broken already: their chunks go bond by bond */
  for (int i = 0; i < n; i += 37)
    if (l->count[i]) sc.len0[i * l->stride] = -sc.len0[i * l->stride];
  for (int a = 0; a < n; a++) sc.s0[a] = 1.0;    /* no bond breaks */

  pd_failure fail;
  check_true("the exact kernel breaks no bond below every s0", evaluate(&sc, PD_FAIL_LEGACY, &fail) == 0);
  memcpy(f_exact, sc.f, sizeof(double) * 3 * n);
  memcpy(note_exact, sc.note, sizeof(double) * n);
  evaluate(&sc, PD_FAIL_LEGACY_GUARDED, &fail);
  const double largest = fail.note_largest;
  check_true("guarded: the exact kernel's forces, to the bit", same(sc.f, f_exact, 3 * n));

  /* the largest stretch of an intact bond, bond by bond */
  pd_bond_view v = lattice_view(l);
  v.len0 = sc.len0;
  double want = -INFINITY;
  int intact = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < l->count[i]; k++) {
      const int idx = i * l->stride + k;
      if (sc.len0[idx] < 0.0) continue;
      pd_bond bd = {.i = i};
      pd_bond_load(&bd, &v, NULL, 2, sc.x, sc.x + 3 * i, NULL, idx, PD_WEIGHT_ONE, 0, 1);
      const double s = pd_bond_stretch(&bd);
      want = s > want ? s : want;
      intact++;
    }
  printf("%d intact bonds, largest stretch %.6e\n", intact, largest);
  check_true("guarded: note_largest is the largest stretch of an intact bond", largest == want && want > 0.0);

  const pd_law_legacy p = {sc.s00, sc.alpha, sc.s0, 0.0};
  pd_law_legacy_notes_at(&v, NULL, 2, sc.x, &p, note_at, n);
  check_true("notes_at: the exact kernel's notes, to the bit", same(note_at, note_exact, n));
  const double floor = pd_law_legacy_note_of(sc.s00[3], sc.alpha[3], largest);
  int above = 1;
  for (int a = 0; a < n; a++) above &= !(note_exact[a] < floor);
  check_true("every atom's new s0 is at least s00 - alpha * (largest stretch)", above);

  /* the guard's test is tight: every s0 at the largest stretch breaks
   * nothing; one s0 a rounding below it breaks a bond */
  for (int a = 0; a < n; a++) sc.s0[a] = largest;
  check_true("s0 = the largest stretch everywhere: nothing breaks", evaluate(&sc, PD_FAIL_LEGACY, &fail) == 0);
  for (int a = 0; a < n; a++) sc.s0[a] = nextafter(largest, -INFINITY);
  const long broke = evaluate(&sc, PD_FAIL_LEGACY, &fail);
  printf("s0 one rounding below the largest stretch: %ld bonds break\n", broke);
  check_true("s0 one rounding below the largest stretch: a bond breaks", broke >= 1);

  free(sc.x), free(sc.f), free(sc.note), free(sc.s0), free(sc.len0);
  free(f_exact), free(note_exact), free(note_at);
  lattice_free(l);
  return check_summary();
}
