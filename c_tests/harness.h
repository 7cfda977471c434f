/* A minimal test harness: CHECK counts, a failure prints where; the program's last line is
 * "N passed, N failed" and its exit status is non-zero on any failure. */
#ifndef CNCROT_TEST_HARNESS_H
#define CNCROT_TEST_HARNESS_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static int g_passed = 0, g_failed = 0;

#define CHECK(cond, ...)                                                       \
  do {                                                                         \
    if (cond) {                                                                \
      g_passed++;                                                              \
    } else {                                                                   \
      g_failed++;                                                              \
      fprintf(stderr, "%s:%d: FAILED %s: ", __FILE__, __LINE__, #cond);        \
      fprintf(stderr, __VA_ARGS__);                                            \
      fprintf(stderr, "\n");                                                   \
    }                                                                          \
  } while (0)

#define CHECK_STATUS(expr, expected)                                           \
  do {                                                                         \
    int32_t s_ = (expr);                                                       \
    CHECK(s_ == (expected), "%s returned %d (%s), expected %d", #expr, s_,     \
          cncrot_status_str(s_), (int)(expected));                             \
  } while (0)

static inline double max_abs_diff(const double *a, const double *b, int n) {
  double worst = 0.0;
  for (int k = 0; k < n; k++) {
    double d = fabs(a[k] - b[k]);
    if (!(d <= worst)) worst = d; /* NaN counts as worst */
  }
  return worst;
}

#define CHECK_NEAR(a, b, n, tol)                                               \
  do {                                                                         \
    double d_ = max_abs_diff((a), (b), (n));                                   \
    CHECK(d_ <= (tol), "%s vs %s differ by %.3g > %.3g", #a, #b, d_,           \
          (double)(tol));                                                      \
  } while (0)

/* Fills a buffer with a sentinel so that a test can prove it was not written. */
static inline void fill_sentinel(double *p, int n) {
  for (int k = 0; k < n; k++) p[k] = -12345.678;
}
static inline int is_sentinel(const double *p, int n) {
  for (int k = 0; k < n; k++)
    if (p[k] != -12345.678) return 0;
  return 1;
}

/* xorshift64*: reproducible random inputs. */
static uint64_t g_rng = 0x9E3779B97F4A7C15ull;
static inline double rnd(double lo, double hi) {
  g_rng ^= g_rng >> 12;
  g_rng ^= g_rng << 25;
  g_rng ^= g_rng >> 27;
  uint64_t r = g_rng * 2685821657736338717ull;
  return lo + (hi - lo) * ((double)(r >> 11) / 9007199254740992.0);
}

static inline int finish(const char *name) {
  printf("%s: %d passed, %d failed\n", name, g_passed, g_failed);
  return g_failed == 0 ? 0 : 1;
}

#endif
