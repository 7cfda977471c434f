/* The dialects' tilted-plane forms through the C interface: the worked numbers of
 * docs/dialects.md, the vendors' examples (TwinCAT, Syntec), the paper's probe use case, hand
 * geometry computed here with the C library's trigonometry, cross-dialect identities, every
 * pair of writable forms round-tripping random frames, and the error paths. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cncrot.h"
#include "harness.h"
#include "geometry.h"

static void worked_numbers(void) {
  double f[16], r[9];
  /* PLANE SPATIAL SPA45 SPB0 SPC90 and SPA27 SPB0 SPC45 (docs/dialects.md). */
  double s1[3] = {45, 0, 90}, e1[9] = {0, -0.707107, 0.707107, 1, 0, 0, 0, 0.707107, 0.707107};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_SPATIAL, 0, s1, 3, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, e1, 9, 5e-7);
  double s2[3] = {27, 0, 45}, e2[9] = {0.707107, -0.630037, 0.321020, 0.707107, 0.630037, -0.321020, 0, 0.453990, 0.891007};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_SPATIAL, 0, s2, 3, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, e2, 9, 5e-7);
  /* PLANE EULER EULPR45 EULNU20 EULROT22 (docs/dialects.md). */
  double s3[3] = {45, 20, 22}, e3[9] = {0.406706, -0.880966, 0.241845, 0.904530, 0.351193, -0.241845, 0.128123, 0.317116, 0.939693};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_EULER, 0, s3, 3, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, e3, 9, 5e-7);
  /* ROTS X30 Y20 (docs/dialects.md): gamma = 28.481238. */
  double s4[2] = {30, 20}, e4[9] = {0.939693, 0.163099, 0.300627, 0, 0.878973, -0.476871, -0.342020, 0.448112, 0.825965};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_SINUMERIK_ROTS, 0, s4, 2, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, e4, 9, 5e-7);
  /* CYCLE800 projection mode X,Y then Z is the same as ROTS X Y. */
  double c8[9] = {0, 0, 0, 30, 20, 0, 0, 0, 0};
  double g[16];
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_CYCLE800, 128 + 57, c8, 9, g), 0);
  CHECK_NEAR(g, f, 16, 1e-15);
}

static void vendors_and_paper(void) {
  double f[16], g[16], v[3], r[9];
  /* TwinCAT (its manual): after ROT Z45, CalcInvRot of (40, 10, 0) is (35.35, -21.21, 0). */
  double z45[3] = {0, 0, 45}, p[3] = {40, 10, 0}, expect[3] = {35.355339, -21.213203, 0};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_TWINCAT_ROT, 0, z45, 3, f), 0);
  rot_of(f, r);
  CHECK_STATUS(cncrot_rotate_vector_inverse(r, p, v), 0);
  CHECK_NEAR(v, expect, 3, 1e-6);
  /* transRotZ(45) twice maps (30, 0, 0) to (0, 30, 0). */
  double q[3] = {30, 0, 0}, q2[3] = {0, 30, 0};
  CHECK_STATUS(cncrot_frame_compose(f, f, g), 0);
  CHECK_STATUS(cncrot_frame_transform_point(g, q, v), 0);
  CHECK_NEAR(v, q2, 3, 1e-14);
  /* TwinCAT order: Z, then Y, then X about the global axes: Rx(x)·Ry(y)·Rz(z). */
  double xyz[3] = {10, 20, 30}, h[9];
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_TWINCAT_ROT, 0, xyz, 3, f), 0);
  rot_of(f, r);
  intrinsic(1, 2, 3, 10, 20, 30, h);
  CHECK_NEAR(r, h, 9, 1e-15);
  /* Syntec (its manual): G158 L1 P10157 X2. Y0. Z10. A20 B20 C-30 U0 V10 W0: translate
   * (2, 0, 10), turn about X 20, the new Y 20, the new Z -30, then (0, 10, 0) in the turned
   * system. */
  double s[9] = {2, 0, 10, 20, 20, -30, 0, 10, 0};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G158, 10157, s, 9, f), 0);
  rot_of(f, r);
  intrinsic(1, 2, 3, 20, 20, -30, h);
  CHECK_NEAR(r, h, 9, 1e-15);
  double t[3] = {2 + 10 * h[1], 10 * h[4], 10 + 10 * h[7]}, ft[3] = {f[3], f[7], f[11]};
  CHECK_NEAR(ft, t, 3, 1e-14);
  /* Syntec P01159 (mode 1, order 59, incremental) as a lone block: on no active plane. */
  double s2[9] = {0, 0, 0, 0, 0, 10, 0, 0, 0};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G158, 1159, s2, 9, f), 0);
  /* The paper: probe angles about the machine axes X, Y, Z = 30, 45, 60 are PLANE SPATIAL,
   * and the same plane is CYCLE800 axis-by-axis Z, X', Y'' with CYCLE600's output. */
  double probe[3] = {30, 45, 60}, ex2[9] = {0.3536, -0.5732, 0.7392, 0.6124, 0.7392, 0.2803, -0.7071, 0.3536, 0.6124};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_SPATIAL, 0, probe, 3, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, ex2, 9, 1e-4);
  double c800[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, w[9];
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_CYCLE800, 39, f, w, 9), 0);
  double cyc600[3] = {37.7923, 20.7048, 49.1066};
  CHECK_NEAR(w + 3, cyc600, 3, 1e-4);
  memcpy(c800 + 3, cyc600, sizeof cyc600);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_CYCLE800, 39, c800, 9, g), 0);
  CHECK_NEAR(g, f, 16, 1e-5);
}

static void dialect_rules(void) {
  double f[16], w[9], r[9], h[9];
  /* SINUMERIK read-back (manual): CROT(x,10,y,90,z,40) -> x 0, y 90, z 30. */
  double a[3] = {10, 90, 40}, e[3] = {0, 90, 30};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_SINUMERIK_ROT, 0, a, 3, f), 0);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_SINUMERIK_ROT, 0, f, w, 3), CNCROT_STATUS_SINGULAR);
  CHECK_NEAR(w, e, 3, 1e-12);
  /* CROT(x,190,y,0,z,-200) -> x -170, y 0, z 160. */
  double b[3] = {190, 0, -200}, eb[3] = {-170, 0, 160};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_SINUMERIK_ROT, 0, b, 3, f), 0);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_SINUMERIK_ROT, 0, f, w, 3), 0);
  CHECK_NEAR(w, eb, 3, 1e-12);
  /* RPY: Rz(z)·Ry(y)·Rx(x). */
  double xyz[3] = {10, 20, 30};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_SINUMERIK_ROT, 0, xyz, 3, f), 0);
  rot_of(f, r);
  intrinsic(3, 2, 1, 30, 20, 10, h);
  CHECK_NEAR(r, h, 9, 1e-15);
  /* G68.2: Rz(I)·Rx(J)·Rz(K) at the origin X Y Z; read back with J >= 0. */
  double g68[6] = {5, 6, 7, 30, -45, 60};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_2, 0, g68, 6, f), 0);
  rot_of(f, r);
  intrinsic(3, 1, 3, 30, -45, 60, h);
  CHECK_NEAR(r, h, 9, 1e-15);
  CHECK(f[3] == 5 && f[7] == 6 && f[11] == 7, "origin");
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_G68_2, 0, f, w, 6), 0);
  CHECK(w[4] >= 0 && fabs(w[4] - 45) < 1e-12, "J = %g", w[4]);
  /* Haas G268 Q123 is PLANE SPATIAL with SPA = I, SPB = J, SPC = K. */
  double q[6] = {0, 0, 0, 10, 20, 30}, sp[3] = {10, 20, 30}, f2[16];
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G268, 123, q, 6, f), 0);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_SPATIAL, 0, sp, 3, f2), 0);
  CHECK_NEAR(f, f2, 16, 0);
  /* PLANE SPATIAL at SPB = 90: SPC = 0 (the last rotation carries no angle). */
  double sing[3] = {10, 90, 40};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_SPATIAL, 0, sing, 3, f), 0);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_PLANE_SPATIAL, 0, f, w, 3), CNCROT_STATUS_SINGULAR);
  CHECK(w[1] == 90 && w[2] == 0, "%g %g %g", w[0], w[1], w[2]);
  /* PLANE POINTS: X' from P1 to P2, P3 on the +Y' side; the datum stays where it is (the
   * Heidenhain manuals: "the position of the active datum is not changed"). */
  double pts[9] = {1, 1, 1, 2, 2, 1, 0, 2, 1}, s2 = sqrt(0.5);
  double ep[9] = {s2, -s2, 0, s2, s2, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_POINTS, 0, pts, 9, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, ep, 9, 1e-15);
  CHECK(f[3] == 0 && f[7] == 0 && f[11] == 0, "points do not move the datum");
  /* G68.3: Z' the tool direction, X' = P x Z' (P = +Z), then R about Z'. Tool tilted about
   * Y: X' along +Y. */
  double g683[7] = {1, 2, 3, 0, 1, 0, 1}, s1 = sqrt(0.5);
  double e683[9] = {0, -s1, s1, 1, 0, 0, 0, s1, s1};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_3, 0, g683, 7, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, e683, 9, 1e-15);
  g683[3] = 90; /* R = 90: X' turns onto the old Y' */
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_3, 0, g683, 7, f), 0);
  CHECK(fabs(f[0] + s1) < 1e-15 && fabs(f[4]) < 1e-15 && fabs(f[8] - s1) < 1e-15, "%g %g %g", f[0], f[4], f[8]);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_G68_3, 0, f, w, 7), 0);
  CHECK(fabs(w[3] - 90) < 1e-12 && fabs(w[4] - s1) < 1e-15, "R %g", w[3]);
  /* PLANE VECTOR keeps N and projects B. */
  double vec[6] = {2, 2, 9, 0, 0, 5};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_VECTOR, 0, vec, 6, f), 0);
  rot_of(f, r);
  CHECK_NEAR(r, ep, 9, 1e-15);
}

/* Every pair of writable forms: words in one form -> frame -> words in another -> frame. */
static void every_pair_round_trips(void) {
  struct {
    int form, sel, n;
  } forms[] = {
      {CNCROT_FORM_CYCLE800, 57, 9},   {CNCROT_FORM_CYCLE800, 27, 9},     {CNCROT_FORM_CYCLE800, 64, 9},
      {CNCROT_FORM_CYCLE800, 185, 9},  {CNCROT_FORM_SINUMERIK_ROT, 0, 3}, {CNCROT_FORM_SINUMERIK_ROT, 1, 3},
      {CNCROT_FORM_PLANE_SPATIAL, 0, 3}, {CNCROT_FORM_PLANE_EULER, 0, 3}, {CNCROT_FORM_PLANE_VECTOR, 0, 6},
      {CNCROT_FORM_PLANE_POINTS, 0, 9}, {CNCROT_FORM_G68_2, 0, 6},        {CNCROT_FORM_G158, 10157, 9},
      {CNCROT_FORM_TWINCAT_ROT, 0, 3}, {CNCROT_FORM_G268, 321, 6},      {CNCROT_FORM_G68_3, 0, 7},
  };
  int nf = (int)(sizeof forms / sizeof forms[0]);
  double singular[4][3] = {{10, 90, 40}, {0, 0, 0}, {90, 90, 90}, {-30, -90, 120}};
  for (int trial = 0; trial < 200; trial++) {
    double a[3] = {rnd(-180, 180), rnd(-90, 90), rnd(-180, 180)}, o[3] = {0, 0, 0}, f[16];
    if (trial < 4) memcpy(a, singular[trial], sizeof a);
    cncrot_frame_from_angles(0, 57, a, o, o, f);
    for (int i = 0; i < nf; i++) {
      double w[9], g[16], w2[9], h[16];
      int si = cncrot_form_values(forms[i].form, forms[i].sel, f, w, (size_t)forms[i].n);
      if (forms[i].sel == 185 && si == CNCROT_STATUS_OUT_OF_RANGE) continue; /* not expressible */
      CHECK(si >= 0, "form %d/%d: %s", forms[i].form, forms[i].sel, cncrot_status_str(si));
      if (si < 0) continue;
      CHECK_STATUS(cncrot_form_frame(forms[i].form, forms[i].sel, w, (size_t)forms[i].n, g), 0);
      CHECK_NEAR(g, f, 16, 1e-12);
      for (int j = 0; j < nf; j++) {
        int sj = cncrot_form_values(forms[j].form, forms[j].sel, g, w2, (size_t)forms[j].n);
        if (forms[j].sel == 185 && sj == CNCROT_STATUS_OUT_OF_RANGE) continue;
        CHECK(sj >= 0, "%d -> %d: %s", forms[i].form, forms[j].form, cncrot_status_str(sj));
        if (sj < 0) continue;
        CHECK_STATUS(cncrot_form_frame(forms[j].form, forms[j].sel, w2, (size_t)forms[j].n, h), 0);
        CHECK_NEAR(h, f, 16, 1e-12);
      }
    }
  }
}

static void errors_leave_outputs_untouched(void) {
  double f[16], w[9], nan = strtod("nan", NULL);
  double ok6[6] = {0, 0, 0, 0, 30, 0}, bad6[6] = {0, 0, 0, 0, nan, 0}, zero9[9] = {0};
  double idf[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double moved[16] = {1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  fill_sentinel(f, 16);
  fill_sentinel(w, 9);
  CHECK_STATUS(cncrot_form_frame(0, 0, ok6, 6, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_form_frame(12, 0, ok6, 6, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_2, 0, ok6, 5, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_2, 1, ok6, 6, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_2, 0, bad6, 6, f), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_2, 0, NULL, 6, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G68_2, 0, ok6, 6, NULL), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_CYCLE800, 192, zero9, 9, f), CNCROT_STATUS_NOT_AVAILABLE);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_CYCLE800, 22, zero9, 9, f), CNCROT_STATUS_BAD_SEQUENCE);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_CYCLE800, 256, zero9, 9, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G158, 10200, zero9, 9, f), CNCROT_STATUS_NOT_AVAILABLE);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_G268, 313, ok6, 6, f), CNCROT_STATUS_BAD_SEQUENCE);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_POINTS, 0, zero9, 9, f), CNCROT_STATUS_COINCIDENT);
  double line9[9] = {0, 0, 0, 1, 1, 1, -2, -2, -2};
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_POINTS, 0, line9, 9, f), CNCROT_STATUS_COLLINEAR);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_VECTOR, 0, ok6, 6, f), CNCROT_STATUS_DEGENERATE);
  CHECK(is_sentinel(f, 16), "frame written on error");
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_SINUMERIK_ROTS, 0, idf, w, 2), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_PLANE_SPATIAL, 0, moved, w, 3), CNCROT_STATUS_HAS_ORIGIN);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_CYCLE800, 192, idf, w, 9), CNCROT_STATUS_NOT_AVAILABLE);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_G158, 1157, idf, w, 9), CNCROT_STATUS_BAD_ARGUMENT);
  double zero16[16] = {0};
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_G68_2, 0, zero16, w, 6), CNCROT_STATUS_NOT_A_ROTATION);
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_G68_2, 0, idf, w, 9), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(is_sentinel(w, 9), "words written on error");
  /* A vertical first projected axis with the plane turned about it: not expressible. */
  double yx[16] = {0, 0.5, 0.8660254037844386, 0, 0, 0.8660254037844386, -0.5, 0, -1, 0, 0, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_CYCLE800, 185, yx, w, 9), CNCROT_STATUS_OUT_OF_RANGE);
  CHECK(is_sentinel(w, 9), "words written on error");
}

/* The paper's use case: a flange tilted about the machine's X by 30 and Y by 45 (extrinsic),
 * probed along X and along Y; the angles go into CYCLE600, whose output feeds CYCLE800. */
static void probing(void) {
  double r[9], rx[9], ry[9];
  elem(1, 30, rx);
  elem(2, 45, ry);
  mul3(ry, rx, r); /* extrinsic X then Y: Ry(45)·Rx(30) */
  double n[3] = {r[2], r[5], r[8]};
#define Z(x, y) (50 - (n[0] * (x) + n[1] * (y)) / n[2])
  double a1[3] = {10, 20, Z(10, 20)}, a2[3] = {110, 20, Z(110, 20)};
  double b1[3] = {10, 20, Z(10, 20)}, b2[3] = {10, 90, Z(10, 90)};
  double ang[3], f[16], e[3] = {30, 45, 0};
  CHECK_STATUS(cncrot_probe_flange(a1, a2, b1, b2, ang, f), 0);
  CHECK_NEAR(ang, e, 3, 1e-12);
  double fr[9];
  rot_of(f, fr);
  CHECK_NEAR(fr, r, 9, 1e-15);
  cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  CHECK_STATUS(cncrot_cycle600(&gud, NULL, 0, "UFK600", 1, 57, 0, 0, 0, ang[0], ang[1], ang[2], 0, 0, 0, 1, 39, 0, 0, 0), 0);
  double w[9], c800[3] = {gud.cyc600_2, gud.cyc600_3, gud.cyc600_4};
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_CYCLE800, 39, f, w, 9), 0);
  CHECK_NEAR(w + 3, c800, 3, 1e-12);
  /* Least squares: eight points of that plane (flatness 0), then two corners 0.01 above and
   * two below in a symmetric pattern (flatness 0.02, rms 0.01). */
  double pts[24], res[2], g[16];
  double grid[8][2] = {{0, 0}, {100, 0}, {0, 80}, {100, 80}, {50, 40}, {20, 70}, {90, 10}, {60, 60}};
  for (int k = 0; k < 8; k++) {
    pts[3 * k] = grid[k][0];
    pts[3 * k + 1] = grid[k][1];
    pts[3 * k + 2] = Z(grid[k][0], grid[k][1]);
  }
  CHECK_STATUS(cncrot_probe_plane(pts, 8, g, res), 0);
  CHECK(res[0] < 1e-12 && res[1] < 1e-12, "flatness %g rms %g", res[0], res[1]);
  double gz[3] = {g[2], g[6], g[10]};
  CHECK_NEAR(gz, n, 3, 1e-13);
  double sym[12], h = 0.01, pat[4][3] = {{1, 1, 1}, {-1, -1, 1}, {1, -1, -1}, {-1, 1, -1}};
  for (int k = 0; k < 4; k++)
    for (int i = 0; i < 3; i++) sym[3 * k + i] = 50 * pat[k][0] * r[3 * i] + 50 * pat[k][1] * r[3 * i + 1] + h * pat[k][2] * r[3 * i + 2];
  CHECK_STATUS(cncrot_probe_plane(sym, 4, g, res), 0);
  CHECK(fabs(res[0] - 0.02) < 1e-12 && fabs(res[1] - 0.01) < 1e-12, "flatness %g rms %g", res[0], res[1]);
  /* Three points: PLANE POINTS's rotation (PLANE POINTS leaves the datum where it is; the
   * probed plane's origin is the first point). */
  double pp[16], rg[9], rpp[9];
  CHECK_STATUS(cncrot_probe_plane(pts, 3, g, res), 0);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_POINTS, 0, pts, 9, pp), 0);
  rot_of(g, rg);
  rot_of(pp, rpp);
  CHECK_NEAR(rg, rpp, 9, 1e-12);
  /* Thin sets once got a wrong plane with success (issue 20). Three points 1e-6 off a
   * 100 mm line: PLANE POINTS's frame, Z' = +Z. Four coplanar points on a strip 101 mm by
   * 9.6e-5 mm: O + a (3, -2, 0) + b (12, 18, -13) with small dyadic a, b are exact doubles
   * on the plane of normal (2, 3, 6)/7; rounding points to doubles costs any fit up to
   * eps * length / width = 2.3e-10 of tilt. */
  double thin[9] = {0, 0, 0, 100, 0, 0, 50, 1e-6, 0}, plus_z[3] = {0, 0, 1};
  CHECK_STATUS(cncrot_probe_plane(thin, 3, g, res), 0);
  CHECK_STATUS(cncrot_form_frame(CNCROT_FORM_PLANE_POINTS, 0, thin, 9, pp), 0);
  CHECK_NEAR(g, pp, 16, 1e-15);
  double thin_z[3] = {g[2], g[6], g[10]};
  CHECK_NEAR(thin_z, plus_z, 3, 1e-15);
  double bw = ldexp(1, -18), ab[4][2] = {{-14, 0}, {14, 0}, {14, bw}, {-14, bw}};
  double o7[3] = {5, -7, 120}, u7[3] = {3, -2, 0}, v7[3] = {12, 18, -13}, strip[12];
  for (int k = 0; k < 4; k++)
    for (int i = 0; i < 3; i++) strip[3 * k + i] = o7[i] + ab[k][0] * u7[i] + ab[k][1] * v7[i];
  CHECK_STATUS(cncrot_probe_plane(strip, 4, g, res), 0);
  double strip_z[3] = {g[2], g[6], g[10]}, n7[3] = {2.0 / 7, 3.0 / 7, 6.0 / 7};
  CHECK_NEAR(strip_z, n7, 3, 2.3e-10);
  /* The tool's side: four corners of a plane falling 10 mm over 100 mm along X, probed
   * clockwise from above, give Z' = (0.1, 0, 1)/|…| turned up, with the remark; in the
   * points' order (toward all zero) Z' points down; toward -Z keeps it down. Hand geometry:
   * the plane is z = -x/10. */
  double cw[12] = {0, 0, 0, 0, 50, 0, 100, 50, -10, 100, 0, -10}, none[3] = {0, 0, 0}, down[3] = {0, 0, -5};
  double up_n[3] = {0.1 / sqrt(1.01), 0, 1 / sqrt(1.01)}, down_n[3] = {-up_n[0], 0, -up_n[2]};
  CHECK_STATUS(cncrot_probe_plane(cw, 4, g, res), CNCROT_STATUS_TURNED);
  double cz[3] = {g[2], g[6], g[10]};
  CHECK_NEAR(cz, up_n, 3, 1e-15);
  double cx[3] = {g[0], g[4], g[8]}, plus_y[3] = {0, 1, 0};
  CHECK_NEAR(cx, plus_y, 3, 1e-15);
  CHECK_STATUS(cncrot_probe_plane_toward(cw, 4, none, g, res), 0);
  double oz[3] = {g[2], g[6], g[10]};
  CHECK_NEAR(oz, down_n, 3, 1e-15);
  CHECK_STATUS(cncrot_probe_plane_toward(cw, 4, down, g, res), 0);
  CHECK_STATUS(cncrot_probe_plane_toward(cw, 4, plus_z, g, res), CNCROT_STATUS_TURNED);
  double nan3[3] = {NAN, 0, 0}, keep[16];
  memcpy(keep, g, sizeof keep);
  CHECK_STATUS(cncrot_probe_plane_toward(cw, 4, nan3, g, res), CNCROT_STATUS_NOT_FINITE);
  CHECK(memcmp(keep, g, sizeof keep) == 0, "a refusal wrote the frame");
  CHECK_STATUS(cncrot_probe_plane_toward(cw, 4, NULL, g, res), CNCROT_STATUS_NULL_POINTER);
  /* An edge at 20 degrees from X' in the tilted plane. */
  double c20 = cos(20 * PI / 180), s20 = sin(20 * PI / 180), e1[3], e2[3], angle, t[16];
  for (int i = 0; i < 3; i++) {
    e1[i] = 10 * r[3 * i] + 10 * r[3 * i + 1];
    e2[i] = (10 + 50 * c20) * r[3 * i] + (10 + 50 * s20) * r[3 * i + 1];
  }
  CHECK_STATUS(cncrot_probe_edge(f, e1, e2, &angle, t), 0);
  CHECK(fabs(angle - 20) < 1e-12, "angle %g", angle);
  /* Refusals, outputs untouched. */
  double o[3] = {0, 0, 0}, x[3] = {100, 0, 0}, xx[3] = {-50, 0, 0}, nanp[3] = {0, strtod("nan", NULL), 0};
  fill_sentinel(ang, 3);
  fill_sentinel(f, 16);
  fill_sentinel(res, 2);
  CHECK_STATUS(cncrot_probe_flange(o, o, o, x, ang, f), CNCROT_STATUS_COINCIDENT);
  CHECK_STATUS(cncrot_probe_flange(o, x, o, xx, ang, f), CNCROT_STATUS_COLLINEAR);
  CHECK_STATUS(cncrot_probe_flange(o, x, nanp, o, ang, f), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(cncrot_probe_flange(o, x, o, NULL, ang, f), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_probe_plane(pts, 2, f, res), CNCROT_STATUS_TOO_FEW);
  double same[9] = {1, 2, 3, 1, 2, 3, 1, 2, 3}, line[9] = {0, 0, 0, 1, 2, 3, -2, -4, -6};
  CHECK_STATUS(cncrot_probe_plane(same, 3, f, res), CNCROT_STATUS_COINCIDENT);
  CHECK_STATUS(cncrot_probe_plane(line, 3, f, res), CNCROT_STATUS_COLLINEAR);
  CHECK_STATUS(cncrot_probe_plane((const double *)((const char *)pts + 1), 3, f, res), CNCROT_STATUS_BAD_ARGUMENT);
  double idf[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, up[3] = {0, 0, 5};
  CHECK_STATUS(cncrot_probe_edge(idf, o, o, &angle, f), CNCROT_STATUS_COINCIDENT);
  CHECK_STATUS(cncrot_probe_edge(idf, o, up, &angle, f), CNCROT_STATUS_COLLINEAR);
  CHECK(is_sentinel(ang, 3) && is_sentinel(f, 16) && is_sentinel(res, 2), "outputs written on error");
#undef Z
}

int main(void) {
  worked_numbers();
  probing();
  vendors_and_paper();
  dialect_rules();
  every_pair_round_trips();
  errors_leave_outputs_untouched();
  return finish("test_dialects");
}
