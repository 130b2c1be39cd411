#include "pd_failure.h"

#include <math.h>
#include <stdlib.h>

/* (eight running minima side by side: one would make each compare wait
 * for the last, about 4 cycles per atom, a percent of a step) */
double pd_failure_floor(const double *value, int n)
{
  enum { LANES = 8 };
  double lane[LANES];
  for (int l = 0; l < LANES; l++) lane[l] = INFINITY;
  int i = 0;
  for (; i + LANES <= n; i += LANES)
    for (int l = 0; l < LANES; l++) lane[l] = value[i + l] < lane[l] ? value[i + l] : lane[l];
  for (; i < n; i++) lane[0] = value[i] < lane[0] ? value[i] : lane[0];
  double floor = INFINITY;
  for (int l = 0; l < LANES; l++) floor = lane[l] < floor ? lane[l] : floor;
  return floor;
}

int pd_failure_note_fresh(pd_failure *f, int idx)
{
  if (f->nfresh == f->maxfresh) {
    const int room = f->maxfresh ? 2 * f->maxfresh : 256;
    int *grown = (int *) realloc(f->fresh, (size_t) room * sizeof(int));
    if (!grown) return 0;
    f->fresh = grown;
    f->maxfresh = room;
  }
  f->fresh[f->nfresh++] = idx;
  return 1;
}
