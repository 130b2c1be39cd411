#include "pd_failure.h"

#include <math.h>
#include <stdlib.h>

double pd_failure_floor(const double *value, int n)
{
  double floor = INFINITY;
  for (int i = 0; i < n; i++) floor = value[i] < floor ? value[i] : floor;
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
