/* Four doubles as one value: the bond loops' sums onto atoms (pd_bond_loop.h).
 * One 4-wide operation where the compiler has vector types (GCC, clang),
 * four scalar ones otherwise: the same arithmetic either way. Lanes 0-2
 * hold a vector; lane 3 is padding, or a failure law's notes (their
 * maximum, pd_sum4_axpy_note). Loaded from and stored to any 4 doubles. */
#ifndef PD_SUM4_H
#define PD_SUM4_H

#include "pd_macros.h"

#include <string.h>

#if defined(__AVX__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PD_SUM4_AVX 1
#if defined(__AVX512VL__)
#define PD_SUM4_AVX512 1
#endif
#endif

#if defined(__GNUC__) || defined(__clang__)
typedef double pd_sum4 __attribute__((vector_size(32)));
PD_INLINE pd_sum4 pd_sum4_make(double a0, double a1, double a2, double a3)
{
  const pd_sum4 v = {a0, a1, a2, a3};
  return v;
}
/* acc + s a */
PD_INLINE pd_sum4 pd_sum4_axpy4(pd_sum4 acc, double s, pd_sum4 a) { return acc + s * a; }
PD_INLINE pd_sum4 pd_sum4_add(pd_sum4 a, pd_sum4 b) { return a + b; }
/* four 64-bit integers: shuffle indices, compare masks */
typedef long long pd_sum4_lanes __attribute__((vector_size(32)));
/* lanes i0 .. i3 of a and b together (0-3 a's, 4-7 b's) */
#if defined(__clang__)
#define PD_SUM4_SHUFFLE(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#else
#define PD_SUM4_SHUFFLE(a, b, i0, i1, i2, i3) \
  __builtin_shuffle(a, b, (pd_sum4_lanes){i0, i1, i2, i3})
#endif
#else
typedef struct pd_sum4 { double v[4]; } pd_sum4;
PD_INLINE pd_sum4 pd_sum4_make(double a0, double a1, double a2, double a3)
{
  const pd_sum4 v = {{a0, a1, a2, a3}};
  return v;
}
PD_INLINE pd_sum4 pd_sum4_axpy4(pd_sum4 acc, double s, pd_sum4 a)
{
  for (int c = 0; c < 4; c++) acc.v[c] += s * a.v[c];
  return acc;
}
PD_INLINE pd_sum4 pd_sum4_add(pd_sum4 a, pd_sum4 b)
{
  for (int c = 0; c < 4; c++) a.v[c] += b.v[c];
  return a;
}
#endif

/* acc + s (a0, a1, a2, 0) */
PD_INLINE pd_sum4 pd_sum4_axpy(pd_sum4 acc, double s, double a0, double a1, double a2)
{
  return pd_sum4_axpy4(acc, s, pd_sum4_make(a0, a1, a2, 0.0));
}
/* lane c of v */
PD_INLINE double pd_sum4_lane(pd_sum4 v, int c)
{
  double a[4];
  memcpy(a, &v, sizeof a);
  return a[c];
}
PD_INLINE pd_sum4 pd_sum4_load(const double *p)
{
  pd_sum4 v;
  memcpy(&v, p, sizeof v);
  return v;
}
PD_INLINE void pd_sum4_store(double *p, pd_sum4 v) { memcpy(p, &v, sizeof v); }
/* p[0..3] += s (a0, a1, a2, 0) */
PD_INLINE void pd_add4(double *restrict p, double s, double a0, double a1, double a2)
{
  pd_sum4_store(p, pd_sum4_axpy(pd_sum4_load(p), s, a0, a1, a2));
}

/* out[k] = (c[0] lane k, c[1] lane k, c[2] lane k, c[3] lane k): four loads
 * and a transpose (8 shuffles) instead of four loads and inserts each. */
PD_INLINE void pd_sum4_transpose(const pd_sum4 c[4], pd_sum4 out[4])
{
#if defined(PD_SUM4_SHUFFLE)
  /* pairs of lanes 0 and 2, 1 and 3 of c[0], c[1] and of c[2], c[3] */
  const pd_sum4 ab02 = PD_SUM4_SHUFFLE(c[0], c[1], 0, 4, 2, 6);
  const pd_sum4 ab13 = PD_SUM4_SHUFFLE(c[0], c[1], 1, 5, 3, 7);
  const pd_sum4 cd02 = PD_SUM4_SHUFFLE(c[2], c[3], 0, 4, 2, 6);
  const pd_sum4 cd13 = PD_SUM4_SHUFFLE(c[2], c[3], 1, 5, 3, 7);
  out[0] = PD_SUM4_SHUFFLE(ab02, cd02, 0, 1, 4, 5);
  out[1] = PD_SUM4_SHUFFLE(ab13, cd13, 0, 1, 4, 5);
  out[2] = PD_SUM4_SHUFFLE(ab02, cd02, 2, 3, 6, 7);
  out[3] = PD_SUM4_SHUFFLE(ab13, cd13, 2, 3, 6, 7);
#else
  for (int k = 0; k < 4; k++)
    out[k] = pd_sum4_make(pd_sum4_lane(c[0], k), pd_sum4_lane(c[1], k), pd_sum4_lane(c[2], k),
                          pd_sum4_lane(c[3], k));
#endif
}

/* The failure laws' notes combine by their maximum (pd_laws.h): *at
 * becomes value if that is larger (a NaN value is ignored). Without a
 * branch: the notes of an unstrained block differ by round-off, and a
 * branch on them is a coin toss. */
PD_INLINE void pd_note_max(double *at, double value) { *at = value > *at ? value : *at; }

/* Lane by lane pd_note_max: at's lanes, or value's where larger. */
PD_INLINE pd_sum4 pd_sum4_max(pd_sum4 value, pd_sum4 at)
{
#if defined(PD_SUM4_AVX)
  /* (vmaxpd gives its second operand unless the first is larger, NaN and
   * signed zeros alike: the same, in one instruction instead of a compare,
   * a blend and a second load of 'at') */
  return (pd_sum4) _mm256_max_pd((__m256d) value, (__m256d) at);
#elif defined(PD_SUM4_SHUFFLE)
  const pd_sum4_lanes larger = (pd_sum4_lanes) (value > at);
  return (pd_sum4) ((larger & (pd_sum4_lanes) value) | (~larger & (pd_sum4_lanes) at));
#else
  double vv[4], av[4];
  memcpy(vv, &value, sizeof vv);
  memcpy(av, &at, sizeof av);
  for (int c = 0; c < 4; c++) pd_note_max(&av[c], vv[c]);
  memcpy(&at, av, sizeof av);
  return at;
#endif
}

/* Lanes 0-2 r + s a, lane 3 r's and a's pd_note_max: a far end's sum with
 * a bond's reaction and note. */
PD_INLINE pd_sum4 pd_sum4_axpy_note(pd_sum4 r, double s, pd_sum4 a)
{
#if defined(PD_SUM4_AVX512)
  const __m256d R = (__m256d) r, A = (__m256d) a;
  const __m256d sum = _mm256_mask_add_pd(R, 0x7, R, _mm256_mul_pd(_mm256_set1_pd(s), A));
  return (pd_sum4) _mm256_mask_max_pd(sum, 0x8, A, sum);
#elif defined(PD_SUM4_SHUFFLE)
  /* (lane by lane through memory, it was more than half the time of a
   * law that notes, on AVX2) */
  return PD_SUM4_SHUFFLE(r + s * a, pd_sum4_max(a, r), 0, 1, 2, 7);
#else
  double rv[4], av[4];
  memcpy(rv, &r, sizeof rv);
  memcpy(av, &a, sizeof av);
  for (int c = 0; c < 3; c++) rv[c] += s * av[c];
  pd_note_max(&rv[3], av[3]);
  memcpy(&r, rv, sizeof rv);
  return r;
#endif
}

#endif
