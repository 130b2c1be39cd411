#include "pd_tangent.h"

#include "pd_bond_loop.h"
#include "pd_seth_hill.h"

#include <math.h>

void pd_tangent_sums(const pd_loop *L, const double *v, const void *ctx, pd_tangent_fn tangent,
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
    for (int k = 0; k < b->count[i]; k++) {
      pd_bond_load(&bd, b, L->type, trow, L->x, xi, L->fail, row + k, b->weight != NULL, failing,
                   1);
      /* the sign of the stretch decides whether a broken bond pushes */
      if (failing && pd_bond_inactive(L->fail, bd.broken, bd.len - bd.r0)) continue;
      const double c = tangent(ctx, &bd);
      sum[i] += c * L->vol[bd.j];
      sum[bd.j] += c * L->vol[i];
      if (v) {
        const double r = pd_closing_rate(bd.d, bd.len, v + 3 * i, v + 3 * bd.j);
        if (r > closing[i]) closing[i] = r;
        if (r > closing[bd.j]) closing[bd.j] = r;
      }
    }
  }
}

double pd_pmb_bond_tangent(const void *ctx, const pd_bond *bd)
{
  const pd_pmb_tangent *p = (const pd_pmb_tangent *) ctx;
  const double cw = p->c[bd->tij] * bd->w;
  const double s = (bd->len - bd->r0) / bd->r0 - (p->plastic ? p->plastic[bd->idx] : 0.0);
  const double axial = cw / bd->r0;
  const double string = bd->len > 0.0 ? cw * fabs(s) / bd->len : 0.0;
  return axial > string ? axial : string;
}

double pd_state_bond_tangent(const void *ctx, const pd_bond *bd)
{
  const pd_state_tangent *p = (const pd_state_tangent *) ctx;
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

double pd_contact_tangent(double cs, double dist, double len, double reach)
{
  if (len >= dist + reach) return 0.0;
  const double axial = cs / dist;
  const double string = len > 0.0 && len < dist ? cs * (dist - len) / (dist * len) : 0.0;
  return axial > string ? axial : string;
}
