/* The bond loop's contract with a material's force hook (core/pd_bond_loop.h):
 * the vectorized first pass takes a row's last bonds as one whole vector
 * that overlaps the one before, so a plain material's hook may see a bond
 * twice; a stateful one (PD_DEFINE_STATEFUL_KERNELS) has its updating hook
 * called exactly once for every bond of a chunk where some bond's state
 * changes, and never for the other chunks (the first pass takes those with
 * the pure 'ahead' hook). A hook that counts its calls per bond tells which. */
#include "check.h"
#include "lattice.h"
#include "pd_bond_loop.h"

#include <stdlib.h>
#include <string.h>

static inline double count_strain(void *calls, const pd_bond *bd)
{
  (void) calls;
  return pd_bond_stretch(bd);
}

/* a linear bond whose hook counts its calls (a state it updates) */
static inline pd_bond_force count_force(void *calls, const pd_bond *bd, double s)
{
  ((int *) calls)[bd->idx]++;
  const pd_bond_force bf = {.tl = s * bd->w / bd->len};
  return bf;
}

/* the same force, counting nothing */
static inline pd_bond_force pure_force(void *calls, const pd_bond *bd, double s)
{
  (void) calls;
  const pd_bond_force bf = {.tl = s * bd->w / bd->len};
  return bf;
}

/* the state of a few bonds changes: those stretched beyond a threshold */
#define CHANGE_STRETCH 4e-4
static inline int stretch_changes(void *calls, const pd_bond *bd, double s)
{
  (void) calls, (void) bd;
  return s > CHANGE_STRETCH;
}

PD_DEFINE_KERNELS(plain, count_strain, count_force)
PD_DEFINE_STATEFUL_KERNELS(stateful, count_strain, count_force, pure_force, stretch_changes)

/* One evaluation with the kernels 'table': forces into f, calls per slot
 * into calls; returns the largest count and the number of bonds seen more
 * than once. */
static int evaluate(const pd_kernel (*table)[6], const lattice *l, const double *x, double *f,
                    int *calls, int *repeated)
{
  pd_bond_view v = lattice_view(l);
  memset(f, 0, sizeof(double) * 3 * l->natoms);
  memset(calls, 0, sizeof(int) * (size_t) l->natoms * l->stride);
  const pd_loop L = {&v, l->type, 1, x, l->vol, f, NULL, NULL, l->reaction, l->natoms, 0, NULL, 0};
  pd_run_kernel(table, &L, calls);
  int most = 0, missed = 0;
  *repeated = 0;
  for (int i = 0; i < l->natoms; i++)
    for (int k = 0; k < l->count[i]; k++) {
      const int n = calls[i * l->stride + k];
      most = n > most ? n : most;
      missed += n == 0;
      *repeated += n > 1;
    }
  /* (a stateful material's updating hook sees only some bonds) */
  if (table == plain_kernels) check_true("every bond's force computed", missed == 0);
  return most;
}

int main(void)
{
  /* 9^3 points, horizon 3.0001 spacings: rows of 0 to 61 bonds (each bond
   * at its lower-index end), so chunks that are and are not whole vectors */
  const double h = 5e-4;
  lattice l = lattice_make(3, 9, h, 3.0001 * h, -1);
  double *x = malloc(sizeof(double) * 3 * l.natoms);
  double *f_plain = malloc(sizeof(double) * 3 * l.natoms);
  double *f_stateful = malloc(sizeof(double) * 3 * l.natoms);
  int *calls = malloc(sizeof(int) * (size_t) l.natoms * l.stride);
  unsigned seed = 7;
  for (int a = 0; a < 3 * l.natoms; a++) x[a] = l.x0[a] + 1e-3 * h * urand(&seed);

  int repeated = 0;
  const int most_plain = evaluate(plain_kernels, &l, x, f_plain, calls, &repeated);
  printf("plain material: %d bonds computed twice, at most %d times\n", repeated, most_plain);
  /* (else the check below would pass without testing anything) */
  check_true("a plain material's first pass computes overlapped bonds twice", repeated > 0);
  check_true("a plain material's first pass computes no bond more than twice", most_plain <= 2);

  const int most_stateful = evaluate(stateful_kernels, &l, x, f_stateful, calls, &repeated);
  check_true("a stateful material's updating hook sees no bond twice",
             most_stateful == 1 && repeated == 0);
  /* per chunk of a row: changing bonds, bonds the updating hook saw */
  pd_bond_view v = lattice_view(&l);
  int changing = 0, updated = 0, wrong = 0, total = 0;
  for (int i = 0; i < l.natoms; i++)
    for (int k0 = 0; k0 < l.count[i]; k0 += PD_CHUNK) {
      const int m = l.count[i] - k0 < PD_CHUNK ? l.count[i] - k0 : PD_CHUNK;
      total += m;
      int changes = 0, seen = 0;
      for (int k = k0; k < k0 + m; k++) {
        pd_bond bd = {.i = i};
        const double xi[3] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
        pd_bond_load(&bd, &v, NULL, 0, x, xi, NULL, i * l.stride + k, v.weight != NULL, 0, 1);
        changes += count_strain(NULL, &bd) > CHANGE_STRETCH;
        seen += calls[i * l.stride + k];
      }
      changing += changes;
      updated += seen;
      wrong += seen != (changes ? m : 0);
    }
  printf("stateful material: %d bonds change, %d bonds updated\n", changing, updated);
  check_true("some bonds change their state, not all", changing > 0 && updated < total);
  check_true("a chunk with a changing bond goes through the updating hook whole, the others not at all",
             wrong == 0);

  int same = 1;
  for (int a = 0; a < 3 * l.natoms; a++) same &= f_plain[a] == f_stateful[a];
  check_true("both ways give the same forces, to the bit", same);

  free(x);
  free(f_plain);
  free(f_stateful);
  free(calls);
  lattice_free(&l);
  return check_summary();
}
