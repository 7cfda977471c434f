/* The rotation core through the C ABI: the paper's numbers (spec tables), exact right
 * angles, every bad input, round trips of all 24 conventions, frames. Expected values come
 * from the paper, the tables of the README and docs/, exact hand-derived values or identities. */
#include "cncrot.h"
#include "harness.h"

static const int32_t CODES[12] = {57, 45, 54, 30, 39, 27, 25, 29, 38, 46, 55, 59};
static int is_proper(int32_t code) { return (code & 3) == (code >> 4); }

static void paper_numbers(void) {
  /* conventions.md "Numbers the implementation must reproduce" (paper Examples 2, 3). */
  const double in[3] = {30, 45, 60};
  const double paper_m[9] = {0.3536, -0.5732, 0.7392, 0.6124, 0.7392,
                             0.2803, -0.7071, 0.3536, 0.6124};
  double m[9], out[3];
  CHECK_STATUS(cncrot_matrix_from_angles(0, 57, in, m), 0);
  CHECK_NEAR(m, paper_m, 9, 1e-4);

  /* Exact value column: extrinsic 57 -> intrinsic 57, 39 and extrinsic 39. */
  const double i57[3] = {-24.5972, 47.6632, 58.3345};
  const double i39[3] = {37.7923, 20.7048, 49.1066};
  const double i39_exact[3] = {37.79235, 20.70481, 49.10661};
  const double e39[3] = {39.6392, -16.2799, 50.3607};
  const double e39_exact[3] = {39.63927, -16.27991, 50.36073};
  CHECK_STATUS(cncrot_convert(0, 57, in, 1, 57, out), 0);
  CHECK_NEAR(out, i57, 3, 1e-4);
  CHECK_STATUS(cncrot_convert(0, 57, in, 1, 39, out), 0);
  CHECK_NEAR(out, i39, 3, 1e-4);
  CHECK_NEAR(out, i39_exact, 3, 1e-5);
  CHECK_STATUS(cncrot_convert(0, 57, in, 0, 39, out), 0);
  CHECK_NEAR(out, e39, 3, 1e-4);
  CHECK_NEAR(out, e39_exact, 3, 1e-5);
  /* The same through the matrix. */
  CHECK_STATUS(cncrot_angles_from_matrix(1, 39, m, out), 0);
  CHECK_NEAR(out, i39, 3, 1e-4);
  CHECK_STATUS(cncrot_angles_from_matrix(0, 39, m, out), 0);
  CHECK_NEAR(out, e39, 3, 1e-4);

  /* The 4-decimal matrix -> intrinsic 57. The paper prints (-24.5939, 47.6633, 58.3301),
   * what its own formulas (eq. 14: -atan(A23/A33), asin(A13), -atan(A12/A11)) give on the
   * rounded elements; the oracle below reproduces that to 1e-4. The matrix is not
   * orthonormal (its elements carry +-5e-5), so different correct formulas disagree in the
   * third decimal: the library's answer is checked to the precision the input carries. */
  const double paper_i57[3] = {-24.5939, 47.6633, 58.3301};
  const double rad = 180.0 / 3.14159265358979323846;
  const double oracle[3] = {-atan(paper_m[5] / paper_m[8]) * rad, asin(paper_m[2]) * rad,
                            -atan(paper_m[1] / paper_m[0]) * rad};
  CHECK_NEAR(oracle, paper_i57, 3, 1e-4);
  CHECK_STATUS(cncrot_angles_from_matrix(1, 57, paper_m, out), 0);
  CHECK_NEAR(out, paper_i57, 3, 5e-3);
  CHECK_NEAR(out, i57, 3, 5e-3);
}

static void exact_right_angles(void) {
  double m[9];
  const double a[3] = {90, 0, 0};
  const double rx90[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  CHECK_STATUS(cncrot_matrix_from_angles(1, 57, a, m), 0);
  CHECK(memcmp(m, rx90, sizeof m) == 0 || max_abs_diff(m, rx90, 9) == 0.0, "Rx(90) exact");
  const double b[3] = {-270, 450, 180}; /* = X90, Y90, Z180 */
  CHECK_STATUS(cncrot_matrix_from_angles(1, 57, b, m), 0);
  /* Ry(90)·Rz(180) = [0 0 1; 0 -1 0; 1 0 0]; Rx(90)·that = [0 0 1; -1 0 0; 0 -1 0]. */
  const double rx_ry_rz[9] = {0, 0, 1, -1, 0, 0, 0, -1, 0};
  CHECK(max_abs_diff(m, rx_ry_rz, 9) == 0.0, "exact product, got %g %g %g", m[3], m[4], m[5]);
  for (int k = 0; k < 9; k++) CHECK(!signbit(m[k]) || m[k] != 0.0, "no -0 at %d", k);
  /* Decomposing exact matrices gives exact angles. */
  double out[3];
  const double a2[3] = {90, 45, -90};
  CHECK_STATUS(cncrot_matrix_from_angles(1, 55, a2, m), 0);
  CHECK_STATUS(cncrot_angles_from_matrix(1, 55, m, out), 0);
  CHECK(out[0] == 90 && out[2] == -90 && fabs(out[1] - 45) < 1e-14, "%g %g %g", out[0], out[1], out[2]);
}

static void singular_cases(void) {
  /* SINUMERIK: CROT(x,10, y,90, z,40) reads back x = 0, y = 90, z = 30 (intrinsic 27). */
  double m[9], out[3];
  const double in[3] = {40, 90, 10};
  const double expect[3] = {30, 90, 0};
  CHECK_STATUS(cncrot_matrix_from_angles(1, 27, in, m), 0);
  CHECK_STATUS(cncrot_angles_from_matrix(1, 27, m, out), CNCROT_STATUS_SINGULAR);
  CHECK_NEAR(out, expect, 3, 1e-12);
  CHECK(out[1] == 90.0 && out[2] == 0.0 && !signbit(out[2]), "exact 90 and +0");
  /* Every convention at both singular middle angles: positive status, theta3 = 0, and an
   * exact decomposition. */
  for (int kind = 0; kind < 2; kind++)
    for (int c = 0; c < 12; c++)
      for (int pole = 0; pole < 2; pole++) {
        double a[3] = {rnd(-180, 180), 0, rnd(-180, 180)}, m2[9];
        a[1] = is_proper(CODES[c]) ? (pole ? 180 : 0) : (pole ? -90 : 90);
        cncrot_matrix_from_angles(kind, CODES[c], a, m);
        CHECK_STATUS(cncrot_angles_from_matrix(kind, CODES[c], m, out), CNCROT_STATUS_SINGULAR);
        CHECK(out[2] == 0.0 && out[1] == a[1], "kind %d code %d: %g %g %g", kind, CODES[c], out[0], out[1], out[2]);
        cncrot_matrix_from_angles(kind, CODES[c], out, m2);
        CHECK_NEAR(m2, m, 9, 1e-15);
      }
  /* The second solution of a proper-Euler middle angle of 180 is 180 (never -180): every
   * returned angle is in (-180, 180]. Found by the property tests. */
  {
    const double pe[3] = {10, 180, 30}, pe_second[3] = {-170, 180, -150};
    double s[3];
    CHECK_STATUS(cncrot_second_solution(25, pe, s), 0);
    CHECK(s[0] == pe_second[0] && s[1] == pe_second[1] && s[2] == pe_second[2],
          "second solution of XYX (10, 180, 30): %g %g %g", s[0], s[1], s[2]);
  }
}

static void round_trips(void) {
  double worst = 0;
  for (int kind = 0; kind < 2; kind++)
    for (int c = 0; c < 12; c++)
      for (int n = 0; n < 2000; n++) {
        double a[3], m[9], out[3], m2[9];
        a[0] = rnd(-180, 180);
        a[1] = is_proper(CODES[c]) ? rnd(0, 180) : rnd(-90, 90);
        a[2] = rnd(-180, 180);
        cncrot_matrix_from_angles(kind, CODES[c], a, m);
        int32_t s = cncrot_angles_from_matrix(kind, CODES[c], m, out);
        CHECK(s == 0, "status %d", s);
        double d = max_abs_diff(a, out, 3);
        if (d > worst) worst = d;
        cncrot_matrix_from_angles(kind, CODES[c], out, m2);
        CHECK(max_abs_diff(m, m2, 9) <= 1e-15, "reconstruction");
        CHECK(out[0] > -180 && out[0] <= 180 && out[2] > -180 && out[2] <= 180, "range");
        CHECK(is_proper(CODES[c]) ? (out[1] >= 0 && out[1] <= 180) : (out[1] >= -90 && out[1] <= 90), "range");
        /* Conversion to any other convention and back gives the same rotation. */
        int32_t c2 = CODES[n % 12];
        double conv[3], back[3], m3[9];
        cncrot_convert(kind, CODES[c], a, 1 - kind, c2, conv);
        cncrot_convert(1 - kind, c2, conv, kind, CODES[c], back);
        cncrot_matrix_from_angles(kind, CODES[c], back, m3);
        CHECK(max_abs_diff(m, m3, 9) <= 2e-15, "convert round trip");
        /* The second solution is the same rotation. */
        double second[3];
        CHECK_STATUS(cncrot_second_solution(CODES[c], out, second), 0);
        cncrot_matrix_from_angles(kind, CODES[c], second, m3);
        CHECK(max_abs_diff(m, m3, 9) <= 2e-15, "second solution");
      }
  /* Away from the singularity the angles themselves come back (conditioning ~1/cos). */
  CHECK(worst < 1e-9, "worst angle difference %g", worst);
}

static void closest_and_unwinding(void) {
  double m[9], out[3];
  const double a[3] = {10, 20, 30};
  const double ref[3] = {-165, -15, 200};
  const double expect[3] = {-170, -20, 210}; /* second solution, +360 on theta3 */
  cncrot_matrix_from_angles(1, 55, a, m);
  CHECK_STATUS(cncrot_closest_angles(1, 55, m, ref, out), 0);
  CHECK_NEAR(out, expect, 3, 1e-12);
  /* Sinumerik: computed 10, specified 750 -> 730. */
  const double b[3] = {10, 0, 0}, ref2[3] = {750, 0, 0};
  cncrot_matrix_from_angles(1, 57, b, m);
  CHECK_STATUS(cncrot_closest_angles(1, 57, m, ref2, out), 0);
  CHECK(fabs(out[0] - 730) < 1e-12 && out[1] == 0 && out[2] == 0, "%g %g %g", out[0], out[1], out[2]);
}

static void vectors_additive_nearest(void) {
  /* TwinCAT: after ROT Z45, CalcInvRot of (40, 10, 0) is (35.35, -21.21, 0). */
  double m[9], out[3];
  const double z45[3] = {45, 0, 0}, v[3] = {40, 10, 0};
  const double expect_inv[3] = {25 * sqrt(2.0), -15 * sqrt(2.0), 0};
  cncrot_matrix_from_angles(1, 3, z45, m);
  CHECK_STATUS(cncrot_rotate_vector_inverse(m, v, out), 0);
  CHECK_NEAR(out, expect_inv, 3, 1e-13);
  const double expect_rot[3] = {15 * sqrt(2.0), 25 * sqrt(2.0), 0};
  CHECK_STATUS(cncrot_rotate_vector(m, v, out), 0);
  CHECK_NEAR(out, expect_rot, 3, 1e-13);
  /* AROT: Z30 then additive Z15 equals Z45; extrinsic addition is a left product. */
  double r[9], r45[9];
  const double z30[3] = {30, 0, 0}, z15[3] = {15, 0, 0};
  cncrot_matrix_from_angles(1, 3, z30, r);
  CHECK_STATUS(cncrot_add_rotation(1, 3, z15, r, r), 0);
  cncrot_matrix_from_angles(1, 3, z45, r45);
  CHECK_NEAR(r, r45, 9, 1e-15);
  /* Intrinsic XYZ(30,45,60) = X30, then additive intrinsic Y45, then Z60;
   * extrinsic XYZ(30,45,60) = X30, then additive extrinsic Y45, then Z60. */
  for (int kind = 0; kind < 2; kind++) {
    const double full[3] = {30, 45, 60}, x30[3] = {30, 0, 0}, y45[3] = {45, 0, 0}, z60[3] = {60, 0, 0};
    double whole[9], step[9];
    cncrot_matrix_from_angles(kind, 57, full, whole);
    cncrot_matrix_from_angles(kind, 1, x30, step);
    cncrot_add_rotation(kind, 2, y45, step, step);
    cncrot_add_rotation(kind, 3, z60, step, step);
    CHECK_NEAR(step, whole, 9, 1e-15);
  }
  /* Nearest rotation of a measured matrix is orthonormal and close. */
  const double measured[9] = {1, 0.001, 0, -0.001, 1, 0, 0, 0, 1.0002};
  double n[9];
  CHECK_STATUS(cncrot_nearest_rotation(measured, n), 0);
  CHECK_STATUS(cncrot_check_rotation(n), 0);
  CHECK_NEAR(n, measured, 9, 3e-4);
  const double mirror[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
  fill_sentinel(n, 9);
  CHECK_STATUS(cncrot_nearest_rotation(mirror, n), CNCROT_STATUS_DEGENERATE);
  CHECK(is_sentinel(n, 9), "untouched");
}

static void frames(void) {
  double f[16], g[16], p[3];
  const double a[3] = {0, 0, 90}, before[3] = {10, 0, 0}, after[3] = {5, 0, 0};
  /* Trans(10,0,0)·Rz(90)·Trans(5,0,0): origin at (10, 5, 0). */
  const double expect[16] = {0, -1, 0, 10, 1, 0, 0, 5, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_frame_from_angles(1, 57, a, before, after, f), 0);
  CHECK_NEAR(f, expect, 16, 0);
  /* Rotation about a point keeps the point. */
  const double z90[3] = {90, 0, 0}, c[3] = {1, 2, 3};
  CHECK_STATUS(cncrot_frame_about_point(1, 3, z90, c, g), 0);
  CHECK_STATUS(cncrot_frame_transform_point(g, c, p), 0);
  CHECK_NEAR(p, c, 3, 0);
  /* f · f⁻¹ = I. */
  double inv[16], id[16];
  const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_frame_inverse(f, inv), 0);
  CHECK_STATUS(cncrot_frame_compose(f, inv, id), 0);
  CHECK_NEAR(id, identity, 16, 1e-15);
  /* TwinCAT: transRotZ(45) twice maps (30, 0, 0) to (0, 30, 0). */
  const double z45[3] = {45, 0, 0}, zero[3] = {0, 0, 0}, q[3] = {30, 0, 0}, q2[3] = {0, 30, 0};
  cncrot_frame_from_angles(1, 3, z45, zero, zero, f);
  CHECK_STATUS(cncrot_frame_compose(f, f, f), 0);
  CHECK_STATUS(cncrot_frame_transform_point(f, q, p), 0);
  CHECK_NEAR(p, q2, 3, 1e-14);
  /* A frame whose last row is not 0 0 0 1 is refused. */
  double bad[16];
  memcpy(bad, identity, sizeof bad);
  bad[12] = 1e-9;
  fill_sentinel(p, 3);
  CHECK_STATUS(cncrot_frame_transform_point(bad, q, p), CNCROT_STATUS_NOT_A_ROTATION);
  CHECK(is_sentinel(p, 3), "untouched");
}

static void dialect_numbers(void) {
  /* dialects.md worked numbers: Heidenhain PLANE SPATIAL = extrinsic 57, EULER = intrinsic 55. */
  double m[9];
  const double spa1[3] = {45, 0, 90};
  const double f1[9] = {0, -0.707107, 0.707107, 1, 0, 0, 0, 0.707107, 0.707107};
  cncrot_matrix_from_angles(0, 57, spa1, m);
  CHECK_NEAR(m, f1, 9, 1e-6);
  const double spa2[3] = {27, 0, 45};
  const double f2[9] = {0.707107, -0.630037, 0.321020, 0.707107, 0.630037, -0.321020, 0, 0.453990, 0.891007};
  cncrot_matrix_from_angles(0, 57, spa2, m);
  CHECK_NEAR(m, f2, 9, 1e-6);
  const double eul[3] = {45, 20, 22};
  const double f3[9] = {0.406706, -0.880966, 0.241845, 0.904530, 0.351193, -0.241845, 0.128123, 0.317116, 0.939693};
  cncrot_matrix_from_angles(1, 55, eul, m);
  CHECK_NEAR(m, f3, 9, 1e-6);
}

static void bad_inputs(void) {
  double m[9], out[3], f[16];
  const double a[3] = {1, 2, 3}, id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double nan_a[3] = {1, NAN, 3}, inf_a[3] = {INFINITY, 0, 0}, ninf_a[3] = {0, 0, -INFINITY};
  const double idf[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  /* NULL pointers. */
  fill_sentinel(m, 9);
  fill_sentinel(out, 3);
  CHECK_STATUS(cncrot_matrix_from_angles(1, 57, NULL, m), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_matrix_from_angles(1, 57, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_angles_from_matrix(1, 57, NULL, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_angles_from_matrix(1, 57, id, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_convert(1, 57, NULL, 1, 39, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_convert(1, 57, a, 1, 39, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_second_solution(57, NULL, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_second_solution(57, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_closest_angles(1, 57, NULL, a, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_closest_angles(1, 57, id, NULL, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_closest_angles(1, 57, id, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_check_rotation(NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_nearest_rotation(NULL, m), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_nearest_rotation(id, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_add_rotation(1, 57, NULL, id, m), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_add_rotation(1, 57, a, NULL, m), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_add_rotation(1, 57, a, id, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_rotate_vector(NULL, a, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_rotate_vector(id, NULL, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_rotate_vector(id, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_rotate_vector_inverse(NULL, a, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_rotate_vector_inverse(id, NULL, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_rotate_vector_inverse(id, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_from_angles(1, 57, NULL, a, a, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_from_angles(1, 57, a, NULL, a, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_from_angles(1, 57, a, a, NULL, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_from_angles(1, 57, a, a, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_about_point(1, 57, NULL, a, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_about_point(1, 57, a, NULL, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_about_point(1, 57, a, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_compose(NULL, idf, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_compose(idf, NULL, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_compose(idf, idf, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_inverse(NULL, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_inverse(idf, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_transform_point(NULL, a, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_transform_point(idf, NULL, out), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_frame_transform_point(idf, a, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK(is_sentinel(m, 9) && is_sentinel(out, 3), "outputs untouched");

  /* NaN and infinities, in every float input position of the main functions. */
  const double *bad_angles[3] = {nan_a, inf_a, ninf_a};
  for (int k = 0; k < 3; k++) {
    fill_sentinel(m, 9);
    fill_sentinel(out, 3);
    fill_sentinel(f, 16);
    CHECK_STATUS(cncrot_matrix_from_angles(1, 57, bad_angles[k], m), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_convert(0, 57, bad_angles[k], 1, 39, out), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_second_solution(57, bad_angles[k], out), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_closest_angles(1, 57, id, bad_angles[k], out), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_rotate_vector(id, bad_angles[k], out), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_frame_from_angles(1, 57, a, a, bad_angles[k], f), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_frame_about_point(1, 57, a, bad_angles[k], f), CNCROT_STATUS_NOT_FINITE);
    CHECK(is_sentinel(m, 9) && is_sentinel(out, 3) && is_sentinel(f, 16), "outputs untouched");
  }
  for (int pos = 0; pos < 9; pos++) {
    double bm[9];
    memcpy(bm, id, sizeof bm);
    bm[pos] = pos % 2 ? NAN : -INFINITY;
    fill_sentinel(out, 3);
    CHECK_STATUS(cncrot_angles_from_matrix(1, 57, bm, out), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_check_rotation(bm), CNCROT_STATUS_NOT_FINITE);
    CHECK_STATUS(cncrot_add_rotation(1, 57, a, bm, m), CNCROT_STATUS_NOT_FINITE);
    CHECK(is_sentinel(out, 3), "untouched");
  }

  /* Flags and codes. */
  fill_sentinel(m, 9);
  fill_sentinel(out, 3);
  const int32_t bad_flags[] = {2, -1, 255, INT32_MIN, INT32_MAX};
  for (size_t k = 0; k < sizeof bad_flags / sizeof *bad_flags; k++) {
    CHECK_STATUS(cncrot_matrix_from_angles(bad_flags[k], 57, a, m), CNCROT_STATUS_BAD_FLAG);
    CHECK_STATUS(cncrot_angles_from_matrix(bad_flags[k], 57, id, out), CNCROT_STATUS_BAD_FLAG);
    CHECK_STATUS(cncrot_convert(bad_flags[k], 57, a, 1, 39, out), CNCROT_STATUS_BAD_FLAG);
    CHECK_STATUS(cncrot_convert(0, 57, a, bad_flags[k], 39, out), CNCROT_STATUS_BAD_FLAG);
  }
  /* -1, 64, huge; and repeated neighbours: Y,X,X (22), Z,Z (15), X,-,X (17). */
  const int32_t bad_codes[] = {-1, 64, 1000, INT32_MIN, INT32_MAX, 22, 15, 17, 63, 21};
  for (size_t k = 0; k < sizeof bad_codes / sizeof *bad_codes; k++) {
    CHECK_STATUS(cncrot_matrix_from_angles(1, bad_codes[k], a, m), CNCROT_STATUS_BAD_SEQUENCE);
    CHECK_STATUS(cncrot_angles_from_matrix(1, bad_codes[k], id, out), CNCROT_STATUS_BAD_SEQUENCE);
    CHECK_STATUS(cncrot_convert(1, bad_codes[k], a, 1, 39, out), CNCROT_STATUS_BAD_SEQUENCE);
    CHECK_STATUS(cncrot_convert(1, 57, a, 1, bad_codes[k], out), CNCROT_STATUS_BAD_SEQUENCE);
  }
  /* Fewer than three rotations cannot be a decomposition target, but compose fine. */
  const int32_t partial[] = {0, 1, 3, 9, 49, 0x30, 0x0c};
  for (size_t k = 0; k < sizeof partial / sizeof *partial; k++) {
    CHECK_STATUS(cncrot_angles_from_matrix(0, partial[k], id, out), CNCROT_STATUS_INCOMPLETE_SEQUENCE);
    CHECK_STATUS(cncrot_convert(1, 57, a, 0, partial[k], out), CNCROT_STATUS_INCOMPLETE_SEQUENCE);
    CHECK_STATUS(cncrot_second_solution(partial[k], a, out), CNCROT_STATUS_INCOMPLETE_SEQUENCE);
  }
  CHECK(is_sentinel(m, 9) && is_sentinel(out, 3), "outputs untouched");
  double partial_m[9];
  CHECK_STATUS(cncrot_matrix_from_angles(1, 0, a, partial_m), 0);
  CHECK_NEAR(partial_m, id, 9, 0);

  /* Matrices that are not rotations. */
  const double scaled[9] = {1.01, 0, 0, 0, 1.01, 0, 0, 0, 1.01};
  const double mirror[9] = {1, 0, 0, 0, 1, 0, 0, 0, -1};
  const double zero[9] = {0};
  const double sheared[9] = {1, 0.1, 0, 0, 1, 0, 0, 0, 1};
  const double *not_rot[4] = {scaled, mirror, zero, sheared};
  for (int k = 0; k < 4; k++) {
    CHECK_STATUS(cncrot_check_rotation(not_rot[k]), CNCROT_STATUS_NOT_A_ROTATION);
    CHECK_STATUS(cncrot_angles_from_matrix(1, 57, not_rot[k], out), CNCROT_STATUS_NOT_A_ROTATION);
    CHECK_STATUS(cncrot_closest_angles(1, 57, not_rot[k], a, out), CNCROT_STATUS_NOT_A_ROTATION);
    CHECK_STATUS(cncrot_add_rotation(1, 57, a, not_rot[k], m), CNCROT_STATUS_NOT_A_ROTATION);
    CHECK_STATUS(cncrot_rotate_vector(not_rot[k], a, out), CNCROT_STATUS_NOT_A_ROTATION);
  }
  CHECK(is_sentinel(m, 9) && is_sentinel(out, 3), "outputs untouched");
  /* Just inside and outside the stated tolerance. */
  const double inside[9] = {1 + 0.4e-3, 0, 0, 0, 1, 0, 0, 0, 1};
  const double outside[9] = {1 + 0.6e-3, 0, 0, 0, 1, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_check_rotation(inside), 0); /* (1+4e-4)^2 - 1 = 8.0e-4 */
  CHECK_STATUS(cncrot_check_rotation(outside), CNCROT_STATUS_NOT_A_ROTATION); /* 1.2e-3 */
  CHECK(CNCROT_ROTATION_TOLERANCE == 1e-3, "documented tolerance");

  /* Finite inputs whose result overflows: a turn of 90 about Z around the point
   * (1e308, 1e308, 0) moves the origin by (2e308, 0, 0), beyond DBL_MAX. Found by fuzzing. */
  {
    const double z90[3] = {90, 0, 0}, far[3] = {1e308, 1e308, 0}, big[3] = {1.5e308, 1.5e308, 0};
    fill_sentinel(f, 16);
    fill_sentinel(out, 3);
    CHECK_STATUS(cncrot_frame_about_point(1, 3, z90, far, f), CNCROT_STATUS_OUT_OF_RANGE);
    const double h = 0.70710678118654752440, r45[9] = {h, -h, 0, h, h, 0, 0, 0, 1};
    CHECK_STATUS(cncrot_rotate_vector_inverse(r45, big, out), CNCROT_STATUS_OUT_OF_RANGE);
    CHECK(is_sentinel(f, 16) && is_sentinel(out, 3), "overflowing results not written");
    CHECK(strncmp(cncrot_status_str(-14), "CNCROT_STATUS_OUT_OF_RANGE", 26) == 0, "name");
  }

  /* Every status has a name. */
  CHECK(strncmp(cncrot_status_str(0), "CNCROT_STATUS_OK", 16) == 0, "name");
  CHECK(strncmp(cncrot_status_str(-6), "CNCROT_STATUS_NOT_A_ROTATION", 28) == 0, "name");
  CHECK(strncmp(cncrot_status_str(12345), "CNCROT_STATUS_UNKNOWN", 21) == 0, "name");
}

int main(void) {
  paper_numbers();
  exact_right_angles();
  singular_cases();
  round_trips();
  closest_and_unwinding();
  vectors_additive_nearest();
  frames();
  dialect_numbers();
  bad_inputs();
  return finish("test_core");
}
