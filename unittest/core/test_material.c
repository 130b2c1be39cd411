/* Material file parsing (potentials/*.pd) and the shipped materials. */
#include "check.h"
#include "pd_material_file.h"

#include <stdlib.h>
#include <string.h>

static char *slurp(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  const long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *s = malloc(n + 1);
  s[fread(s, 1, n, f)] = '\0';
  fclose(f);
  return s;
}

int main(void)
{
  const char *text = "# test file\n"
                     "material A   # first\n  E 1e9  # source\n  nu 0.3\nend\n"
                     "material B\n  E -5e9\nend\n"
                     "material C\n  E 2e9 3\nend\n"
                     "material D\n  nu 0.7\nend\n";
  pd_material m;
  char err[256];
  check_true("material A found", pd_material_find(text, "A", &m, err, sizeof err) == 0);
  check_rel("material A: E", pd_material_get(&m, "E"), 1e9, 0);
  check_rel("material A: nu", pd_material_get(&m, "nu"), 0.3, 0);
  check_true("material A: absent key is NaN", isnan(pd_material_get(&m, "Gc")));
  check_true("missing material named in the error",
             pd_material_find(text, "Z", &m, err, sizeof err) == -1 && strstr(err, "Z is not in the file"));
  check_true("negative modulus refused",
             pd_material_find(text, "B", &m, err, sizeof err) == -1 && strstr(err, "E = -5e+09 must be positive"));
  check_true("malformed line refused",
             pd_material_find(text, "C", &m, err, sizeof err) == -1 && strstr(err, "expected 'key value'"));
  check_true("Poisson's ratio out of range refused",
             pd_material_find(text, "D", &m, err, sizeof err) == -1 && strstr(err, "nu = 0.7"));
  /* the shipped file: every required material present with elastic data */
  char *file = slurp(PD_MATERIALS_FILE);
  check_true("potentials/materials.pd readable", file != NULL);
  const char *names[] = {"PMMA", "maraging_steel", "soda_lime_glass", "Al6061_T6", "OFHC_copper"};
  for (int k = 0; file && k < 5; k++) {
    const int ok = pd_material_find(file, names[k], &m, err, sizeof err) == 0;
    const int elastic = (!isnan(pd_material_get(&m, "E")) && !isnan(pd_material_get(&m, "nu"))) ||
                        (!isnan(pd_material_get(&m, "K")) && !isnan(pd_material_get(&m, "G")));
    char what[96];
    snprintf(what, sizeof what, "shipped material %s has density and elastic constants", names[k]);
    check_true(what, ok && elastic && pd_material_get(&m, "density") > 0.0);
  }
  free(file);
  return check_summary();
}
