/* Correspondence material (pair_style pd/corr): a classical constitutive
 * law (pd_corr_law.h) evaluated at each atom from a nonlocal strain.
 *
 * classical (T14 eq. 2.6-2.10): K = sum w xi (x) xi V, F = [sum w Y (x) xi V] K^-1;
 *   the law's stress at F gives P and A = P K^-1 per atom; a bond's force
 *   per V_i V_j is w (A_i + A_j) xi (not along the bond).
 * extended (T14 eq. 4.3-4.7): E_m = M^-1 : sum w eps_m (n (x) n) V with
 *   n = xi/|xi| and M = sum w (n (x) n) (x) (n (x) n) V, the family's
 *   fourth moment. In the continuum (isotropic M, sum w V = d) M^-1 : n (x) n
 *   is T14's H<xi> = (d+2)/2 n (x) n - 1/2 1 (3D 5/2, 2D 2); the discrete M
 *   makes E_m exact for every uniform small strain on any lattice and at
 *   free surfaces, and the log strain of any uniform dilatation at m = 0.
 *   With Sigma = M^-1 : T per atom (T conjugate to E_m), a bond's force
 *   state is t = w (n . (Sigma_i + Sigma_j) . n) d eps_m / d|Y| along the
 *   bond (T14 eq. 4.7).
 * Optional stabilization (both strains): a central force G c ((Y - F_avg xi)
 * . e)/|xi| on the non-affine part of each bond (Littlewood 2010's hourglass
 * control; c the PMB micromodulus of the material, G the user's coefficient).
 * Damage through the influence function (T14 eq. 7.1-7.2): a bond with an
 * end whose damage exceeds D_c neither counts in the sums nor acts. */
#ifndef PD_CORR_H
#define PD_CORR_H

#include "pd_coefs.h"
#include "pd_corr_law.h"
#include "pd_loop.h"

/* The pair_coeff keywords of pair_style pd/corr (pd_corr_coefs). */
enum {
  PD_CORR_HORIZON,
  PD_CORR_K,
  PD_CORR_G,
  PD_CORR_E,
  PD_CORR_NU,
  PD_CORR_M,
  PD_CORR_YIELD,
  PD_CORR_HARDENING,
  PD_CORR_JC_B,
  PD_CORR_JC_N,
  PD_CORR_JC_C,
  PD_CORR_JC_RATE0,
  PD_CORR_T_ROOM,
  PD_CORR_T_MELT,
  PD_CORR_T_EXP,
  PD_CORR_HEAT_CAPACITY,
  PD_CORR_TAYLOR_QUINNEY,
  PD_CORR_D1,
  PD_CORR_D2,
  PD_CORR_D3,
  PD_CORR_D4,
  PD_CORR_D5,
  PD_CORR_DC,
  PD_CORR_NCOEFS
};
extern const pd_coef pd_corr_coefs[PD_CORR_NCOEFS];

/* The per-atom sums of each step's first pass: N = sum w Y (x) xi V (9),
 * the deformation gradient's; extended adds G = sum w eps (n (x) n) V (6)
 * after them. Extended's strain needs G alone: without a deformation
 * gradient (pd_corr_state.deformation 0) its sums are G, 6 wide. */
enum { PD_CORR_SUMS_CLASSICAL = 9, PD_CORR_SUMS_EXTENDED = 15, PD_CORR_SUMS_STRAIN = 6 };
/* The sums of the family's shape, which change only when bonds stop
 * acting: K = sum w xi (x) xi V (6, symmetric); extended adds M (21). */
enum { PD_CORR_SHAPE_SUMS_CLASSICAL = 6, PD_CORR_SHAPE_SUMS_EXTENDED = 27 };
/* An atom's shape from those: K^-1 (9) and M^-1 (21; extended), all zero
 * for a family too flat to give a strain (pd_corr_shape). */
enum { PD_CORR_SHAPE = 30 };

typedef struct pd_corr_state {
  int extended;           /* 1: extended, 0: classical */
  int deformation;        /* extended: 1 when the step's sums give F (an
                             output, the stabilization); classical always
                             has F (its strain) */
  int dim;                /* 2 or 3 */
  double order;           /* Seth-Hill order m of the strain */
  const double *xi;       /* per bond, laid out as the bonds: the reference
                             vector x0_j - x0_i (nearest image) */
  double *sum;            /* per atom: the first pass's sums */
  const double *tensor;   /* per atom, 9: A (classical) or Sigma (extended, 6) */
  const double *defgrad;  /* per atom, 9: F (classical with stabilization) */
  double stabilization;   /* G (classical), 0: none */
  const double *spring;   /* per type pair: PMB micromodulus c (broken bonds
                             in contact, stabilization) */
  const double *damage;   /* per atom, or NULL: no damage */
  double damage_max;      /* D_c */
} pd_corr_state;

/* The width of st's step sums per atom (their last 6 are extended's G). */
static inline int pd_corr_sums_width(const pd_corr_state *st)
{
  if (!st->extended) return PD_CORR_SUMS_CLASSICAL;
  return st->deformation ? PD_CORR_SUMS_EXTENDED : PD_CORR_SUMS_STRAIN;
}

/* Whether atom i's damage is beyond D_c: its bonds neither count in the
 * sums nor act (T14 eq. 7.2). st->damage must be set. */
static inline int pd_corr_past_damage(const pd_corr_state *st, int i)
{
  return !(st->damage[i] <= st->damage_max);
}

/* The shape sums of every atom (owned + ghost; the caller zeroes st->sum,
 * width PD_CORR_SHAPE_SUMS_*, and sums the ghosts' share onto owners):
 * once, and again after bonds stopped acting. */
void pd_corr_shape_sums(const pd_loop *L, const pd_corr_state *st);

/* An atom's shape (PD_CORR_SHAPE numbers) from its shape sums. Returns 1;
 * 0 when the family is too flat to give a strain (no bonds left, or its
 * shape tensor's smallest principal value below PD_CORR_FLAT times its
 * largest; a corner's complete family is about 0.3): shape all zero, the
 * atom carries no stress. */
#define PD_CORR_FLAT 0.1
int pd_corr_shape(const pd_corr_state *st, const double *shape_sum, double *shape);

/* Each step's first pass: the sums of every atom (owned + ghost; the caller
 * zeroes st->sum, width pd_corr_sums_width, and sums the ghosts' share
 * onto owners). */
void pd_corr_sums(const pd_loop *L, const pd_corr_state *st);

/* Second pass: forces, and with a tally the virial (the energy is per atom:
 * pd_corr_atom). */
void pd_corr_forces(const pd_loop *L, const pd_corr_state *st);

/* An atom's kinematics, before its law: the deformation gradient from its
 * sums (zero for extended without st->deformation) and, classical, the
 * principal frame of C = F^T F (C - 1 = Q diag(a) Q^T: small strains keep
 * their digits). */
typedef struct pd_corr_kinematics {
  int flat;           /* a flat family (its shape zero): no strain, no stress */
  double F[9];
  double a[3], q[9];  /* classical */
} pd_corr_kinematics;
/* Those of n consecutive atoms (their sums and shapes laid out as in
 * st->sum and the shapes), the frames solved side by side in vector lanes
 * (pd_sym_eigen_many: 3x faster per atom than one at a time, the same
 * numbers). */
void pd_corr_kinematics_of(const pd_corr_state *st, int n, const double *sums, const double *shapes,
                           pd_corr_kinematics *kin);

/* One atom: from its kinematics to its strain, stress (the law advances h;
 * with inc, an evaluation at the same strain repeats the increment, see
 * pd_corr_increment) and the tensor its bonds need. The Cauchy stress only
 * 'with_stress' (an output: the bonds need the tensor alone, and
 * extended's stress takes an eigen solve of E per atom; it needs F, so
 * st->deformation). */
typedef struct pd_corr_atom_out {
  double F[9];
  double tensor[9];   /* A = P K^-1 (classical) or Sigma = M^-1 : T (extended) */
  double stress[6];   /* Cauchy stress (zero unless with_stress) */
  double energy;      /* stored energy density */
} pd_corr_atom_out;
/* Returns 1; 0 for a flat family (its shape zero: out all zero) and -1
 * when the law rejects the state (out undefined). */
int pd_corr_atom(const pd_corr_state *st, const pd_corr_material *mat, const double *sum,
                 const double *shape, const pd_corr_kinematics *kin, pd_corr_history *h,
                 pd_corr_increment *inc, double dt, double rho, int with_stress,
                 pd_corr_atom_out *out);

#endif
