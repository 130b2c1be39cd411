#!/usr/bin/env python3
"""The polynomial of pd_log_ratio (src/PERIDYNAMICS_EXT/core/pd_log.h).

log(u / v) = 2 s + s T(z), s = (u - v) / (u + v), z = s^2, |s| <= (sqrt 2 - 1) /
(sqrt 2 + 1); T(z) = z R(z) with R(z) = (2 atanh(s) / s - 2) / z = 2/3 + 2 z/5
+ ... This prints the coefficients of R of degree 6 (a Chebyshev fit on
[0, zmax], near the best uniform approximation) and the fit's worst error
relative to the logarithm. Needs mpmath (Debian: python3-mpmath).
"""
import mpmath as mp

mp.mp.dps = 50
S_MAX = (mp.sqrt(2) - 1) / (mp.sqrt(2) + 1)
Z_MAX = S_MAX ** 2 * mp.mpf("1.0001")    # (the reduction's comparisons round)
DEGREE = 6


def r_of(z):
    if z == 0:
        return mp.mpf(2) / 3
    s = mp.sqrt(z)
    return (2 * mp.atanh(s) / s - 2) / z


poly, err = mp.chebyfit(r_of, [0, Z_MAX], DEGREE + 1, error=True)
print("R(z), constant term first:")
for c in reversed(poly):
    print(f"  {float(c)!r}")
# the logarithm is 2 s (1 + T / 2): an error dR moves it by z dR / 2 of itself
print(f"worst error relative to log(u / v): {mp.nstr(Z_MAX * err / 2, 3)}")
