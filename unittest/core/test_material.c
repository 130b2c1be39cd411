/* Material file parsing (the .pd files of potentials/) and the shipped
 * materials. Values read compare exactly (tolerance 0, ==): each is the
 * double nearest its literal, as strtod() and the compiler both round it. */
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

/* before + one line of exactly len characters (start, filler, end) + "\n"
 * + after; a line far longer than any fixed buffer a reader might use. */
static char *with_long_line(const char *before, const char *start, char filler, size_t len,
                            const char *end, const char *after)
{
  const size_t nb = strlen(before), ns = strlen(start), ne = strlen(end), na = strlen(after);
  char *s = malloc(nb + len + 1 + na + 1);
  memcpy(s, before, nb);
  memcpy(s + nb, start, ns);
  memset(s + nb + ns, filler, len - ns - ne);
  memcpy(s + nb + len - ne, end, ne);
  s[nb + len] = '\n';
  memcpy(s + nb + len + 1, after, na + 1);
  return s;
}

/* find() fails and its message contains every one of the given pieces. */
static int refused(const char *text, const char *name, const char *piece1, const char *piece2)
{
  pd_material m;
  char err[512] = "";
  const int ok = pd_material_find(text, name, &m, err, sizeof err) == -1 && strstr(err, piece1) &&
                 (!piece2 || strstr(err, piece2));
  if (!ok) printf("     message was: %s\n", err);
  return ok;
}

static void test_basics(void)
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
  check_true("negative modulus refused, with material and line",
             refused(text, "B", "material B, line 7: E = -5e+09 must be positive", NULL));
  check_true("malformed line refused",
             pd_material_find(text, "C", &m, err, sizeof err) == -1 && strstr(err, "expected 'key value'"));
  check_true("Poisson's ratio out of range refused",
             pd_material_find(text, "D", &m, err, sizeof err) == -1 && strstr(err, "nu = 0.7"));
  /* documented: a block also ends at the next 'material' line */
  const char *open = "material P\n  E 1e9\nmaterial Q\n  E 2e9\n  nu 0.2\nend\n";
  const int p_ok = pd_material_find(open, "P", &m, err, sizeof err) == 0;
  check_true("block without 'end' stops at the next material (P: E only)",
             p_ok && pd_material_get(&m, "E") == 1e9 && m.nkeys == 1);
  const int q_ok = pd_material_find(open, "Q", &m, err, sizeof err) == 0;
  check_true("block after one without 'end' is read (Q: E, nu)",
             q_ok && pd_material_get(&m, "E") == 2e9 && pd_material_get(&m, "nu") == 0.2);
}

/* Lines of 2000 characters, 4x the 512-byte buffer the reader once had: a
 * split line would parse its tail as a line of its own and shift the line
 * numbers after it. */
static void test_long_lines(void)
{
  pd_material m;
  char err[512];
  char *comment = with_long_line("material L\n  nu 0.3\n", "# ", 'x', 2000, " E 1e6", "end\n");
  const int ok = pd_material_find(comment, "L", &m, err, sizeof err) == 0;
  check_true("2000-character comment ending in 'E 1e6' does not set E",
             ok && isnan(pd_material_get(&m, "E")) && pd_material_get(&m, "nu") == 0.3);
  free(comment);
  char *spaced = with_long_line("material L\n", "  density", ' ', 2000, "1000", "end\n");
  const int read = pd_material_find(spaced, "L", &m, err, sizeof err) == 0;
  check_true("2000-character 'density ... 1000' line is read whole",
             read && pd_material_get(&m, "density") == 1000.0 && m.nkeys == 1);
  free(spaced);
  char *after = with_long_line("material L\n", "# ", 'x', 2000, "", "  E -1\nend\n");
  check_true("error on the line after a 2000-character line reports line 3",
             refused(after, "L", "material L, line 3: E = -1 must be positive", NULL));
  free(after);
  char *key = with_long_line("material L\n", "k", 'k', 42, " 1", "  E 1e9\nend\n");
  check_true("40-character key refused (keys hold 31)",
             refused(key, "L", "material L, line 2: key 'kkkk", "longer than 31 characters"));
  free(key);
}

static void test_duplicates(void)
{
  const char *key = "material K\n  E 1e9\n  nu 0.3\n  E 2e9\nend\n";
  check_true("key given twice in a block refused (material, line, key)",
             refused(key, "K", "material K, line 4: key E given twice (first on line 2)", NULL));
  const char *block = "material A\n  E 1e9\nend\nmaterial B\n  E 2e9\nend\n"
                      "# again\nmaterial A\n  E 3e9\nend\n";
  check_true("material block named twice refused at the second",
             refused(block, "A", "material A defined twice (lines 1 and 8)", NULL));
  pd_material m;
  char err[256];
  check_true("a block named once is read although another name repeats",
             pd_material_find(block, "B", &m, err, sizeof err) == 0 && pd_material_get(&m, "E") == 2e9);
}

/* strtod() reads nan, inf and (overflowing) 1e400 as numbers; horizon has
 * no range check, so only the finiteness check can refuse them there. */
static void test_non_finite(void)
{
  const char *values[] = {"inf", "nan", "1e400", "-INF", "-1e400"};
  for (int k = 0; k < 5; k++) {
    char text[128], piece[96], what[96];
    snprintf(text, sizeof text, "material N\n  E 1e9\n  horizon %s  # m\nend\n", values[k]);
    snprintf(piece, sizeof piece, "material N, line 3: horizon = %s must be a finite number", values[k]);
    snprintf(what, sizeof what, "non-finite value %s refused", values[k]);
    check_true(what, refused(text, "N", piece, NULL));
  }
}

/* The shipped file: every required material present with elastic data. */
static void test_shipped(void)
{
  pd_material m;
  char err[256];
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
    if (!ok) printf("     message was: %s\n", err);
  }
  free(file);
}

int main(void)
{
  test_basics();
  test_long_lines();
  test_duplicates();
  test_non_finite();
  test_shipped();
  return check_summary();
}
