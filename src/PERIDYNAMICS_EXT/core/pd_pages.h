/* Large blocks of memory that the kernel may back with huge pages.
 *
 * The first touch of a 4 kB page is a page fault; on the virtual machines
 * we measure on it costs 10-13 us (0.3 us per 4 kB with huge pages), and
 * the bond tables of a 16^3 block (1000 pages) took as long to fault in as
 * to build. On Linux a block of at least 256 KiB is mapped on its own,
 * aligned to and rounded up to whole huge pages (2 MiB; at most that much
 * more than asked for) and marked MADV_HUGEPAGE: where transparent huge
 * pages are on ('always' or 'madvise', the common settings) it faults in
 * once per 2 MiB. Elsewhere, and for smaller blocks, it is heap memory.
 * Either way a block is 64-byte aligned and uninitialized. */
#ifndef PD_PAGES_H
#define PD_PAGES_H

#include <stddef.h>

/* NULL if memory ran out (or bytes is 0). */
void *pd_pages_alloc(size_t bytes);

/* Gives back the whole pages past the first 'bytes' of a mapped block,
 * keeping its start (a heap block stays as it is). */
void pd_pages_shrink(void *p, size_t bytes);

/* Gives back the memory of the whole huge pages within the first 'bytes'
 * of a mapped block (past its first page), whose contents the caller no
 * longer reads: a block read once from start to end (the family build's
 * candidate lists) shrinks from the front as the tables it fills grow.
 * The block stays valid; the pages read as zeros if touched again. A heap
 * block is left as it is. */
void pd_pages_release(void *p, size_t bytes);

/* Frees a block of pd_pages_alloc (NULL: nothing). */
void pd_pages_free(void *p);

/* 1 if a block of this size is mapped on its own, with the hint. */
int pd_pages_mapped(size_t bytes);

#endif
