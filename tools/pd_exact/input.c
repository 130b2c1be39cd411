#include "input.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int word(char *dst, size_t size, const char *v)
{
  if (strlen(v) >= size) return -1;
  strcpy(dst, v);
  return 0;
}

static int number(double *dst, const char *v)
{
  char *end;
  *dst = strtod(v, &end);
  return (end == v || *end || !isfinite(*dst)) ? -1 : 0;
}

/* One "key value..." line; 1 if the key is unknown, -1 if the value is bad. */
static int parse(exact_input *in, const char *key, char **val, int nval)
{
  const char *v = nval ? val[0] : "";
  if (!nval) return -1;
  struct { const char *name; double *dst; } nums[] = {
      {"spacing", &in->spacing}, {"horizon", &in->horizon}, {"K", &in->K}, {"G", &in->G},
      {"E", &in->E}, {"nu", &in->nu}, {"c", &in->c}, {"density", &in->density},
      {"thickness", &in->thickness}, {"time", &in->time}};
  for (size_t k = 0; k < sizeof(nums) / sizeof(nums[0]); k++)
    if (strcmp(key, nums[k].name) == 0) return nval == 1 ? number(nums[k].dst, v) : -1;
  if (strcmp(key, "lattice") == 0) return word(in->lattice, sizeof in->lattice, v);
  if (strcmp(key, "model") == 0) return word(in->model, sizeof in->model, v);
  if (strcmp(key, "influence") == 0) return word(in->influence, sizeof in->influence, v);
  if (strcmp(key, "plane") == 0) return word(in->plane, sizeof in->plane, v);
  if (strcmp(key, "quadrature") == 0) return word(in->quadrature, sizeof in->quadrature, v);
  if (strcmp(key, "directional_correction") == 0) return word(in->directional, sizeof in->directional, v);
  if (strcmp(key, "fields") == 0) return word(in->fields, sizeof in->fields, v);
  if (strcmp(key, "output") == 0) return word(in->output, sizeof in->output, v);
  if (strcmp(key, "dim") == 0) {
    in->dim = atoi(v);
    return in->dim >= 1 && in->dim <= 3 ? 0 : -1;
  }
  if (strcmp(key, "n") == 0) {
    if (nval > 3) return -1;
    for (int d = 0; d < 3; d++) {
      in->n[d] = atoi(val[d < nval ? d : nval - 1]);
      if (in->n[d] < 1) return -1;
    }
    return 0;
  }
  if (strcmp(key, "origin") == 0) {
    if (nval > 3) return -1;
    for (int d = 0; d < nval; d++)
      if (number(&in->origin[d], val[d])) return -1;
    return 0;
  }
  return 1;
}

int exact_read_input(const char *path, exact_input *in, FILE *err)
{
  memset(in, 0, sizeof(*in));
  in->K = in->G = in->E = in->nu = in->c = in->density = in->horizon = in->spacing = in->time = NAN;
  in->thickness = 1.0;
  FILE *fp = fopen(path, "r");
  if (!fp) {
    fprintf(err, "pd_exact: cannot open input '%s'\n", path);
    return -1;
  }
  char line[2048];
  int lineno = 0, bad = 0;
  while (fgets(line, sizeof line, fp)) {
    lineno++;
    char *hash = strchr(line, '#');
    if (hash) *hash = 0;
    char *tok[8];
    int nt = 0;
    for (char *t = strtok(line, " \t\r\n"); t && nt < 8; t = strtok(NULL, " \t\r\n")) tok[nt++] = t;
    if (!nt) continue;
    const int r = parse(in, tok[0], tok + 1, nt - 1);
    if (r) {
      fprintf(err, "pd_exact: %s:%d: %s '%s'\n", path, lineno,
              r > 0 ? "unknown key" : "bad value for", tok[0]);
      bad = 1;
    }
  }
  fclose(fp);
  /* without fields, only the report (time and output then unused) */
  const char *need[] = {"lattice", "n", "spacing", "model", "density", "time", "output"};
  const int solve = in->fields[0] != 0;
  const int missing[] = {!in->lattice[0], !in->n[0], isnan(in->spacing), !in->model[0],
                         isnan(in->density), solve && isnan(in->time), solve && !in->output[0]};
  for (size_t k = 0; k < sizeof(need) / sizeof(need[0]); k++)
    if (missing[k]) {
      fprintf(err, "pd_exact: %s: missing key '%s'\n", path, need[k]);
      bad = 1;
    }
  return bad ? -1 : 0;
}
