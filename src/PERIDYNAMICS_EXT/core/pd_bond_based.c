/* Bond-based materials: their per-bond math for the bond loop. */
#include "pd_bond_based.h"

#include "pd_bond_loop.h"
#include "pd_timestep.h"

#include <math.h>

const pd_coef pd_bond_coefs[PD_BOND_NCOEFS] = {
    [PD_BOND_HORIZON] = PD_COEF_HORIZON,
    [PD_BOND_C] = {.name = "c", .what = "micromodulus", .mix = PD_MIX_MEAN,
                   .flags = PD_COEF_PAIR | PD_COEF_FILE, .check = PD_CHECK_POSITIVE},
    [PD_BOND_K] = {.name = "K", .what = "bulk modulus", .mix = PD_MIX_MEAN,
                   .flags = PD_COEF_PAIR | PD_COEF_FILE, .check = PD_CHECK_POSITIVE},
    [PD_BOND_E] = {.name = "E", .what = "Young's modulus", .mix = PD_MIX_MEAN,
                   .flags = PD_COEF_PAIR | PD_COEF_FILE, .check = PD_CHECK_POSITIVE},
    /* not from files: theirs is the real material's, not the model's */
    [PD_BOND_NU] = {.name = "nu", .what = "Poisson's ratio", .mix = PD_MIX_MEAN,
                    .flags = PD_COEF_PAIR, .check = PD_CHECK_FINITE},
    /* the model checks it (microplastic needs it, pmb refuses it) */
    [PD_BOND_YIELD] = {.name = "yield_stretch", .what = "yield stretch", .mix = PD_MIX_MEAN,
                       .flags = PD_COEF_PAIR | PD_COEF_FILE, .check = PD_CHECK_FINITE},
};

PD_INLINE double pmb_strain(void *mat, const pd_bond *bd)
{
  (void) mat;
  return pd_bond_stretch(bd);
}

/* force c s w, given as s / |Y| (sl), of a stretch s whose extension s |xi|
 * is ext; energy 1/4 c s^2 |xi| w per partner volume at each end, released
 * whole when the bond breaks, as 1/4 (c sl w |Y|) ext: three products on
 * the force's (from s itself, the tallied first pass took nine operations
 * a bond more than the untallied one; 0 at zero length, where the force
 * is 0 too) */
PD_INLINE pd_bond_force pmb_bond(double c, double sl, double ext, const pd_bond *bd)
{
  const double tl = c * sl * bd->w;
  const double e = 0.25 * (tl * bd->len) * ext;
  const pd_bond_force bf = {.tl = tl, .stored = e, .release_i = e, .release_j = e, .release = e + e};
  return bf;
}

/* mat: the micromodulus table itself (one load less per bond than
 * through the pd_pmb) */
PD_INLINE pd_bond_force pmb_force(void *c, const pd_bond *bd, double s)
{
  /* s / |Y| = (|Y| - |xi|) q: no divide but the stretch's (an elastic
   * evaluation needs s itself only for failure) */
  (void) s;
  const double ext = bd->len - bd->r0;
  return pmb_bond(((const double *) c)[bd->tij], ext * pd_bond_inverse(bd), ext, bd);
}

PD_DEFINE_KERNELS(pmb, pmb_strain, pmb_force)

void pd_pmb_forces(const pd_loop *L, const pd_pmb *mat)
{
  pd_run_kernel(pmb_kernels, L, (void *) mat->c);
}

/* Microplastic: what the hook needs besides the bond. */
typedef struct plastic_ctx {
  const pd_pmb *pmb;
  pd_microplastic *mp;
  const double *vol;
} plastic_ctx;

/* the force of elastic stretch e = s - sp (s / |Y| = e |xi| / (|xi| |Y|)) */
PD_INLINE pd_bond_force microplastic_elastic(const plastic_ctx *p, const pd_bond *bd, double e)
{
  return pmb_bond(p->pmb->c[bd->tij], e * (bd->r0 * pd_bond_inverse(bd)), e * bd->r0, bd);
}

/* return map: the elastic stretch s - sp stays within [-sy, sy]; the
 * plastic work 1/2 c sy |d sp| |xi| w per partner volume at each end */
PD_INLINE pd_bond_force microplastic_force(void *ctx, const pd_bond *bd, double s)
{
  const plastic_ctx *p = (const plastic_ctx *) ctx;
  pd_microplastic *mp = p->mp;
  const double c = p->pmb->c[bd->tij], sy = mp->sy[bd->tij];
  double *sp = mp->plastic + bd->idx;
  const double e = s - *sp;
  const double excess = e > sy ? e - sy : (e < -sy ? e + sy : 0.0);
  if (excess != 0.0) {
    *sp += excess;
    const double wp = c * sy * fabs(excess) * bd->r0 * bd->w;
    const double vi = p->vol[bd->i], vj = p->vol[bd->j];
    mp->dissipated += wp * 0.5 * (vj + vi);
    mp->dissipated_joule += wp * vj * vi;
    if (mp->work_atom) {   /* half at each end: sum_i V_i d_i is the joules */
      mp->work_atom[bd->i] += 0.5 * wp * vj;
      mp->work_atom[bd->j] += 0.5 * wp * vi;
    }
  }
  return microplastic_elastic(p, bd, s - *sp);
}

/* The first pass's hooks: the force of a bond that does not yield (the
 * plastic stretch read, not written: the pass vectorizes, and an elastic
 * scene costs about what pmb does), and whether it yields (its chunk then
 * goes bond by bond, through the return map above). */
PD_INLINE pd_bond_force microplastic_ahead(void *ctx, const pd_bond *bd, double s)
{
  const plastic_ctx *p = (const plastic_ctx *) ctx;
  return microplastic_elastic(p, bd, s - p->mp->plastic[bd->idx]);
}

PD_INLINE int microplastic_yields(void *ctx, const pd_bond *bd, double s)
{
  const plastic_ctx *p = (const plastic_ctx *) ctx;
  return fabs(s - p->mp->plastic[bd->idx]) > p->mp->sy[bd->tij];
}

PD_DEFINE_STATEFUL_KERNELS(microplastic, pmb_strain, microplastic_force, microplastic_ahead,
                           microplastic_yields)

void pd_microplastic_forces(const pd_loop *L, const pd_pmb *mat, pd_microplastic *mp)
{
  plastic_ctx ctx = {mat, mp, L->vol};
  pd_run_kernel(microplastic_kernels, L, &ctx);
}

/* |C| = c w / |xi| at both ends (MS07 eq. 41) */
PD_INLINE void pmb_stiffness(const void *mat, const pd_bond *bd, double *a, double *b)
{
  const pd_pmb *m = (const pd_pmb *) mat;
  *a = *b = m->c[bd->tij] * bd->w / bd->r0;
}

void pd_pmb_stiffness(const pd_bond_view *b, const pd_pmb *mat, const int *type, int ntypes,
                      const double *vol, double *sum)
{
  pd_reference_sums(b, type, ntypes, vol, sum, mat, pmb_stiffness, 0);
}
