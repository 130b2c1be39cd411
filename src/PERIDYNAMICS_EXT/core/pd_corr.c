/* The correspondence material: its sums, bond forces and per-atom step. */
#include "pd_corr.h"

#include "pd_bond_loop.h"
#include "pd_seth_hill.h"
#include "pd_tensor.h"

#include <math.h>
#include <string.h>

#define MODULUS(key, what) \
  [key] = {.name = #key, .what = what, .mix = PD_MIX_OWN, .flags = PD_COEF_FILE, .check = PD_CHECK_POSITIVE}
#define OWN(nm, wh, chk, lo_, hi_, def, fl)                                                  \
  {.name = nm, .what = wh, .mix = PD_MIX_OWN, .flags = PD_COEF_FILE | (fl), .check = chk, .lo = lo_, \
   .hi = hi_, .value = def}

/* Each atom's stress uses its own type's material: every constant but the
 * horizon is given on the type's own line (or its material file). */
const pd_coef pd_corr_coefs[PD_CORR_NCOEFS] = {
    [PD_CORR_HORIZON] = PD_COEF_HORIZON,
    [PD_CORR_K] = OWN("K", "bulk modulus", PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_G] = OWN("G", "shear modulus", PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_E] = OWN("E", "Young's modulus", PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_NU] = OWN("nu", "Poisson's ratio", PD_CHECK_FINITE, 0, 0, 0, 0),
    /* Seth-Hill order of the strain the law works on; one for all types */
    [PD_CORR_M] = OWN("m", "strain order", PD_CHECK_RANGE, -4.0, 1.0, 0.0, PD_COEF_DEFAULT),
    [PD_CORR_YIELD] = OWN("yield", "initial yield stress", PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_HARDENING] = OWN("hardening", "linear hardening modulus", PD_CHECK_RANGE, 0.0, HUGE_VAL, 0, 0),
    [PD_CORR_JC_B] = OWN("jc_B", "Johnson-Cook hardening stress B", PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_JC_N] = OWN("jc_n", "Johnson-Cook hardening exponent n", PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_JC_C] = OWN("jc_C", "Johnson-Cook rate constant C", PD_CHECK_RANGE, 0.0, HUGE_VAL, 0.0,
                         PD_COEF_DEFAULT),
    [PD_CORR_JC_RATE0] = OWN("jc_rate0", "Johnson-Cook reference plastic strain rate",
                             PD_CHECK_POSITIVE, 0, 0, 1.0, PD_COEF_DEFAULT),
    [PD_CORR_T_ROOM] = OWN("T_room", "initial (room) temperature", PD_CHECK_POSITIVE, 0, 0, 293.15,
                           PD_COEF_DEFAULT),
    [PD_CORR_T_MELT] = OWN("T_melt", "melting temperature (gives thermal softening)",
                           PD_CHECK_POSITIVE, 0, 0, 0, 0),
    [PD_CORR_T_EXP] = OWN("T_exp", "thermal softening exponent", PD_CHECK_POSITIVE, 0, 0, 1.0,
                          PD_COEF_DEFAULT),
    [PD_CORR_HEAT_CAPACITY] = OWN("heat_capacity", "specific heat capacity", PD_CHECK_POSITIVE, 0, 0,
                                  0, 0),
    [PD_CORR_TAYLOR_QUINNEY] = OWN("taylor_quinney", "fraction of plastic work turned into heat",
                                   PD_CHECK_RANGE, 0.0, 1.0, 0.9, PD_COEF_DEFAULT),
    [PD_CORR_D1] = OWN("d1", "Johnson-Cook damage d1 (gives damage)", PD_CHECK_FINITE, 0, 0, 0, 0),
    [PD_CORR_D2] = OWN("d2", "Johnson-Cook damage d2", PD_CHECK_FINITE, 0, 0, 0.0, PD_COEF_DEFAULT),
    [PD_CORR_D3] = OWN("d3", "Johnson-Cook damage d3", PD_CHECK_FINITE, 0, 0, 0.0, PD_COEF_DEFAULT),
    [PD_CORR_D4] = OWN("d4", "Johnson-Cook damage d4", PD_CHECK_FINITE, 0, 0, 0.0, PD_COEF_DEFAULT),
    [PD_CORR_D5] = OWN("d5", "Johnson-Cook damage d5", PD_CHECK_FINITE, 0, 0, 0.0, PD_COEF_DEFAULT),
    [PD_CORR_DC] = OWN("Dc", "critical damage (bonds stop acting beyond it)", PD_CHECK_RANGE, 0.0,
                       1.0, 0.99, PD_COEF_DEFAULT),
};

/* ---- per bond ---------------------------------------------------------- */

/* A bond counts (in the sums) and acts unless an end's damage is beyond D_c
 * (T14 eq. 7.2). */
PD_INLINE int
alive(const pd_corr_state *st, const pd_bond *bd, int damaged)
{
  return !damaged || !(pd_corr_past_damage(st, bd->i) || pd_corr_past_damage(st, bd->j));
}

/* The reference vector of a bond that counts in its atoms' sums; NULL,
 * with its width sums zeroed, for a broken or fully damaged one. */
PD_INLINE const double *
counted_xi(const pd_corr_state *st, const pd_bond *bd, int damaged, double *t, int width)
{
  if (bd->broken || !alive(st, bd, damaged)) {
    for (int c = 0; c < width; c++) t[c] = 0.0;
    return NULL;
  }
  return st->xi + 3 * bd->idx;
}

/* The first pass's sums of one bond, the same at both ends: N (unless
 * extended without 'deformation'), then extended's G. */
PD_INLINE void
bond_sums(void *s, const pd_bond *bd, double eps, double *t, int extended, int deformation,
          int damaged)
{
  const pd_corr_state *st = (const pd_corr_state *) s;
  const int width = !extended ? PD_CORR_SUMS_CLASSICAL
                              : deformation ? PD_CORR_SUMS_EXTENDED : PD_CORR_SUMS_STRAIN;
  const double *xi = counted_xi(st, bd, damaged, t, width);
  if (!xi) return;
  const double w = bd->w;
  if (deformation)
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) t[3 * r + c] = w * bd->d[r] * xi[c];
  if (!extended) return;
  double *g = t + width - PD_CORR_SUMS_STRAIN;
  const double we = w * eps / (bd->r0 * bd->r0);
  g[0] = we * xi[0] * xi[0], g[1] = we * xi[1] * xi[1], g[2] = we * xi[2] * xi[2];
  g[3] = we * xi[0] * xi[1], g[4] = we * xi[0] * xi[2], g[5] = we * xi[1] * xi[2];
}

/* The shape sums of one bond, the same at both ends. */
PD_INLINE void
bond_shape_sums(void *s, const pd_bond *bd, double eps, double *t, int extended, int damaged)
{
  (void) eps;
  const pd_corr_state *st = (const pd_corr_state *) s;
  const double *xi = counted_xi(st, bd, damaged, t,
                                extended ? PD_CORR_SHAPE_SUMS_EXTENDED : PD_CORR_SHAPE_SUMS_CLASSICAL);
  if (!xi) return;
  const double w = bd->w;
  t[0] = w * xi[0] * xi[0], t[1] = w * xi[1] * xi[1], t[2] = w * xi[2] * xi[2];
  t[3] = w * xi[0] * xi[1], t[4] = w * xi[0] * xi[2], t[5] = w * xi[1] * xi[2];
  if (!extended) return;
  const double n[3] = {xi[0] / bd->r0, xi[1] / bd->r0, xi[2] / bd->r0};
  for (int c = 6; c < PD_CORR_SHAPE_SUMS_EXTENDED; c++) t[c] = 0.0;
  pd_sym4_add_dyad(t + 6, n, w);
}

/* n . S . n for atom a's symmetric S (the first six of its 9 in s; an
 * int offset, as in classical_force) */
PD_INLINE double
normal_component(const double *s, int a, const double n[3])
{
  const int o = 9 * a;
  return s[o] * n[0] * n[0] + s[o + 1] * n[1] * n[1] + s[o + 2] * n[2] * n[2] +
      2.0 * (s[o + 3] * n[0] * n[1] + s[o + 4] * n[0] * n[2] + s[o + 5] * n[1] * n[2]);
}

/* Row r of (X_i + X_j) xi for per-atom 3x3 tensors X (9 per atom in x):
 * X_i through its pointer xi_t, X_j at an int offset (through a pointer to
 * it, the force's first pass did not vectorize). The classical force (A)
 * and the stabilization (F) both take it. */
PD_INLINE double
pair_tensor_row(const double *xi_t, const double *x, int j, int r, const double xi[3])
{
  return (xi_t[3 * r] + x[j + 3 * r]) * xi[0] + (xi_t[3 * r + 1] + x[j + 3 * r + 1]) * xi[1] +
         (xi_t[3 * r + 2] + x[j + 3 * r + 2]) * xi[2];
}

/* A broken bond in contact (recontact) pushes as a bond-based spring in
 * the material's bond strain (extended: Seth-Hill order m, so that for
 * m <= 0 full collapse costs infinite energy, as for intact bonds), its
 * force c eps |xi| d eps/d|Y| along the bond. */
PD_INLINE double
contact_spring(const pd_corr_state *st, const pd_bond *bd, double eps, int kind)
{
  return st->spring[bd->tij] * eps * bd->r0 * pd_bond_strain_rate(kind, st->order, eps, bd);
}

/* The stabilization's central force along the bond: G c ((Y - F_avg xi) . e)
 * / |xi|, the non-affine part of the bond as a bond-based spring. */
PD_INLINE double
stabilizing_force(const pd_corr_state *st, const pd_bond *bd, const double *xi)
{
  if (bd->len <= 0.0) return 0.0;
  const double *f = st->defgrad;
  double z = 0.0;
  for (int r = 0; r < 3; r++) {
    const double fxi = 0.5 * pair_tensor_row(f + 9 * bd->i, f, 9 * bd->j, r, xi);
    z += (bd->d[r] - fxi) * bd->d[r];
  }
  return st->stabilization * st->spring[bd->tij] * z / (bd->len * bd->r0);
}

/* A central part t along the bond, as t Y / |Y|. */
PD_INLINE void add_central(pd_bond_force *bf, const pd_bond *bd, double t)
{
  if (bd->len > 0.0)
    for (int r = 0; r < 3; r++) bf->v[r] += t * bd->d[r] / bd->len;
}

/* classical: its strain hook gives the stretch (the order-1/2 form).
 * 'stabilizing' 0: the stabilization left out, for the first pass (its
 * gathers of F behind a test kept that pass from vectorizing): with
 * stabilization every row goes bond by bond (pd_corr_forces). */
PD_INLINE pd_bond_force
classical_force(const pd_corr_state *st, const pd_bond *bd, double eps, int damaged, int stabilizing)
{
  pd_bond_force bf = {0};
  if (bd->broken) {
    add_central(&bf, bd, contact_spring(st, bd, eps, PD_ORDER_HALF));
    return bf;
  }
  if (!alive(st, bd, damaged)) return bf;
  const double *xi = st->xi + 3 * bd->idx, *a = st->tensor;
  for (int r = 0; r < 3; r++) bf.v[r] = bd->w * pair_tensor_row(a + 9 * bd->i, a, 9 * bd->j, r, xi);
  if (stabilizing && st->stabilization > 0.0) add_central(&bf, bd, stabilizing_force(st, bd, xi));
  return bf;
}

PD_INLINE pd_bond_force
extended_force(const pd_corr_state *st, const pd_bond *bd, double eps, int kind, int damaged,
               int stabilizing)
{
  pd_bond_force bf = {0};
  if (bd->broken) {
    bf.tl = pd_per_length(contact_spring(st, bd, eps, kind), bd);
    return bf;
  }
  if (!alive(st, bd, damaged)) return bf;
  const double *xi = st->xi + 3 * bd->idx;
  const double n[3] = {xi[0] / bd->r0, xi[1] / bd->r0, xi[2] / bd->r0};
  const double si = normal_component(st->tensor, bd->i, n);
  const double sj = normal_component(st->tensor, bd->j, n);
  double t = bd->w * (si + sj) * pd_bond_strain_rate(kind, st->order, eps, bd);
  if (stabilizing && st->stabilization > 0.0) t += stabilizing_force(st, bd, xi);
  bf.tl = pd_per_length(t, bd);
  /* the instantaneous bond energy d psi / d phi at each end ('fail energy') */
  bf.release_i = bd->w * eps * si;
  bf.release_j = bd->w * eps * sj;
  bf.release = bd->w * eps * (si + sj);
  return bf;
}

/* ---- hooks and kernels: classical, extended (log, any m) x damage ------- */

PD_INLINE double stretch(void *st, const pd_bond *bd)
{
  (void) st;
  return (bd->len - bd->r0) / bd->r0;
}
/* (the package's own log, as pd/ordinary's m = 0: with libm's the sums'
 * first pass stays scalar; a kernel that needs no bond energy drops it:
 * only the energies and the failure laws read it) */
PD_INLINE double strain_log(void *st, const pd_bond *bd)
{
  (void) st;
  return pd_bond_strain(PD_ORDER_LOG, 0.0, bd);
}
PD_INLINE double strain_any(void *st, const pd_bond *bd)
{
  return pd_bond_strain(PD_ORDER_ANY, ((const pd_corr_state *) st)->order, bd);
}

#define CORR_HOOKS(name, DAMAGED)                                                                  \
  PD_INLINE pd_bond_force classical_##name(void *st, const pd_bond *bd, double eps)                \
  {                                                                                                \
    return classical_force((const pd_corr_state *) st, bd, eps, DAMAGED, 1);                       \
  }                                                                                                \
  PD_INLINE pd_bond_force classical_ahead_##name(void *st, const pd_bond *bd, double eps)          \
  {                                                                                                \
    return classical_force((const pd_corr_state *) st, bd, eps, DAMAGED, 0);                       \
  }                                                                                                \
  PD_INLINE pd_bond_force log_##name(void *st, const pd_bond *bd, double eps)                      \
  {                                                                                                \
    return extended_force((const pd_corr_state *) st, bd, eps, PD_ORDER_LOG, DAMAGED, 1);          \
  }                                                                                                \
  PD_INLINE pd_bond_force log_ahead_##name(void *st, const pd_bond *bd, double eps)                \
  {                                                                                                \
    return extended_force((const pd_corr_state *) st, bd, eps, PD_ORDER_LOG, DAMAGED, 0);          \
  }                                                                                                \
  PD_INLINE pd_bond_force any_##name(void *st, const pd_bond *bd, double eps)                      \
  {                                                                                                \
    return extended_force((const pd_corr_state *) st, bd, eps, PD_ORDER_ANY, DAMAGED, 1);          \
  }                                                                                                \
  PD_INLINE pd_bond_force any_ahead_##name(void *st, const pd_bond *bd, double eps)                \
  {                                                                                                \
    return extended_force((const pd_corr_state *) st, bd, eps, PD_ORDER_ANY, DAMAGED, 0);          \
  }                                                                                                \
  PD_INLINE void classical_sums_##name(void *st, const pd_bond *bd, double eps, double *t)     \
  {                                                                                                \
    bond_sums(st, bd, eps, t, 0, 1, DAMAGED);                                                      \
  }                                                                                                \
  PD_INLINE void extended_sums_##name(void *st, const pd_bond *bd, double eps, double *t)      \
  {                                                                                                \
    bond_sums(st, bd, eps, t, 1, 1, DAMAGED);                                                      \
  }                                                                                                \
  PD_INLINE void strain_sums_##name(void *st, const pd_bond *bd, double eps, double *t)        \
  {                                                                                                \
    bond_sums(st, bd, eps, t, 1, 0, DAMAGED);                                                      \
  }                                                                                                \
  PD_INLINE void classical_shape_##name(void *st, const pd_bond *bd, double eps, double *t)    \
  {                                                                                                \
    bond_shape_sums(st, bd, eps, t, 0, DAMAGED);                                                   \
  }                                                                                                \
  PD_INLINE void extended_shape_##name(void *st, const pd_bond *bd, double eps, double *t)     \
  {                                                                                                \
    bond_shape_sums(st, bd, eps, t, 1, DAMAGED);                                                   \
  }
CORR_HOOKS(intact, 0)
CORR_HOOKS(damaged, 1)

#define CORR_KERNELS(strain_kind, damage, strain, kind)                                          \
  PD_DEFINE_KERNELS_AHEAD(strain_kind##_##damage, strain, strain_kind##_##damage,                  \
                          strain_kind##_ahead_##damage, pd_state_kept, kind)
CORR_KERNELS(classical, intact, stretch, PD_MATERIAL_DIRECTED)
CORR_KERNELS(classical, damaged, stretch, PD_MATERIAL_DIRECTED)
CORR_KERNELS(log, intact, strain_log, PD_MATERIAL_PLAIN)
CORR_KERNELS(log, damaged, strain_log, PD_MATERIAL_PLAIN)
CORR_KERNELS(any, intact, strain_any, PD_MATERIAL_PLAIN)
CORR_KERNELS(any, damaged, strain_any, PD_MATERIAL_PLAIN)

void pd_corr_forces(const pd_loop *L, const pd_corr_state *st)
{
  const int damaged = st->damage != NULL;
  const pd_kernel (*table)[6];
  if (!st->extended) table = damaged ? classical_damaged_kernels : classical_intact_kernels;
  else if (st->order == 0.0) table = damaged ? log_damaged_kernels : log_intact_kernels;
  else table = damaged ? any_damaged_kernels : any_intact_kernels;
  pd_loop l = *L;
  l.bond_by_bond |= st->stabilization > 0.0;  /* (the first pass leaves it out) */
  pd_run_kernel(table, &l, (void *) st);
}

#define SUMS(width, strain, value, failing) pd_current_sums(L, st->sum, width, (void *) st, strain, value, failing)
#define SUMS_LATE(width, strain, value, failing) \
  pd_current_sums_late(L, st->sum, width, (void *) st, strain, value, failing)

/* the four copies of one kind of sums: intact or damaged, without or with
 * a failure law */
#define SUMS_CASES(base, sums, width, strain, value)                          \
  case base: sums(width, strain, value##_intact, 0); break;                   \
  case base + 1: sums(width, strain, value##_intact, 1); break;               \
  case base + 2: sums(width, strain, value##_damaged, 0); break;              \
  case base + 3: sums(width, strain, value##_damaged, 1); break;

void pd_corr_sums(const pd_loop *L, const pd_corr_state *st)
{
  const int failing = L->fail != NULL, damaged = st->damage != NULL;
  /* classical; extended log or any m, with N and G or G alone */
  const int kind = !st->extended ? 0 : 1 + (st->order == 0.0 ? 0 : 1) + (st->deformation ? 0 : 2);
  switch (kind * 4 + damaged * 2 + failing) {
    SUMS_CASES(0, SUMS, PD_CORR_SUMS_CLASSICAL, stretch, classical_sums)
    SUMS_CASES(4, SUMS_LATE, PD_CORR_SUMS_EXTENDED, strain_log, extended_sums)
    SUMS_CASES(8, SUMS_LATE, PD_CORR_SUMS_EXTENDED, strain_any, extended_sums)
    SUMS_CASES(12, SUMS_LATE, PD_CORR_SUMS_STRAIN, strain_log, strain_sums)
    default:
    SUMS_CASES(16, SUMS_LATE, PD_CORR_SUMS_STRAIN, strain_any, strain_sums)
  }
}

/* not every step: one copy serves all (the bond's strain is not used) */
void pd_corr_shape_sums(const pd_loop *L, const pd_corr_state *st)
{
  const int failing = L->fail != NULL;
  if (st->extended) {
    if (st->damage) SUMS(PD_CORR_SHAPE_SUMS_EXTENDED, stretch, extended_shape_damaged, failing);
    else SUMS(PD_CORR_SHAPE_SUMS_EXTENDED, stretch, extended_shape_intact, failing);
  } else {
    if (st->damage) SUMS(PD_CORR_SHAPE_SUMS_CLASSICAL, stretch, classical_shape_damaged, failing);
    else SUMS(PD_CORR_SHAPE_SUMS_CLASSICAL, stretch, classical_shape_intact, failing);
  }
}

/* ---- per atom ----------------------------------------------------------- */

/* C - 1 of F, as H + H^T + H^T H with H = F - 1: small strains keep their
 * digits. */
static void stretch_excess(const double F[9], double excess[6])
{
  double H[9], HtH[9];
  for (int k = 0; k < 9; k++) H[k] = F[k] - (k % 4 == 0);
  pd_mat_tmul(H, H, HtH);
  for (int k = 0; k < 9; k++) HtH[k] += H[k] + H[3 * (k % 3) + k / 3];
  pd_full_to_sym(HtH, excess);
}

int pd_corr_shape(const pd_corr_state *st, const double *shape_sum, double *shape)
{
  memset(shape, 0, PD_CORR_SHAPE * sizeof(double));
  double K[9], kl[3], kq[9], ks[6];
  pd_sym_to_full(shape_sum, K);
  /* a plane family: K_33 at the family's own scale (pd_corr_atom sets
   * N_33 to match: F_33 = 1) */
  if (st->dim == 2) K[8] = 0.5 * (K[0] + K[4]);
  pd_full_to_sym(K, ks);
  pd_sym_eigen(ks, kl, kq);
  const double kmax = fmax(kl[0], fmax(kl[1], kl[2])), kmin = fmin(kl[0], fmin(kl[1], kl[2]));
  if (!(kmin > PD_CORR_FLAT * kmax)) return 0;
  if (st->extended) {
    memcpy(shape + 9, shape_sum + 6, PD_SYM4 * sizeof(double));
    if (!pd_sym4_invert(shape + 9, st->dim)) return 0;
  }
  pd_inverse3(K, shape, 0.0);
  return 1;
}

void pd_corr_kinematics_of(const pd_corr_state *st, int n, const double *sums, const double *shapes,
                           pd_corr_kinematics *kin)
{
  enum { CHUNK = 64 };
  const int width = pd_corr_sums_width(st);
  double excess[6 * CHUNK], a[3 * CHUNK], q[9 * CHUNK];
  for (int k0 = 0; k0 < n; k0 += CHUNK) {
    const int m = n - k0 < CHUNK ? n - k0 : CHUNK;
    for (int k = 0; k < m; k++) {
      pd_corr_kinematics *o = kin + k0 + k;
      const double *sum = sums + (size_t) width * (k0 + k), *Kinv = shapes + (size_t) PD_CORR_SHAPE * (k0 + k);
      memset(o, 0, sizeof(*o));
      memset(excess + 6 * k, 0, 6 * sizeof(double));
      o->flat = Kinv[0] == 0.0 && Kinv[4] == 0.0;
      if (o->flat || (st->extended && !st->deformation)) continue;
      double N[9];
      memcpy(N, sum, sizeof(N));
      /* 2D: F_33 = 1 (plane strain kinematics; a plane stress law sets its
       * own E_33) */
      if (st->dim == 2) N[8] = 1.0 / Kinv[8];
      pd_mat_mul(N, Kinv, o->F);
      if (!st->extended) stretch_excess(o->F, excess + 6 * k);
    }
    if (st->extended) continue;
    pd_sym_eigen_many(m, excess, a, q);
    for (int k = 0; k < m; k++) {
      memcpy(kin[k0 + k].a, a + 3 * k, sizeof(kin->a));
      memcpy(kin[k0 + k].q, q + 9 * k, sizeof(kin->q));
    }
  }
}

int pd_corr_atom(const pd_corr_state *st, const pd_corr_material *mat, const double *sum,
                 const double *shape, const pd_corr_kinematics *kin, pd_corr_history *h,
                 pd_corr_increment *inc, double dt, double rho, int with_stress,
                 pd_corr_atom_out *o)
{
  memset(o, 0, sizeof(*o));
  const double *Kinv = shape, *M = shape + 9;
  if (kin->flat) return 0;
  memcpy(o->F, kin->F, sizeof(o->F));

  /* the strain of order m, classical from C's principal frame */
  double E[6], c[3], q[9];
  if (st->extended) {
    pd_sym4_apply(M, sum + pd_corr_sums_width(st) - PD_CORR_SUMS_STRAIN, E);
  } else {
    double e[3];
    for (int k = 0; k < 3; k++) {
      c[k] = 1.0 + kin->a[k];
      e[k] = pd_seth_hill_excess(st->order, kin->a[k]);
    }
    memcpy(q, kin->q, sizeof(q));
    pd_sym_from_eigen(e, q, E);
  }
  if (inc) pd_corr_increment_enter(inc, E, h);
  pd_corr_stress s;
  if (!pd_corr_law_stress(mat, st->order, E, h, dt, rho, &s)) return -1;
  o->energy = s.energy;

  /* S for classical's P and the Cauchy stress; the extended strain's
   * principal frame stands in for C's */
  if (st->extended) {
    pd_sym4_apply(M, s.T, o->tensor);
    if (!with_stress) return 1;
    double e[3];
    pd_sym_eigen(E, e, q);
    for (int k = 0; k < 3; k++) c[k] = pd_seth_hill_inverse(st->order, e[k]);
  }
  double S[6], Sf[9], P[9];
  pd_corr_second_pk(st->order, c, q, s.T, S);
  pd_sym_to_full(S, Sf);
  pd_mat_mul(o->F, Sf, P);
  if (!st->extended) {
    pd_mat_mul(P, Kinv, o->tensor);
    if (st->dim == 2) o->tensor[2] = o->tensor[5] = o->tensor[6] = o->tensor[7] = o->tensor[8] = 0.0;
    if (!with_stress) return 1;
  }
  const double J = pd_det3(o->F);
  if (J > 0.0) {
    double PFt[9];
    pd_mat_mult(P, o->F, PFt);
    pd_full_to_sym(PFt, o->stress);
    for (int k = 0; k < 6; k++) o->stress[k] /= J;
  }
  return 1;
}
