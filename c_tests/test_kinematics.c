/* Swivel kinematics through the C interface: a fork head, a table, a mixed machine from
 * SINUMERIK swivel data, a 45-degree nutating head and the paper's three-axis machine (a
 * rotary table with a two-axis head) built axis by axis; the tool direction against hand
 * geometry with the C library's trigonometry; every inverse solution reproduced by the
 * forward computation; the choice rules, travel limits, Hirth grids, singular poses; the
 * tool-tip follow-up; CYCLE600 positioning; refusals with the outputs untouched. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cncrot.h"
#include "harness.h"
#include "geometry.h"

static const double Z[3] = {0, 0, 1}, Y[3] = {0, 1, 0}, X[3] = {1, 0, 0}, O[3] = {0, 0, 0};

static cncrot_machine from_carr(const char *text) {
  cncrot_machine m;
  memset(&m, 0, sizeof m);
  CHECK_STATUS(cncrot_machine_from_carr(&m, text, strlen(text), 1), CNCROT_STATUS_OK);
  return m;
}

/* The frame of a rotation (no translation). */
static void frame_of(const double r[9], double f[16]) {
  memset(f, 0, 16 * sizeof f[0]);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) f[4 * i + j] = r[3 * i + j];
  f[15] = 1;
}

/* Largest difference of the tool direction (or the whole rotation when whole != 0). */
static double miss(const cncrot_machine *m, const double ax[3], const double target[16], int whole) {
  double f[16];
  if (cncrot_machine_forward(m, ax, f) != CNCROT_STATUS_OK) return 1e9;
  double worst = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      if (whole || j == 2) worst = fmax(worst, fabs(f[4 * i + j] - target[4 * i + j]));
  return worst;
}

/* Every solution of the inverse reproduces the target; returns the count. */
static size_t all_reproduce(const cncrot_machine *m, const double target[16], int whole, int32_t expect) {
  double sol[6];
  size_t n = 99;
  CHECK_STATUS(cncrot_machine_inverse(m, target, sol, 2, &n), expect);
  for (size_t k = 0; k < n && k < 2; k++) CHECK(miss(m, sol + 3 * k, target, whole) < 1e-12, "solution %zu", k);
  return n;
}

static const char HEAD_T[] =
    "; fork head: C about Z carrying B about Y, pivot 150 mm above the adapter\n"
    "N10 $TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1\n"
    "N20 $TC_CARR10[1]=0 $TC_CARR11[1]=1 $TC_CARR12[1]=0\n"
    "N30 $TC_CARR4[1]=0 $TC_CARR5[1]=0 $TC_CARR6[1]=-150 $TC_CARR23[1]=\"T\"\n"
    "N40 $TC_CARR31[1]=-100 $TC_CARR33[1]=100 $TC_CARR34[1]=\"HEAD_CB\"\nM17\n";

static void fork_head(void) {
  cncrot_machine m = from_carr(HEAD_T);
  CHECK(m.count == 2 && strcmp(m.name, "HEAD_CB") == 0, "count %d", m.count);
  /* p2 = -l1 - l2; $TC_CARR31/33 are axis 2's limits, axis 1 has none. */
  CHECK(m.axes[1].point[2] == 150 && m.axes[1].min_deg == -100 && m.axes[1].max_deg == 100, "axis 2");
  CHECK(m.axes[0].min_deg == 0 && m.axes[0].max_deg == 0, "axis 1 modulo");
  double ax[3] = {30, 40, 0}, f[16];
  CHECK_STATUS(cncrot_machine_forward(&m, ax, f), CNCROT_STATUS_OK);
  double c = cos(30 * PI / 180), s = sin(30 * PI / 180), sb = sin(40 * PI / 180), cb = cos(40 * PI / 180);
  double dir[3] = {c * sb, s * sb, cb}, got[3] = {f[2], f[6], f[10]};
  CHECK_NEAR(got, dir, 3, 1e-15);
  /* The adapter turns about the pivot (0, 0, 150): it sits at pivot - 150·dir. */
  double org[3] = {f[3], f[7], f[11]}, want[3] = {-150 * dir[0], -150 * dir[1], 150 - 150 * dir[2]};
  CHECK_NEAR(org, want, 3, 1e-12);
  CHECK(all_reproduce(&m, f, 0, CNCROT_STATUS_OK) == 2, "two solutions");

  /* Choice: from C = 750 the closest turn of C = 30 is 30 + 720 = 750. */
  double cur[3] = {750, 0, 0}, out[3], res[3], rem[16];
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_OK);
  double want_c[3] = {750, 40, 0};
  CHECK_NEAR(out, want_c, 3, 1e-9);
  /* A fork head reaches Rz·Ry entirely: nothing remains. */
  CHECK(fabs(rem[0] - 1) < 1e-14 && fabs(rem[5] - 1) < 1e-14 && fabs(rem[10] - 1) < 1e-14, "remaining");
  double cur2[3] = {0, 0, 0};
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_MINUS, 2, out, res, rem), CNCROT_STATUS_OK);
  double want_m[3] = {-150, -40, 0};
  CHECK_NEAR(out, want_m, 3, 1e-9);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_INVERSE, 0, out, res, rem), CNCROT_STATUS_OK);
  CHECK_NEAR(out, want_m, 3, 1e-9);
  /* The other branch turns the tool half a turn about itself: the frame keeps Rz(180). */
  CHECK(fabs(rem[0] + 1) < 1e-14 && fabs(rem[5] + 1) < 1e-14 && fabs(rem[10] - 1) < 1e-14, "remaining");
  /* Directions of travel of C from 0: turning up, C 30 comes after 30 degrees and -150
   * after 210; turning down, -150 after 150 and 30 after 330. */
  double want_p[3] = {30, 40, 0};
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_POSITIVE_TURN, 1, out, res, rem), CNCROT_STATUS_OK);
  CHECK_NEAR(out, want_p, 3, 1e-9);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_NEGATIVE_TURN, 1, out, res, rem), CNCROT_STATUS_OK);
  CHECK_NEAR(out, want_m, 3, 1e-9);
  /* Master first (Fanuc's G53.1): from C 110, B -40 the master C turns 80 to 30 and 100 to
   * 210 (-150 unwound): (C 30, B 40), though the sum of squares (80² + 80² against 100²)
   * takes (C 210, B -40). */
  double cur_f[3] = {110, -40, 0}, want_f[3] = {30, 40, 0}, want_s[3] = {210, -40, 0};
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur_f, CNCROT_CHOOSE_MASTER_FIRST, 1, out, res, rem), CNCROT_STATUS_OK);
  CHECK_NEAR(out, want_f, 3, 1e-9);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur_f, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_OK);
  CHECK_NEAR(out, want_s, 3, 1e-9);
  fill_sentinel(out, 3);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_MASTER_FIRST, 0, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_POSITIVE_TURN, 0, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_NEGATIVE_TURN, 3, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur2, CNCROT_CHOOSE_MASTER_FIRST + 1, 1, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(is_sentinel(out, 3), "untouched");

  /* Limits: B within 0..100 leaves only B = +40 even for "minus". */
  cncrot_machine lim = m;
  lim.axes[1].min_deg = 0;
  lim.axes[1].max_deg = 100;
  CHECK_STATUS(cncrot_machine_choose(&lim, f, cur2, CNCROT_CHOOSE_MINUS, 2, out, res, rem), CNCROT_STATUS_OK);
  CHECK(fabs(out[1] - 40) < 1e-9, "B %g", out[1]);
  lim.axes[1].max_deg = 20;
  fill_sentinel(out, 3);
  CHECK_STATUS(cncrot_machine_choose(&lim, f, cur2, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem),
               CNCROT_STATUS_OUT_OF_TRAVEL);
  CHECK(is_sentinel(out, 3), "untouched");

  /* Hirth: B on a 15-degree grid reaches 40 as 45, residual +5; the remaining frame turns
   * back by 5 degrees about the tilted Y. */
  cncrot_machine h = m;
  h.axes[1].hirth_step_deg = 15;
  CHECK_STATUS(cncrot_machine_choose(&h, f, cur2, CNCROT_CHOOSE_PLUS, 2, out, res, rem), CNCROT_STATUS_SNAPPED);
  CHECK(fabs(out[1] - 45) < 1e-12 && fabs(res[1] - 5) < 1e-12, "hirth %g %g", out[1], res[1]);
  double ry[9];
  elem(2, -5, ry);
  double rr[9];
  rot_of(rem, rr);
  CHECK_NEAR(rr, ry, 9, 1e-14);

  /* Singular: the tool straight down leaves C free at its current position. */
  double idf[16];
  double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  frame_of(id, idf);
  double cur3[3] = {123, 5, 0};
  CHECK_STATUS(cncrot_machine_choose(&m, idf, cur3, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_FREE_AXIS);
  CHECK(out[0] == 123 && fabs(out[1]) < 1e-12, "free C %g %g", out[0], out[1]);
  all_reproduce(&m, idf, 0, CNCROT_STATUS_FREE_AXIS);

  /* Tool-tip follow-up: the tip F·(0, 0, -L) stays on the workpiece. */
  double from[3] = {0, 0, 0}, to[3] = {30, 40, 0}, lin[3] = {10, 20, 30}, next[3];
  CHECK_STATUS(cncrot_machine_follow(&m, from, to, lin, 100, next), CNCROT_STATUS_OK);
  /* Tip before: lin + (0, 0, -100); after: next + adapter(to) - 100·dir. */
  double tip0[3] = {10, 20, -70};
  double tip1[3] = {next[0] + want[0] - 100 * dir[0], next[1] + want[1] - 100 * dir[1],
                    next[2] + want[2] - 100 * dir[2]};
  CHECK_NEAR(tip1, tip0, 3, 1e-9);
}

static void table_and_mixed(void) {
  /* Table A (about X) carrying C (about -Z, as commissioned for C+ clockwise). */
  static const char TABLE_P[] =
      "$TC_CARR7[1]=1 $TC_CARR8[1]=0 $TC_CARR9[1]=0\n$TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=-1\n"
      "$TC_CARR4[1]=0 $TC_CARR5[1]=0 $TC_CARR6[1]=-100 $TC_CARR15[1]=0 $TC_CARR16[1]=0 $TC_CARR17[1]=0\n"
      "$TC_CARR23[1]=\"p\" $TC_CARR30[1]=-120 $TC_CARR32[1]=20\n";
  cncrot_machine t = from_carr(TABLE_P);
  CHECK(t.count == 2 && t.axes[0].work_side == 1 && t.axes[1].work_side == 1, "P: both on the work");
  CHECK(t.axes[0].point[2] == -100 && t.axes[1].point[2] == -100, "P pivots l2, l2 + l3");
  /* The tool (+Z in the machine) seen from the workpiece: Rz(+C)·Rx(-A)·e_z (C about -Z). */
  double ax[3] = {-30, 50, 0}, f[16];
  CHECK_STATUS(cncrot_machine_forward(&t, ax, f), CNCROT_STATUS_OK);
  double rz[9], rx[9], r[9];
  elem(3, 50, rz);
  elem(1, 30, rx);
  mul3(rz, rx, r);
  double dir[3] = {r[2], r[5], r[8]}, got[3] = {f[2], f[6], f[10]};
  CHECK_NEAR(got, dir, 3, 1e-15);
  all_reproduce(&t, f, 0, CNCROT_STATUS_OK);
  double cur[3] = {0, 0, 0}, out[3], res[3], rem[16];
  /* The other solution (A = 30, C = -130) is beyond A's travel -120..20. */
  CHECK_STATUS(cncrot_machine_choose(&t, f, cur, CNCROT_CHOOSE_PLUS, 1, out, res, rem), CNCROT_STATUS_OK);
  CHECK(fabs(out[0] + 30) < 1e-9 && fabs(out[1] - 50) < 1e-9, "A %g C %g", out[0], out[1]);

  /* Mixed: B head (tool) and C table (work). */
  static const char MIXED_M[] =
      "$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0 $TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=1\n"
      "$TC_CARR4[1]=0 $TC_CARR5[1]=0 $TC_CARR6[1]=200 $TC_CARR15[1]=300 $TC_CARR16[1]=0 $TC_CARR17[1]=0\n"
      "$TC_CARR23[1]=\"M\" $TC_CARR24[1]=0.5\n";
  cncrot_machine mx = from_carr(MIXED_M);
  CHECK(mx.axes[0].work_side == 0 && mx.axes[1].work_side == 1, "M sides");
  CHECK(mx.axes[0].point[2] == 200 && mx.axes[1].point[0] == 300 && mx.axes[0].offset_deg == 0.5, "M");
  double am[3] = {20.5, 70, 0};
  CHECK_STATUS(cncrot_machine_forward(&mx, am, f), CNCROT_STATUS_OK);
  all_reproduce(&mx, f, 0, CNCROT_STATUS_OK);
  /* B turns by 20.5 - 0.5 = 20: the tool direction Rz(-70)·Ry(20)·e_z. */
  double ry[9];
  elem(3, -70, rz);
  elem(2, 20, ry);
  mul3(rz, ry, r);
  double d2[3] = {r[2], r[5], r[8]}, g2[3] = {f[2], f[6], f[10]};
  CHECK_NEAR(g2, d2, 3, 1e-15);
}

static void nutating_and_three_axes(void) {
  /* 45-degree nutating head: C, then B' about (0, 1, 1)/sqrt 2. Tilt b needs B' = theta with
   * cos b = (1 + cos theta) / 2. */
  cncrot_machine n;
  memset(&n, 0, sizeof n);
  double v45[3] = {0, 1, 1}, p[3] = {0, 0, 120};
  CHECK_STATUS(cncrot_machine_add_axis(&n, 0, Z, O, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&n, 0, v45, p, 0, 0), CNCROT_STATUS_OK);
  CHECK(fabs(n.axes[1].direction[1] - sqrt(0.5)) < 1e-15, "stored as a unit vector");
  for (double b = 5; b <= 85; b += 20) {
    double rx[9], f[16], sol[6];
    elem(1, -b, rx);
    frame_of(rx, f);
    size_t cnt = 0;
    CHECK_STATUS(cncrot_machine_inverse(&n, f, sol, 2, &cnt), CNCROT_STATUS_OK);
    double theta = acos(2 * cos(b * PI / 180) - 1) * 180 / PI;
    CHECK(cnt == 2, "two");
    for (size_t k = 0; k < cnt; k++) {
      CHECK(fabs(fabs(sol[3 * k + 1]) - theta) < 1e-9, "theta %g %g", sol[3 * k + 1], theta);
      CHECK(miss(&n, sol + 3 * k, f, 0) < 1e-12, "nutating");
    }
  }
  /* Beyond 90 degrees: unreachable, nothing written. */
  double rx[9], f[16], sol[6];
  size_t cnt = 77;
  elem(1, -120, rx);
  frame_of(rx, f);
  fill_sentinel(sol, 6);
  CHECK_STATUS(cncrot_machine_inverse(&n, f, sol, 2, &cnt), CNCROT_STATUS_UNREACHABLE);
  CHECK(cnt == 77 && is_sentinel(sol, 6), "untouched");

  /* The paper's machine: a rotary table C (work) and a two-axis head (tool: about Y, then
   * about X): the whole orientation is reachable. */
  cncrot_machine three;
  memset(&three, 0, sizeof three);
  double piv[3] = {0, 0, 540.735}, piv2[3] = {0.011, -0.041, 250.049}, ctr[3] = {500, 300, 0};
  CHECK_STATUS(cncrot_machine_add_axis(&three, 1, Z, ctr, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&three, 0, Y, piv, -120, 120), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&three, 0, X, piv2, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&three, 0, X, piv2, 0, 0), CNCROT_STATUS_TABLE_FULL);
  for (int k = 0; k < 200; k++) {
    double a[3] = {rnd(-180, 180), rnd(-120, 120), rnd(-180, 180)};
    CHECK_STATUS(cncrot_machine_forward(&three, a, f), CNCROT_STATUS_OK);
    all_reproduce(&three, f, 1, CNCROT_STATUS_OK);
  }
  /* The paper's Example 3 target (intrinsic Z, X', Y'' = 37.7923, 20.7048, 49.1066). */
  double fr[16];
  double ang[3] = {37.7923, 20.7048, 49.1066};
  CHECK_STATUS(cncrot_frame_from_angles(1, 39, ang, O, O, fr), CNCROT_STATUS_OK);
  double cur[3] = {0, 0, 0}, out[3], res[3], rem[16];
  CHECK_STATUS(cncrot_machine_choose(&three, fr, cur, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_OK);
  CHECK(miss(&three, out, fr, 1) < 1e-12, "paper target reached whole");
  CHECK(fabs(rem[0] - 1) < 1e-12 && fabs(rem[5] - 1) < 1e-12 && fabs(rem[10] - 1) < 1e-12, "nothing remains");
}

static void cycle600_and_refusals(void) {
  cncrot_machine m = from_carr(HEAD_T);
  cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  /* Intrinsic Z, X' = 30, 40 is C = 30 with the tilt about X; this head tilts about Y:
   * Rz(30)·Rx(40)·e_z = Rz(30 - 90)·Ry(40)·e_z, so C = -60, B = 40. */
  CHECK_STATUS(cncrot_cycle600(&gud, NULL, 1, "HEAD_CB", 0, 7, 0, 0, 0, 30, 40, 0, 0, 0, 0, 1, 39, 0, 0, 0),
               CNCROT_STATUS_OK);
  double cur[3] = {0, 0, 0}, out[3], res[3], rem[16];
  CHECK_STATUS(cncrot_cycle600_position(&gud, &m, cur, out, res, rem), CNCROT_STATUS_OK);
  double want[3] = {-60, 40, 0};
  CHECK_NEAR(out, want, 3, 1e-9);
  CHECK_STATUS(cncrot_cycle600(&gud, NULL, 1, "HEAD_CB", 0, 7, 0, 0, 0, 30, 40, 0, 0, 0, 0, 1, 39, 0, 1, 0),
               CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_cycle600_position(&gud, &m, cur, out, res, rem), CNCROT_STATUS_OK);
  double inv[3] = {120, -40, 0};
  CHECK_NEAR(out, inv, 3, 1e-9);

  /* Swivel-data errors name their line. */
  int32_t line = -1;
  const char *bad = "$TC_CARR7[1]=1\n\n$TC_CARR8[1]=R1\n";
  cncrot_machine keep = m;
  CHECK_STATUS(cncrot_machine_from_carr(&m, bad, strlen(bad), 1), CNCROT_STATUS_NOT_A_NUMBER);
  CHECK(memcmp(&keep, &m, sizeof m) == 0, "untouched");
  CHECK_STATUS(cncrot_machine_carr_error_line(bad, strlen(bad), 1, &line), CNCROT_STATUS_NOT_A_NUMBER);
  CHECK(line == 3, "line %d", line);
  const char *undef = "$TC_CARR52[1]=0\n";
  CHECK_STATUS(cncrot_machine_from_carr(&m, undef, strlen(undef), 1), CNCROT_STATUS_UNKNOWN_WORD);
  CHECK_STATUS(cncrot_machine_from_carr(&m, HEAD_T, strlen(HEAD_T), 2), CNCROT_STATUS_UNKNOWN_HEAD);
  const char *only2 = "$TC_CARR12[1]=1\n";
  CHECK_STATUS(cncrot_machine_from_carr(&m, only2, strlen(only2), 1), CNCROT_STATUS_BAD_ARGUMENT);
  /* A data set that makes no machine: the line that assigned the parameter at fault (the
   * kinematics type on line 3, the second axis on line 1); none for a missing data set. */
  const char *kind = "$TC_CARR7[1]=1\n$TC_CARR9[2]=1\n$TC_CARR23[1]=\"X\"\n";
  CHECK_STATUS(cncrot_machine_carr_error_line(kind, strlen(kind), 1, &line), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(line == 3, "line %d", line);
  CHECK_STATUS(cncrot_machine_carr_error_line(only2, strlen(only2), 1, &line), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(line == 1, "line %d", line);
  CHECK_STATUS(cncrot_machine_carr_error_line(kind, strlen(kind), 3, &line), CNCROT_STATUS_UNKNOWN_HEAD);
  CHECK(line == 0, "line %d", line);
  /* Limits the wrong way round, or beyond the angle bound, an offset beyond it: the limit or
   * offset line (the later of a pair), not the axis direction's. */
  const char *limits = "$TC_CARR23[1]=\"P\"\n$TC_CARR7[1]=1\n$TC_CARR30[1]=10\n$TC_CARR32[1]=5\n";
  CHECK_STATUS(cncrot_machine_carr_error_line(limits, strlen(limits), 1, &line), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(line == 4, "line %d", line);
  const char *wide = "$TC_CARR23[1]=\"P\"\n$TC_CARR7[1]=1\n$TC_CARR30[1]=-70000\n$TC_CARR32[1]=70000\n";
  CHECK_STATUS(cncrot_machine_carr_error_line(wide, strlen(wide), 1, &line), CNCROT_STATUS_OUT_OF_RANGE);
  CHECK(line == 4, "line %d", line);
  const char *offset = "$TC_CARR23[1]=\"P\"\n$TC_CARR7[1]=1\n$TC_CARR24[1]=70000\n";
  CHECK_STATUS(cncrot_machine_carr_error_line(offset, strlen(offset), 1, &line), CNCROT_STATUS_OUT_OF_RANGE);
  CHECK(line == 3, "line %d", line);

  /* Description errors, pointers, numbers. */
  double ax[3] = {0, 0, 0}, f[16];
  cncrot_machine broken = m;
  broken.axes[0].work_side = 2;
  CHECK_STATUS(cncrot_machine_forward(&broken, ax, f), CNCROT_STATUS_BAD_FLAG);
  broken = m;
  broken.axes[1].direction[0] = NAN;
  CHECK_STATUS(cncrot_machine_forward(&broken, ax, f), CNCROT_STATUS_NOT_FINITE);
  broken = m;
  memset(broken.name, 'x', sizeof broken.name);
  CHECK_STATUS(cncrot_machine_forward(&broken, ax, f), CNCROT_STATUS_NAME_TOO_LONG);
  CHECK_STATUS(cncrot_machine_forward(NULL, ax, f), CNCROT_STATUS_NULL_POINTER);
  double third[3] = {0, 0, 1};
  CHECK_STATUS(cncrot_machine_forward(&m, third, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_add_axis(&m, 0, Z, O, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&m, 0, Z, O, 0, 0), CNCROT_STATUS_TABLE_FULL);
  cncrot_machine two;
  memset(&two, 0, sizeof two);
  CHECK_STATUS(cncrot_machine_add_axis(&two, 0, Z, O, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&two, 0, Z, O, 0, 0), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_add_axis(&two, 0, Y, O, 10, -10), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(two.count == 1, "untouched");
  double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, idf[16], sol[6];
  size_t n;
  frame_of(id, idf);
  CHECK_STATUS(cncrot_machine_inverse(&m, idf, sol, 0, &n), CNCROT_STATUS_NO_ROOM);
  CHECK_STATUS(cncrot_machine_choose(&two, idf, cur, 7, 0, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_choose(&two, idf, cur, CNCROT_CHOOSE_MINUS, 2, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_machine_choose(&two, idf, cur, CNCROT_CHOOSE_CLOSEST, 1, out, res, rem), CNCROT_STATUS_BAD_ARGUMENT);
  idf[0] = 2;
  CHECK_STATUS(cncrot_machine_choose(&two, idf, cur, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_NOT_A_ROTATION);
}

/* Issue 20, class 3: a target made with an axis exactly at an end of its travel, seen from
 * those positions, is reached at that end (not refused, not half a turn of C away); the
 * position never lies outside the travel. CYCLE600 positioning shares the choice. */
static void travel_ends(void) {
  double out[3], res[3], rem[16], f[16];
  /* One B about Y within 0..10, target and current B = 10 (the inverse computes B a few
   * ulp beyond 10): B = 10 exactly. Likewise B = 0. */
  cncrot_machine b;
  memset(&b, 0, sizeof b);
  CHECK_STATUS(cncrot_machine_add_axis(&b, 0, Y, O, 0, 10), CNCROT_STATUS_OK);
  for (double end = 0; end <= 10; end += 10) {
    double at[3] = {end, 0, 0};
    CHECK_STATUS(cncrot_machine_forward(&b, at, f), CNCROT_STATUS_OK);
    CHECK_STATUS(cncrot_machine_choose(&b, f, at, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_OK);
    CHECK(out[0] == end, "B %.17g, want %g", out[0], end);
  }

  /* A fork head C/A and a table A/C, A within 0..30: A at either end, C every 2.5 degrees. */
  cncrot_machine head, table;
  memset(&head, 0, sizeof head);
  memset(&table, 0, sizeof table);
  double up[3] = {0, 0, 150}, down[3] = {0, 0, -100};
  CHECK_STATUS(cncrot_machine_add_axis(&head, 0, Z, O, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&head, 0, X, up, 0, 30), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&table, 1, X, down, 0, 30), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&table, 1, Z, O, 0, 0), CNCROT_STATUS_OK);
  int refused = 0, moved = 0, total = 0;
  for (int which = 0; which < 2; which++) {
    const cncrot_machine *m = which ? &table : &head;
    int a = which ? 0 : 1, c = which ? 1 : 0;
    for (double end = 0; end <= 30; end += 30)
      for (double deg = -180; deg < 180; deg += 2.5) {
        double at[3] = {0, 0, 0};
        at[a] = end;
        at[c] = deg;
        if (cncrot_machine_forward(m, at, f) != CNCROT_STATUS_OK) continue;
        int32_t st = cncrot_machine_choose(m, f, at, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem);
        total++;
        if (st < 0)
          refused++;
        else if (fabs(out[a] - end) > 1e-9 || out[a] < 0 || out[a] > 30 || fabs(out[c] - deg) > 1e-9)
          moved++;
      }
  }
  CHECK(total == 576 && refused == 0 && moved == 0, "%d of %d refused, %d moved", refused, total, moved);

  /* A table A (about X) carrying C (about Z), A within -120..30, standing at (30, -162.5)
   * with that orientation as target: it stays, rather than (-30, -342.5). */
  cncrot_machine ac;
  memset(&ac, 0, sizeof ac);
  CHECK_STATUS(cncrot_machine_add_axis(&ac, 1, X, O, -120, 30), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&ac, 1, Z, O, 0, 0), CNCROT_STATUS_OK);
  double here[3] = {30, -162.5, 0};
  CHECK_STATUS(cncrot_machine_forward(&ac, here, f), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_choose(&ac, f, here, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem), CNCROT_STATUS_OK);
  CHECK(out[0] == 30 && fabs(out[1] + 162.5) < 1e-9, "A %.17g C %.17g", out[0], out[1]);
  /* The same through CYCLE600: the table's frame W^-1 = Rz(162.5)·Rx(-30), intrinsic Z, X'
   * (code 7). */
  cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  CHECK_STATUS(cncrot_cycle600(&gud, NULL, 1, "", 0, 7, 0, 0, 0, 162.5, -30, 0, 0, 0, 0, 1, 39, 0, 0, 0),
               CNCROT_STATUS_OK);
  fill_sentinel(out, 3);
  CHECK_STATUS(cncrot_cycle600_position(&gud, &ac, here, out, res, rem), CNCROT_STATUS_OK);
  CHECK(out[0] == 30 && fabs(out[1] + 162.5) < 1e-9, "CYCLE600: A %.17g C %.17g", out[0], out[1]);
}

/* Issue 20, classes 1 and 4: a description filled by hand is checked; parameters whose
 * magnitude loses the degree or the millimetre are refused with OUT_OF_RANGE, a Hirth step
 * finer than any grid and garbage in an unused entry with BAD_ARGUMENT; nothing written. */
static void hand_filled_descriptions(void) {
  cncrot_machine m;
  memset(&m, 0, sizeof m);
  double up[3] = {0, 0, 150};
  CHECK_STATUS(cncrot_machine_add_axis(&m, 0, Z, O, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(&m, 0, Y, up, -100, 100), CNCROT_STATUS_OK);
  double ax[3] = {10, 20, 0}, f[16], out[3], res[3], rem[16];
  CHECK_STATUS(cncrot_machine_forward(&m, ax, f), CNCROT_STATUS_OK);
  struct {
    const char *what;
    int axis;
    int field; /* 0 min/max, 1 offset, 2 Hirth offset/step, 3 point x, 4 Hirth step, 5 unused entry */
    double v1, v2;
    int32_t want;
  } cases[] = {
      {"travel at 1e15", 1, 0, 1e15, 1e15 + 720, CNCROT_STATUS_OUT_OF_RANGE},
      {"a limit at 65536", 1, 0, 0, 65536, CNCROT_STATUS_OUT_OF_RANGE},
      {"offset 1e12", 0, 1, 1e12, 0, CNCROT_STATUS_OUT_OF_RANGE},
      {"offset -65536", 0, 1, -65536, 0, CNCROT_STATUS_OUT_OF_RANGE},
      {"Hirth offset 1e17", 1, 2, 1e17, 1, CNCROT_STATUS_OUT_OF_RANGE},
      {"point 1e12", 1, 3, 1e12, 0, CNCROT_STATUS_OUT_OF_RANGE},
      {"point beyond 1e6", 1, 3, 1.0000001e6, 0, CNCROT_STATUS_OUT_OF_RANGE},
      {"Hirth step 1e-310", 1, 4, 1e-310, 0, CNCROT_STATUS_BAD_ARGUMENT},
      {"Hirth step below 1e-6", 1, 4, 0.999e-6, 0, CNCROT_STATUS_BAD_ARGUMENT},
      {"garbage in an unused entry", 2, 5, 1, 0, CNCROT_STATUS_BAD_ARGUMENT},
      {"NaN in an unused entry", 2, 5, NAN, 0, CNCROT_STATUS_BAD_ARGUMENT},
      {"limits within 65536", 1, 0, -65535.75, 65535.75, CNCROT_STATUS_OK},
      {"point at 1e6", 1, 3, 1e6, 0, CNCROT_STATUS_OK},
      {"the finest Hirth step", 1, 4, 1e-6, 0, CNCROT_STATUS_SNAPPED},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    cncrot_machine e = m;
    cncrot_machine_axis *a = &e.axes[cases[k].axis];
    switch (cases[k].field) {
      case 0: a->min_deg = cases[k].v1; a->max_deg = cases[k].v2; break;
      case 1: a->offset_deg = cases[k].v1; break;
      case 2: a->hirth_offset_deg = cases[k].v1; a->hirth_step_deg = cases[k].v2; break;
      case 3: a->point[0] = cases[k].v1; break;
      case 4: a->hirth_step_deg = cases[k].v1; break;
      default: a->offset_deg = cases[k].v1; break;
    }
    int32_t want = cases[k].want, want_fwd = want == CNCROT_STATUS_SNAPPED ? CNCROT_STATUS_OK : want;
    double g[16];
    fill_sentinel(g, 16);
    fill_sentinel(out, 3);
    int32_t s = cncrot_machine_forward(&e, ax, g);
    CHECK(s == want_fwd, "%s: forward %d, want %d", cases[k].what, s, want_fwd);
    s = cncrot_machine_choose(&e, f, ax, CNCROT_CHOOSE_CLOSEST, 0, out, res, rem);
    /* The finest grid snaps B = 20 by at most half a micro-degree (or not at all). */
    int ok = s == want || (want == CNCROT_STATUS_SNAPPED && s == CNCROT_STATUS_OK);
    CHECK(ok, "%s: choose %d (%s), want %d", cases[k].what, s, cncrot_status_str(s), want);
    if (want < 0) CHECK(is_sentinel(g, 16) && is_sentinel(out, 3), "%s: untouched", cases[k].what);
  }
  /* Adding an axis with a travel beyond the bound. */
  cncrot_machine keep = m;
  CHECK_STATUS(cncrot_machine_add_axis(&m, 1, X, O, -1e15, 0), CNCROT_STATUS_OUT_OF_RANGE);
  CHECK(memcmp(&keep, &m, sizeof m) == 0, "untouched");
}

/* The AC table of the five-axis tests: A about X through (0, 0, 100), C about Z on it. */
static void ac_table(cncrot_machine *m) {
  memset(m, 0, sizeof *m);
  double x[3] = {1, 0, 0}, z[3] = {0, 0, 1}, pa[3] = {0, 0, 100}, pc[3] = {0, 0, 0};
  CHECK_STATUS(cncrot_machine_add_axis(m, 1, x, pa, 0, 0), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_add_axis(m, 1, z, pc, 0, 0), CNCROT_STATUS_OK);
}

/* The five-axis transformation on an AC table (A about X through (0, 0, 100), C about Z
 * carried by it), tool 50 mm, by hand: tip at the workpiece point (10, 0, 0), direction
 * (0.5, 0, sqrt(3)/2) = (sin A sin C, sin A cos C, cos A) at A = 30, C = 90; the adapter
 * at W·tip + (0, 0, 50) = (0, 50 + 5·sqrt(3), 155 - 50·sqrt(3)). */
static void five_axis_transformation(void) {
  cncrot_machine m;
  ac_table(&m);
  double s3 = sqrt(3.0);
  /* Rz(-90)·Rx(-30): the workpiece's view of the tool at A = 30, C = 90. */
  double pose[16] = {0, s3 / 2, 0.5, 10, -1, 0, 0, 0, 0, -0.5, s3 / 2, 0, 0, 0, 0, 1};
  double prev[6] = {0, 0, 0, 20, 80, 0}, ax[6];
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, pose, 50, prev, ax), CNCROT_STATUS_OK);
  double want[6] = {0, 50 + 5 * s3, 155 - 50 * s3, 30, 90, 0};
  CHECK_NEAR(ax, want, 6, 1e-12);
  /* And forward again: the tip and the direction. */
  double back[16];
  CHECK_STATUS(cncrot_machine_tcp_forward(&m, ax, 50, back), CNCROT_STATUS_OK);
  double tip[3] = {back[3], back[7], back[11]}, tip0[3] = {10, 0, 0};
  double dir[3] = {back[2], back[6], back[10]}, dir0[3] = {0.5, 0, s3 / 2};
  CHECK_NEAR(tip, tip0, 3, 1e-12);
  CHECK_NEAR(dir, dir0, 3, 1e-15);
  /* The output may be the previous positions (one cycle after another). */
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, pose, 50, prev, prev), CNCROT_STATUS_OK);
  CHECK_NEAR(prev, want, 6, 1e-12);
  /* A priority axis: A's lower position is the other solution (A = -30, C = -90), from the
   * same previous positions; its higher one is the first; a rule that is not one, refused. */
  double prev2[6] = {0, 0, 0, 20, 80, 0}, low[6], high[6];
  CHECK_STATUS(cncrot_machine_tcp_inverse_rule(&m, pose, 50, prev2, CNCROT_CHOOSE_MINUS, 1, low), CNCROT_STATUS_OK);
  CHECK(fabs(low[3] + 30) < 1e-12 && fabs(low[4] + 90) < 1e-12, "minus on A: %g %g", low[3], low[4]);
  CHECK_STATUS(cncrot_machine_tcp_inverse_rule(&m, pose, 50, prev2, CNCROT_CHOOSE_PLUS, 1, high), CNCROT_STATUS_OK);
  CHECK_NEAR(high, want, 6, 1e-12);
  CHECK_STATUS(cncrot_machine_tcp_inverse_rule(&m, pose, 50, prev2, CNCROT_CHOOSE_MINUS, 3, high), CNCROT_STATUS_BAD_ARGUMENT);
  /* The CL point (10, 0, 0) along (0.5, 0, sqrt 3 / 2), given twice as long: the pose of
   * the worked example (X' the part of X perpendicular to the direction), hence its axes. */
  double tip10[3] = {10, 0, 0}, dir2[3] = {1, 0, s3}, clp[16], clx[6];
  CHECK_STATUS(cncrot_cl_pose(tip10, dir2, clp), CNCROT_STATUS_OK);
  double clz[3] = {clp[2], clp[6], clp[10]}, clt[3] = {clp[3], clp[7], clp[11]}, clxx[3] = {clp[0], clp[4], clp[8]};
  double xw[3] = {s3 / 2, 0, -0.5};
  CHECK_NEAR(clz, dir0, 3, 1e-15);
  CHECK_NEAR(clt, tip10, 3, 0);
  CHECK_NEAR(clxx, xw, 3, 1e-15);
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, clp, 50, prev2, clx), CNCROT_STATUS_OK);
  CHECK_NEAR(clx, want, 6, 1e-12);
  double zero3[3] = {0, 0, 0}, nan3[3] = {0, NAN, 1};
  fill_sentinel(clp, 16);
  CHECK_STATUS(cncrot_cl_pose(tip10, zero3, clp), CNCROT_STATUS_DEGENERATE);
  CHECK_STATUS(cncrot_cl_pose(tip10, nan3, clp), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(cncrot_cl_pose(NULL, dir2, clp), CNCROT_STATUS_NULL_POINTER);
  CHECK(is_sentinel(clp, 16), "untouched");
  /* Carried from that pose to the direction +X: the turn of 60 degrees about +Y takes X'
   * (sqrt 3 / 2, 0, -1/2) to (0, 0, -1), Y' stays +Y; cncrot_cl_pose would take X' = +Y. */
  double car[16], xdir[3] = {3, 0, 0};
  CHECK_STATUS(cncrot_cl_pose(tip10, dir2, clp), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_cl_pose_toward(tip10, xdir, clp, car), CNCROT_STATUS_OK);
  double carx[3] = {car[0], car[4], car[8]}, cary[3] = {car[1], car[5], car[9]}, carz[3] = {car[2], car[6], car[10]};
  double mz[3] = {0, 0, -1}, py[3] = {0, 1, 0}, px[3] = {1, 0, 0}, cart[3] = {car[3], car[7], car[11]};
  CHECK_NEAR(carx, mz, 3, 1e-15);
  CHECK_NEAR(cary, py, 3, 1e-15);
  CHECK_NEAR(carz, px, 3, 0);
  CHECK_NEAR(cart, tip10, 3, 0);
  /* In place, to its own direction: the pose itself. */
  double same[16];
  memcpy(same, clp, sizeof same);
  CHECK_STATUS(cncrot_cl_pose_toward(tip10, dir2, same, same), CNCROT_STATUS_OK);
  CHECK_NEAR(same, clp, 16, 1e-15);
  double bent[16];
  memcpy(bent, clp, sizeof bent);
  bent[0] = 2;
  fill_sentinel(car, 16);
  CHECK_STATUS(cncrot_cl_pose_toward(tip10, xdir, bent, car), CNCROT_STATUS_NOT_A_ROTATION);
  bent[0] = clp[0];
  bent[15] = 2;
  CHECK_STATUS(cncrot_cl_pose_toward(tip10, xdir, bent, car), CNCROT_STATUS_NOT_A_ROTATION);
  CHECK_STATUS(cncrot_cl_pose_toward(tip10, zero3, clp, car), CNCROT_STATUS_DEGENERATE);
  CHECK_STATUS(cncrot_cl_pose_toward(tip10, xdir, NULL, car), CNCROT_STATUS_NULL_POINTER);
  CHECK(is_sentinel(car, 16), "untouched");
  /* C's direction of travel from 80: up, C 90 is 10 degrees ahead (-90 only 190); down,
   * -90 comes after 170 degrees (90 after 350): the other solution. */
  double up[6], down[6];
  CHECK_STATUS(cncrot_machine_tcp_inverse_rule(&m, pose, 50, prev2, CNCROT_CHOOSE_POSITIVE_TURN, 2, up), CNCROT_STATUS_OK);
  CHECK_NEAR(up, want, 6, 1e-12);
  CHECK_STATUS(cncrot_machine_tcp_inverse_rule(&m, pose, 50, prev2, CNCROT_CHOOSE_NEGATIVE_TURN, 2, down), CNCROT_STATUS_OK);
  CHECK_NEAR(down, low, 6, 1e-12);
  /* The tip is the same from either solution. */
  double tl[16];
  CHECK_STATUS(cncrot_machine_tcp_forward(&m, low, 50, tl), CNCROT_STATUS_OK);
  double tip_low[3] = {tl[3], tl[7], tl[11]}, dir_low[3] = {tl[2], tl[6], tl[10]};
  CHECK_NEAR(tip_low, tip0, 3, 1e-12);
  CHECK_NEAR(dir_low, dir0, 3, 1e-15);
  /* At the pole C is free and stays where it was. */
  double pole[16] = {1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
  double at[6] = {0, 0, 0, 0, 123, 0}, out[6];
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, pole, 50, at, out), CNCROT_STATUS_FREE_AXIS);
  CHECK(out[3] == 0 && out[4] == 123, "C kept at the pole: %g %g", out[3], out[4]);
  /* Refusals leave the output untouched. */
  double keep[6] = {7, 7, 7, 7, 7, 7}, seven[6] = {7, 7, 7, 7, 7, 7};
  double skew[16];
  memcpy(skew, pose, sizeof skew);
  skew[0] = 2;
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, skew, 50, prev, keep), CNCROT_STATUS_NOT_A_ROTATION);
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, pose, NAN, prev, keep), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(cncrot_machine_tcp_inverse(NULL, pose, 50, prev, keep), CNCROT_STATUS_NULL_POINTER);
  double unused[6] = {0, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_machine_tcp_inverse(&m, pose, 50, unused, keep), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_NEAR(keep, seven, 6, 0);
  CHECK_STATUS(cncrot_machine_tcp_forward(&m, unused, 50, back), CNCROT_STATUS_BAD_ARGUMENT);
}

/* Sealed descriptions: what the library writes carries its seal; a hand-filled one computes
 * exactly as its sealed form; an edit after sealing takes effect (the stale seal is not
 * trusted); a seal over what is not a machine is refused with nothing written. */
static void sealed_descriptions(void) {
  cncrot_machine m;
  ac_table(&m);
  CHECK(m.reserved != 0, "add_axis wrote no seal");
  /* The same table filled by hand, directions of other lengths, a seal that is not one. */
  cncrot_machine h;
  memset(&h, 0, sizeof h);
  h.count = 2;
  h.reserved = 12345;
  h.axes[0].work_side = 1;
  h.axes[0].direction[0] = 3;
  h.axes[0].point[2] = 100;
  h.axes[1].work_side = 1;
  h.axes[1].direction[2] = 0.5;
  double s3 = sqrt(3.0);
  double pose[16] = {0, s3 / 2, 0.5, 10, -1, 0, 0, 0, 0, -0.5, s3 / 2, 0, 0, 0, 0, 1};
  double prev[6] = {0, 0, 0, 20, 80, 0}, a1[6], a2[6], a3[6];
  CHECK_STATUS(cncrot_machine_tcp_inverse(&h, pose, 50, prev, a1), CNCROT_STATUS_OK);
  cncrot_machine sealed = h;
  CHECK_STATUS(cncrot_machine_seal(&sealed), CNCROT_STATUS_OK);
  CHECK(sealed.reserved != 0 && sealed.axes[0].direction[0] == 1 && sealed.axes[1].direction[2] == 1,
        "seal: %u, directions %g %g", (unsigned)sealed.reserved, sealed.axes[0].direction[0],
        sealed.axes[1].direction[2]);
  CHECK(memcmp(&sealed, &m, sizeof m) == 0, "the sealed hand-filled table differs from the built one");
  CHECK_STATUS(cncrot_machine_tcp_inverse(&sealed, pose, 50, prev, a2), CNCROT_STATUS_OK);
  CHECK(memcmp(a1, a2, sizeof a1) == 0, "sealed and unsealed differ");
  /* Sealing twice changes nothing. */
  cncrot_machine again = sealed;
  CHECK_STATUS(cncrot_machine_seal(&again), CNCROT_STATUS_OK);
  CHECK(memcmp(&again, &sealed, sizeof again) == 0, "a second seal changed the description");
  /* An edit after sealing: A within ±10° now, so A = ±30° is out of travel. */
  sealed.axes[0].min_deg = -10;
  sealed.axes[0].max_deg = 10;
  double keep[6] = {7, 7, 7, 7, 7, 7}, seven[6] = {7, 7, 7, 7, 7, 7};
  CHECK_STATUS(cncrot_machine_tcp_inverse(&sealed, pose, 50, prev, keep), CNCROT_STATUS_OUT_OF_TRAVEL);
  CHECK_NEAR(keep, seven, 6, 0);
  sealed.axes[0].min_deg = -40;
  sealed.axes[0].max_deg = 40;
  CHECK_STATUS(cncrot_machine_seal(&sealed), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_machine_tcp_inverse(&sealed, pose, 50, prev, a3), CNCROT_STATUS_OK);
  CHECK(memcmp(a1, a3, sizeof a1) == 0, "limits that admit the solution changed it");
  /* An edited count with its old seal: checked, refused. */
  cncrot_machine bad = m;
  bad.count = 5;
  CHECK_STATUS(cncrot_machine_tcp_inverse(&bad, pose, 50, prev, keep), CNCROT_STATUS_BAD_ARGUMENT);
  /* Not a machine: refused, nothing written. */
  cncrot_machine zero = h, copy;
  zero.axes[1].direction[2] = 0;
  copy = zero;
  CHECK_STATUS(cncrot_machine_seal(&zero), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(memcmp(&zero, &copy, sizeof zero) == 0, "a refused seal wrote");
  CHECK_STATUS(cncrot_machine_seal(NULL), CNCROT_STATUS_NULL_POINTER);
}

/* Five-axis programs: each dialect's blocks read into CL points, and the axes for them
 * equal to the transformation's from the same tip and direction (the worked AC table). */
static void five_axis_programs(void) {
  cncrot_machine m;
  ac_table(&m);
  double s3 = sqrt(3.0);
  double want[6] = {0, 50 + 5 * s3, 155 - 50 * s3, 30, 90, 0}, prev[6] = {0, 0, 0, 20, 80, 0}, ax[6];
  static const struct {
    int32_t dialect;
    const char *lines[3];
  } programs[] = {
      {CNCROT_DIALECT_SINUMERIK, {"N10 TRAORI", "N20 G1 X10 Y0 Z0 A3=0.5 B3=0 C3=0.8660254037844386", NULL}},
      {CNCROT_DIALECT_SINUMERIK, {"TRAORI", "ORIEULER", "G1 X10 Y0 Z0 A2=90 B2=30"}},
      {CNCROT_DIALECT_HEIDENHAIN, {"1 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS", "2 L X+10 Y+0 Z+0 A+30 C+90 FMAX", NULL}},
      {CNCROT_DIALECT_HEIDENHAIN, {"1 L Z+100 R0 FMAX M128", "2 LN X+10 Y+0 Z+0 TX+0.5 TY+0 TZ+0.8660254037844386", NULL}},
      /* AXIS SPAT: B+30 a spatial angle, the direction Ry(30°)·e_z (flags bit 2). */
      {CNCROT_DIALECT_HEIDENHAIN, {"1 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS", "2 L X+10 Y+0 Z+0 A+0 B+30 C+0 FMAX", NULL}},
      {CNCROT_DIALECT_FANUC, {"G43.4 H1", "G1 X10. Y0. Z0. A30. C90.", NULL}},
      {CNCROT_DIALECT_SYNTEC, {"G43.5 H1", "G1 X10. Y0. Z0. I0.5 J0. K0.8660254037844386", NULL}},
      {CNCROT_DIALECT_HAAS, {"G234 H1", "G1 X10. Y0. Z0. A30. C90.", NULL}},
  };
  for (size_t k = 0; k < sizeof programs / sizeof programs[0]; k++) {
    cncrot_tool_path t;
    memset(&t, 0, sizeof t);
    int32_t s = 0;
    for (int j = 0; j < 3 && programs[k].lines[j]; j++)
      s = cncrot_tool_path_line(&t, programs[k].dialect, programs[k].lines[j], strlen(programs[k].lines[j]));
    CHECK(s == 0 && t.on == 1 && t.point == 1, "program %zu: status %d, on %d, point %d", k, s, t.on, t.point);
    double tip[3] = {10, 0, 0};
    CHECK_NEAR(t.tip, tip, 3, 0);
    CHECK_STATUS(cncrot_tool_path_axes(&t, &m, 50, prev, CNCROT_CHOOSE_CLOSEST, 0, ax), CNCROT_STATUS_OK);
    CHECK_NEAR(ax, want, 6, 1e-9);
  }
  /* Passed and not followed blocks leave the state byte for byte; refusals too. */
  cncrot_tool_path t, before;
  memset(&t, 0, sizeof t);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G43.5 H1", 8), CNCROT_STATUS_OK);
  CHECK(t.on == 1 && t.point == 0, "G43.5: on %d point %d", t.on, t.point);
  before = t;
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "M8", 2), CNCROT_STATUS_PASSED);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G1 I0 J0 K0", 11), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_TWINCAT, "G1 X1", 5), CNCROT_STATUS_NOT_AVAILABLE);
  CHECK_STATUS(cncrot_tool_path_line(&t, 99, "G1 X1", 5), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_tool_path_line(NULL, CNCROT_DIALECT_FANUC, "G1 X1", 5), CNCROT_STATUS_NULL_POINTER);
  CHECK(memcmp(&t, &before, sizeof t) == 0, "a passed or refused block changed the state");
  /* A reference-point return is not followed, and where the machine is after it is not
     known: the tip lost (flags bit 5), so an incremental move from it is not followed
     either, until a block states X Y Z absolutely. Its G91 is kept. */
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G91 G28 Z0.", 11), CNCROT_STATUS_NOT_FOLLOWED);
  CHECK(t.flags == (32 | 2) && memcmp(t.tip, before.tip, sizeof t.tip) == 0, "G91 G28: flags %d", t.flags);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "X10.", 4), CNCROT_STATUS_NOT_FOLLOWED);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G90", 3), CNCROT_STATUS_OK);
  CHECK(t.flags == 32, "G90: flags %d", t.flags);
  /* X, Y and Z known (flags bits 14 to 16): stated absolutely since the tip was lost. */
  const int KNOWN = 7 << 14;
  /* An arc's mode is modal until G1, a canned cycle's until G80: the blocks in them are
     not followed (an arc's I J K are its centre, not the tool); an arc's end point is
     taken, a hole's loses the tip. */
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G1 X1. Y2. Z3. I0. J0. K1.", 26), CNCROT_STATUS_OK);
  CHECK(t.flags == KNOWN && t.point == 1, "G1 X Y Z: flags %d", t.flags);
  before = t;
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G2 X1. Y1. R1.", 14), CNCROT_STATUS_NOT_FOLLOWED);
  CHECK(t.flags == (KNOWN | 8) && t.point == 0, "G2: flags %d point %d", t.flags, t.point);
  CHECK(t.tip[0] == 1 && t.tip[1] == 1 && t.tip[2] == 3 &&
            memcmp(t.direction, before.direction, sizeof t.direction) == 0,
        "an arc's end point: %g %g %g", t.tip[0], t.tip[1], t.tip[2]);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "X5. I1. J0. K0.", 15), CNCROT_STATUS_NOT_FOLLOWED);
  CHECK(memcmp(t.direction, before.direction, sizeof t.direction) == 0, "an arc's centre became the tool");
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G1 X4.", 6), CNCROT_STATUS_OK);
  CHECK(t.flags == KNOWN && t.point == 1 && t.tip[0] == 4 && t.tip[1] == 1, "G1 after G2: flags %d point %d", t.flags,
        t.point);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G81 X5. Y5. Z-3. R1.", 20), CNCROT_STATUS_NOT_FOLLOWED);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "X6.", 3), CNCROT_STATUS_NOT_FOLLOWED);
  CHECK(t.flags == (16 | 32) && t.tip[0] == 4, "G81: flags %d tip %g", t.flags, t.tip[0]);
  CHECK_STATUS(cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, "G80", 3), CNCROT_STATUS_OK);
  CHECK(t.flags == 32 && t.point == 0, "G80: flags %d", t.flags);
  cncrot_tool_path bad = t;
  bad.flags = 1 << 17;
  CHECK_STATUS(cncrot_tool_path_line(&bad, CNCROT_DIALECT_FANUC, "X1", 2), CNCROT_STATUS_BAD_STATE);
  bad = t;
  bad.direction[0] = 2;
  bad.orientation = CNCROT_ORIENTATION_DIRECTION;
  CHECK_STATUS(cncrot_tool_path_line(&bad, CNCROT_DIALECT_FANUC, "X1", 2), CNCROT_STATUS_BAD_STATE);
  double keep[6] = {7, 7, 7, 7, 7, 7}, seven[6] = {7, 7, 7, 7, 7, 7};
  CHECK_STATUS(cncrot_tool_path_axes(&bad, &m, 50, prev, 0, 0, keep), CNCROT_STATUS_BAD_STATE);
  CHECK_NEAR(keep, seven, 6, 0);
}

int main(void) {
  fork_head();
  sealed_descriptions();
  five_axis_programs();
  table_and_mixed();
  nutating_and_three_axes();
  cycle600_and_refusals();
  travel_ends();
  hand_filled_descriptions();
  five_axis_transformation();
  return finish("test_kinematics");
}
