#include "pd_material_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Keys that must be positive (densities, moduli, energies, stresses). */
static const char *const positive_keys[] = {"density", "E", "K", "G", "Gc", "KIc", "yield", "hardening"};

static int check_value(const char *key, double v, char *err, size_t errlen, const char *name, int line)
{
  for (size_t k = 0; k < sizeof(positive_keys) / sizeof(positive_keys[0]); k++)
    if (strcmp(key, positive_keys[k]) == 0 && !(v > 0.0)) {
      snprintf(err, errlen, "material %s, line %d: %s = %g must be positive (SI units)", name, line, key, v);
      return -1;
    }
  if (strcmp(key, "nu") == 0 && !(v > -1.0 && v < 0.5)) {
    snprintf(err, errlen, "material %s, line %d: nu = %g is outside (-1, 1/2)", name, line, v);
    return -1;
  }
  return 0;
}

int pd_material_find(const char *text, const char *name, pd_material *out, char *err, size_t errlen)
{
  out->nkeys = 0;
  int inside = 0, found = 0, lineno = 0;
  const char *p = text;
  while (*p) {
    const char *eol = strchr(p, '\n');
    size_t n = eol ? (size_t) (eol - p) : strlen(p);
    char line[512];
    if (n >= sizeof line) n = sizeof line - 1;
    memcpy(line, p, n);
    line[n] = '\0';
    p += eol ? n + 1 : n;
    lineno++;
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char w1[PD_MATERIAL_KEY + 1], w2[128], w3[8];
    const int nw = sscanf(line, "%32s %127s %7s", w1, w2, w3);
    if (nw <= 0) continue;
    if (strcmp(w1, "material") == 0 && nw == 2) {
      if (inside) break;
      inside = strcmp(w2, name) == 0;
      found |= inside;
      continue;
    }
    if (strcmp(w1, "end") == 0 && nw == 1) {
      if (inside) break;
      continue;
    }
    if (!inside) continue;
    char *endp;
    const double v = strtod(w2, &endp);
    if (nw != 2 || *endp != '\0') {
      snprintf(err, errlen, "material %s, line %d: expected 'key value', got '%s'", name, lineno, line);
      return -1;
    }
    if (check_value(w1, v, err, errlen, name, lineno)) return -1;
    if (out->nkeys == PD_MATERIAL_MAXKEYS) {
      snprintf(err, errlen, "material %s: more than %d keys", name, PD_MATERIAL_MAXKEYS);
      return -1;
    }
    snprintf(out->key[out->nkeys], PD_MATERIAL_KEY, "%s", w1);
    out->value[out->nkeys++] = v;
  }
  if (!found) {
    snprintf(err, errlen, "material %s is not in the file", name);
    return -1;
  }
  return 0;
}

double pd_material_get(const pd_material *m, const char *key)
{
  for (int k = 0; k < m->nkeys; k++)
    if (strcmp(m->key[k], key) == 0) return m->value[k];
  return NAN;
}
