/* Contact candidates and the short list taken from them.
 *
 * A candidate is a pair of a neighbor list that may touch, with its contact
 * distance, both fixed between two reneighborings. Atoms move less than half
 * a list's skin between two builds of it, so two atoms farther apart than
 * dist + skin at a build cannot come within dist before the next build: the
 * short list holds the candidates closer than dist + skin at its build, in
 * their order (the forces are summed in the same order as over all
 * candidates, bit for bit), and stays valid while no atom of a candidate
 * moved farther than skin / 2 since then. x[] are positions, 3 per atom. */
#ifndef PD_CONTACT_LIST_H
#define PD_CONTACT_LIST_H

typedef struct {
  int i, j;       /* atom indices */
  double dist;    /* contact distance of the pair */
} pd_contact_cand;

/* Copies to out[] the candidates closer than dist + skin now; returns how
 * many. */
int pd_contact_select(const pd_contact_cand *cand, int n, const double *x, double skin,
                      pd_contact_cand *out);

/* 1 if one of the atoms[0..n-1] moved farther than `limit` from its
 * position in ref[] (3 per entry of atoms[], in its order). */
int pd_contact_moved(const int *atoms, int n, const double *x, const double *ref, double limit);

#endif
