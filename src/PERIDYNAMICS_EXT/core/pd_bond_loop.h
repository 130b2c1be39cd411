/* The bond loops, written once for every material.
 *
 * A material supplies its per-bond math as static inline functions:
 *   double strain(void *mat, const pd_bond *bd)
 *       the bond's strain (its sign decides whether a broken bond pushes);
 *   pd_bond_force force(void *mat, const pd_bond *bd, double eps)
 *       the force state (over the current length) and the energies of
 *       the bond (pd_bonds.h).
 * pd_force_loop walks every bond once: decodes it (broken bonds, recontact),
 * asks the material, asks the failure law, applies the force to both ends
 * (half of it when the bond breaks now) and tallies energy and virial.
 * PD_DEFINE_KERNELS instantiates it for every failure law and every
 * combination of effects (weights, tally, broken bonds); a material picks
 * one per evaluation with pd_run_kernel. The flags and hooks are constants
 * in each copy: an effect that is off costs nothing per bond, and no hook
 * is an indirect call.
 *
 * Speed: a row (one atom's bonds) goes in two passes, a vectorizable one
 * that computes every bond's force (gathering the far ends' positions)
 * and a scalar one that adds them onto the far ends (and tallies the
 * energies). Rows with a broken or breaking bond go bond by bond. Both
 * ways do the same arithmetic in the same order, so the results are the
 * same to the bit (lammps.kernels). The far ends'
 * sums go into a scratch of 4 doubles per atom (pd_loop.reaction,
 * pd_sum4.h), added onto f at the end: a bond's reaction is then one
 * 4-wide add instead of three scalar ones (pd/bond 1.13x, pd/ordinary
 * 1.06x at 32^3). The 4th lane keeps the failure law's notes or, on a
 * tallied step, the far end's energy, so that they ride in the same
 * update. */
#ifndef PD_BOND_LOOP_H
#define PD_BOND_LOOP_H

#include "pd_bonds.h"
#include "pd_failure.h"
#include "pd_law_hooks.h"
#include "pd_loop.h"
#include "pd_sum4.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

typedef double (*pd_strain_fn)(void *mat, const pd_bond *bd);
typedef pd_bond_force (*pd_force_fn)(void *mat, const pd_bond *bd, double eps);
typedef int (*pd_breaks_now_fn)(const pd_failure *f, const pd_bond *bd, double eps,
                                const pd_bond_force *bf);
typedef int (*pd_breaks_after_fn)(const pd_failure *f, const pd_bond *bd, double eps);
typedef int (*pd_may_break_fn)(const pd_failure *f, const pd_bond *bd, double eps,
                               const pd_bond_force *bf);
typedef double (*pd_law_notes_fn)(const pd_failure *f, const pd_bond *bd);
typedef int (*pd_state_changes_fn)(void *mat, const pd_bond *bd, double eps);

/* A material without a state of its bonds: its state never changes. */
PD_INLINE int pd_state_kept(void *mat, const pd_bond *bd, double eps)
{
  (void) mat, (void) bd, (void) eps;
  return 0;
}

/* What a material's force hook is: its force along the bond (plain), not
 * along it (directed: pd_bond_force.v), or along it with a state that the
 * hook updates (stateful). A stateful material gives the first pass two
 * hooks more: its force with the state read as it is ('ahead', no store:
 * the pass vectorizes) and whether the state would change ('changes': the
 * chunk is then taken bond by bond, through the updating hook). */
enum { PD_MATERIAL_PLAIN, PD_MATERIAL_DIRECTED, PD_MATERIAL_STATEFUL };

/* How a loop takes each bond's weight: 1, the table, or weight_horizon
 * times 1/|xi| (pd_bond_view). */
enum { PD_WEIGHT_ONE, PD_WEIGHT_TABLE, PD_WEIGHT_INVERSE };
PD_INLINE int pd_weight_mode(const pd_bond_view *b)
{
  return b->weight_horizon > 0.0 ? PD_WEIGHT_INVERSE : b->weight ? PD_WEIGHT_TABLE : PD_WEIGHT_ONE;
}

/* Slot idx of atom bd->i's row: its far end, types, weight and reference
 * length (intact unless 'failing'; a reference walk, not 'current', takes
 * a broken bond with its length); with 'current' also its current
 * separation and length. trow: ti * ntypes; xi: the owner's position. */
PD_INLINE void
pd_bond_load(pd_bond *bd, const pd_bond_view *restrict b, const int *restrict type, int trow,
             const double *restrict x, const double xi[3], const pd_failure *fail, int idx,
             int weighted, int failing, int current)
{
  const int j = b->far[idx];
  bd->j = j;
  bd->idx = idx;
  bd->tj = type ? type[j] : 1;
  bd->tij = trow + bd->tj;
  bd->broken = 0;
  if (failing) bd->r0 = pd_bond_reference(fail, b->len0[idx], bd->i, j, &bd->broken);
  else if (current) bd->r0 = b->len0[idx];
  else bd->r0 = fabs(b->len0[idx]);
  /* (the inverse weight through 1/|xi|, as pd_influence makes it: the
   * reciprocal that the strain of m = 1/2 takes too, so one divide) */
  if (weighted == PD_WEIGHT_INVERSE)
    bd->w = b->weight_horizon * (1.0 / (failing || !current ? fabs(b->len0[idx]) : bd->r0));
  else
    bd->w = weighted ? b->weight[idx] : 1.0;
  if (current) {
    bd->d[0] = x[3 * j] - xi[0];
    bd->d[1] = x[3 * j + 1] - xi[1];
    bd->d[2] = x[3 * j + 2] - xi[2];
    bd->len2 = bd->d[0] * bd->d[0] + bd->d[1] * bd->d[1] + bd->d[2] * bd->d[2];
    bd->len = sqrt(bd->len2);
  }
}

/* Atom i's row begins: bd's near end and its type (1 without types);
 * returns the row's offset in the type-pair tables (trow). */
PD_INLINE int pd_row_begin(pd_bond *bd, const int *restrict type, int ntypes, int i)
{
  bd->i = i;
  bd->ti = type ? type[i] : 1;
  return bd->ti * ntypes;
}

/* The energies a tallied step sums: each intact bond stores e s_i (per
 * partner volume) at its owner i and e s_j at its far end j, e =
 * pd_bond_force.stored and s the ends' factors (pd_loop.energy_scale).
 * When the law keeps no notes in the sums' 4th lane (pd_energy_in_lane),
 * e rides there, negated: the owner's sum gathers -e V_j (taken times
 * -s_i at the row's end), j's reaction e V_i (times s_j after the loop),
 * in the same 4-wide adds as the force. Else the bond's ei = e s_i and
 * ej = e s_j go onto lane k % PD_ENERGY_LANES of the row's sums (one
 * chain of adds waited on the previous bond's add: 4 cycles a bond),
 * summed as (0 + 1) + (2 + 3) at the row's end, and ej onto eatom[j]. */
enum { PD_ENERGY_LANES = 4 };
typedef struct pd_row_energy {
  double total[PD_ENERGY_LANES];    /* (only when not in the lane) */
  double owner[PD_ENERGY_LANES];
} pd_row_energy;

/* Atom a's factor of its bonds' stored energies (1 without a table). */
PD_INLINE double pd_energy_scale(const double *restrict scale, int stride, int a)
{
  return scale ? scale[stride * (ptrdiff_t) a] : 1.0;
}

PD_INLINE int pd_energy_in_lane(int tallied, int failing, int takes_notes)
{
  return tallied && !(failing && takes_notes != PD_NOTES_NONE);
}

/* One intact bond's energies when they are not in the lane: onto a lane's
 * total and owner's sum, and onto j's per-atom energy (eatom, or NULL). */
PD_INLINE void pd_tally_energy(double *total, double *owner, double *restrict eatom, int j,
                               double vi, double vj, double ei, double ej)
{
  *total += ei * vj + ej * vi;
  *owner += ei * vj;
  if (eatom) eatom[j] += ej * vi;
}

/* The virial of the loop's forces on one atom: x (x) F, F = V f (f per
 * unit volume). Every bond's force is equal and opposite at its two ends:
 * summed over the atoms that received them (owned and ghost), these are
 * the bonds' (x_i - x_j) (x) F_ij, at a cost per atom instead of per bond.
 * A bond along its direction makes that tensor symmetric; a directed
 * material's (not along the bond) is symmetrized. */
PD_INLINE void pd_atom_virial(pd_tally *t, const double *restrict x, const double *restrict f,
                              double v, int directed)
{
  if (t->skip_virial) return;
  const double F[3] = {v * f[0], v * f[1], v * f[2]};
  t->virial[0] += x[0] * F[0];
  t->virial[1] += x[1] * F[1];
  t->virial[2] += x[2] * F[2];
  if (directed) {
    t->virial[3] += 0.5 * (x[0] * F[1] + x[1] * F[0]);
    t->virial[4] += 0.5 * (x[0] * F[2] + x[2] * F[0]);
    t->virial[5] += 0.5 * (x[1] * F[2] + x[2] * F[1]);
    return;
  }
  t->virial[3] += x[0] * F[1];
  t->virial[4] += x[0] * F[2];
  t->virial[5] += x[1] * F[2];
}

/* pd_tally_atom_virial with xx yy zz xy as one 4-wide add onto each end
 * (the far end's six loads, adds and stores one by one were most of a
 * per-atom virial step): the same numbers. */
PD_INLINE void pd_tally_atom_virial4(double *restrict vatom, double *restrict own, int j,
                                     const double r[3], const double F[3])
{
  double w[6];
  pd_atom_virial_share(r, F, w);
  const pd_sum4 w4 = pd_sum4_load(w);
  double *restrict vj = vatom + 6 * (ptrdiff_t) j;
  pd_sum4_store(own, pd_sum4_add(pd_sum4_load(own), w4));
  pd_sum4_store(vj, pd_sum4_add(pd_sum4_load(vj), w4));
  own[4] += w[4];
  own[5] += w[5];
  vj[4] += w[4];
  vj[5] += w[5];
}

PD_INLINE double pd_lanes_sum(const double *lane)
{
  return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

/* One bond of the force loop: decode (broken bonds, recontact), ask the
 * material and the failure law, add the force on i to fi and the reaction
 * on j to its sum (pd_loop.reaction), tally (the energies onto the row's
 * lane 'lane', the virial onto the row's tally); when 'noting', the law's note
 * onto row_note and, when 'ends' too, onto j's sum (its 4th lane). The
 * arrays are parameters so that 'restrict' holds (GCC honours it on
 * parameters): the force stores then do not make it reload x or the
 * material's tables. */
PD_INLINE void
pd_force_bond(const pd_bond_view *restrict b, const int *restrict type, int trow,
              const double *restrict x, const double xi[3], const double *restrict vol,
              double *restrict reaction, pd_sum4 *fi, pd_bond *bd, int idx, pd_break_sums *sums,
              pd_tally *tally, pd_row_energy *re, int lane, pd_failure *fail, void *restrict mat,
              pd_strain_fn strain,
              pd_force_fn force, pd_breaks_now_fn breaks_now, pd_breaks_after_fn breaks_after,
              pd_law_notes_fn notes, double *row_note, int noting, int ends, int weighted,
              int tallied, int in_lane, int failing, int directed, const double *restrict escale,
              int estride)
{
  pd_bond_load(bd, b, type, trow, x, xi, fail, idx, weighted, failing, 1);
  const double eps = strain(mat, bd);
  if (failing && pd_bond_inactive(fail, bd->broken, eps)) return;
  const pd_bond_force bf = force(mat, bd, eps);
  const int i = bd->i, j = bd->j;
  const double vi = vol[i], vj = vol[j];
  /* a bond that fails releases its energy now and acts with half its
   * force: the half-kicks around this step then carry it up to this
   * step and no further, so the balance of kinetic, elastic and
   * dissipated energy stays second order in dt (a bond dropped whole
   * here would miss half a kick: first order) */
  double share = 1.0;
  if (failing && !bd->broken && breaks_now(fail, bd, eps, &bf)) {
    pd_break_bond(fail, sums, bd, bf.release_i, bf.release_j, vi, vj, 1);
    share = 0.5;
  }
  /* the force on i per V_i V_j */
  double fij[3];
  const double tl = directed ? 0.0 : share * bf.tl;
  for (int c = 0; c < 3; c++) fij[c] = directed ? share * bf.v[c] : tl * bd->d[c];
  /* a breaking bond's energy is booked as dissipated instead */
  const double e = share == 1.0 ? bf.stored : 0.0;
  /* the force and, in the lane, the energy, negated (pd_row_energy) */
  const pd_sum4 a = pd_sum4_make(fij[0], fij[1], fij[2], in_lane ? -e : 0.0);
  *fi = pd_sum4_axpy4(*fi, vj, a);
  double *restrict rj = reaction + 4 * (ptrdiff_t) j;
  pd_sum4_store(rj, pd_sum4_axpy4(pd_sum4_load(rj), -vi, a));
  /* (the loop takes the global virial from the atoms' summed forces,
   * pd_atom_virial; the per-atom one needs each bond's) */
  if (tallied && tally->vatom) {
    const double r[3] = {-bd->d[0], -bd->d[1], -bd->d[2]};
    const double vv = vi * vj;
    const double F[3] = {vv * fij[0], vv * fij[1], vv * fij[2]};
    pd_tally_atom_virial4(tally->vatom, tally->own_virial, j, r, F);
  }
  if (tallied && !in_lane)
    pd_tally_energy(&re->total[lane], &re->owner[lane], tally->eatom, j, vi, vj,
                    e * pd_energy_scale(escale, estride, i), e * pd_energy_scale(escale, estride, j));
  if (failing && !bd->broken) {
    if (noting) {
      const double value = notes(fail, bd);
      if (ends) pd_note_max(reaction + 4 * (ptrdiff_t) j + 3, value);
      pd_note_max(row_note, value);
    }
    if (breaks_after(fail, bd, eps))
      pd_break_bond(fail, sums, bd, bf.release_i, bf.release_j, vi, vj, 0);
  }
}

/* Bonds a row's first pass takes at a time (its buffers live on the stack). */
enum { PD_CHUNK = 64 };

/* Bonds a first pass takes as one vector (AVX-512: 16, as two registers
 * of 8 doubles, their far ends' indices in one). */
enum { PD_VECTOR_BONDS = 16 };

/* A first pass takes a chunk of m bonds in whole vectors: those that fit,
 * then its last PD_VECTOR_BONDS bonds once more as one (the overlap
 * computed again, to the same numbers); else its last bonds went one by
 * one (a row of 61 bonds: 48 in vectors of 16, 8 in one of 8 and 5
 * alone). Returns where that last vector starts, or -1 when m takes no
 * such vector (at most one vector, or whole vectors only). */
PD_INLINE int pd_vector_overlap(int m)
{
  return m <= PD_VECTOR_BONDS || m % PD_VECTOR_BONDS == 0 ? -1 : m - PD_VECTOR_BONDS;
}

/* A first pass's load: pd_bond_load with the current separation, a broken
 * bond (possible only when 'failing') not decoded but flagged (returns 1;
 * its length made positive so that the pass stays finite): the caller then
 * takes the chunk bond by bond. */
PD_INLINE int
pd_bond_load_ahead(pd_bond *bd, const pd_bond_view *restrict b, const int *restrict type, int trow,
                   const double *restrict x, const double xi[3], int idx, int weighted, int failing)
{
  pd_bond_load(bd, b, type, trow, x, xi, NULL, idx, weighted, 0, 1);
  if (!failing) return 0;
  const int broken = bd->r0 < 0.0;
  bd->r0 = fabs(bd->r0);
  /* the inverse weight from |xi|, as bond by bond: its reciprocal is then
   * the one that the strain of m = 1/2 takes too (pd/ordinary with a
   * failure law: one divide per bond less). (Loaded as bond by bond,
   * through pd_bond_reference without a failure state, the energy law's
   * kernel took 4.7% more modeled cycles.) */
  if (weighted == PD_WEIGHT_INVERSE) bd->w = b->weight_horizon * (1.0 / bd->r0);
  return broken;
}

/* The first pass over bonds row .. row+m-1 (of one row): every intact bond's
 * force on i per V_i V_j into g (component c of bond k at c * PD_CHUNK + k)
 * and, for the failure law's note, what it notes (at 3 * PD_CHUNK + k);
 * when 'tallied', the energy it stores (pd_bond_force.stored: at 5 *
 * PD_CHUNK + k, or negated at 3 * PD_CHUNK + k when it rides in the lane,
 * pd_energy_in_lane). No
 * store that another bond could read, so the compiler vectorizes it (the
 * far ends' positions gathered). Returns nonzero if a bond is broken or
 * might break now or after (the law's screen, _ahead): the caller then
 * takes the chunk bond by bond instead. */
PD_INLINE int
pd_force_bonds(const pd_bond_view *restrict b, const int *restrict type, int trow, int ti,
               const double *restrict x, const double xi[3], int i, int row, int m,
               double *restrict g, const pd_failure *fail, void *restrict mat, pd_strain_fn strain,
               pd_force_fn force, pd_state_changes_fn changes, pd_may_break_fn may_break,
               pd_law_notes_fn notes, int takes_notes, int weighted, int failing, int tallied,
               int directed)
{
  /* (64 bits wide, as the tests' masks are: an int made AVX2 pack them;
   * each test negated, so that its mask (-1) is ORed in as it is, not
   * first made 1: PERI's rule's kernel 1% fewer instructions) */
  long long special = 0;
  for (int k = 0; k < m; k++) {
    pd_bond bd;
    bd.i = i;
    bd.ti = ti;
    special |= -(long long) pd_bond_load_ahead(&bd, b, type, trow, x, xi, row + k, weighted, failing);
    const double eps = strain(mat, &bd);
    const pd_bond_force bf = force(mat, &bd, eps);
    special |= -(long long) changes(mat, &bd, eps);
    if (failing) {
      special |= -(long long) may_break(fail, &bd, eps, &bf);
      /* (when the law takes notes, whether or not this evaluation keeps
       * them: a run-time condition here stopped the vectorizer) */
      if (takes_notes) g[3 * PD_CHUNK + k] = notes(fail, &bd);
    }
    for (int c = 0; c < 3; c++) g[c * PD_CHUNK + k] = directed ? bf.v[c] : bf.tl * bd.d[c];
    if (tallied) {
      if (pd_energy_in_lane(tallied, failing, takes_notes)) g[3 * PD_CHUNK + k] = -bf.stored;
      else g[5 * PD_CHUNK + k] = bf.stored;
    }
  }
  return special != 0;
}

/* pd_force_bonds for a chunk in whole vectors (pd_vector_overlap). With the
 * scratch's memset gone, per step of the benchmark block in llvm-mca's
 * cycles: pd/ordinary 5.137 M -> 4.867 M, PERI's rule with alpha > 0
 * 3.630 M -> 3.452 M. */
PD_INLINE int
pd_force_chunk(const pd_bond_view *restrict b, const int *restrict type, int trow, int ti,
               const double *restrict x, const double xi[3], int i, int row, int m,
               double *restrict g, const pd_failure *fail, void *restrict mat, pd_strain_fn strain,
               pd_force_fn force, pd_state_changes_fn changes, pd_may_break_fn may_break,
               pd_law_notes_fn notes, int takes_notes, int weighted, int failing, int tallied,
               int directed)
{
  const int last = pd_vector_overlap(m);
  if (last < 0)
    return pd_force_bonds(b, type, trow, ti, x, xi, i, row, m, g, fail, mat, strain, force,
                          changes, may_break, notes, takes_notes, weighted, failing, tallied,
                          directed);
  return pd_force_bonds(b, type, trow, ti, x, xi, i, row, m - m % PD_VECTOR_BONDS, g, fail, mat,
                        strain, force, changes, may_break, notes, takes_notes, weighted, failing,
                        tallied, directed) ||
         pd_force_bonds(b, type, trow, ti, x, xi, i, row + last, PD_VECTOR_BONDS, g + last, fail,
                        mat, strain, force, changes, may_break, notes, takes_notes, weighted,
                        failing, tallied, directed);
}

/* The first pass's numbers of bond k as one vector: its force (lanes 0-2)
 * and, when 'lane3', what it keeps at 3 * PD_CHUNK + k (its note, or its
 * energy negated; else 0). */
PD_INLINE pd_sum4 pd_chunk_record(const double *restrict g, int k, int lane3)
{
  return pd_sum4_make(g[k], g[PD_CHUNK + k], g[2 * PD_CHUNK + k],
                      lane3 ? g[3 * PD_CHUNK + k] : 0.0);
}

/* The same for bonds k .. k+3 at once: four loads and a transpose. */
PD_INLINE void pd_chunk_records4(const double *restrict g, int k, int lane3, pd_sum4 a[4])
{
  const pd_sum4 zero = pd_sum4_make(0.0, 0.0, 0.0, 0.0);
  const pd_sum4 c[4] = {pd_sum4_load(g + k), pd_sum4_load(g + PD_CHUNK + k),
                        pd_sum4_load(g + 2 * PD_CHUNK + k),
                        lane3 ? pd_sum4_load(g + 3 * PD_CHUNK + k) : zero};
  pd_sum4_transpose(c, a);
}

/* A chunk's second pass for one bond, its record a (pd_chunk_record) and
 * far end j: its force onto sum_i and its reaction onto the far end's sum;
 * when 'ends', its note onto the far end's sum (lane 3). */
PD_INLINE pd_sum4
pd_scatter_bond(pd_sum4 sum_i, pd_sum4 a, int j, const double *restrict vol, double vi,
                double *restrict reaction, int ends)
{
  double *restrict rj = reaction + 4 * (ptrdiff_t) j;
  if (ends)
    pd_sum4_store(rj, pd_sum4_axpy_note(pd_sum4_load(rj), -vi, a));
  else
    pd_sum4_store(rj, pd_sum4_axpy4(pd_sum4_load(rj), -vi, a));
  /* (lane 3 then sums notes, never read, or the energies, pd_row_energy) */
  return pd_sum4_axpy4(sum_i, vol[j], a);
}

/* A chunk's second pass: pd_scatter_bond for its m bonds, the even ones
 * onto fi[0] and the odd ones onto fi[1], their notes onto the far ends
 * when 'ends' (their maximum), their energies (lane 3) when 'energies'
 * (added, pd_row_energy); when 'noting', the largest note onto row_note. */
PD_INLINE void
pd_scatter_chunk(pd_sum4 fi[2], const int *restrict far, const double *restrict g,
                 const double *restrict vol, double vi, double *restrict reaction,
                 double *row_note, int m, int noting, int ends, int energies)
{
  const double *restrict note = g + 3 * PD_CHUNK;
  /* (fi's halves as locals: their memory would be loaded and stored again
   * for every bond; the notes' largest four at a time, lane l that of
   * bonds l, l + 4, ..) */
  pd_sum4 sum[2] = {fi[0], fi[1]};
  pd_sum4 rn = pd_sum4_make(*row_note, *row_note, *row_note, *row_note);
  int k = 0;
  for (; k + 3 < m; k += 4) {
    pd_sum4 a[4];
    pd_chunk_records4(g, k, ends || energies, a);
    if (noting) rn = pd_sum4_max(pd_sum4_load(note + k), rn);
    for (int c = 0; c < 4; c++)
      sum[c & 1] = pd_scatter_bond(sum[c & 1], a[c], far[k + c], vol, vi, reaction, ends);
  }
  for (; k < m; k++) {
    sum[k & 1] = pd_scatter_bond(sum[k & 1], pd_chunk_record(g, k, ends || energies), far[k], vol,
                                 vi, reaction, ends);
    if (noting) pd_note_max(row_note, note[k]);
  }
  fi[0] = sum[0];
  fi[1] = sum[1];
  for (int c = 0; noting && c < 4; c++) pd_note_max(row_note, pd_sum4_lane(rn, c));
}

/* The per-atom virial of a chunk's m bonds (their forces per V_i V_j in
 * g, pd_force_bonds), as pd_force_bond tallies an intact bond's, to the
 * same numbers: the far ends' shares onto vatom, the owner's onto the
 * row's own_virial (in registers here: in memory, each bond's adds
 * waited on the previous bond's stores). Out of line, so that the
 * tallied kernels carry one call instead of a copy of this loop (inlined,
 * it grew each of them by a tenth; its cost in time stayed below this
 * machine's noise). */
PD_NOINLINE void pd_chunk_atom_virial(double *restrict vatom, double *restrict own_virial,
                                    const int *restrict far, const double *restrict g,
                                    const double *restrict x, const double xi[3],
                                    const double *restrict vol, double vi, int m)
{
  double own[6];
  for (int c = 0; c < 6; c++) own[c] = own_virial[c];
  for (int k = 0; k < m; k++) {
    const int j = far[k];
    const double r[3] = {xi[0] - x[3 * j], xi[1] - x[3 * j + 1], xi[2] - x[3 * j + 2]};
    const double vv = vi * vol[j];
    const double F[3] = {vv * g[k], vv * g[PD_CHUNK + k], vv * g[2 * PD_CHUNK + k]};
    pd_tally_atom_virial4(vatom, own, j, r, F);
  }
  for (int c = 0; c < 6; c++) own_virial[c] = own[c];
}

/* Walks every bond once. Directed materials (and every material when
 * bond_by_bond) go bond by bond (pd_force_bond); the others take each row
 * in chunks: the vectorized first pass, then the scalar sums onto i and
 * its (distinct) far ends, the failure law's notes and the energies (total
 * and per atom), in the same order and with the same arithmetic as bond
 * by bond. A row tallies onto locals (its energies in lanes,
 * pd_row_energy), added to the tally at its end: in memory, each bond's
 * adds waited on the previous bond's stores (the per-atom energy's
 * far-end store may alias them). The virial is that of each atom's summed
 * force (pd_atom_virial). The far ends' sums (reaction, nall atoms, zero
 * on entry) are added onto f last and zeroed as they are; the notes'
 * maximum (their 4th lane, -inf where none) then goes to
 * pd_failure.note_atom, or for a law that keeps only the largest note,
 * that one to pd_failure.note_largest. */
PD_INLINE void
pd_force_loop_on(const pd_bond_view *restrict b, const int *restrict type, int ntypes,
                 const double *restrict x, const double *restrict vol, double *restrict f,
                 double *restrict reaction, int nall, pd_tally *tally, pd_failure *fail,
                 void *restrict mat, pd_strain_fn strain, pd_force_fn force, pd_force_fn ahead,
                 pd_state_changes_fn changes, pd_breaks_now_fn breaks_now,
                 pd_breaks_after_fn breaks_after, pd_may_break_fn may_break,
                 pd_law_notes_fn notes, int takes_notes, int weighted, int tallied, int failing,
                 int kind, int bond_by_bond, const double *restrict escale, int estride)
{
  pd_break_sums sums = {0.0, 0.0, 0};
  const int directed = kind == PD_MATERIAL_DIRECTED;
  const int chunked = !bond_by_bond;
  double *restrict vatom = tallied ? tally->vatom : NULL;
  double *restrict eatom = tallied ? tally->eatom : NULL;
  /* (a local: read through fail, it was loaded again after every
   * reaction store) */
  double *restrict note_atom = failing && takes_notes == PD_NOTES_ENDS ? fail->note_atom : NULL;
  const int ends = note_atom != NULL;
  const int noting = ends || (failing && takes_notes == PD_NOTES_LARGEST);
  const int in_lane = pd_energy_in_lane(tallied, failing, takes_notes);
  double largest = -INFINITY;    /* PD_NOTES_LARGEST: the largest note */
  /* the notes' maximum in the sums' 4th lane: one 4-wide update per bond
   * (the sums come zero and leave zero: no pass of their own to clear them) */
  if (ends)
    for (int a = 0; a < nall; a++) reaction[4 * (ptrdiff_t) a + 3] = -INFINITY;
  pd_bond bd;
  double g[6 * PD_CHUNK];
  for (int i = 0; i < b->nowner; i++) {
    const int n = b->count[i];
    if (!n) continue;
    const int row = i * b->stride;
    const double vi = vol[i], si = tallied ? pd_energy_scale(escale, estride, i) : 0.0;
    /* the sum on i in two halves, bonds 0, 2, 4 .. of the row and 1, 3, ..:
     * two chains of adds instead of one (the scalar pass waited on it) */
    pd_sum4 fi[2];
    memset(fi, 0, sizeof fi);
    const int trow = pd_row_begin(&bd, type, ntypes, i);
    const double xi[3] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    double row_note = -INFINITY;    /* the largest of the row's notes */
    pd_tally rt = {0.0, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, eatom, tallied ? tally->skip_virial : 1,
                   vatom, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}};
    pd_row_energy re;
    memset(&re, 0, sizeof re);
    for (int k0 = 0; k0 < n; k0 += PD_CHUNK) {
      const int m = n - k0 < PD_CHUNK ? n - k0 : PD_CHUNK;
      /* (one copy of the first pass for one atom type: no type loads) */
      if (chunked &&
          !(type ? pd_force_chunk(b, type, trow, bd.ti, x, xi, i, row + k0, m, g, fail, mat,
                                  strain, ahead, changes, may_break, notes, takes_notes,
                                  weighted, failing, tallied, directed)
                 : pd_force_chunk(b, NULL, trow, bd.ti, x, xi, i, row + k0, m, g, fail, mat,
                                  strain, ahead, changes, may_break, notes, takes_notes,
                                  weighted, failing, tallied, directed))) {
        /* (a copy per case: a test per bond cost the legacy law 9%) */
        if (ends)
          pd_scatter_chunk(fi, b->far + row + k0, g, vol, vi, reaction, &row_note, m, 1, 1, 0);
        else if (noting)
          pd_scatter_chunk(fi, b->far + row + k0, g, vol, vi, reaction, &row_note, m, 1, 0, 0);
        else if (in_lane)
          pd_scatter_chunk(fi, b->far + row + k0, g, vol, vi, reaction, &row_note, m, 0, 0, 1);
        else
          pd_scatter_chunk(fi, b->far + row + k0, g, vol, vi, reaction, &row_note, m, 0, 0, 0);
        const int *restrict far = b->far + row + k0;
        if (vatom) pd_chunk_atom_virial(vatom, rt.own_virial, far, g, x, xi, vol, vi, m);
        /* as pd_force_bond tallies an intact bond, bond after bond (its
         * arithmetic written again here: through shared helpers this
         * pass ran 6% slower on tallied steps), onto copies of the row's
         * sums that live in registers (the row's own are in memory: the
         * bond-by-bond path takes their address) */
        if (tallied && !in_lane) {
          pd_row_energy r = re;
          const double *restrict e = g + 5 * PD_CHUNK;
          int k = 0;
          for (; k + PD_ENERGY_LANES <= m; k += PD_ENERGY_LANES)
            for (int l = 0; l < PD_ENERGY_LANES; l++)
              pd_tally_energy(&r.total[l], &r.owner[l], eatom, far[k + l], vi, vol[far[k + l]],
                              e[k + l] * si, e[k + l] * pd_energy_scale(escale, estride, far[k + l]));
          for (; k < m; k++)
            pd_tally_energy(&r.total[k % PD_ENERGY_LANES], &r.owner[k % PD_ENERGY_LANES], eatom,
                            far[k], vi, vol[far[k]], e[k] * si,
                            e[k] * pd_energy_scale(escale, estride, far[k]));
          re = r;
        }
        continue;
      }
      for (int k = 0; k < m; k++)
        pd_force_bond(b, type, trow, x, xi, vol, reaction, &fi[k & 1], &bd, row + k0 + k,
                      &sums, &rt, &re, k % PD_ENERGY_LANES, fail, mat, strain, force, breaks_now,
                      breaks_after, notes, &row_note, noting, ends, weighted, tallied, in_lane,
                      failing, directed, escale, estride);
    }
    double fsum[3];
    for (int c = 0; c < 3; c++) {
      fsum[c] = pd_sum4_lane(fi[0], c) + pd_sum4_lane(fi[1], c);
      f[3 * i + c] += fsum[c];
    }
    if (tallied) {
      pd_atom_virial(&rt, xi, fsum, vi, directed);
      const double own = in_lane ? -si * (pd_sum4_lane(fi[0], 3) + pd_sum4_lane(fi[1], 3))
                                 : pd_lanes_sum(re.owner);
      tally->energy += in_lane ? own : pd_lanes_sum(re.total);
      for (int c = 0; c < 6; c++) tally->virial[c] += rt.virial[c];
      if (eatom) eatom[i] += own;
      for (int c = 0; vatom && c < 6; c++) vatom[6 * (ptrdiff_t) i + c] += rt.own_virial[c];
    }
    if (ends) pd_note_max(reaction + 4 * (ptrdiff_t) i + 3, row_note);
    else if (noting) pd_note_max(&largest, row_note);
  }
  double far_energy[PD_ENERGY_LANES] = {0.0, 0.0, 0.0, 0.0};    /* (in_lane: atom a's onto lane a % 4) */
  pd_tally far_virial = {0.0, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, NULL, tallied ? tally->skip_virial : 1,
                         NULL, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}};
  for (int a = 0; a < nall; a++) {
    for (int c = 0; c < 3; c++) f[3 * a + c] += reaction[4 * a + c];
    if (tallied) pd_atom_virial(&far_virial, x + 3 * a, reaction + 4 * a, vol[a], directed);
    if (ends) note_atom[a] = reaction[4 * a + 3];
    if (in_lane) {
      const double e = pd_energy_scale(escale, estride, a) * reaction[4 * a + 3];
      far_energy[a % PD_ENERGY_LANES] += e;
      if (eatom) eatom[a] += e;
    }
    for (int c = 0; c < 4; c++) reaction[4 * a + c] = 0.0;    /* (vectorized with the adds) */
  }
  if (in_lane) tally->energy += pd_lanes_sum(far_energy);
  if (tallied)
    for (int c = 0; c < 6; c++) tally->virial[c] += far_virial.virial[c];
  if (failing) pd_add_break_sums(fail, &sums);
  if (failing && takes_notes == PD_NOTES_LARGEST) fail->note_largest = largest;
}

PD_INLINE void
pd_force_loop(const pd_loop *L, void *mat, pd_strain_fn strain, pd_force_fn force,
              pd_force_fn ahead, pd_state_changes_fn changes, pd_breaks_now_fn breaks_now,
              pd_breaks_after_fn breaks_after, pd_may_break_fn may_break, pd_law_notes_fn notes,
              int takes_notes, int weighted, int tallied, int failing, int kind)
{
  pd_force_loop_on(L->b, L->type, L->ntypes, L->x, L->vol, L->f, L->reaction, L->nall, L->tally,
                   L->fail, mat, strain, force, ahead, changes, breaks_now, breaks_after,
                   may_break, notes, takes_notes, weighted, tallied, failing, kind,
                   L->bond_by_bond, L->energy_scale, L->energy_scale_stride);
}

/* A kernel: pd_force_loop for one material, one law, one set of effects. */
typedef void (*pd_kernel)(const pd_loop *L, void *mat);

#define PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, weighted, tallied, kind) \
  static void prefix##_##law##_##failing##weighted##tallied(const pd_loop *L, void *mat)        \
  {                                                                                              \
    pd_force_loop(L, mat, strain, force, ahead, changes, pd_law_##law##_now,                     \
                  pd_law_##law##_after, pd_law_##law##_ahead, pd_law_##law##_notes,              \
                  pd_law_##law##_takes_notes(), weighted, tallied, failing, kind);               \
  }
#define PD_KERNELS_OF_LAW_(ID, law, prefix, strain, force, ahead, changes, failing, kind) \
  PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, 0, 0, kind)             \
  PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, 0, 1, kind)             \
  PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, 1, 0, kind)             \
  PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, 1, 1, kind)             \
  PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, 2, 0, kind)             \
  PD_KERNEL_(prefix, strain, force, ahead, changes, law, failing, 2, 1, kind)
#define PD_KERNEL_ROW_(ID, law, prefix, failing)                                      \
  {prefix##_##law##_##failing##00, prefix##_##law##_##failing##01,                    \
   prefix##_##law##_##failing##10, prefix##_##law##_##failing##11,                    \
   prefix##_##law##_##failing##20, prefix##_##law##_##failing##21},
#define PD_FAILING_KERNELS_(ID, law, prefix, strain, force, ahead, changes, kind) \
  PD_KERNELS_OF_LAW_(ID, law, prefix, strain, force, ahead, changes, 1, kind)
#define PD_FAILING_ROW_(ID, law, prefix) PD_KERNEL_ROW_(ID, law, prefix, 1)

/* Defines prefix_kernels: row 0 for intact bonds only (nothing can be or
 * become broken), then one row per failure law of pd_laws.h; in each row
 * the six combinations of weight mode (PD_WEIGHT_*) and tally. */
#define PD_DEFINE_KERNELS_(prefix, strain, force, ahead, changes, kind)                  \
  PD_KERNELS_OF_LAW_(NONE, none, prefix, strain, force, ahead, changes, 0, kind)         \
  PD_FAILURE_LAWS(PD_FAILING_KERNELS_, prefix, strain, force, ahead, changes, kind)      \
  static const pd_kernel prefix##_kernels[PD_NLAWS + 1][6] = {                          \
      PD_KERNEL_ROW_(NONE, none, prefix, 0) PD_FAILURE_LAWS(PD_FAILING_ROW_, prefix)};
#define PD_DEFINE_KERNELS(prefix, strain, force) \
  PD_DEFINE_KERNELS_(prefix, strain, force, force, pd_state_kept, PD_MATERIAL_PLAIN)
/* The same for a material whose first pass takes a force hook of its own
 * (ahead) and whose rows go bond by bond where changes() says so, of any
 * kind: pd/corr (classical: PD_MATERIAL_DIRECTED, its force hook fills
 * pd_bond_force.v), whose first pass leaves the stabilization out (a
 * stabilized run goes bond by bond, pd_loop.bond_by_bond). */
#define PD_DEFINE_KERNELS_AHEAD(prefix, strain, force, ahead, changes, kind) \
  PD_DEFINE_KERNELS_(prefix, strain, force, ahead, changes, kind)
/* The same for a material whose force hook updates a state of the bond
 * (microplastic's plastic stretch), with its first pass's hooks: the
 * force with the state as it is, and whether the state would change. */
#define PD_DEFINE_STATEFUL_KERNELS(prefix, strain, force, ahead, changes) \
  PD_DEFINE_KERNELS_(prefix, strain, force, ahead, changes, PD_MATERIAL_STATEFUL)

/* Run the kernel of a table that L asks for: its failure law (or none),
 * the bond view's weight mode, tally when L has one. */
static inline void pd_run_kernel(const pd_kernel (*table)[6], const pd_loop *L, void *mat)
{
  const int row = L->fail ? 1 + (int) L->fail->law : 0;
  table[row][pd_weight_mode(L->b) * 2 + (L->tally != NULL)](L, mat);
}

/* Sums over bonds onto both ends in the reference configuration:
 * sum[i] += a V_j and sum[j] += b V_i with (a, b) = value(ctx, bond). Only
 * intact bonds when 'intact_only'. The caller adds the ghosts' share onto
 * their owners. */
typedef void (*pd_bond_value_fn)(const void *ctx, const pd_bond *bd, double *a, double *b);

PD_INLINE void
pd_reference_sums(const pd_bond_view *restrict b, const int *type, int ntypes,
                  const double *restrict vol, double *restrict sum, const void *ctx,
                  pd_bond_value_fn value, int intact_only)
{
  pd_bond bd;
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    const int trow = pd_row_begin(&bd, type, ntypes, i);
    for (int k = 0; k < b->count[i]; k++) {
      if (intact_only && pd_bond_broken(b->len0[row + k])) continue;
      pd_bond_load(&bd, b, type, trow, NULL, NULL, NULL, row + k, b->weight != NULL, 0, 0);
      double vi_share, vj_share;
      value(ctx, &bd, &vi_share, &vj_share);
      sum[i] += vi_share * vol[bd.j];
      sum[bd.j] += vj_share * vol[i];
    }
  }
}

enum { PD_MAX_SUM_WIDTH = 48 };
typedef void (*pd_bond_strain_value_fn)(void *ctx, const pd_bond *bd, double eps, double *t);

/* One bond's values t onto its two ends: t V_j onto si (atom i's), t V_i
 * onto j's sum. Both ways of pd_current_sums add through it, so they agree
 * to the bit. */
PD_INLINE void
pd_scatter_sum(double *restrict si, double *restrict sum, int width, const double *restrict t,
               int j, const double *restrict vol, double vi)
{
  const double vj = vol[j];
  double *restrict sj = sum + width * (ptrdiff_t) j;
  /* four at a time where the width allows (the correspondence's 9 and 15:
   * the compiler kept every value scalar), the same arithmetic per value */
  int c = 0;
  for (; c + 4 <= width; c += 4) {
    const pd_sum4 tc = pd_sum4_load(t + c);
    pd_sum4_store(si + c, pd_sum4_axpy4(pd_sum4_load(si + c), vj, tc));
    pd_sum4_store(sj + c, pd_sum4_axpy4(pd_sum4_load(sj + c), vi, tc));
  }
  for (; c < width; c++) {
    si[c] += t[c] * vj;
    sj[c] += t[c] * vi;
  }
}

/* One bond of pd_current_sums: its values onto sum[j] and si (atom i's). */
PD_INLINE void
pd_current_sum_bond(const pd_loop *L, double *restrict sum, double *restrict si, int width,
                    const double xi[3], pd_bond *bd, int idx, void *mat, pd_strain_fn strain,
                    pd_bond_strain_value_fn value, double *restrict keep, int weighted,
                    int failing)
{
  const pd_bond_view *restrict b = L->b;
  /* value() writes all width entries of t; zeroing them only keeps the
   * compiler from doubting it */
  double t[PD_MAX_SUM_WIDTH];
  for (int c = 0; c < width; c++) t[c] = 0.0;
  pd_bond_load(bd, b, NULL, 0, L->x, xi, L->fail, idx, weighted, failing, 1);
  const double eps = strain(mat, bd);
  if (keep) keep[idx] = eps;
  if (failing && pd_bond_inactive(L->fail, bd->broken, eps)) return;
  value(mat, bd, eps, t);
  pd_scatter_sum(si, sum, width, t, bd->j, L->vol, L->vol[bd->i]);
}

/* A chunk's bonds as a first pass loaded them, one array per number, for
 * values formed later (pd_current_sums_late). */
typedef struct pd_chunk_bonds {
  double d[3][PD_CHUNK], len[PD_CHUNK], len2[PD_CHUNK], r0[PD_CHUNK], w[PD_CHUNK];
} pd_chunk_bonds;

/* A bond as pd_bond_load_ahead left it, into slot k of such a chunk, and
 * back (of atom i's row, from slot row): the numbers a late value reads. */
PD_INLINE void pd_chunk_keep(pd_chunk_bonds *restrict cb, int k, const pd_bond *bd)
{
  for (int c = 0; c < 3; c++) cb->d[c][k] = bd->d[c];
  cb->len[k] = bd->len, cb->len2[k] = bd->len2, cb->r0[k] = bd->r0;
  cb->w[k] = bd->w;
}
PD_INLINE pd_bond pd_chunk_bond(const pd_chunk_bonds *restrict cb, const int *restrict far, int i,
                                int row, int k)
{
  const pd_bond bd = {.i = i, .j = far[k], .idx = row + k, .ti = 0, .tj = 1, .tij = 1, .broken = 0,
                      .r0 = cb->r0[k], .w = cb->w[k], .len = cb->len[k], .len2 = cb->len2[k],
                      .d = {cb->d[0][k], cb->d[1][k], cb->d[2][k]}};
  return bd;
}

/* Bond k of a chunk of pd_current_sums_late: its values formed from the
 * chunk's numbers and strain, added onto si (a half of atom i's sum) and
 * sum[j]. */
PD_INLINE void
pd_late_sum_bond(double *restrict si, double *restrict sum, int width, void *mat,
                 pd_bond_strain_value_fn value, const pd_chunk_bonds *restrict cb,
                 const double *restrict eb, const int *restrict far, int i, int row, int k,
                 const double *restrict vol, double vi)
{
  double t[PD_MAX_SUM_WIDTH];
  for (int c = 0; c < width; c++) t[c] = 0.0;  /* (as pd_current_sum_bond) */
  const pd_bond bk = pd_chunk_bond(cb, far, i, row, k);
  value(mat, &bk, eb[k], t);
  pd_scatter_sum(si, sum, width, t, far[k], vol, vi);
}

/* Its first pass over bonds row .. row+m-1 of a row, as pd_force_bonds: the
 * values of every bond into tb (width per bond), or with cb the bonds'
 * numbers into cb instead (from index at); unless eb is NULL, their strains into eb (a
 * value that does not read the strain then costs none); nonzero if a bond
 * is broken (the caller then takes the chunk bond by bond). */
PD_INLINE int
pd_current_sum_bonds(const pd_loop *L, int width, const double xi[3], int i, int row, int m,
                     double *restrict tb, void *mat, pd_strain_fn strain,
                     pd_bond_strain_value_fn value, double *restrict eb, pd_chunk_bonds *restrict cb,
                     int at, int weighted, int failing)
{
  const pd_bond_view *restrict b = L->b;
  long long broken = 0;    /* (as pd_force_bonds' 'special') */
  for (int k = 0; k < m; k++) {
    pd_bond bd;
    bd.i = i;
    bd.ti = 0;
    broken |= -(long long) pd_bond_load_ahead(&bd, b, NULL, 0, L->x, xi, row + k, weighted, failing);
    const double eps = strain(mat, &bd);
    if (eb) eb[k] = eps;
    if (cb) pd_chunk_keep(cb, at + k, &bd);
    else value(mat, &bd, eps, tb + k * width);
  }
  return broken != 0;
}

/* pd_current_sum_bonds for a chunk in whole vectors (pd_vector_overlap:
 * pd/ordinary 1.03x, its m = 0 1.10x faster at 16^3); the strains into
 * eb, for a caller that keeps them (a local array: a store into the
 * caller's, which the compiler cannot tell from the gathered positions,
 * kept the loop scalar). */
PD_INLINE int
pd_current_sum_chunk(const pd_loop *L, int width, const double xi[3], int i, int row, int m,
                     double *restrict tb, void *mat, pd_strain_fn strain,
                     pd_bond_strain_value_fn value, double *restrict eb, pd_chunk_bonds *restrict cb,
                     int weighted, int failing)
{
  const int last = pd_vector_overlap(m);
  if (last < 0)
    return pd_current_sum_bonds(L, width, xi, i, row, m, tb, mat, strain, value, eb, cb, 0,
                                weighted, failing);
  return pd_current_sum_bonds(L, width, xi, i, row, m - m % PD_VECTOR_BONDS, tb, mat, strain,
                              value, eb, cb, 0, weighted, failing) ||
         pd_current_sum_bonds(L, width, xi, i, row + last, PD_VECTOR_BONDS,
                              cb ? NULL : tb + last * width, mat, strain, value,
                              eb ? eb + last : NULL, cb, last, weighted, failing);
}

/* The same in the current configuration, over the bonds that act (a broken
 * bond only in compression, with recontact): value(ctx, bond, strain, t)
 * gives 'width' numbers t, added as t V_j onto sum[i * width ..] and t V_i
 * onto sum[j * width ..]; keep (or NULL) receives every bond's strain, laid
 * out as the bonds, for a second pass to read back. A state-based material's first pass (dilatation,
 * deformation gradient); types are not loaded. Rows go in chunks as in
 * pd_force_loop_on: a vectorizable pass computes the values, a scalar one
 * adds them in the order and with the arithmetic of bond by bond. The sum
 * on i goes in two halves, as the force loop's (bonds 0, 2, 4 .. of a row
 * and 1, 3, ..): a width of 1 waited on one chain of adds. */
PD_INLINE void
pd_current_sums_on(const pd_loop *L, double *restrict sum, int width, void *mat,
                   pd_strain_fn strain, pd_bond_strain_value_fn value, double *restrict keep,
                   int weighted, int failing, int late)
{
  const pd_bond_view *restrict b = L->b;
  const double *restrict vol = L->vol;
  pd_bond bd;
  double tb[PD_CHUNK * PD_MAX_SUM_WIDTH], eb[PD_CHUNK];
  pd_chunk_bonds cb;
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride, n = b->count[i];
    const double vi = vol[i];
    bd.i = i;
    bd.ti = 0;
    /* (two arrays, not one of two: indexed by k & 1 they lived in memory) */
    double even[PD_MAX_SUM_WIDTH], odd[PD_MAX_SUM_WIDTH];
    for (int c = 0; c < width; c++) even[c] = odd[c] = 0.0;
    const double xi[3] = {L->x[3 * i], L->x[3 * i + 1], L->x[3 * i + 2]};
    for (int k0 = 0; k0 < n; k0 += PD_CHUNK) {
      const int m = n - k0 < PD_CHUNK ? n - k0 : PD_CHUNK;
      if (!L->bond_by_bond &&
          !pd_current_sum_chunk(L, width, xi, i, row + k0, m, tb, mat, strain, value,
                                keep || late ? eb : NULL, late ? &cb : NULL, weighted, failing)) {
        const int *restrict far = b->far + row + k0;
        if (keep)
          for (int k = 0; k < m; k++) keep[row + k0 + k] = eb[k];
        if (late) {
          /* (each half named, as below: a half chosen per bond by k & 1
           * was one pointer, and each bond's adds waited on its loads) */
          int k = 0;
          for (; k + 1 < m; k += 2) {
            pd_late_sum_bond(even, sum, width, mat, value, &cb, eb, far, i, row + k0, k, vol, vi);
            pd_late_sum_bond(odd, sum, width, mat, value, &cb, eb, far, i, row + k0, k + 1, vol, vi);
          }
          if (k < m) pd_late_sum_bond(even, sum, width, mat, value, &cb, eb, far, i, row + k0, k, vol, vi);
          continue;
        }
        int k = 0;
        for (; k + 1 < m; k += 2) {
          pd_scatter_sum(even, sum, width, tb + k * width, far[k], vol, vi);
          pd_scatter_sum(odd, sum, width, tb + (k + 1) * width, far[k + 1], vol, vi);
        }
        if (k < m) pd_scatter_sum(even, sum, width, tb + k * width, far[k], vol, vi);
        continue;
      }
      for (int k = 0; k < m; k++)
        pd_current_sum_bond(L, sum, k & 1 ? odd : even, width, xi, &bd, row + k0 + k, mat, strain,
                            value, keep, weighted, failing);
    }
    for (int c = 0; c < width; c++) sum[i * width + c] += even[c] + odd[c];
  }
}

/* (one copy per weight mode, so that it is a constant in each) */
PD_INLINE void
pd_current_sums_mode(const pd_loop *L, double *restrict sum, int width, void *mat,
                     pd_strain_fn strain, pd_bond_strain_value_fn value, double *restrict keep,
                     int failing, int late)
{
  switch (pd_weight_mode(L->b)) {
  case PD_WEIGHT_INVERSE:
    pd_current_sums_on(L, sum, width, mat, strain, value, keep, PD_WEIGHT_INVERSE, failing, late);
    break;
  case PD_WEIGHT_TABLE:
    pd_current_sums_on(L, sum, width, mat, strain, value, keep, PD_WEIGHT_TABLE, failing, late);
    break;
  default:
    pd_current_sums_on(L, sum, width, mat, strain, value, keep, PD_WEIGHT_ONE, failing, late);
    break;
  }
}

PD_INLINE void
pd_current_sums_keep(const pd_loop *L, double *restrict sum, int width, void *mat,
                     pd_strain_fn strain, pd_bond_strain_value_fn value, double *restrict keep,
                     int failing)
{
  pd_current_sums_mode(L, sum, width, mat, strain, value, keep, failing, 0);
}

PD_INLINE void
pd_current_sums(const pd_loop *L, double *restrict sum, int width, void *mat, pd_strain_fn strain,
                pd_bond_strain_value_fn value, int failing)
{
  pd_current_sums_mode(L, sum, width, mat, strain, value, NULL, failing, 0);
}

/* The same for wide values that read the strain (pd/corr's extended
 * sums, 15 per bond): the first pass keeps each bond's numbers and strain
 * (in vectors: stores of 15 values per bond kept it scalar, and with it
 * the strain's log), and the scalar pass forms each bond's values just
 * before it adds them. The same numbers as pd_current_sums. */
PD_INLINE void
pd_current_sums_late(const pd_loop *L, double *restrict sum, int width, void *mat,
                     pd_strain_fn strain, pd_bond_strain_value_fn value, int failing)
{
  pd_current_sums_mode(L, sum, width, mat, strain, value, NULL, failing, 1);
}

#endif
