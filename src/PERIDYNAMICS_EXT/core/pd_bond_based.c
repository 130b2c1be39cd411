#include "pd_bond_based.h"

#include <math.h>
#include <stddef.h>

/* One loop body, inlined into specialized copies: the flags are constants at
 * each call site, so no copy carries a branch it does not need. */
PD_INLINE void
pmb_loop(const pd_bond_view *restrict b, const pd_pmb *restrict mat, pd_microplastic *mp,
         pd_failure *fail, const int *restrict type, const double *restrict x,
         const double *restrict vol, double *restrict f, pd_tally *tally,
         const int weighted, const int tallied, const int plastic, const int failing)
{
  double work = 0.0, work_joule = 0.0;
  pd_break_sums sums = {0.0, 0.0, 0};
  const int nt = mat->ntypes;
  for (int i = 0; i < b->nowner; i++) {
    const int n = b->count[i];
    if (!n) continue;
    const int row = i * b->stride;
    const double *restrict ci = mat->c + type[i] * nt;
    const double *restrict syi = plastic ? mp->sy + type[i] * nt : NULL;
    const double *restrict s0i = failing && fail->s0 ? fail->s0 + type[i] * nt : NULL;
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    const double vi = vol[i];
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;
    for (int k = 0; k < n; k++) {
      const int j = b->far[row + k];
      double r0 = b->len0[row + k];
      int broken = 0;
      if (failing) {
        r0 = pd_bond_reference(fail, r0, i, j, &broken);
      }
      const double dx = x[3 * j] - xi, dy = x[3 * j + 1] - yi, dz = x[3 * j + 2] - zi;
      const double len = sqrt(dx * dx + dy * dy + dz * dz);
      double s = (len - r0) / r0;
      if (failing && pd_bond_inactive(fail, broken, s)) continue;
      const double c = ci[type[j]];
      if (plastic) {
        /* return map: the elastic stretch s - sp stays within [-sy, sy] */
        double *sp = mp->plastic + row + k;
        const double sy = syi[type[j]], e = s - *sp;
        const double excess = e > sy ? e - sy : (e < -sy ? e + sy : 0.0);
        if (excess != 0.0) {
          *sp += excess;
          const double wp = c * sy * fabs(excess) * r0 * (weighted ? b->weight[row + k] : 1.0);
          work += wp * 0.5 * (vol[j] + vi);
          work_joule += wp * vol[j] * vi;
          if (mp->work_atom) {   /* half at each end: sum_i V_i d_i is the joules */
            mp->work_atom[i] += 0.5 * wp * vol[j];
            mp->work_atom[j] += 0.5 * wp * vi;
          }
        }
        s -= *sp;
      }
      double t = c * s;
      if (weighted) t *= b->weight[row + k];
      const double vj = vol[j];
      const double w = 0.25 * t * s * r0; /* energy density per partner volume */
      /* critical stretch: the bond breaks now, releasing the energy it
       * stores in this configuration, and acts with half its force, so that
       * the half-kicks around this step carry it up to this step (the
       * energy balance stays second order in dt; see pd_ordinary.c) */
      double share = 1.0;
      if (failing && !broken && s0i && fail->law == PD_FAIL_STRETCH && s > s0i[type[j]]) {
        pd_break_bond(fail, &sums, row + k, r0, i, j, w, w, vi, vj);
        share = 0.5;
      }
      const double tl = len > 0.0 ? share * t / len : 0.0;
      fxi += vj * tl * dx;
      fyi += vj * tl * dy;
      fzi += vj * tl * dz;
      f[3 * j] -= vi * tl * dx;
      f[3 * j + 1] -= vi * tl * dy;
      f[3 * j + 2] -= vi * tl * dz;
      if (tallied) {
        const double we = share == 1.0 ? w : 0.0;   /* a breaking bond's is booked as dissipated */
        tally->energy += we * (vj + vi);
        if (tally->eatom) {
          tally->eatom[i] += we * vj;
          tally->eatom[j] += we * vi;
        }
        const double d[3] = {-dx, -dy, -dz};
        pd_tally_virial(tally, d, -tl * vi * vj);
      }
      /* legacy PERI: the bond breaks after its force acted */
      if (failing && !broken && fail->law == PD_FAIL_LEGACY &&
          pd_legacy_failure(fail, type[i] * nt + type[j], i, j, s))
        pd_break_bond(fail, &sums, row + k, r0, i, j, w, w, vi, vj);
    }
    f[3 * i] += fxi;
    f[3 * i + 1] += fyi;
    f[3 * i + 2] += fzi;
  }
  if (plastic) {
    mp->dissipated += work;
    mp->dissipated_joule += work_joule;
  }
  if (failing) pd_add_break_sums(fail, &sums);
}

#define PMB_VARIANTS(mp, fail, plastic, failing)                                              \
  do {                                                                                        \
    const int weighted = b->weight != NULL;                                                   \
    if (tally) {                                                                              \
      if (weighted) pmb_loop(b, mat, mp, fail, type, x, vol, f, tally, 1, 1, plastic, failing); \
      else pmb_loop(b, mat, mp, fail, type, x, vol, f, tally, 0, 1, plastic, failing);          \
    } else {                                                                                  \
      if (weighted) pmb_loop(b, mat, mp, fail, type, x, vol, f, NULL, 1, 0, plastic, failing);  \
      else pmb_loop(b, mat, mp, fail, type, x, vol, f, NULL, 0, 0, plastic, failing);           \
    }                                                                                         \
  } while (0)

void pd_pmb_forces(const pd_bond_view *b, const pd_pmb *mat, pd_failure *fail, const int *type,
                   const double *x, const double *vol, double *f, pd_tally *tally)
{
  if (fail) PMB_VARIANTS(NULL, fail, 0, 1);
  else PMB_VARIANTS(NULL, NULL, 0, 0);
}

void pd_microplastic_forces(const pd_bond_view *b, const pd_pmb *mat, pd_microplastic *mp,
                            const int *type, const double *x, const double *vol, double *f,
                            pd_tally *tally)
{
  PMB_VARIANTS(mp, NULL, 1, 0);
}
