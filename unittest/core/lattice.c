#include "lattice.h"

#include <math.h>
#include <stdlib.h>

lattice lattice_make(int dim, int n, double h, double delta, int kind)
{
  lattice l = {0};
  l.n = n;
  l.h = h;
  l.delta = delta;
  l.natoms = dim == 2 ? n * n : n * n * n;
  l.x0 = calloc(3 * (size_t) l.natoms, sizeof(double));
  l.vol = malloc(sizeof(double) * l.natoms);
  l.type = calloc(l.natoms, sizeof(int));
  l.count = calloc(l.natoms, sizeof(int));
  const int nz = dim == 2 ? 1 : n;
  int a = 0;
  for (int k = 0; k < nz; k++)
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++, a++) {
        l.x0[3 * a] = i * h;
        l.x0[3 * a + 1] = j * h;
        l.x0[3 * a + 2] = k * h;
        l.vol[a] = dim == 2 ? h * h : h * h * h;
      }
  const int reach = (int) ceil(delta / h);
  l.stride = dim == 2 ? (2 * reach + 1) * (2 * reach + 1) : (2 * reach + 1) * (2 * reach + 1) * (2 * reach + 1);
  l.far = malloc(sizeof(int) * (size_t) l.stride * l.natoms);
  l.len0 = malloc(sizeof(double) * (size_t) l.stride * l.natoms);
  l.weight = kind >= 0 ? malloc(sizeof(double) * (size_t) l.stride * l.natoms) : NULL;
  l.reaction = calloc(4 * (size_t) l.natoms, sizeof(double));
  for (int p = 0; p < l.natoms; p++)
    for (int q = p + 1; q < l.natoms; q++) {
      const double dx = l.x0[3 * q] - l.x0[3 * p], dy = l.x0[3 * q + 1] - l.x0[3 * p + 1],
                   dz = l.x0[3 * q + 2] - l.x0[3 * p + 2];
      const double r = sqrt(dx * dx + dy * dy + dz * dz);
      if (r > delta) continue;
      const int slot = p * l.stride + l.count[p]++;
      l.far[slot] = q;
      l.len0[slot] = r;
      if (l.weight) l.weight[slot] = pd_influence((pd_influence_kind) kind, dim, r, delta);
    }
  return l;
}

void lattice_free(lattice *l)
{
  free(l->x0);
  free(l->vol);
  free(l->type);
  free(l->count);
  free(l->far);
  free(l->len0);
  free(l->weight);
  free(l->reaction);
}

pd_bond_view lattice_view(const lattice *l)
{
  pd_bond_view v = {l->natoms, l->stride, l->count, l->far, l->len0, l->weight, 0.0};
  return v;
}

int lattice_center(const lattice *l)
{
  const int c = l->n / 2;
  const int is2d = l->natoms == l->n * l->n;
  return is2d ? c + l->n * c : c + l->n * (c + l->n * c);
}

void lattice_strain(const lattice *l, double eps[3][3], double *x)
{
  for (int a = 0; a < l->natoms; a++)
    for (int r = 0; r < 3; r++) {
      double u = 0.0;
      for (int c = 0; c < 3; c++) u += eps[r][c] * l->x0[3 * a + c];
      x[3 * a + r] = l->x0[3 * a + r] + u;
    }
}

void rotate(double R[3][3], int n, const double *in, double *out)
{
  for (int a = 0; a < n; a++)
    for (int r = 0; r < 3; r++)
      out[3 * a + r] = R[r][0] * in[3 * a] + R[r][1] * in[3 * a + 1] + R[r][2] * in[3 * a + 2];
}

void rotation_matrix(double ax, double ay, double az, double R[3][3])
{
  const double cx = cos(ax), sx = sin(ax), cy = cos(ay), sy = sin(ay), cz = cos(az), sz = sin(az);
  const double X[3][3] = {{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}};
  const double Y[3][3] = {{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}};
  const double Z[3][3] = {{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}};
  double T[3][3];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      T[i][j] = 0;
      for (int k = 0; k < 3; k++) T[i][j] += Y[i][k] * X[k][j];
    }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      R[i][j] = 0;
      for (int k = 0; k < 3; k++) R[i][j] += Z[i][k] * T[k][j];
    }
}

double urand(unsigned *state)
{
  *state = *state * 1664525u + 1013904223u;
  return (*state >> 8) * (2.0 / 16777216.0) - 1.0;
}
