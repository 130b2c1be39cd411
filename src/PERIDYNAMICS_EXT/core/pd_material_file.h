/* Material files (the .pd files of potentials/): blocks 'material NAME' ...
 * 'end' of 'key value' lines in SI units, '#' comments; lines of any length. */
#ifndef PD_MATERIAL_FILE_H
#define PD_MATERIAL_FILE_H

#include <stddef.h>

#define PD_MATERIAL_KEY 32
#define PD_MATERIAL_MAXKEYS 32

typedef struct pd_material {
  int nkeys;
  char key[PD_MATERIAL_MAXKEYS][PD_MATERIAL_KEY];
  double value[PD_MATERIAL_MAXKEYS];
} pd_material;

/* Find material 'name' in the file text. Returns 0 and fills *out, or -1
 * with a message in err naming the material and, for a line of its block,
 * the line number: material not found, a second block of that name,
 * malformed line, a key longer than PD_MATERIAL_KEY - 1 characters or given
 * twice, a value that is not a finite number (nan, inf, overflow), or a
 * value without physical sense (negative or zero density or modulus,
 * Poisson's ratio outside (-1, 1/2)). Other blocks are not checked. */
int pd_material_find(const char *text, const char *name, pd_material *out, char *err, size_t errlen);

/* Value of a key, or NaN when the material does not give it. */
double pd_material_get(const pd_material *m, const char *key);

#endif
