#include "pd_tangent.h"

#include "pd_bond_loop.h"
#include "pd_seth_hill.h"

#include <math.h>

/* The loop of both materials, with the material's |C| of a bond (its
 * current length and reference length set) inlined. */
typedef double (*tangent_fn)(const void *mat, const pd_bond *bd);

PD_INLINE void tangent_sums(const pd_loop *L, const double *v, const void *mat, tangent_fn tangent,
                            double *sum, double *closing)
{
  const pd_bond_view *b = L->b;
  const int failing = L->fail != NULL;
  pd_bond bd;
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    const double xi[3] = {L->x[3 * i], L->x[3 * i + 1], L->x[3 * i + 2]};
    bd.i = i;
    bd.ti = L->type ? L->type[i] : 1;
    const int trow = bd.ti * L->ntypes;
    /* atom i's own sums in registers (its far ends are other atoms) */
    double si = 0.0, ci = 0.0;
    for (int k = 0; k < b->count[i]; k++) {
      pd_bond_load(&bd, b, L->type, trow, L->x, xi, L->fail, row + k, b->weight != NULL, failing,
                   1);
      /* the sign of the stretch decides whether a broken bond pushes */
      if (failing && pd_bond_inactive(L->fail, bd.broken, bd.len - bd.r0)) continue;
      const double c = tangent(mat, &bd);
      si += c * L->vol[bd.j];
      sum[bd.j] += c * L->vol[i];
      if (v) {
        const double r = pd_closing_rate(bd.d, bd.len, v + 3 * i, v + 3 * bd.j);
        ci = r > ci ? r : ci;
        if (r > closing[bd.j]) closing[bd.j] = r;
      }
    }
    sum[i] += si;
    if (v && ci > closing[i]) closing[i] = ci;
  }
}

PD_INLINE double pmb_bond(const void *mat, const pd_bond *bd)
{
  const pd_pmb_tangent *p = (const pd_pmb_tangent *) mat;
  const double cw = p->c[bd->tij] * bd->w;
  /* axial c w / r0, string c w |s| / |Y| = c w |len - r0 (1 + s_p)| / (r0 |Y|):
   * max(|Y|, |len - r0 (1 + s_p)|) c w / (r0 |Y|), one divide */
  const double stretched = fabs(bd->len - bd->r0 * (1.0 + (p->plastic ? p->plastic[bd->idx] : 0.0)));
  if (bd->len <= 0.0) return cw / bd->r0;
  return cw * (bd->len > stretched ? bd->len : stretched) / (bd->r0 * bd->len);
}

PD_INLINE double state_bond(const void *mat, const pd_bond *bd)
{
  const pd_state_tangent *p = (const pd_state_tangent *) mat;
  const int kind = pd_order_kind(p->order);
  const double eps = pd_bond_strain(kind, p->order, bd);
  const double g = pd_bond_strain_rate(kind, p->order, eps, bd);
  /* dg/d|Y| = (2m - 1) g / |Y| for eps = (c^m - 1)/(2m) */
  const double dg = (2.0 * p->order - 1.0) * g / bd->len;
  double axial = (p->k[bd->i] + p->k[bd->j]) * bd->w * g * g, string = 0.0;
  if (p->ab) {
    const double *ab = p->ab;
    const double s = ab[2 * bd->i] + ab[2 * bd->j] + (ab[2 * bd->i + 1] + ab[2 * bd->j + 1]) * eps;
    axial += fabs(s) * bd->w * fabs(dg);
    string = fabs(s * bd->w * g) / bd->len;
  }
  return axial > string ? axial : string;
}

void pd_pmb_tangent_sums(const pd_loop *L, const double *v, const pd_pmb_tangent *mat, double *sum,
                         double *closing)
{
  tangent_sums(L, v, mat, pmb_bond, sum, closing);
}

void pd_state_tangent_sums(const pd_loop *L, const double *v, const pd_state_tangent *mat,
                           double *sum, double *closing)
{
  tangent_sums(L, v, mat, state_bond, sum, closing);
}

double pd_contact_tangent(double cs, double dist, double len, double reach)
{
  if (len >= dist + reach) return 0.0;
  const double axial = cs / dist;
  const double string = len > 0.0 && len < dist ? cs * (dist - len) / (dist * len) : 0.0;
  return axial > string ? axial : string;
}
