#include "pd_material_file.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A piece of the file text, by bounds: lines are parsed where they lie, so a
 * line of any length is read whole (no buffer to truncate or split it). */
typedef struct span {
  const char *s;
  size_t n;
} span;

/* The requested block as it is read: what an error message needs to name. */
typedef struct reader {
  const char *name; /* material asked for */
  int line;         /* current line, from 1 */
  int key_line[PD_MATERIAL_MAXKEYS]; /* where each key read was given */
  pd_material *out;
  char *err;
  size_t errlen;
} reader;

/* Keys that must be positive (densities, moduli, energies, stresses). */
static const char *const positive_keys[] = {"density", "E", "K", "G", "Gc", "KIc", "yield", "hardening"};

/* The line starting at *p up to its comment or end; moves *p to the next. */
static span next_line(const char **p)
{
  const char *eol = strchr(*p, '\n');
  const size_t n = eol ? (size_t) (eol - *p) : strlen(*p);
  const char *hash = memchr(*p, '#', n);
  const span line = {*p, hash ? (size_t) (hash - *p) : n};
  *p += eol ? n + 1 : n;
  return line;
}

/* Cuts the line into words (at most 3 kept; 3 means "3 or more"). */
static int split_words(span line, span w[3])
{
  int nw = 0;
  size_t k = 0;
  while (nw < 3) {
    while (k < line.n && isspace((unsigned char) line.s[k])) k++;
    if (k == line.n) break;
    const size_t start = k;
    while (k < line.n && !isspace((unsigned char) line.s[k])) k++;
    w[nw].s = line.s + start;
    w[nw++].n = k - start;
  }
  return nw;
}

static int span_is(span w, const char *s)
{
  return strlen(s) == w.n && memcmp(w.s, s, w.n) == 0;
}

/* Writes "material NAME, line N: " and the message; returns -1. */
static int fail(reader *r, const char *fmt, ...)
{
  const int n = snprintf(r->err, r->errlen, "material %s, line %d: ", r->name, r->line);
  if (n < 0 || (size_t) n >= r->errlen) return -1;
  va_list args;
  va_start(args, fmt);
  vsnprintf(r->err + n, r->errlen - (size_t) n, fmt, args);
  va_end(args);
  return -1;
}

static int check_value(reader *r, const char *key, double v)
{
  for (size_t k = 0; k < sizeof(positive_keys) / sizeof(positive_keys[0]); k++)
    if (strcmp(key, positive_keys[k]) == 0 && !(v > 0.0))
      return fail(r, "%s = %g must be positive (SI units)", key, v);
  if (strcmp(key, "nu") == 0 && !(v > -1.0 && v < 0.5))
    return fail(r, "nu = %g is outside (-1, 1/2)", v);
  return 0;
}

/* The number a value word holds, or -1 with the error written. */
static int parse_value(reader *r, const char *key, span word, span line, double *v)
{
  char *end;
  errno = 0;
  *v = strtod(word.s, &end);
  if (end != word.s + word.n)
    return fail(r, "expected 'key value', got '%.*s'", (int) line.n, line.s);
  /* nan and inf parse; 1e400 overflows to HUGE_VAL with ERANGE (an underflow
   * also sets ERANGE but leaves a tiny value for the range checks). */
  if (!isfinite(*v) || (errno == ERANGE && fabs(*v) > 1.0))
    return fail(r, "%s = %.*s must be a finite number", key, (int) word.n, word.s);
  return 0;
}

/* Index of a key already read, or -1. */
static int key_index(const pd_material *m, const char *key)
{
  for (int k = 0; k < m->nkeys; k++)
    if (strcmp(m->key[k], key) == 0) return k;
  return -1;
}

/* One 'key value' line of the requested block into r->out. */
static int read_pair(reader *r, span line, const span w[3], int nw)
{
  if (nw != 2) return fail(r, "expected 'key value', got '%.*s'", (int) line.n, line.s);
  if (w[0].n >= PD_MATERIAL_KEY)
    return fail(r, "key '%.*s' is longer than %d characters", (int) w[0].n, w[0].s, PD_MATERIAL_KEY - 1);
  char key[PD_MATERIAL_KEY];
  memcpy(key, w[0].s, w[0].n);
  key[w[0].n] = '\0';
  double v;
  if (parse_value(r, key, w[1], line, &v) || check_value(r, key, v)) return -1;
  /* A second value would silently win or lose: refuse it. */
  const int seen = key_index(r->out, key);
  if (seen >= 0) return fail(r, "key %s given twice (first on line %d)", key, r->key_line[seen]);
  pd_material *m = r->out;
  if (m->nkeys == PD_MATERIAL_MAXKEYS) return fail(r, "more than %d keys", PD_MATERIAL_MAXKEYS);
  memcpy(m->key[m->nkeys], key, w[0].n + 1);
  m->value[m->nkeys] = v;
  r->key_line[m->nkeys++] = r->line;
  return 0;
}

int pd_material_find(const char *text, const char *name, pd_material *out, char *err, size_t errlen)
{
  reader r = {name, 0, {0}, out, err, errlen};
  out->nkeys = 0;
  int inside = 0, first = 0; /* first: line of 'material name', 0 if none yet */
  for (const char *p = text; *p;) {
    r.line++;
    const span line = next_line(&p);
    span w[3];
    const int nw = split_words(line, w);
    if (nw == 0) continue;
    if (nw == 2 && span_is(w[0], "material")) {
      inside = span_is(w[1], name);
      /* Read on past the block: a second one of that name makes it ambiguous. */
      if (inside && first) {
        snprintf(err, errlen, "material %s defined twice (lines %d and %d)", name, first, r.line);
        return -1;
      }
      if (inside) first = r.line;
      continue;
    }
    if (nw == 1 && span_is(w[0], "end")) {
      inside = 0;
      continue;
    }
    if (inside && read_pair(&r, line, w, nw)) return -1;
  }
  if (!first) {
    snprintf(err, errlen, "material %s is not in the file", name);
    return -1;
  }
  return 0;
}

double pd_material_get(const pd_material *m, const char *key)
{
  const int k = key_index(m, key);
  return k >= 0 ? m->value[k] : NAN;
}
