/* pd_sum4.h's note lane against pd_note_max, the scalar rule it stands
 * for: value > at ? value : at, so that a NaN value is ignored, a NaN
 * already kept stays, and of +0 and -0 the one kept stays. Built with the
 * core's own flags (CMakeLists.txt), so it checks the path the bond loops
 * take on this machine (AVX-512 masks, AVX's vmaxpd, the generic compare
 * and blend, or plain C). Every pair of special values, in every lane, to
 * the bit; the reactions' lanes of pd_sum4_axpy_note to the bit against
 * r + s a. */
#include "check.h"
#include "pd_sum4.h"

#include <float.h>
#include <math.h>
#include <string.h>

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static double note_max(double at, double value)
{
  pd_note_max(&at, value);
  return at;
}

int main(void)
{
  const double v[] = {NAN, -NAN, 0.0, -0.0, 1.0, -1.0, INFINITY, -INFINITY,
                      DBL_MIN, -DBL_MIN, DBL_MAX, 1e-310, 0.75, 0.7500000000000001};
  const int n = (int) (sizeof v / sizeof v[0]);
  int max_bad = 0, note_bad = 0, sum_bad = 0, cases = 0;
  for (int p = 0; p < n; p++)
    for (int q = 0; q < n; q++)
      for (int lane = 0; lane < 4; lane++) {
        /* (value, at) in one lane, ordinary numbers in the others */
        double val[4] = {2.0, -3.0, 0.5, 7.0}, at[4] = {1.0, 4.0, -0.5, 7.5};
        val[lane] = v[p];
        at[lane] = v[q];
        const pd_sum4 vv = pd_sum4_load(val), av = pd_sum4_load(at);
        const pd_sum4 mx = pd_sum4_max(vv, av);
        for (int c = 0; c < 4; c++)
          max_bad += !same_bits(pd_sum4_lane(mx, c), note_max(at[c], val[c]));
        /* a far end's sum r with a bond's record a = (force, note) */
        const double s = -1.25;
        const pd_sum4 r = pd_sum4_axpy_note(av, s, vv);
        for (int c = 0; c < 3; c++) {
          const double want = at[c] + s * val[c], got = pd_sum4_lane(r, c);
          sum_bad += want != want ? got == got : !same_bits(got, want);
        }
        note_bad += !same_bits(pd_sum4_lane(r, 3), note_max(at[3], val[3]));
        cases++;
      }
  printf("%d cases (%d special values, each pair in each lane)\n", cases, n);
  check_true("pd_sum4_max lane by lane is pd_note_max, to the bit", max_bad == 0);
  check_true("pd_sum4_axpy_note's lane 3 is pd_note_max, to the bit", note_bad == 0);
  check_true("pd_sum4_axpy_note's lanes 0-2 are r + s a, to the bit (NaN as NaN)", sum_bad == 0);
  /* the rule itself: a NaN note never replaces a number, a number never
   * replaces a kept NaN, and -0 does not replace +0 */
  check_true("a NaN note is ignored", note_max(1.0, NAN) == 1.0);
  check_true("a kept NaN stays", isnan(note_max(NAN, 1.0)));
  check_true("-0 does not replace +0", !signbit(note_max(0.0, -0.0)));
  check_true("+0 does not replace -0", signbit(note_max(-0.0, 0.0)));
  return check_summary();
}
