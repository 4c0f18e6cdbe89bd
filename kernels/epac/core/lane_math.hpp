#pragma once
// exp, acos and 2 asin(sqrt x) as straight-line arithmetic, for loops the host compiler vectorises (contacts in
// lanes): a call to libm's exp or acos keeps a loop scalar (g++ takes glibc's vector forms only
// under -ffast-math). Both are also what GPUs and the one-contact code run where a value must
// have the lanes' bits (models/mdr/mdr_contact_penalty.hpp). Double precision; a float argument
// is computed in double and rounded once.
// Accuracy against glibc (tests/core/test_lane_math.cpp, 3e6 arguments each): lane_exp within
// 1 ulp, lane_acos and lane_two_asin_sqrt within 2 ulp.
#include <epac/core/kokkos_compat.hpp>
#include <epac/core/simd_lanes.hpp>

#include <cstdint>
#include <cstring>

namespace epac {

// e^x. Domain: every double. Below -708 the result is 0 (the true value is below 3.3e-308, the
// normal range's end: subnormals are not produced), above 709 +inf (e^709.78 overflows), NaN stays
// NaN. Cody-Waite reduction x = k ln2 + r, |r| <= ln2/2, with k rounded by the 1.5 * 2^52 shifter
// (no conversion instruction: k's bits are the shifted sum's low bits), e^r by its Taylor series
// through r^13 (the next term is below 4e-18 of the sum), 2^k built in the exponent field.
KOKKOS_FORCEINLINE_FUNCTION double lane_exp(double x) {
  const double log2e = 1.4426950408889634074;
  const double ln2_hi = 6.93147180369123816490e-01;  // 32 significant bits: k * ln2_hi is exact for |k| < 2^20
  const double ln2_lo = 1.90821492927058770002e-10;
  const double shifter = 6755399441055744.0;  // 1.5 * 2^52
  // clamped: k stays in [-1022, 1023], where 2^k is a normal number (the selects below give the ends)
  const double xc = lane_select(x < -708.0, -708.0, lane_select(x > 709.0, 709.0, x));
  const double t = xc * log2e + shifter;  // the shifter rounds xc log2e to an integer k in its low bits
  const double k = t - shifter;
  const double r = (xc - k * ln2_hi) - k * ln2_lo;
  // a chain of about 6 operations instead of Horner's 13, for loops whose blocks are bound by
  // their chains' latency
  // e^r = 1 + (r + r^2 q(r)), the small tail q by Estrin's scheme
  const double r2 = r * r, r4 = r2 * r2;
  const double c23 = 0.5 + r * (1.0 / 6.0), c45 = 1.0 / 24.0 + r * (1.0 / 120.0),
               c67 = 1.0 / 720.0 + r * (1.0 / 5040.0), c89 = 1.0 / 40320.0 + r * (1.0 / 362880.0),
               c1011 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0), c1213 = 1.0 / 479001600.0 + r * (1.0 / 6227020800.0);
  const double c27 = c23 + r2 * (c45 + r2 * c67), c813 = c89 + r2 * (c1011 + r2 * c1213);
  const double q = c27 + (r4 * r2) * c813;
  const double p = 1.0 + (r + r2 * q);
  std::uint64_t tb;
  memcpy(&tb, &t, sizeof(double));
  // t's bits are those of 1.5 * 2^52 plus k: subtracting them leaves k (two's complement)
  const std::uint64_t bits = (tb - std::uint64_t(0x4338000000000000ull) + std::uint64_t(1023)) << 52;
  double scale;
  memcpy(&scale, &bits, sizeof(double));
  const std::uint64_t inf_bits = 0x7ff0000000000000ull;
  double inf;
  memcpy(&inf, &inf_bits, sizeof(double));
  return lane_select(x < -708.0, 0.0, lane_select(x > 709.0, inf, p * scale));
}
KOKKOS_FORCEINLINE_FUNCTION float lane_exp(float x) { return float(lane_exp(double(x))); }

// fdlibm's rational approximation R(z) of asin(s)/s - 1 in z = s^2 (e_asin.c, e_acos.c), for
// z in [0, 1/2]: lane_acos and lane_two_asin_sqrt. One division, by a denominator >= 0.5 there.
KOKKOS_FORCEINLINE_FUNCTION double lane_asin_rational(double z) {
  const double pS0 = 1.66666666666666657415e-01, pS1 = -3.25565818622400915405e-01, pS2 = 2.01212532134862925881e-01,
               pS3 = -4.00555345006794114027e-02, pS4 = 7.91534994289814532176e-04, pS5 = 3.47933107596021167570e-05;
  const double qS1 = -2.40339491173441421878e+00, qS2 = 2.02094576023350569471e+00, qS3 = -6.88283971605453293030e-01,
               qS4 = 7.70381505559019352791e-02;
  const double num = z * (pS0 + z * (pS1 + z * (pS2 + z * (pS3 + z * (pS4 + z * pS5)))));
  const double den = 1.0 + z * (qS1 + z * (qS2 + z * (qS3 + z * qS4)));  // >= 0.5 on [0, 1/2]
  return num / den;
}

// acos(x) in [0, pi]. Domain: [-1, 1]; x is clamped into it first (acos_clamped's guard: a cosine
// formed from rounded lengths can leave it by an ulp). fdlibm's rational approximation of
// asin(s)/s - 1 in s^2 (e_acos.c): |x| < 1/2 from pi/2 - asin(x), |x| >= 1/2 from
// 2 asin(sqrt((1 - |x|)/2)); the branches are selects (one square root and one division, both
// of operands >= 0 and >= 0.5 respectively). Without fdlibm's split of the square root: 2 ulp.
KOKKOS_FORCEINLINE_FUNCTION double lane_acos(double x) {
  const double pi = 3.14159265358979311600e+00;
  const double pio2_hi = 1.57079632679489655800e+00, pio2_lo = 6.12323399573676603587e-17;
  const double xc = lane_select(x < -1.0, -1.0, lane_select(x > 1.0, 1.0, x));  // NaN passes through
  const double ax = lane_select(xc < 0.0, -xc, xc);
  const bool small = ax < 0.5;
  const double z = lane_select(small, xc * xc, (1.0 - ax) * 0.5);  // in [0, 1/2]
  const double R = lane_asin_rational(z);
  const double s = math::sqrt(z);                              // z >= 0
  const double a_small = pio2_hi - (xc - (pio2_lo - xc * R));  // pi/2 - asin(x)
  const double a_pos = 2.0 * (s + s * R);                      // x >= 1/2: 2 asin(s)
  const double a_neg = pi - 2.0 * (s + (s * R - pio2_lo));     // x <= -1/2: pi - 2 asin(s)
  return lane_select(small, a_small, lane_select(xc < 0.0, a_neg, a_pos));
}
KOKKOS_FORCEINLINE_FUNCTION float lane_acos(float x) { return float(lane_acos(double(x))); }

// 2 asin(sqrt(x)) = acos(1 - 2x), x in [0, 1], given sx = sqrt(x) and s1x = sqrt(1 - x), which
// the callers have (the MDR ellipse's angle, models/mdr/detail/mdr_ellipse.hpp): no root of its
// own, and no libm call, so that the same source runs in lanes. lane_acos's rational R(z) in one of
// three arguments, selected (one division):
//   x < 1/4:         2 asin(sx) = 2 (sx + sx R(x))        (fdlibm's asin, |sx| < 1/2, z = sx^2 = x)
//   1/4 <= x <= 3/4: acos(c), c = 1 - 2x, exact there (Sterbenz) and |c| <= 1/2: pi/2 - (c + c R(c^2))
//   x > 3/4:         pi - 2 asin(s1x) = pi - 2 (s1x + s1x R(1 - x)), 1 - x exact
// Unlike acos(1 - 2x) it keeps full precision for small x (1 - 2x would round x away). Domain:
// x is clamped into [0, 1] (NaN passes through); sx and s1x are the caller's roots of the clamped
// x. Within 2 ulp of 2 asin(sqrt x) (tests/core/test_lane_math.cpp).
KOKKOS_FORCEINLINE_FUNCTION double lane_two_asin_sqrt(double x, double sx, double s1x) {
  const double pi = 3.14159265358979311600e+00;
  const double pio2_hi = 1.57079632679489655800e+00, pio2_lo = 6.12323399573676603587e-17;
  const double xc = lane_select(x < 0.0, 0.0, lane_select(x > 1.0, 1.0, x));  // NaN passes through
  const bool low = xc < 0.25;
  const bool high = xc > 0.75;
  const double c = 1.0 - 2.0 * xc;
  const double z = lane_select(low, xc, lane_select(high, 1.0 - xc, c * c));  // in [0, 1/4]
  const double R = lane_asin_rational(z);
  const double a_low = 2.0 * (sx + sx * R);
  const double a_mid = pio2_hi - (c - (pio2_lo - c * R));
  const double a_high = pi - 2.0 * (s1x + (s1x * R - pio2_lo));
  return lane_select(low, a_low, lane_select(high, a_high, a_mid));
}
// float: computed in double from the float roots (their rounding moves theta by under 1 ulp of float)
KOKKOS_FORCEINLINE_FUNCTION float lane_two_asin_sqrt(float x, float sx, float s1x) {
  return float(lane_two_asin_sqrt(double(x), double(sx), double(s1x)));
}

}  // namespace epac
