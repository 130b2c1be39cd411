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
  bf.stored = we2;    /* times each end's B: pd_loop.energy_scale */
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
ORDER_HOOKS(PD_ORDER_RECIPROCAL, reciprocal)
ORDER_HOOKS(PD_ORDER_ANY, any)

/* m = 0 and the orders other than 1/2 and the negative integers, with a
 * strain scratch: the dilatation pass keeps each bond's strain, the force
 * pass reads it back (m = 0: one logarithm per bond and step instead of two,
 * 1.33x faster on the benchmark block; the others: one log and one
 * expm1). m = 1/2 and the negative integers compute theirs in both
 * passes, with no log. */
int pd_ordinary_keeps_strain(double m)
{
  const int kind = pd_order_kind(m);
  return kind == PD_ORDER_LOG || kind == PD_ORDER_ANY;
}

PD_INLINE double strain_cached(void *st, const pd_bond *bd)
{
  return ((const pd_ordinary_state *) st)->strain[bd->idx];
}

/* m = 1/2 and m = 0 (its strains kept) with one B for all atoms: one
 * gather less per bond (m = 1/2: 1.07x at 32^3, 1.1x at 64^3) */
PD_INLINE pd_bond_force force_half_uniform(void *st, const pd_bond *bd, double eps)
{
  return ordinary_bond(PD_ORDER_HALF, 1, (const pd_ordinary_state *) st, bd, eps);
}
PD_INLINE pd_bond_force force_log_uniform(void *st, const pd_bond *bd, double eps)
{
  return ordinary_bond(PD_ORDER_LOG, 1, (const pd_ordinary_state *) st, bd, eps);
}

PD_DEFINE_KERNELS(half, strain_half, force_half)
PD_DEFINE_KERNELS(half_uniform, strain_half, force_half_uniform)
PD_DEFINE_KERNELS(log, strain_log, force_log)
PD_DEFINE_KERNELS(log_cached, strain_cached, force_log)
PD_DEFINE_KERNELS(log_cached_uniform, strain_cached, force_log_uniform)
PD_DEFINE_KERNELS(reciprocal, strain_reciprocal, force_reciprocal)
PD_DEFINE_KERNELS(any, strain_any, force_any)
PD_DEFINE_KERNELS(any_cached, strain_cached, force_any)

/* whether this state's dilatation pass keeps the strains */
static int kept(const pd_ordinary_state *st)
{
  return st->strain != NULL && pd_ordinary_keeps_strain(st->order);
}

void pd_ordinary_forces(const pd_loop *L, const pd_ordinary_state *st)
{
  /* [kind][kept][uniform B] */
  static const pd_kernel(*const table[PD_ORDER_KINDS][2][2])[6] = {
      [PD_ORDER_HALF] = {{half_kernels, half_uniform_kernels}, {half_kernels, half_uniform_kernels}},
      [PD_ORDER_LOG] = {{log_kernels, log_kernels}, {log_cached_kernels, log_cached_uniform_kernels}},
      [PD_ORDER_RECIPROCAL] = {{reciprocal_kernels, reciprocal_kernels},
                               {reciprocal_kernels, reciprocal_kernels}},
      [PD_ORDER_ANY] = {{any_kernels, any_kernels}, {any_cached_kernels, any_cached_kernels}},
  };
  const int kind = pd_order_kind(st->order);
  pd_loop l = *L;
  l.energy_scale = st->ab + 1;    /* B, interleaved with A */
  l.energy_scale_stride = 2;
  pd_run_kernel(table[kind][kept(st)][st->uniform_b != 0], &l, (void *) st);
}

PD_INLINE void weighted_strain(void *st, const pd_bond *bd, double eps, double *t)
{
  (void) st;
  *t = bd->w * eps;
}

/* The dilatation pass of each strain hook, intact and failing, keeping
 * the strains in st->strain or not */
typedef void (*dilatation_fn)(const pd_loop *L, const pd_ordinary_state *st);
#define DILATATION(name, hook, keeping)                                                         \
  static void dilatation_##name(const pd_loop *L, const pd_ordinary_state *st)                 \
  {                                                                                            \
    pd_current_sums_keep(L, st->sum, 1, (void *) st, hook, weighted_strain,                    \
                         keeping ? st->strain : NULL, 0);                                      \
  }                                                                                            \
  static void dilatation_##name##_failing(const pd_loop *L, const pd_ordinary_state *st)       \
  {                                                                                            \
    pd_current_sums_keep(L, st->sum, 1, (void *) st, hook, weighted_strain,                    \
                         keeping ? st->strain : NULL, 1);                                      \
  }
DILATATION(half, strain_half, 0)
DILATATION(log, strain_log, 0)
DILATATION(log_kept, strain_log, 1)
DILATATION(reciprocal, strain_reciprocal, 0)
DILATATION(any, strain_any, 0)
DILATATION(any_kept, strain_any, 1)
#undef DILATATION

void pd_ordinary_dilatation(const pd_loop *L, const pd_ordinary_state *st)
{
  /* [kind][kept][failing] */
  static const dilatation_fn pass[PD_ORDER_KINDS][2][2] = {
      [PD_ORDER_HALF] = {{dilatation_half, dilatation_half_failing}},
      [PD_ORDER_LOG] = {{dilatation_log, dilatation_log_failing},
                        {dilatation_log_kept, dilatation_log_kept_failing}},
      [PD_ORDER_RECIPROCAL] = {{dilatation_reciprocal, dilatation_reciprocal_failing}},
      [PD_ORDER_ANY] = {{dilatation_any, dilatation_any_failing},
                        {dilatation_any_kept, dilatation_any_kept_failing}},
  };
  pass[pd_order_kind(st->order)][kept(st)][L->fail != NULL](L, st);
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
