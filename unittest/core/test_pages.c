/* Large blocks (pd_pages.h): every size gives 64-byte aligned memory that
 * holds what is written to it; blocks of 256 KiB and more are, on Linux,
 * mapped on their own, aligned to a huge page and eligible for huge pages
 * (the kernel's own word, /proc/self/smaps, where transparent huge pages
 * are on); shrinking keeps a block's start; releasing a block's front
 * gives its whole huge pages back (mincore: no longer resident) and keeps
 * the rest. */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* mincore under -std=c11 */
#endif
#include "check.h"
#include "pd_pages.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

#define HUGE_PAGE ((uintptr_t) 2 << 20)

/* the byte written at offset k of a block: not constant, not periodic in
 * 4 kB pages */
static unsigned char pattern(size_t k) { return (unsigned char) ((k * 2654435761u) >> 13); }

static int fill_and_check(unsigned char *p, size_t bytes)
{
  for (size_t k = 0; k < bytes; k++) p[k] = pattern(k);
  for (size_t k = 0; k < bytes; k++)
    if (p[k] != pattern(k)) return 0;
  return 1;
}

/* The kernel's THPeligible of the mapping that holds p: 1 or 0, -1 if
 * /proc/self/smaps does not say (not Linux, or an older kernel). */
static int huge_page_eligible(const void *p)
{
  FILE *f = fopen("/proc/self/smaps", "r");
  if (!f) return -1;
  char line[512];
  int inside = 0, eligible = -1;
  while (fgets(line, sizeof line, f)) {
    unsigned long lo, hi;
    char dash;
    if (sscanf(line, "%lx%c%lx", &lo, &dash, &hi) == 3 && dash == '-') {
      if (inside) break;
      inside = (uintptr_t) p >= lo && (uintptr_t) p < hi;
    } else if (inside && strncmp(line, "THPeligible:", 12) == 0) {
      eligible = atoi(line + 12);
    }
  }
  fclose(f);
  return eligible;
}

#ifdef __linux__
/* how many of the 4 kB pages of [p, p + bytes) are resident (p page-aligned) */
static size_t resident_pages(void *p, size_t bytes)
{
  const size_t page = (size_t) sysconf(_SC_PAGESIZE), n = (bytes + page - 1) / page;
  unsigned char *in = malloc(n);
  size_t count = 0;
  if (in && mincore(p, bytes, in) == 0)
    for (size_t k = 0; k < n; k++) count += in[k] & 1;
  free(in);
  return count;
}
#endif

/* 1 if transparent huge pages are 'always' or 'madvise' here */
static int huge_pages_on(void)
{
  FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
  if (!f) return 0;
  char line[128] = "";
  const int got = fgets(line, sizeof line, f) != NULL;
  fclose(f);
  return got && (strstr(line, "[always]") || strstr(line, "[madvise]"));
}

int main(void)
{
  const size_t sizes[] = {1, 100, 4096, 65536, 262143, 262144, 1000000, 2097152, 3145735};
  const int nsize = (int) (sizeof sizes / sizeof sizes[0]);
  int checked_eligible = 0;
  for (int s = 0; s < nsize; s++) {
    const size_t bytes = sizes[s];
    char what[128];
    unsigned char *p = pd_pages_alloc(bytes);
    snprintf(what, sizeof what, "%zu bytes: a block, 64-byte aligned, holds what is written", bytes);
    check_true(what, p && (uintptr_t) p % 64 == 0 && fill_and_check(p, bytes));
#ifdef __linux__
    snprintf(what, sizeof what, "%zu bytes: mapped on its own from 256 KiB on", bytes);
    check_true(what, pd_pages_mapped(bytes) == (bytes >= 262144));
    if (pd_pages_mapped(bytes)) {
      /* the block (and its 64-byte header) starts on a huge page */
      snprintf(what, sizeof what, "%zu bytes: the mapping starts on a 2 MiB boundary", bytes);
      check_true(what, ((uintptr_t) p - 64) % HUGE_PAGE == 0);
      const int eligible = huge_page_eligible(p);
      if (huge_pages_on() && eligible >= 0) {
        snprintf(what, sizeof what, "%zu bytes: the kernel may back it with huge pages (THPeligible)", bytes);
        check_true(what, eligible == 1);
        checked_eligible++;
      }
    }
#endif
    pd_pages_free(p);
  }
  if (!checked_eligible) printf("(huge pages off, or not reported here: THPeligible not checked)\n");

  /* shrinking keeps the start's contents, and the block stays usable */
  const size_t big = 5u << 20, kept = 1u << 20;
  unsigned char *p = pd_pages_alloc(big);
  check_true("5 MiB block", p && fill_and_check(p, big));
  pd_pages_shrink(p, kept);
  int same = 1;
  for (size_t k = 0; k < kept; k++) same &= p[k] == pattern(k);
  check_true("shrunk to 1 MiB: its first 1 MiB unchanged", same);
  check_true("shrunk to 1 MiB: still writable", fill_and_check(p, kept));
  pd_pages_shrink(p, kept); /* again: nothing to give back */
  pd_pages_free(p);

  /* releasing the front of a 10 MiB block read once: the whole 2 MiB pages
   * below 7 MiB (past the header's first) go, the rest stays as written */
  const size_t block = 10u << 20, done = 7u << 20;
  unsigned char *q = pd_pages_alloc(block);
  check_true("10 MiB block", q && fill_and_check(q, block));
  pd_pages_release(q, done);
  int rest = 1;
  for (size_t k = done; k < block; k++) rest &= q[k] == pattern(k);
  check_true("released its first 7 MiB: the rest unchanged", rest);
#ifdef __linux__
  if (pd_pages_mapped(block)) {
    unsigned char *base = q - 64;
    check_true("released its first 7 MiB: the 2 MiB pages from 2 to 6 MiB no longer resident",
               resident_pages(base + HUGE_PAGE, 2 * HUGE_PAGE) == 0);
    check_true("released its first 7 MiB: the first page (its header) and the pages from 6 MiB resident",
               resident_pages(base, 4096) == 1 && resident_pages(base + 3 * HUGE_PAGE, 4096) == 1);
  }
#endif
  pd_pages_release(q, done); /* again: nothing more to give back */
  pd_pages_release(q, block);
  pd_pages_free(q);

  check_true("0 bytes: none", pd_pages_alloc(0) == NULL);
  check_true("more than the address space: none", pd_pages_alloc(SIZE_MAX / 2) == NULL);
  pd_pages_free(NULL);
  pd_pages_shrink(NULL, 0);
  pd_pages_release(NULL, 0);
  return check_summary();
}
