#include "pd_tangent.h"

#include "pd_bond_loop.h"
#include "pd_seth_hill.h"

#include <math.h>
#include <string.h>

/* The loop of both materials, with the material's |C| of a bond (its
 * current length and reference length set) inlined. Rows go in chunks as
 * the force loop's (pd_bond_loop.h): a vectorizable pass computes every
 * bond's |C| and closing rate, a scalar one adds them onto both ends; a
 * chunk with a broken bond goes bond by bond, with the same arithmetic in
 * the same order. A check costs about 1.6 force steps of pd/bond (make
 * bench's block): the first pass gathers velocities too (six gathers a
 * vector of bonds to the force pass's three) and takes two divides. */
typedef double (*tangent_fn)(const void *mat, const pd_bond *bd);

/* One bond's |C| onto i's sum si and j's, its closing rate onto j's
 * largest (i's largest is taken apart: a max chain through this loop
 * went through integer registers, several cycles a bond) */
PD_INLINE void tangent_scatter(double c, double r, int j, double vi, const double *restrict vol,
                               double *si, double *restrict sum, double *restrict closing)
{
  *si += c * vol[j];
  sum[j] += c * vi;
  if (closing) {
    /* (stored either way: no branch on the rates' signs) */
    const double cj = closing[j];
    closing[j] = r > cj ? r : cj;
  }
}

/* pd_closing_rate's number, written so that the first pass vectorizes
 * (GCC gave up on the pointers v + 3 i and v + 3 j, and on '&&') */
PD_INLINE double tangent_rate(const double *restrict v, const pd_bond *bd, int closes)
{
  if (!closes) return 0.0;
  const int i = bd->i, j = bd->j;
  const double rate = -((v[3 * j] - v[3 * i]) * bd->d[0] + (v[3 * j + 1] - v[3 * i + 1]) * bd->d[1] +
                        (v[3 * j + 2] - v[3 * i + 2]) * bd->d[2]);
  const int ok = (rate > 0.0) & (bd->len > 0.0);
  return ok ? rate / (ok ? bd->len * bd->len : 1.0) : 0.0;
}

/* the first pass over bonds row .. row+m-1: |C| into c, the closing rate
 * into r; nonzero if a bond is broken */
PD_INLINE int tangent_bonds(const pd_bond_view *restrict b, const int *restrict type, int trow,
                            int ti, const double *restrict x, const double xi[3], int i, int row,
                            int m, const double *restrict v, const void *mat, tangent_fn tangent,
                            double *restrict c, double *restrict r, int weighted, int failing,
                            int closes)
{
  long long broken = 0;    /* (as pd_force_bonds' 'special') */
  for (int k = 0; k < m; k++) {
    pd_bond bd;
    bd.i = i;
    bd.ti = ti;
    broken |= -(long long) pd_bond_load_ahead(&bd, b, type, trow, x, xi, row + k, weighted, failing);
    c[k] = tangent(mat, &bd);
    r[k] = tangent_rate(v, &bd, closes);
  }
  return broken != 0;
}

/* max(ci, r[0..m-1]) for rates >= 0, whose bit patterns order as the
 * numbers do: an integer maximum vectorizes, a floating-point one does
 * not (it must keep the order of NaNs) */
PD_INLINE double largest_rate(const double *restrict r, int m, double ci)
{
  long long top, bits;
  memcpy(&top, &ci, sizeof top);
  for (int k = 0; k < m; k++) {
    memcpy(&bits, r + k, sizeof bits);
    top = bits > top ? bits : top;
  }
  memcpy(&ci, &top, sizeof ci);
  return ci;
}

/* tangent_bonds over a chunk in whole vectors, as pd_force_chunk */
PD_INLINE int tangent_chunk(const pd_bond_view *restrict b, const int *restrict type, int trow,
                            int ti, const double *restrict x, const double xi[3], int i, int row,
                            int m, const double *restrict v, const void *mat, tangent_fn tangent,
                            double *restrict c, double *restrict r, int weighted, int failing,
                            int closes)
{
  const int last = pd_vector_overlap(m);
  if (last < 0)
    return tangent_bonds(b, type, trow, ti, x, xi, i, row, m, v, mat, tangent, c, r, weighted,
                         failing, closes);
  return tangent_bonds(b, type, trow, ti, x, xi, i, row, m - m % PD_VECTOR_BONDS, v, mat, tangent,
                       c, r, weighted, failing, closes) |
         tangent_bonds(b, type, trow, ti, x, xi, i, row + last, PD_VECTOR_BONDS, v, mat, tangent,
                       c + last, r + last, weighted, failing, closes);
}

PD_INLINE void tangent_sums_on(const pd_loop *L, const double *v, const void *mat,
                               tangent_fn tangent, double *restrict sum, double *restrict closing,
                               int weighted, int closes, int failing)
{
  const pd_bond_view *restrict b = L->b;
  const double *restrict vol = L->vol;
  pd_bond bd;
  double c[PD_CHUNK], r[PD_CHUNK];
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride, n = b->count[i];
    const double xi[3] = {L->x[3 * i], L->x[3 * i + 1], L->x[3 * i + 2]};
    const double vi = vol[i];
    const int trow = pd_row_begin(&bd, L->type, L->ntypes, i);
    /* atom i's own sums in registers (its far ends are other atoms) */
    double si = 0.0, ci = 0.0;
    for (int k0 = 0; k0 < n; k0 += PD_CHUNK) {
      const int m = n - k0 < PD_CHUNK ? n - k0 : PD_CHUNK;
      const int *restrict far = b->far + row + k0;
      /* (one copy for one atom type: no type loads) */
      if (!(L->type ? tangent_chunk(b, L->type, trow, bd.ti, L->x, xi, i, row + k0, m, v, mat,
                                    tangent, c, r, weighted, failing, closes)
                    : tangent_chunk(b, NULL, trow, bd.ti, L->x, xi, i, row + k0, m, v, mat, tangent,
                                    c, r, weighted, failing, closes))) {
        for (int k = 0; k < m; k++)
          tangent_scatter(c[k], r[k], far[k], vi, vol, &si, sum, closes ? closing : NULL);
        if (closes) ci = largest_rate(r, m, ci);
        continue;
      }
      for (int k = 0; k < m; k++) {
        pd_bond_load(&bd, b, L->type, trow, L->x, xi, L->fail, row + k0 + k, weighted, failing, 1);
        /* the sign of the stretch decides whether a broken bond pushes */
        if (failing && pd_bond_inactive(L->fail, bd.broken, bd.len - bd.r0)) continue;
        const double rate = tangent_rate(v, &bd, closes);
        tangent_scatter(tangent(mat, &bd), rate, bd.j, vi, vol, &si, sum, closes ? closing : NULL);
        ci = rate > ci ? rate : ci;
      }
    }
    sum[i] += si;
    if (closes && ci > closing[i]) closing[i] = ci;
  }
}

/* (one copy per weight mode, with or without closing rates and broken
 * bonds, so that each is a constant in it: a test per bond stopped the
 * vectorizer) */
PD_INLINE void tangent_sums_weighted(const pd_loop *L, const double *v, const void *mat,
                                     tangent_fn tangent, double *sum, double *closing, int closes,
                                     int failing)
{
  switch (pd_weight_mode(L->b)) {
  case PD_WEIGHT_INVERSE:
    tangent_sums_on(L, v, mat, tangent, sum, closing, PD_WEIGHT_INVERSE, closes, failing);
    break;
  case PD_WEIGHT_TABLE:
    tangent_sums_on(L, v, mat, tangent, sum, closing, PD_WEIGHT_TABLE, closes, failing);
    break;
  default: tangent_sums_on(L, v, mat, tangent, sum, closing, PD_WEIGHT_ONE, closes, failing); break;
  }
}

PD_INLINE void tangent_sums(const pd_loop *L, const double *v, const void *mat, tangent_fn tangent,
                            double *sum, double *closing)
{
  const int failing = L->fail != NULL;
  if (v && failing) tangent_sums_weighted(L, v, mat, tangent, sum, closing, 1, 1);
  else if (v) tangent_sums_weighted(L, v, mat, tangent, sum, closing, 1, 0);
  else if (failing) tangent_sums_weighted(L, v, mat, tangent, sum, closing, 0, 1);
  else tangent_sums_weighted(L, v, mat, tangent, sum, closing, 0, 0);
}

/* axial c w / r0, string c w |s| / |Y| = c w |len - r0 (1 + s_p)| / (r0 |Y|):
 * max(|Y|, |len - r0 (1 + s_p)|) c w / (r0 |Y|), one divide (c w / r0 at
 * zero length); no branch, so that the first pass vectorizes */
PD_INLINE double pmb_tangent_of(const pd_pmb_tangent *p, const pd_bond *bd, double plastic)
{
  const double cw = p->c[bd->tij] * bd->w;
  const double stretched = fabs(bd->len - bd->r0 * (1.0 + plastic));
  const int some = bd->len > 0.0;
  const double top = some ? (bd->len > stretched ? bd->len : stretched) : 1.0;
  return cw * top / (bd->r0 * (some ? bd->len : 1.0));
}

PD_INLINE double pmb_bond(const void *mat, const pd_bond *bd)
{
  return pmb_tangent_of((const pd_pmb_tangent *) mat, bd, 0.0);
}

PD_INLINE double pmb_plastic_bond(const void *mat, const pd_bond *bd)
{
  const pd_pmb_tangent *p = (const pd_pmb_tangent *) mat;
  return pmb_tangent_of(p, bd, p->plastic[bd->idx]);
}

/* kind (pd_order_kind) and whether the ends' stress terms A, B exist
 * (ab) as constants, so that the first pass vectorizes for m = 1/2, 0
 * and the negative integers (any other order takes libm's logarithm and
 * exponential) */
PD_INLINE double state_tangent_of(const pd_state_tangent *p, const pd_bond *bd, int kind, int stress)
{
  const double eps = pd_bond_strain(kind, p->order, bd);
  const double g = pd_bond_strain_rate(kind, p->order, eps, bd);
  /* dg/d|Y| = (2m - 1) g / |Y| for eps = (c^m - 1)/(2m) */
  const double dg = (2.0 * p->order - 1.0) * g / bd->len;
  double axial = (p->k[bd->i] + p->k[bd->j]) * bd->w * g * g, string = 0.0;
  if (stress) {
    const double *ab = p->ab;
    const double s = ab[2 * bd->i] + ab[2 * bd->j] + (ab[2 * bd->i + 1] + ab[2 * bd->j + 1]) * eps;
    axial += fabs(s) * bd->w * fabs(dg);
    string = fabs(s * bd->w * g) / bd->len;
  }
  return axial > string ? axial : string;
}

#define PD_STATE_BOND(name, kind, stress)                                  \
  PD_INLINE double name(const void *mat, const pd_bond *bd)                \
  {                                                                        \
    return state_tangent_of((const pd_state_tangent *) mat, bd, kind, stress); \
  }
PD_STATE_BOND(state_half, PD_ORDER_HALF, 0)
PD_STATE_BOND(state_half_stress, PD_ORDER_HALF, 1)
PD_STATE_BOND(state_log, PD_ORDER_LOG, 0)
PD_STATE_BOND(state_log_stress, PD_ORDER_LOG, 1)
PD_STATE_BOND(state_reciprocal, PD_ORDER_RECIPROCAL, 0)
PD_STATE_BOND(state_reciprocal_stress, PD_ORDER_RECIPROCAL, 1)
PD_STATE_BOND(state_any, PD_ORDER_ANY, 0)
PD_STATE_BOND(state_any_stress, PD_ORDER_ANY, 1)
#undef PD_STATE_BOND

void pd_pmb_tangent_sums(const pd_loop *L, const double *v, const pd_pmb_tangent *mat, double *sum,
                         double *closing)
{
  if (mat->plastic) tangent_sums(L, v, mat, pmb_plastic_bond, sum, closing);
  else tangent_sums(L, v, mat, pmb_bond, sum, closing);
}

void pd_state_tangent_sums(const pd_loop *L, const double *v, const pd_state_tangent *mat,
                           double *sum, double *closing)
{
  /* (each hook named in its own call: a pointer chosen at run time would
   * not be inlined) */
  const int kind = pd_order_kind(mat->order);
  if (mat->ab) {
    if (kind == PD_ORDER_HALF) tangent_sums(L, v, mat, state_half_stress, sum, closing);
    else if (kind == PD_ORDER_LOG) tangent_sums(L, v, mat, state_log_stress, sum, closing);
    else if (kind == PD_ORDER_RECIPROCAL) tangent_sums(L, v, mat, state_reciprocal_stress, sum, closing);
    else tangent_sums(L, v, mat, state_any_stress, sum, closing);
  } else {
    if (kind == PD_ORDER_HALF) tangent_sums(L, v, mat, state_half, sum, closing);
    else if (kind == PD_ORDER_LOG) tangent_sums(L, v, mat, state_log, sum, closing);
    else if (kind == PD_ORDER_RECIPROCAL) tangent_sums(L, v, mat, state_reciprocal, sum, closing);
    else tangent_sums(L, v, mat, state_any, sum, closing);
  }
}

double pd_contact_tangent(double cs, double dist, double len, double reach)
{
  if (len >= dist + reach) return 0.0;
  const double axial = cs / dist;
  const double string = len > 0.0 && len < dist ? cs * (dist - len) / (dist * len) : 0.0;
  return axial > string ? axial : string;
}
