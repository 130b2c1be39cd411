/* Large blocks that the kernel may back with huge pages (pd_pages.h). */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS and MADV_HUGEPAGE under -std=c11 */
#endif
#include "pd_pages.h"

#include <stdint.h>
#include <stdlib.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define PD_PAGES_MAP 1
#else
#define PD_PAGES_MAP 0
#endif

#define HUGE_PAGE ((size_t) 2 << 20)
#define SMALL_PAGE ((size_t) 4096)
/* The header before the caller's bytes: where the block begins and, for
 * a mapped block, its length (0: heap). 64 bytes keep the caller's part
 * aligned to a cache line. */
#define HEADER ((size_t) 64)

typedef struct block_header {
  void *base;
  size_t length;
  size_t released; /* pd_pages_release: the pages below are given back */
} block_header;

static size_t round_up(size_t n, size_t to) { return (n + to - 1) / to * to; }

static block_header *header_of(void *p) { return (block_header *) ((char *) p - HEADER); }

int pd_pages_mapped(size_t bytes)
{
  return PD_PAGES_MAP && bytes >= HUGE_PAGE / 8 && bytes <= SIZE_MAX / 4;
}

#if PD_PAGES_MAP
static void *map_block(size_t bytes)
{
  const size_t length = round_up(bytes + HEADER, HUGE_PAGE);
  /* a huge page more than asked for, to cut an aligned block out of */
  char *map = mmap(NULL, length + HUGE_PAGE, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (map == MAP_FAILED) return NULL;
  char *start = (char *) round_up((uintptr_t) map, HUGE_PAGE);
  if (start > map) munmap(map, (size_t) (start - map));
  const size_t after = (size_t) (map + length + HUGE_PAGE - (start + length));
  if (after) munmap(start + length, after);
  madvise(start, length, MADV_HUGEPAGE); /* a hint: without huge pages, 4 kB pages */
  block_header *h = (block_header *) start;
  h->base = start;
  h->length = length;
  h->released = 0;
  return start + HEADER;
}
#endif

void *pd_pages_alloc(size_t bytes)
{
  if (bytes == 0 || bytes > SIZE_MAX / 4) return NULL;
#if PD_PAGES_MAP
  if (pd_pages_mapped(bytes)) {
    void *p = map_block(bytes);
    if (p) return p;
  }
#endif
  /* a header's room and an alignment's slack */
  char *base = malloc(bytes + 2 * HEADER);
  if (!base) return NULL;
  char *p = (char *) round_up((uintptr_t) base + HEADER, HEADER);
  block_header *h = header_of(p);
  h->base = base;
  h->length = 0;
  h->released = 0;
  return p;
}

void pd_pages_shrink(void *p, size_t bytes)
{
#if PD_PAGES_MAP
  if (!p) return;
  block_header *h = header_of(p);
  const size_t keep = round_up(bytes + HEADER, SMALL_PAGE);
  if (h->length == 0 || keep >= h->length) return;
  munmap((char *) h->base + keep, h->length - keep);
  h->length = keep;
#else
  (void) p;
  (void) bytes;
#endif
}

void pd_pages_release(void *p, size_t bytes)
{
#if PD_PAGES_MAP
  if (!p) return;
  block_header *h = header_of(p);
  if (h->length == 0) return;
  /* the whole huge pages below the caller's end, past the header's */
  size_t end = ((size_t) ((char *) p - (char *) h->base) + bytes) / HUGE_PAGE * HUGE_PAGE;
  if (end > h->length) end = h->length;
  const size_t begin = h->released > HUGE_PAGE ? h->released : HUGE_PAGE;
  if (end <= begin) return;
  madvise((char *) h->base + begin, end - begin, MADV_DONTNEED);
  h->released = end;
#else
  (void) p;
  (void) bytes;
#endif
}

void pd_pages_free(void *p)
{
  if (!p) return;
  block_header *h = header_of(p);
#if PD_PAGES_MAP
  if (h->length) {
    munmap(h->base, h->length);
    return;
  }
#endif
  free(h->base);
}
