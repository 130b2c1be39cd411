/* Fragments: the connected components of the graph of intact bonds.
 *
 * A host that spreads atoms over processors (LAMMPS) finds them in three
 * steps. (1) A union-find forest over its owned and ghost atoms joins the
 * two ends of every intact bond it stores (pd_fragments_join), once per
 * evaluation. (2) Labels (the smallest atom ID of the fragment, 0 for atoms
 * that take no part) relax to the smallest label of each local tree
 * (pd_fragments_relax), alternating with the host's exchange of labels
 * between owners and ghosts, until no label changes anywhere: a fragment
 * joined only through another processor's bonds, or through a periodic
 * image, ends with one label. (3) Each processor adds up the masses of its
 * owned atoms per tree (pd_fragments_pieces); the pieces of one fragment
 * from all processors are gathered by label and added
 * (pd_fragments_merge), and the fragments tallied and binned by mass
 * (pd_fragments_tally, pd_fragments_histogram).
 *
 * No allocation: the caller passes every array. */
#ifndef PD_FRAGMENTS_H
#define PD_FRAGMENTS_H

#include "pd_bonds.h"

#include <stdint.h>

/* parent[i] = i for i < n: every atom its own tree. */
void pd_uf_init(int *parent, int n);

/* The root of i's tree, halving the path on the way (amortized near O(1)). */
int pd_uf_find(int *parent, int i);

/* Joins the trees of a and b; the larger root is hung under the smaller, so
 * a root is the smallest index of its tree. */
void pd_uf_union(int *parent, int a, int b);

/* parent[i] = the root of i for every i < n: afterwards parent is the
 * table of roots that pd_fragments_relax and pd_fragments_pieces read. */
void pd_uf_flatten(int *parent, int n);

/* Joins the two ends of every intact bond of b (len0 > 0; a broken bond's
 * length is negative) whose ends are both members: (mask[i] & bit) != 0,
 * or every atom when mask is NULL. parent covers every far end. */
void pd_fragments_join(const pd_bond_view *b, const int *mask, int bit, int *parent);

/* One relaxation: every atom takes the smallest label of its tree (root:
 * the flattened table). Labels are >= 0; an atom that takes no part has
 * label 0 and a tree of its own. Returns 1 if the label of an atom below
 * nwatch (the owned atoms) went down, else 0. */
int pd_fragments_relax(const int *root, int64_t *label, int n, int nwatch);

/* A fragment, or the share of it that one processor holds. */
typedef struct pd_fragment {
  int64_t id;      /* its label: the smallest atom ID in it */
  int64_t atoms;   /* number of atoms */
  double mass;
} pd_fragment;

/* The shares of fragments that atoms 0 .. nown-1 hold (those with a label
 * > 0), one per tree: written to out (room for nown entries), in the order
 * of their first atom; returns their number. slot: scratch of one int per
 * atom of the forest (any content on entry). */
int pd_fragments_pieces(const int *root, const int64_t *label, const double *mass, int nown, int *slot,
                        pd_fragment *out);

/* Sorts f by id and adds up the entries of equal id, in an order fixed by
 * their values (not by their order on entry); returns the number of
 * fragments left at the start of f. */
int pd_fragments_merge(pd_fragment *f, int n);

/* What fragments add up to. 'Counted' fragments have at least min_atoms
 * atoms (the others are debris: single particles by default). */
typedef struct pd_fragment_tally {
  double counted;        /* number of counted fragments */
  double all;            /* number of all fragments */
  double counted_mass;   /* mass in counted fragments */
  double debris_mass;    /* mass in the others */
  double largest;        /* mass of the heaviest fragment (counted or not) */
  double largest_atoms;  /* its number of atoms (the larger when two weigh the same) */
} pd_fragment_tally;

/* Adds the fragments f[0 .. n-1] to t (which the caller zeroes first). */
void pd_fragments_tally(const pd_fragment *f, int n, int64_t min_atoms, pd_fragment_tally *t);

/* nbins log-spaced mass bins from lo to hi (0 < lo < hi): the upper edge of
 * bin k is lo (hi/lo)^((k+1)/nbins), the last one hi itself. */
void pd_mass_edges(double lo, double hi, int nbins, double *edge);

/* The bin of mass m > 0: the first whose upper edge is not below m (a mass
 * within 1e-9 of a bin's log-width above an edge counts as on it, so that
 * round-off in adding up a fragment does not push it past an edge it sits
 * on); 0 for m <= lo, nbins for m above hi. With hi <= lo, one bin: 0 if
 * m <= hi (same slack), else nbins. */
int pd_mass_bin(double m, double lo, double hi, int nbins);

/* Adds the counted fragments (>= min_atoms atoms) to count[k] and mass[k]
 * of their bin (fragments above hi to none). */
void pd_fragments_histogram(const pd_fragment *f, int n, int64_t min_atoms, double lo, double hi, int nbins,
                            double *count, double *mass);

/* a[k] = a[0] + ... + a[k], in place. */
void pd_cumulate(double *a, int n);

#endif
