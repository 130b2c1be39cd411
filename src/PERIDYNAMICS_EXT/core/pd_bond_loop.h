/* The bond loops, written once for every material.
 *
 * A material supplies its per-bond math as static inline functions:
 *   double strain(void *mat, const pd_bond *bd)
 *       the bond's strain (its sign decides whether a broken bond pushes);
 *   pd_bond_force force(void *mat, const pd_bond *bd, double eps)
 *       the force state and the energies of the bond (pd_bonds.h).
 * pd_force_loop walks every bond once: decodes it (broken bonds, recontact),
 * asks the material, asks the failure law, applies the force to both ends
 * (half of it when the bond breaks now) and tallies energy and virial.
 * PD_DEFINE_KERNELS instantiates it for every failure law and every
 * combination of effects (weights, tally, broken bonds); a material picks
 * one per evaluation with pd_run_kernel. The flags and hooks are constants
 * in each copy: an effect that is off costs nothing per bond, and no hook
 * is an indirect call. */
#ifndef PD_BOND_LOOP_H
#define PD_BOND_LOOP_H

#include "pd_bonds.h"
#include "pd_failure.h"
#include "pd_law_hooks.h"
#include "pd_loop.h"

#include <math.h>
#include <stddef.h>

typedef double (*pd_strain_fn)(void *mat, const pd_bond *bd);
typedef pd_bond_force (*pd_force_fn)(void *mat, const pd_bond *bd, double eps);
typedef int (*pd_breaks_now_fn)(const pd_failure *f, const pd_bond *bd, double eps,
                                const pd_bond_force *bf);
typedef int (*pd_breaks_after_fn)(const pd_failure *f, const pd_bond *bd, double eps);

/* Slot idx of atom bd->i's row: its far end, types, weight and reference
 * length (intact unless 'failing'; a reference walk, not 'current', takes
 * a broken bond with its length); with 'current' also its current
 * separation and length. trow: ti * ntypes; xi: the owner's position. */
PD_INLINE void
pd_bond_load(pd_bond *bd, const pd_bond_view *restrict b, const int *restrict type, int trow,
             const double *restrict x, const double xi[3], const pd_failure *fail, int idx,
             int weighted, int failing, int current)
{
  const int j = b->far[idx];
  bd->j = j;
  bd->idx = idx;
  bd->tj = type ? type[j] : 0;
  bd->tij = trow + bd->tj;
  bd->w = weighted ? b->weight[idx] : 1.0;
  bd->broken = 0;
  if (failing) bd->r0 = pd_bond_reference(fail, b->len0[idx], bd->i, j, &bd->broken);
  else if (current) bd->r0 = b->len0[idx];
  else bd->r0 = fabs(b->len0[idx]);
  if (current) {
    bd->d[0] = x[3 * j] - xi[0];
    bd->d[1] = x[3 * j + 1] - xi[1];
    bd->d[2] = x[3 * j + 2] - xi[2];
    bd->len = sqrt(bd->d[0] * bd->d[0] + bd->d[1] * bd->d[1] + bd->d[2] * bd->d[2]);
  }
}

/* The arrays are parameters so that 'restrict' holds (GCC honours it on
 * parameters): the force stores then do not make it reload x or the
 * material's tables. */
PD_INLINE void
pd_force_loop_on(const pd_bond_view *restrict b, const int *restrict type, int ntypes,
                 const double *restrict x, const double *restrict vol, double *restrict f,
                 pd_tally *tally, pd_failure *fail, void *restrict mat, pd_strain_fn strain,
                 pd_force_fn force, pd_breaks_now_fn breaks_now, pd_breaks_after_fn breaks_after,
                 int weighted, int tallied, int failing, int directed)
{
  pd_break_sums sums = {0.0, 0.0, 0};
  pd_bond bd;
  for (int i = 0; i < b->nowner; i++) {
    const int n = b->count[i];
    if (!n) continue;
    const int row = i * b->stride;
    const double vi = vol[i];
    double fi[3] = {0.0, 0.0, 0.0};
    bd.i = i;
    bd.ti = type[i];
    const int trow = bd.ti * ntypes;
    const double xi[3] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    for (int k = 0; k < n; k++) {
      pd_bond_load(&bd, b, type, trow, x, xi, fail, row + k, weighted, failing, 1);
      const double eps = strain(mat, &bd);
      if (failing && pd_bond_inactive(fail, bd.broken, eps)) continue;
      const pd_bond_force bf = force(mat, &bd, eps);
      const int j = bd.j;
      const double vj = vol[j];
      /* a bond that fails releases its energy now and acts with half its
       * force: the half-kicks around this step then carry it up to this
       * step and no further, so the balance of kinetic, elastic and
       * dissipated energy stays second order in dt (a bond dropped whole
       * here would miss half a kick: first order) */
      double share = 1.0;
      if (failing && !bd.broken && breaks_now(fail, &bd, eps, &bf)) {
        pd_break_bond(fail, &sums, &bd, bf.release_i, bf.release_j, vi, vj, 1);
        share = 0.5;
      }
      /* the force on i per V_i V_j */
      double fij[3];
      const double tl = directed || bd.len <= 0.0 ? 0.0 : share * bf.t / bd.len;
      for (int c = 0; c < 3; c++) fij[c] = directed ? share * bf.v[c] : tl * bd.d[c];
      for (int c = 0; c < 3; c++) {
        fi[c] += vj * fij[c];
        f[3 * j + c] -= vi * fij[c];
      }
      if (tallied) {
        /* a breaking bond's energy is booked as dissipated instead */
        const double ei = share == 1.0 ? bf.stored_i : 0.0, ej = share == 1.0 ? bf.stored_j : 0.0;
        tally->energy += ei * vj + ej * vi;
        if (tally->eatom) {
          tally->eatom[i] += ei * vj;
          tally->eatom[j] += ej * vi;
        }
        const double dij[3] = {-bd.d[0], -bd.d[1], -bd.d[2]};
        if (directed) {
          const double fv[3] = {vi * vj * fij[0], vi * vj * fij[1], vi * vj * fij[2]};
          pd_tally_virial_pair(tally, dij, fv);
        } else {
          pd_tally_virial(tally, dij, -tl * vi * vj);
        }
      }
      if (failing && !bd.broken && breaks_after(fail, &bd, eps))
        pd_break_bond(fail, &sums, &bd, bf.release_i, bf.release_j, vi, vj, 0);
    }
    for (int c = 0; c < 3; c++) f[3 * i + c] += fi[c];
  }
  if (failing) pd_add_break_sums(fail, &sums);
}

PD_INLINE void
pd_force_loop(const pd_loop *L, void *mat, pd_strain_fn strain, pd_force_fn force,
              pd_breaks_now_fn breaks_now, pd_breaks_after_fn breaks_after, int weighted,
              int tallied, int failing, int directed)
{
  pd_force_loop_on(L->b, L->type, L->ntypes, L->x, L->vol, L->f, L->tally, L->fail, mat, strain,
                   force, breaks_now, breaks_after, weighted, tallied, failing, directed);
}

/* A kernel: pd_force_loop for one material, one law, one set of effects. */
typedef void (*pd_kernel)(const pd_loop *L, void *mat);

#define PD_KERNEL_(prefix, strain, force, law, failing, weighted, tallied, directed)     \
  static void prefix##_##law##_##failing##weighted##tallied(const pd_loop *L, void *mat) \
  {                                                                                       \
    pd_force_loop(L, mat, strain, force, pd_law_##law##_now, pd_law_##law##_after,        \
                  weighted, tallied, failing, directed);                                  \
  }
#define PD_KERNELS_OF_LAW_(ID, law, prefix, strain, force, failing, directed) \
  PD_KERNEL_(prefix, strain, force, law, failing, 0, 0, directed)             \
  PD_KERNEL_(prefix, strain, force, law, failing, 0, 1, directed)             \
  PD_KERNEL_(prefix, strain, force, law, failing, 1, 0, directed)             \
  PD_KERNEL_(prefix, strain, force, law, failing, 1, 1, directed)
#define PD_KERNEL_ROW_(ID, law, prefix, failing)                                      \
  {prefix##_##law##_##failing##00, prefix##_##law##_##failing##01,                    \
   prefix##_##law##_##failing##10, prefix##_##law##_##failing##11},
#define PD_FAILING_KERNELS_(ID, law, prefix, strain, force, directed) \
  PD_KERNELS_OF_LAW_(ID, law, prefix, strain, force, 1, directed)
#define PD_FAILING_ROW_(ID, law, prefix) PD_KERNEL_ROW_(ID, law, prefix, 1)

/* Defines prefix_kernels: row 0 for intact bonds only (nothing can be or
 * become broken), then one row per failure law of pd_laws.h; in each row
 * the four combinations of weights and tally. */
#define PD_DEFINE_KERNELS_(prefix, strain, force, directed)                           \
  PD_KERNELS_OF_LAW_(NONE, none, prefix, strain, force, 0, directed)                  \
  PD_FAILURE_LAWS(PD_FAILING_KERNELS_, prefix, strain, force, directed)               \
  static const pd_kernel prefix##_kernels[PD_NLAWS + 1][4] = {                       \
      PD_KERNEL_ROW_(NONE, none, prefix, 0) PD_FAILURE_LAWS(PD_FAILING_ROW_, prefix)};
#define PD_DEFINE_KERNELS(prefix, strain, force) PD_DEFINE_KERNELS_(prefix, strain, force, 0)
/* The same for a material whose bond force is not along the bond (its
 * force hook fills pd_bond_force.v): the classical correspondence. */
#define PD_DEFINE_DIRECTED_KERNELS(prefix, strain, force) \
  PD_DEFINE_KERNELS_(prefix, strain, force, 1)

/* Run the kernel of a table that L asks for: its failure law (or none),
 * weights when the bond view has them, tally when L has one. */
static inline void pd_run_kernel(const pd_kernel (*table)[4], const pd_loop *L, void *mat)
{
  const int row = L->fail ? 1 + (int) L->fail->law : 0;
  table[row][(L->b->weight != NULL) * 2 + (L->tally != NULL)](L, mat);
}

/* Sums over bonds onto both ends in the reference configuration:
 * sum[i] += a V_j and sum[j] += b V_i with (a, b) = value(ctx, bond). Only
 * intact bonds when 'intact_only'. The caller adds the ghosts' share onto
 * their owners. */
typedef void (*pd_bond_value_fn)(const void *ctx, const pd_bond *bd, double *a, double *b);

PD_INLINE void
pd_reference_sums(const pd_bond_view *restrict b, const int *type, int ntypes,
                  const double *restrict vol, double *restrict sum, const void *ctx,
                  pd_bond_value_fn value, int intact_only)
{
  pd_bond bd;
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    bd.i = i;
    bd.ti = type ? type[i] : 0;
    const int trow = bd.ti * ntypes;
    for (int k = 0; k < b->count[i]; k++) {
      if (intact_only && pd_bond_broken(b->len0[row + k])) continue;
      pd_bond_load(&bd, b, type, trow, NULL, NULL, NULL, row + k, b->weight != NULL, 0, 0);
      double vi_share, vj_share;
      value(ctx, &bd, &vi_share, &vj_share);
      sum[i] += vi_share * vol[bd.j];
      sum[bd.j] += vj_share * vol[i];
    }
  }
}

/* The same in the current configuration, over the bonds that act (a broken
 * bond only in compression, with recontact): value(ctx, bond, strain, t)
 * gives 'width' numbers t, added as t V_j onto sum[i * width ..] and t V_i
 * onto sum[j * width ..]. A state-based material's first pass (dilatation,
 * deformation gradient); types are not loaded. */
enum { PD_MAX_SUM_WIDTH = 48 };
typedef void (*pd_bond_strain_value_fn)(void *ctx, const pd_bond *bd, double eps, double *t);

PD_INLINE void
pd_current_sums(const pd_loop *L, double *restrict sum, int width, void *mat, pd_strain_fn strain,
                pd_bond_strain_value_fn value, int failing)
{
  const pd_bond_view *restrict b = L->b;
  const double *restrict vol = L->vol;
  pd_bond bd;
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    bd.i = i;
    bd.ti = 0;
    /* value() writes all width entries of t; zeroing it once per atom only
     * keeps the compiler from doubting it */
    double si[PD_MAX_SUM_WIDTH], t[PD_MAX_SUM_WIDTH] = {0.0};
    for (int c = 0; c < width; c++) si[c] = 0.0;
    const double xi[3] = {L->x[3 * i], L->x[3 * i + 1], L->x[3 * i + 2]};
    for (int k = 0; k < b->count[i]; k++) {
      pd_bond_load(&bd, b, NULL, 0, L->x, xi, L->fail, row + k, b->weight != NULL, failing, 1);
      const double eps = strain(mat, &bd);
      if (failing && pd_bond_inactive(L->fail, bd.broken, eps)) continue;
      value(mat, &bd, eps, t);
      const double vj = vol[bd.j], vi = vol[i];
      for (int c = 0; c < width; c++) {
        si[c] += t[c] * vj;
        sum[bd.j * width + c] += t[c] * vi;
      }
    }
    for (int c = 0; c < width; c++) sum[i * width + c] += si[c];
  }
}

#endif
