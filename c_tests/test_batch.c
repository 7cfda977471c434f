/* The batch functions through the C ABI: the paper's Example 3 as rows, each row bit for bit
 * the single call's, failing rows untouched, the batch status, in-place conversion, and
 * refusals that write nothing (statuses included). */
#include <stdlib.h>
#include "cncrot.h"
#include "harness.h"

#define N 200

static int same_bits(const double *a, const double *b, int n) { return memcmp(a, b, (size_t)n * sizeof(double)) == 0; }

static void paper_rows(void) {
  /* The paper's Example 3, twice. */
  double a[6] = {30, 45, 60, 30, 45, 60}, out[6];
  int32_t st[2] = {7, 7};
  CHECK_STATUS(cncrot_convert_many(0, 57, a, 2, 1, 39, out, st), 0);
  const double i39[3] = {37.7923, 20.7048, 49.1066};
  CHECK_NEAR(out, i39, 3, 1e-4);
  CHECK_NEAR(out + 3, i39, 3, 1e-4);
  CHECK(st[0] == 0 && st[1] == 0, "%d %d", st[0], st[1]);
  /* Extrinsic: the paper's second call. */
  CHECK_STATUS(cncrot_convert_many(0, 57, a, 2, 0, 39, a, NULL), 0);
  const double e39[3] = {39.6392, -16.2799, 50.3607};
  CHECK_NEAR(a, e39, 3, 1e-4);
  CHECK_NEAR(a + 3, e39, 3, 1e-4);
  /* Paper, Example 2: the matrix of extrinsic X, Y, Z = 30, 45, 60, row-major. */
  double angles[3] = {30, 45, 60}, m[9];
  const double printed[9] = {0.3536, -0.5732, 0.7392, 0.6124, 0.7392, 0.2803, -0.7071, 0.3536, 0.6124};
  CHECK_STATUS(cncrot_matrices_from_angles(0, 57, angles, 1, m, NULL), 0);
  CHECK_NEAR(m, printed, 9, 1e-4);
}

static void rows_equal_single_calls(void) {
  static double a[3 * N], m[9 * N], back[3 * N], conv[3 * N];
  static int32_t st[N], st2[N], st3[N];
  int k;
  for (k = 0; k < N; k++) {
    a[3 * k] = rnd(-180, 180);
    a[3 * k + 1] = (k % 10 == 3) ? 90 : rnd(-90, 90); /* singular rows for Tait-Bryan */
    a[3 * k + 2] = rnd(-180, 180);
  }
  a[3 * 17 + 1] = strtod("nan", NULL); /* a failing row */
  fill_sentinel(m, 9 * N);
  fill_sentinel(back, 3 * N);
  fill_sentinel(conv, 3 * N);
  int32_t r1 = cncrot_matrices_from_angles(1, 39, a, N, m, st);
  CHECK_STATUS(r1, CNCROT_STATUS_NOT_FINITE);
  /* Row 17's matrix is a sentinel, so it fails again in the decomposition. */
  int32_t r2 = cncrot_angles_from_matrices(1, 39, m, N, back, st2);
  CHECK_STATUS(r2, CNCROT_STATUS_NOT_A_ROTATION);
  int32_t r3 = cncrot_convert_many(1, 39, a, N, 0, 27, conv, st3);
  CHECK_STATUS(r3, CNCROT_STATUS_NOT_FINITE);
  int first_remark = 0;
  for (k = 0; k < N; k++) {
    double m1[9], b1[3], c1[3];
    fill_sentinel(m1, 9);
    fill_sentinel(b1, 3);
    fill_sentinel(c1, 3);
    int32_t s1 = cncrot_matrix_from_angles(1, 39, a + 3 * k, m1);
    int32_t s2 = cncrot_angles_from_matrix(1, 39, m + 9 * k, b1);
    int32_t s3 = cncrot_convert(1, 39, a + 3 * k, 0, 27, c1);
    CHECK(st[k] == s1 && st2[k] == s2 && st3[k] == s3, "row %d: %d %d %d", k, st[k], st2[k], st3[k]);
    CHECK(same_bits(m + 9 * k, m1, 9) && same_bits(back + 3 * k, b1, 3) && same_bits(conv + 3 * k, c1, 3),
          "row %d differs from the single call", k);
    if (s2 > 0 && !first_remark) first_remark = k;
  }
  CHECK(is_sentinel(m + 9 * 17, 9) && is_sentinel(back + 3 * 17, 3), "the failing row was written");
  /* Singular rows (Z, X', Y'' with X' = 90) give the remark; without errors it is returned. */
  CHECK(first_remark > 0, "no singular row");
  CHECK_STATUS(cncrot_angles_from_matrices(1, 39, m, 17, back, NULL), CNCROT_STATUS_SINGULAR);
  /* The round trip reproduces the angles of the regular rows. */
  CHECK_NEAR(back, a, 3, 1e-12);
}

static void refusals(void) {
  double a[3] = {1, 2, 3}, out[9];
  int32_t st[1] = {7};
  fill_sentinel(out, 9);
  CHECK_STATUS(cncrot_matrices_from_angles(2, 57, a, 1, out, st), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(cncrot_angles_from_matrices(1, 7, out, 1, a, st), CNCROT_STATUS_INCOMPLETE_SEQUENCE);
  CHECK_STATUS(cncrot_convert_many(0, 60, a, 1, 1, 39, out, st), CNCROT_STATUS_BAD_SEQUENCE);
  CHECK_STATUS(cncrot_convert_many(0, 57, NULL, 1, 1, 39, out, st), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_convert_many(0, 57, a, SIZE_MAX / 16, 1, 39, out, st), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_convert_many(0, 57, a, 0, 1, 39, out, st), 0);
  CHECK(is_sentinel(out, 9) && st[0] == 7 && a[0] == 1, "a refusal wrote");
}

int main(void) {
  paper_rows();
  rows_equal_single_calls();
  refusals();
  return finish("test_batch");
}
