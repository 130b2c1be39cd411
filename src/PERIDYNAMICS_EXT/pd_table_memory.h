/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: the storage of fix pd/bonds' per-atom bond tables.

   A table is rows of equal length in one block (row i at table[0] + i x
   the row length), like LAMMPS's memory->create, but in memory that the
   kernel may back with huge pages (core/pd_pages.h): the family build
   writes every table once, and a first touch page by page cost as much as
   the build itself.
------------------------------------------------------------------------- */

#ifndef LMP_PD_TABLE_MEMORY_H
#define LMP_PD_TABLE_MEMORY_H

#include "error.h"

#include <cstdlib>
#include <cstring>

extern "C" {
#include "pd_pages.h"
}

namespace PDTableMemory {

// n values of T in a block of pd_pages, freed with its owner (the family
// build's scratch).
template <typename T> class Block {
 public:
  explicit Block(size_t n) : data(static_cast<T *>(pd_pages_alloc(n * sizeof(T)))) {}
  ~Block() { pd_pages_free(data); }
  Block(const Block &) = delete;
  Block &operator=(const Block &) = delete;
  // room for n values, the first 'keep' kept; false if memory ran out
  bool resize(size_t n, size_t keep)
  {
    T *to = static_cast<T *>(pd_pages_alloc(n * sizeof(T)));
    if (!to) return false;
    if (data && keep) memcpy(to, data, (keep < n ? keep : n) * sizeof(T));
    pd_pages_free(data);
    data = to;
    return true;
  }
  T *data;    // nullptr: out of memory (or n is 0)
};

template <typename T> void destroy(T **&table)
{
  if (table) pd_pages_free(table[0]);
  free(table);
  table = nullptr;
}

// A table of nrows x ncols, its first 'keep' rows (of the same length)
// copied from the old one, the rest uninitialized; none if either count
// is 0.
template <typename T> void grow(LAMMPS_NS::Error *error, T **&table, int nrows, int ncols, int keep, const char *name)
{
  if (nrows <= 0 || ncols <= 0) {
    destroy(table);
    return;
  }
  const size_t row = (size_t) ncols * sizeof(T);
  T *data = static_cast<T *>(pd_pages_alloc((size_t) nrows * row));
  T **rows = static_cast<T **>(malloc((size_t) nrows * sizeof(T *)));
  if (!data || !rows)
    error->one(FLERR, "Fix pd/bonds: out of memory for the bond table {} ({} rows of {} bytes)", name, nrows, row);
  for (int i = 0; i < nrows; i++) rows[i] = data + (size_t) i * ncols;
  if (table && keep > 0) memcpy(data, table[0], (size_t) (keep < nrows ? keep : nrows) * row);
  destroy(table);
  table = rows;
}

// Shorter rows, in place: each keeps its first 'to' of 'from' entries; the
// memory past the new end is given back.
template <typename T> void narrow(T **table, int nrows, int from, int to)
{
  if (!table || to >= from) return;
  for (int i = 1; i < nrows; i++) memmove(table[0] + (size_t) i * to, table[i], (size_t) to * sizeof(T));
  for (int i = 0; i < nrows; i++) table[i] = table[0] + (size_t) i * to;
  pd_pages_shrink(table[0], (size_t) nrows * to * sizeof(T));
}

}    // namespace PDTableMemory

#endif
