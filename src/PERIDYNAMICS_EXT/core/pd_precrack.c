#include "pd_precrack.h"

static double orient(const double a[2], const double b[2], const double c[2])
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

int pd_crosses_segment(const double p[2], const double q[2], const double a[2], const double b[2])
{
  const double sp = orient(a, b, p), sq = orient(a, b, q);
  if (!((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0))) return 0;
  const double sa = orient(p, q, a), sb = orient(p, q, b);
  return !((sa > 0.0 && sb > 0.0) || (sa < 0.0 && sb < 0.0));
}

static double dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int pd_crosses_patch(const double p[3], const double q[3], const double o[3], const double e1[3],
                     const double e2[3])
{
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
  const double dp[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
  const double dq[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
  const double hp = dot(dp, n), hq = dot(dq, n);
  if (!((hp > 0.0 && hq < 0.0) || (hp < 0.0 && hq > 0.0))) return 0;
  const double t = hp / (hp - hq);
  const double x[3] = {dp[0] + t * (dq[0] - dp[0]), dp[1] + t * (dq[1] - dp[1]),
                       dp[2] + t * (dq[2] - dp[2])};
  /* solve x = u e1 + v e2 in the plane (Gram system) */
  const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
  const double r1 = dot(x, e1), r2 = dot(x, e2), det = g11 * g22 - g12 * g12;
  const double u = (r1 * g22 - r2 * g12) / det, v = (r2 * g11 - r1 * g12) / det;
  return u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0;
}

int pd_crack_crosses(const pd_crack *crack, const double p[3], const double q[3])
{
  return crack->patch ? pd_crosses_patch(p, q, crack->a, crack->b, crack->c)
                      : pd_crosses_segment(p, q, crack->a, crack->b);
}
