/* Fragments (pd_fragments.h) against a brute-force breadth-first search.
 *
 * 1. One forest: random bond tables (broken bonds, atoms outside the
 *    group, far ends among "ghost" atoms) joined by pd_fragments_join: each
 *    atom's root is the smallest index of its component as the search
 *    finds it, and one relaxation gives each atom the smallest label of
 *    its component.
 * 2. Spread over processors: a random graph whose atoms are owned by P
 *    simulated processors, each bond stored once, at one end's owner, its
 *    far end an owned atom or a ghost copy (several copies of one atom, as
 *    periodic images give); labels relax with the owner -> ghost and
 *    ghost -> owner exchanges of the LAMMPS glue until nothing changes:
 *    every atom ends with the smallest ID of its component, and the pieces
 *    of all processors merged give each component's atoms and mass.
 * 3. Mass bins: edges, the bin of masses on and off the edges, the
 *    histogram against counting by hand, the cumulative sums.
 * Every comparison is exact (integers, or sums of the same numbers). */
#include "check.h"
#include "pd_fragments.h"

#include <stdlib.h>
#include <string.h>

static unsigned long long rng_state;
static unsigned next_random(void)
{
  rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (unsigned) (rng_state >> 33);
}
static int below(int n)
{
  return (int) (next_random() % (unsigned) n);
}

/* A plain graph: the reference the tests compare with. */
typedef struct graph {
  int n, m;
  int *a, *b;       /* edge e joins a[e] and b[e] */
  int *intact;
  int *member;      /* atom in the group */
} graph;

static graph random_graph(int n, int m)
{
  graph g = {n, m, malloc(sizeof(int) * m), malloc(sizeof(int) * m), malloc(sizeof(int) * m),
             malloc(sizeof(int) * n)};
  for (int e = 0; e < m; e++) {
    g.a[e] = below(n);
    g.b[e] = below(n);
    g.intact[e] = below(5) != 0;
  }
  for (int i = 0; i < n; i++) g.member[i] = below(8) != 0;
  return g;
}

static void free_graph(graph *g)
{
  free(g->a);
  free(g->b);
  free(g->intact);
  free(g->member);
}

/* comp[i]: the smallest index of i's component (intact edges between
 * members), by breadth-first search over an adjacency list; -1 for atoms
 * outside the group. */
static void bfs_components(const graph *g, int *comp)
{
  int *deg = calloc((size_t) g->n + 1, sizeof(int)), *adj = malloc(sizeof(int) * 2 * (size_t) g->m + 1);
  int *queue = malloc(sizeof(int) * (size_t) g->n);
  for (int e = 0; e < g->m; e++)
    if (g->intact[e] && g->member[g->a[e]] && g->member[g->b[e]]) {
      deg[g->a[e] + 1]++;
      deg[g->b[e] + 1]++;
    }
  for (int i = 0; i < g->n; i++) deg[i + 1] += deg[i];
  int *fill = malloc(sizeof(int) * (size_t) g->n);
  memcpy(fill, deg, sizeof(int) * (size_t) g->n);
  for (int e = 0; e < g->m; e++)
    if (g->intact[e] && g->member[g->a[e]] && g->member[g->b[e]]) {
      adj[fill[g->a[e]]++] = g->b[e];
      adj[fill[g->b[e]]++] = g->a[e];
    }
  for (int i = 0; i < g->n; i++) comp[i] = g->member[i] ? g->n : -1;
  for (int s = 0; s < g->n; s++) {
    if (comp[s] != g->n) continue;    /* visited in increasing order: s is its component's smallest */
    int head = 0, tail = 0;
    queue[tail++] = s;
    comp[s] = s;
    while (head < tail) {
      const int u = queue[head++];
      for (int q = deg[u]; q < deg[u + 1]; q++)
        if (comp[adj[q]] == g->n) {
          comp[adj[q]] = s;
          queue[tail++] = adj[q];
        }
    }
  }
  free(deg);
  free(adj);
  free(queue);
  free(fill);
}

/* 1. One forest over all atoms: atoms 0 .. nowner-1 store the bonds, the
 * rest ("ghosts") none; a bond is stored at its lower end when that is an
 * owner, else dropped from the graph (the reference drops it too). */
static int forest_case(int n, int m, int with_mask)
{
  graph g = random_graph(n, m);
  if (!with_mask)
    for (int i = 0; i < n; i++) g.member[i] = 1;
  const int nowner = n - n / 4;
  int *count = calloc((size_t) n, sizeof(int));
  for (int e = 0; e < m; e++) {
    if (g.a[e] > g.b[e]) {
      const int t = g.a[e];
      g.a[e] = g.b[e];
      g.b[e] = t;
    }
    if (g.a[e] < nowner) count[g.a[e]]++;
    else g.intact[e] = 0;
  }
  int stride = 1;
  for (int i = 0; i < n; i++)
    if (count[i] > stride) stride = count[i];
  int *far = malloc(sizeof(int) * (size_t) n * stride), *mask = malloc(sizeof(int) * (size_t) n);
  double *len0 = malloc(sizeof(double) * (size_t) n * stride);
  memset(count, 0, sizeof(int) * (size_t) n);
  for (int e = 0; e < m; e++) {
    if (g.a[e] >= nowner) continue;
    const int slot = g.a[e] * stride + count[g.a[e]]++;
    far[slot] = g.b[e];
    len0[slot] = g.intact[e] ? 1.0 + 0.01 * e : -1.0;
  }
  for (int i = 0; i < n; i++) mask[i] = g.member[i] ? 1 | 4 : 1;
  pd_bond_view v = {nowner, stride, count, far, len0, NULL, 0.0};
  int *root = malloc(sizeof(int) * (size_t) n), *comp = malloc(sizeof(int) * (size_t) n);
  pd_uf_init(root, n);
  pd_fragments_join(&v, with_mask ? mask : NULL, 4, root);
  pd_uf_flatten(root, n);
  bfs_components(&g, comp);
  int ok = 1;
  for (int i = 0; i < n; i++) ok &= root[i] == (comp[i] < 0 ? i : comp[i]);
  /* the same forest from pd_uf_union, edge by edge */
  int *again = malloc(sizeof(int) * (size_t) n);
  pd_uf_init(again, n);
  for (int e = 0; e < m; e++)
    if (g.intact[e] && g.member[g.a[e]] && g.member[g.b[e]]) pd_uf_union(again, g.b[e], g.a[e]);
  pd_uf_flatten(again, n);
  for (int i = 0; i < n; i++) ok &= again[i] == root[i];
  free(again);
  /* labels: a random distinct permutation of 1..n on members, 0 outside */
  int64_t *label = malloc(sizeof(int64_t) * (size_t) n), *least = malloc(sizeof(int64_t) * (size_t) n);
  for (int i = 0; i < n; i++) label[i] = i + 1;
  for (int i = n - 1; i > 0; i--) {
    const int j = below(i + 1);
    const int64_t t = label[i];
    label[i] = label[j];
    label[j] = t;
  }
  for (int i = 0; i < n; i++) {
    if (!g.member[i]) label[i] = 0;
    least[i] = INT64_MAX;
  }
  for (int i = 0; i < n; i++)
    if (comp[i] >= 0 && label[i] < least[comp[i]]) least[comp[i]] = label[i];
  const int changed = pd_fragments_relax(root, label, n, n);
  for (int i = 0; i < n; i++) ok &= label[i] == (comp[i] < 0 ? 0 : least[comp[i]]);
  ok &= pd_fragments_relax(root, label, n, n) == 0;    /* a fixed point */
  (void) changed;
  free(root);
  free(comp);
  free(label);
  free(least);
  free(far);
  free(mask);
  free(len0);
  free(count);
  free_graph(&g);
  return ok;
}

/* 2. The distributed algorithm on P simulated processors. */
typedef struct proc {
  int nown, nall;
  int *global;      /* global atom of each local atom (owned first, then ghosts) */
  int *count, *far, stride;
  double *len0;
  int *mask;
  int *root;
  int64_t *label;
  double *mass;
} proc;

static int distributed_case(int n, int m, int nproc, int *iterations)
{
  graph g = random_graph(n, m);
  int *owner = malloc(sizeof(int) * (size_t) n), *local = malloc(sizeof(int) * (size_t) n * nproc);
  double *mass = malloc(sizeof(double) * (size_t) n);
  for (int i = 0; i < n; i++) {
    owner[i] = below(nproc);
    mass[i] = 0.5 + below(1000) / 1000.0;    /* sums in another order: compared to round-off */
  }
  proc *p = calloc((size_t) nproc, sizeof(proc));
  const int cap = n + 2 * m + 1;
  for (int q = 0; q < nproc; q++) {
    p[q].global = malloc(sizeof(int) * (size_t) cap);
    for (int i = 0; i < n; i++) local[q * n + i] = -1;
    for (int i = 0; i < n; i++)
      if (owner[i] == q) {
        local[q * n + i] = p[q].nown;
        p[q].global[p[q].nown++] = i;
      }
    p[q].nall = p[q].nown;
  }
  /* each edge stored at the owner of a random end; its far end a ghost
     copy on that processor (a new copy one time in three, as a periodic
     image adds one, else the first), or the owned atom itself when local */
  int *store_at = malloc(sizeof(int) * (size_t) m), *far_local = malloc(sizeof(int) * (size_t) m);
  int *near_local = malloc(sizeof(int) * (size_t) m);
  for (int e = 0; e < m; e++) {
    if (below(2)) {
      const int t = g.a[e];
      g.a[e] = g.b[e];
      g.b[e] = t;
    }
    const int q = owner[g.a[e]], j = g.b[e];
    store_at[e] = q;
    near_local[e] = local[q * n + g.a[e]];
    if (owner[j] == q && below(3)) far_local[e] = local[q * n + j];
    else if (local[q * n + j] >= p[q].nown && below(3)) far_local[e] = local[q * n + j];
    else {
      far_local[e] = p[q].nall;
      if (local[q * n + j] < 0) local[q * n + j] = p[q].nall;
      p[q].global[p[q].nall++] = j;
    }
  }
  for (int q = 0; q < nproc; q++) {
    proc *r = &p[q];
    r->count = calloc((size_t) r->nall, sizeof(int));
    for (int e = 0; e < m; e++)
      if (store_at[e] == q) r->count[near_local[e]]++;
    r->stride = 1;
    for (int i = 0; i < r->nown; i++)
      if (r->count[i] > r->stride) r->stride = r->count[i];
    r->far = malloc(sizeof(int) * (size_t) r->nown * r->stride + 1);
    r->len0 = malloc(sizeof(double) * (size_t) r->nown * r->stride + 1);
    memset(r->count, 0, sizeof(int) * (size_t) r->nall);
    for (int e = 0; e < m; e++)
      if (store_at[e] == q) {
        const int i = near_local[e], slot = i * r->stride + r->count[i]++;
        r->far[slot] = far_local[e];
        r->len0[slot] = g.intact[e] ? 1.0 : -1.0;
      }
    r->mask = malloc(sizeof(int) * (size_t) r->nall);
    r->root = malloc(sizeof(int) * (size_t) r->nall);
    r->label = malloc(sizeof(int64_t) * (size_t) r->nall);
    r->mass = malloc(sizeof(double) * (size_t) r->nall);
    for (int i = 0; i < r->nall; i++) {
      r->mask[i] = g.member[r->global[i]] ? 3 : 1;
      r->mass[i] = mass[r->global[i]];
    }
    pd_bond_view v = {r->nown, r->stride, r->count, r->far, r->len0, NULL, 0.0};
    pd_uf_init(r->root, r->nall);
    pd_fragments_join(&v, r->mask, 2, r->root);
    pd_uf_flatten(r->root, r->nall);
    for (int i = 0; i < r->nown; i++) r->label[i] = g.member[r->global[i]] ? r->global[i] + 1 : 0;
  }
  /* owned labels by global atom, for the exchanges */
  int64_t *owned_label = malloc(sizeof(int64_t) * (size_t) n);
  int changed = 1;
  *iterations = 0;
  while (changed && *iterations < 10 * nproc + 10) {
    changed = 0;
    ++*iterations;
    for (int q = 0; q < nproc; q++)
      for (int i = 0; i < p[q].nown; i++) owned_label[p[q].global[i]] = p[q].label[i];
    for (int q = 0; q < nproc; q++) /* forward: owners' labels to their ghosts */
      for (int i = p[q].nown; i < p[q].nall; i++) p[q].label[i] = owned_label[p[q].global[i]];
    for (int q = 0; q < nproc; q++) changed |= pd_fragments_relax(p[q].root, p[q].label, p[q].nall, p[q].nown);
    for (int q = 0; q < nproc; q++) /* reverse: the smallest of the ghosts' labels to the owner */
      for (int i = p[q].nown; i < p[q].nall; i++) {
        const int a = p[q].global[i];
        proc *o = &p[owner[a]];
        int64_t *mine = &o->label[local[owner[a] * n + a]];
        if (p[q].label[i] < *mine) {
          *mine = p[q].label[i];
          changed = 1;
        }
      }
  }
  int *comp = malloc(sizeof(int) * (size_t) n);
  bfs_components(&g, comp);
  int ok = !changed;
  for (int q = 0; q < nproc; q++)
    for (int i = 0; i < p[q].nown; i++) {
      const int a = p[q].global[i];
      ok &= p[q].label[i] == (comp[a] < 0 ? 0 : comp[a] + 1);
    }
  /* pieces of every processor, merged, against the components */
  pd_fragment *pieces = malloc(sizeof(pd_fragment) * (size_t) n + 1);
  int npieces = 0;
  for (int q = 0; q < nproc; q++) {
    int *slot = malloc(sizeof(int) * (size_t) p[q].nall + 1);
    npieces += pd_fragments_pieces(p[q].root, p[q].label, p[q].mass, p[q].nown, slot, pieces + npieces);
    free(slot);
  }
  const int nfrag = pd_fragments_merge(pieces, npieces);
  int64_t *atoms = calloc((size_t) n, sizeof(int64_t));
  double *cmass = calloc((size_t) n, sizeof(double));
  int ncomp = 0;
  for (int a = 0; a < n; a++)
    if (comp[a] >= 0) {
      ncomp += comp[a] == a;
      atoms[comp[a]]++;
      cmass[comp[a]] += mass[a];
    }
  ok &= nfrag == ncomp;
  for (int k = 0; k < nfrag && ok; k++) {
    const int c = (int) pieces[k].id - 1;
    ok &= (k == 0 || pieces[k].id > pieces[k - 1].id) && c >= 0 && c < n && comp[c] == c;
    ok &= pieces[k].atoms == atoms[c] && fabs(pieces[k].mass - cmass[c]) <= 1e-12 * cmass[c];
  }
  free(atoms);
  free(cmass);
  free(pieces);
  free(comp);
  free(owned_label);
  for (int q = 0; q < nproc; q++) {
    free(p[q].global);
    free(p[q].count);
    free(p[q].far);
    free(p[q].len0);
    free(p[q].mask);
    free(p[q].root);
    free(p[q].label);
    free(p[q].mass);
  }
  free(p);
  free(owner);
  free(local);
  free(mass);
  free(store_at);
  free(far_local);
  free(near_local);
  free_graph(&g);
  return ok;
}

/* 3. Mass bins. */
static void bins(void)
{
  enum { N = 7 };
  const double lo = 2.0, hi = 2.0 * 128.0;    /* a factor 2 per bin: edges exact powers of 2 */
  double edge[N];
  pd_mass_edges(lo, hi, N, edge);
  int exact = 1;
  for (int k = 0; k < N; k++) exact &= fabs(edge[k] - lo * pow(2.0, k + 1)) <= 1e-14 * edge[k];
  check_true("edges lo (hi/lo)^((k+1)/n), the last exactly hi", exact && edge[N - 1] == hi);
  int on = 1, above = 1;
  for (int k = 0; k < N; k++) {
    on &= pd_mass_bin(edge[k], lo, hi, N) == k && pd_mass_bin(edge[k] * (1 + 1e-13), lo, hi, N) == k;
    above &= pd_mass_bin(edge[k] * (1 + 1e-6), lo, hi, N) == k + 1;
  }
  check_true("a mass on an edge (or a round-off above) is in the bin the edge closes", on);
  check_true("a mass 1e-6 above an edge is in the next bin (beyond hi: none)", above);
  check_true("masses at or below lo are in the first bin",
             pd_mass_bin(lo, lo, hi, N) == 0 && pd_mass_bin(0.1, lo, hi, N) == 0);
  check_true("one bin when hi <= lo", pd_mass_bin(3.0, 3.0, 3.0, N) == 0 && pd_mass_bin(3.1, 3.0, 3.0, N) == N);
  /* random fragments: bins against the first edge not below the mass */
  enum { M = 2000 };
  pd_fragment f[M];
  double count[N] = {0}, mass[N] = {0}, want_count[N] = {0}, want_mass[N] = {0};
  for (int k = 0; k < M; k++) {
    f[k].id = k + 1;
    f[k].atoms = 1 + below(4);
    f[k].mass = lo * pow(2.0, below(100000) / 10000.0);    /* up to 2^10 lo: some beyond hi */
  }
  f[0].mass = edge[3];
  f[0].atoms = 3;
  pd_fragments_histogram(f, M, 2, lo, hi, N, count, mass);
  for (int k = 0; k < M; k++) {
    if (f[k].atoms < 2) continue;
    int b = 0;
    while (b < N && f[k].mass > edge[b] * (1 + 1e-12)) b++;
    if (b == N) continue;
    want_count[b] += 1;
    want_mass[b] += f[k].mass;
  }
  int same = 1;
  for (int k = 0; k < N; k++) same &= count[k] == want_count[k] && fabs(mass[k] - want_mass[k]) <= 1e-12 * want_mass[k];
  check_true("histogram of 2000 fragments (min 2 atoms) equals counting against the edges", same);
  pd_cumulate(count, N);
  double run = 0;
  int cum = 1;
  for (int k = 0; k < N; k++) {
    run += want_count[k];
    cum &= count[k] == run;
  }
  check_true("cumulative counts", cum);
  pd_fragment_tally t = {0};
  pd_fragments_tally(f, M, 2, &t);
  double counted = 0, cmass = 0, dmass = 0, largest = 0;
  for (int k = 0; k < M; k++) {
    if (f[k].atoms >= 2) {
      counted++;
      cmass += f[k].mass;
    } else
      dmass += f[k].mass;
    if (f[k].mass > largest) largest = f[k].mass;
  }
  check_true("tally: counted, all, masses, largest",
             t.all == M && t.counted == counted && t.counted_mass == cmass && t.debris_mass == dmass &&
                 t.largest == largest);
}

int main(void)
{
  int ok = 1;
  for (unsigned seed = 1; seed <= 300; seed++) {
    rng_state = seed;
    const int n = 2 + below(200), m = below(3 * n);
    ok &= forest_case(n, m, seed % 3 != 0);
  }
  check_true("300 random forests (sparse to dense, with and without a group): roots (by rows and by single "
             "unions) and labels as the search finds",
             ok);
  ok = 1;
  int worst = 0;
  for (unsigned seed = 1; seed <= 300; seed++) {
    rng_state = 1000 + seed;
    const int n = 2 + below(300), m = below(2 * n), nproc = 1 + below(6);
    int iterations;
    ok &= distributed_case(n, m, nproc, &iterations);
    if (iterations > worst) worst = iterations;
  }
  check_true("300 random graphs on 1-6 processors with ghost copies: labels, atoms and masses per fragment", ok);
  printf("(at most %d exchange rounds)\n", worst);
  rng_state = 7;
  bins();
  return check_summary();
}
