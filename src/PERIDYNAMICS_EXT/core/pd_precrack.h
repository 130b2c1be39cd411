/* Pre-cracks: does a bond (its reference segment) cross a crack? */
#ifndef PD_PRECRACK_H
#define PD_PRECRACK_H

/* 2D: the bond p-q crosses the crack segment a-b when p and q lie strictly
 * on opposite sides of the crack's line and the crack's ends are not both
 * strictly on one side of the bond's line. Coordinates: x, y. */
int pd_crosses_segment(const double p[2], const double q[2], const double a[2], const double b[2]);

/* 3D: the bond p-q crosses the parallelogram o + u e1 + v e2 (u, v in
 * [0, 1]) when p and q lie strictly on opposite sides of its plane and the
 * crossing point lies in the parallelogram. */
int pd_crosses_patch(const double p[3], const double q[3], const double o[3], const double e1[3],
                     const double e2[3]);

/* A crack: a 2D segment a-b (patch 0; x, y used), or a 3D parallelogram
 * a + u b + v c with u, v in [0, 1] (patch 1). */
typedef struct pd_crack {
  int patch;
  double a[3], b[3], c[3];
} pd_crack;

/* Does the bond p-q cross the crack? */
int pd_crack_crosses(const pd_crack *crack, const double p[3], const double q[3]);

#endif
