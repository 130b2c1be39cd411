/* The ordinary state-based solid: its per-bond math for the bond loop. */
#include "pd_ordinary.h"

#include "pd_bond_loop.h"
#include "pd_seth_hill.h"

#include <math.h>

const pd_coef pd_ordinary_coefs[PD_ORD_NCOEFS] = {
    [PD_ORD_HORIZON] = PD_COEF_HORIZON,
    [PD_ORD_K] = {.name = "K", .what = "bulk modulus", .mix = PD_MIX_OWN, .flags = PD_COEF_FILE,
                  .check = PD_CHECK_POSITIVE},
    [PD_ORD_G] = {.name = "G", .what = "shear modulus", .mix = PD_MIX_OWN, .flags = PD_COEF_FILE,
                  .check = PD_CHECK_POSITIVE},
    [PD_ORD_E] = {.name = "E", .what = "Young's modulus", .mix = PD_MIX_OWN, .flags = PD_COEF_FILE,
                  .check = PD_CHECK_POSITIVE},
    /* its range with the other constant: an isotropic elastic material */
    [PD_ORD_NU] = {.name = "nu", .what = "Poisson's ratio", .mix = PD_MIX_OWN, .flags = PD_COEF_FILE,
                   .check = PD_CHECK_FINITE},
    /* Seth-Hill order; one for all types (checked when a run starts) */
    [PD_ORD_M] = {.name = "m", .what = "strain order", .mix = PD_MIX_OWN,
                  .flags = PD_COEF_FILE | PD_COEF_DEFAULT, .check = PD_CHECK_RANGE, .lo = -4.0,
                  .hi = 1.0, .value = 0.5},
};

/* t = (A_i + A_j + (B_i + B_j) eps) w d(eps)/d|Y|, answered over |Y|;
 * stored B/2 w eps^2 and released w eps (A + B eps / 2) at each end, per
 * partner volume */
PD_INLINE pd_bond_force
ordinary_bond(int kind, int uniform_b, const pd_ordinary_state *st, const pd_bond *bd, double eps)
{
  const double *ab = st->ab;
  const double ai = ab[2 * bd->i], bi = ab[2 * bd->i + 1];
  const double aj = ab[2 * bd->j], bj = uniform_b ? bi : ab[2 * bd->j + 1];
  const double w = bd->w, we2 = 0.5 * w * eps * eps;
  pd_bond_force bf;
  bf.tl = (ai + aj + (bi + bj) * eps) * w *
          pd_bond_strain_rate_per_length(kind, st->order, eps, bd);
  bf.stored_i = we2 * bi;
  bf.stored_j = we2 * bj;
  bf.release_i = w * eps * (ai + 0.5 * bi * eps);
  bf.release_j = w * eps * (aj + 0.5 * bj * eps);
  bf.release = w * eps * (ai + aj + 0.5 * (bi + bj) * eps);
  return bf;
}

/* The hooks of each strain order: strain computed, force. */
#define ORDER_HOOKS(KIND, name)                                                           \
  PD_INLINE double strain_##name(void *st, const pd_bond *bd)                             \
  {                                                                                       \
    return pd_bond_strain(KIND, ((const pd_ordinary_state *) st)->order, bd);                \
  }                                                                                       \
  PD_INLINE pd_bond_force force_##name(void *st, const pd_bond *bd, double eps)           \
  {                                                                                       \
    return ordinary_bond(KIND, 0, (const pd_ordinary_state *) st, bd, eps);               \
  }
ORDER_HOOKS(PD_ORDER_HALF, half)
ORDER_HOOKS(PD_ORDER_LOG, log)
ORDER_HOOKS(PD_ORDER_ANY, any)

/* m other than 1/2 and 0, with a strain scratch: the dilatation pass
 * stores each bond's strain, the force pass reads it back (one log and one
 * expm1 per bond). m = 0 computes its strain in both passes: its log is
 * pd_log, and the loops stay vectorized (a store through the state's
 * pointer would stop that). */
int pd_ordinary_keeps_strain(double m) { return pd_order_kind(m) == PD_ORDER_ANY; }

PD_INLINE double strain_any_stored(void *st, const pd_bond *bd)
{
  const pd_ordinary_state *s = (const pd_ordinary_state *) st;
  return s->strain[bd->idx] = pd_bond_strain(PD_ORDER_ANY, s->order, bd);
}

PD_INLINE double strain_cached(void *st, const pd_bond *bd)
{
  return ((const pd_ordinary_state *) st)->strain[bd->idx];
}

/* m = 1/2 with one B for all atoms: one gather less per bond (1.07x at
 * 32^3, 1.1x at 64^3) */
PD_INLINE pd_bond_force force_half_uniform(void *st, const pd_bond *bd, double eps)
{
  return ordinary_bond(PD_ORDER_HALF, 1, (const pd_ordinary_state *) st, bd, eps);
}

PD_DEFINE_KERNELS(half, strain_half, force_half)
PD_DEFINE_KERNELS(half_uniform, strain_half, force_half_uniform)
PD_DEFINE_KERNELS(log, strain_log, force_log)
PD_DEFINE_KERNELS(any_computed, strain_any, force_any)
PD_DEFINE_KERNELS(any_cached, strain_cached, force_any)


void pd_ordinary_forces(const pd_loop *L, const pd_ordinary_state *st)
{
  const int kind = pd_order_kind(st->order), cached = st->strain != NULL;
  const pd_kernel (*table)[6] = kind == PD_ORDER_HALF ? (st->uniform_b ? half_uniform_kernels : half_kernels)
      : kind == PD_ORDER_LOG ? log_kernels
                          : (cached ? any_cached_kernels : any_computed_kernels);
  pd_run_kernel(table, L, (void *) st);
}

PD_INLINE void weighted_strain(void *st, const pd_bond *bd, double eps, double *t)
{
  (void) st;
  *t = bd->w * eps;
}

#define DILATATION(strain, failing) pd_current_sums(L, st->sum, 1, (void *) st, strain, weighted_strain, failing)

void pd_ordinary_dilatation(const pd_loop *L, const pd_ordinary_state *st)
{
  const int kind = pd_order_kind(st->order),
            stored = st->strain != NULL && pd_ordinary_keeps_strain(st->order);
  switch ((kind * 2 + stored) * 2 + (L->fail != NULL)) {
  case (PD_ORDER_HALF * 2) * 2: DILATATION(strain_half, 0); break;
  case (PD_ORDER_HALF * 2) * 2 + 1: DILATATION(strain_half, 1); break;
  case (PD_ORDER_LOG * 2) * 2: DILATATION(strain_log, 0); break;
  case (PD_ORDER_LOG * 2) * 2 + 1: DILATATION(strain_log, 1); break;
  case (PD_ORDER_ANY * 2) * 2: DILATATION(strain_any, 0); break;
  case (PD_ORDER_ANY * 2) * 2 + 1: DILATATION(strain_any, 1); break;
  case (PD_ORDER_ANY * 2 + 1) * 2: DILATATION(strain_any_stored, 0); break;
  default: DILATATION(strain_any_stored, 1); break;
  }
}

PD_INLINE void bond_stiffness(const void *k, const pd_bond *bd, double *a, double *b)
{
  const double *kc = (const double *) k;
  *a = *b = (kc[bd->i] + kc[bd->j]) * bd->w / (bd->r0 * bd->r0);
}

void pd_ordinary_stiffness(const pd_bond_view *b, const double *k, const double *vol, double *sum)
{
  pd_reference_sums(b, NULL, 0, vol, sum, k, bond_stiffness, 0);
}

pd_ordinary_atom_out pd_ordinary_atom(double lambda, double mu, double norm, double sum)
{
  pd_ordinary_atom_out o;
  o.theta = norm * sum;
  o.a = lambda * o.theta * norm;
  o.b = 2.0 * mu * norm;
  o.energy = 0.5 * lambda * o.theta * o.theta;
  return o;
}
