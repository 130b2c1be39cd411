/* Ordinary state-based solid with Seth-Hill bond strain of order m
 * (T14 eq. 5.1); m = 1/2 is the linear peridynamic solid (LPS, T14 2.12-2.14).
 *
 * For an atom i with normalization N_i = d / m_i, where the weighted volume
 * m_i = sum_bonds w V_other and w is the bond's weight, the energy density is
 *   psi_i = lambda/2 theta_i^2 + mu N_i sum_bonds w eps^2 V_other,
 *   theta_i = N_i sum_bonds w eps V_other,
 * and a bond's force state, with A = lambda theta N and B = 2 mu N at each
 * end, is t = (A_i + A_j + (B_i + B_j) eps) w d(eps)/d|Y|. */
#ifndef PD_ORDINARY_H
#define PD_ORDINARY_H

#include "pd_coefs.h"
#include "pd_loop.h"

/* The pair_coeff keywords of pair_style pd/ordinary (pd_ordinary_coefs, in
 * this order): horizon, the elastic constants (K and G or E and nu) and the
 * strain order m. Each atom's force state uses its own type's material, so
 * a line between two types gives only the horizon (and failure) of their
 * bonds. */
enum {
  PD_ORD_HORIZON,
  PD_ORD_K,
  PD_ORD_G,
  PD_ORD_E,
  PD_ORD_NU,
  PD_ORD_M,
  PD_ORD_NCOEFS
};
extern const pd_coef pd_ordinary_coefs[PD_ORD_NCOEFS];

/* Per-step work arrays over owned and ghost atoms. */
typedef struct pd_ordinary_state {
  double order;    /* Seth-Hill order m */
  double *sum;     /* dilatation sums, before normalization */
  const double *ab;/* per atom, interleaved: A = lambda theta N, B = 2 mu N */
  double *strain;  /* per-bond scratch laid out as the bonds, or NULL: for
                      the orders that keep it (pd_ordinary_keeps_strain) the
                      dilatation pass stores each bond's strain there and
                      the force pass reuses it; the others ignore it */
  int uniform_b;   /* every atom's B is the same (no surface correction, one
                      B for all types): the m = 1/2 force pass takes the
                      owner's for the far end's instead of gathering it */
} pd_ordinary_state;

/* Whether order m keeps each bond's strain in pd_ordinary_state.strain
 * between the passes (the other orders compute it in both). */
int pd_ordinary_keeps_strain(double m);

/* Dilatation sums: st->sum[i] += w eps V_j, st->sum[j] += w eps V_i.
 * The caller zeroes st->sum over owned and ghost atoms and then sums the
 * ghosts' share onto their owners. */
void pd_ordinary_dilatation(const pd_loop *L, const pd_ordinary_state *st);

/* Force density on every bond end; with a tally, the bond part of the energy
 * (B/2 w eps^2 V_other at each end) and the virial. The dilatation part of
 * the energy is per atom: see pd_ordinary_atom. With L->fail, broken bonds
 * act only in compression (recontact), and intact bonds break by its law; a breaking bond releases at each end
 * its instantaneous energy s = w eps (A + B eps / 2) per partner volume
 * (T14 eq. 6.5): s_i V_j + s_j V_i in all. */
void pd_ordinary_forces(const pd_loop *L, const pd_ordinary_state *st);

/* Stable time step sums (pd_timestep.h): |C| <= (k_i + k_j) w / |xi|^2 with
 * k = N (2 mu + d |lambda|) per atom; the d |lambda| part bounds the
 * coupling through the dilatation (Cauchy-Schwarz over the family). */
void pd_ordinary_stiffness(const pd_bond_view *b, const double *k, const double *vol, double *sum);

/* Per-atom state from the summed dilatation: theta, A, B and the
 * dilatation part of the energy density, lambda/2 theta^2. */
typedef struct pd_ordinary_atom_out {
  double theta, a, b, energy;
} pd_ordinary_atom_out;
pd_ordinary_atom_out pd_ordinary_atom(double lambda, double mu, double norm, double sum);

#endif
