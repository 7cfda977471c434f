/* Program lines through the C interface: the vendors' example lines (TwinCAT, Syntec), the
 * worked numbers of docs/dialects.md, SINUMERIK's documented read-back, the paper's CYCLE600
 * call equal to its CYCLE800 call and to PLANE SPATIAL, hand geometry with the C library's
 * trigonometry; every writer's line converted into every other dialect and back; refused
 * lines with their columns and the state byte-identical; the writer's buffer rules. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cncrot.h"
#include "harness.h"
#include "geometry.h"

/* Applies lines in order to a fresh program; returns the status of the first refusal. */
static int32_t run(int32_t dialect, const char *const *lines, int n, double f[16]) {
  cncrot_program p;
  memset(&p, 0, sizeof p);
  for (int k = 0; k < n; k++) {
    int32_t s = cncrot_program_line(&p, dialect, lines[k], strlen(lines[k]));
    if (s < 0) return s;
  }
  return cncrot_program_frame(&p, f);
}

static void one(int32_t dialect, const char *line, double r[9]) {
  double f[16];
  CHECK_STATUS(run(dialect, &line, 1, f), CNCROT_STATUS_OK);
  rot_of(f, r);
}

static void vendors(void) {
  double f[16], r[9], want[9];
  /* TwinCAT: ROT Z30, then AROT Z15, is 45 about Z; CalcInvRot of (40, 10, 0) after ROT Z45
   * is (35.36, -21.21, 0). */
  const char *tc[] = {"N65 ROT Z30", "N90 AROT Z15 (add)"};
  CHECK_STATUS(run(CNCROT_DIALECT_TWINCAT, tc, 2, f), CNCROT_STATUS_OK);
  rot_of(f, r);
  elem(3, 45, want);
  CHECK_NEAR(r, want, 9, 1e-15);
  one(CNCROT_DIALECT_TWINCAT, "N30 ROT Z45", r);
  double v[3] = {40, 10, 0}, back[3];
  for (int k = 0; k < 3; k++) back[k] = r[k] * v[0] + r[3 + k] * v[1] + r[6 + k] * v[2];
  CHECK(fabs(back[0] - 35.3553) < 1e-4 && fabs(back[1] + 21.2132) < 1e-4, "%g %g", back[0], back[1]);
  /* The manual's zero offset shift: the rotation turns about the whole shift, which G58 sets
   * (Z omitted: 0) and moves with it. */
  const char *shifted[] = {"N60 G58 X200 Y200", "N65 ROT Z30", "N80 G58 X0 Y200", "N90 AROT Z15"};
  CHECK_STATUS(run(CNCROT_DIALECT_TWINCAT, shifted, 4, f), CNCROT_STATUS_OK);
  rot_of(f, r);
  elem(3, 45, want);
  CHECK_NEAR(r, want, 9, 1e-15);
  double tc_origin[3] = {0, 200, 0}, tc_got[3] = {f[3], f[7], f[11]};
  CHECK_NEAR(tc_got, tc_origin, 3, 0);
  /* Heidenhain: a datum shift programmed under a tilt shifts the tilted system. SPB+30 is
   * Ry(30): X' = (cos 30, 0, -sin 30), so X+10 puts the datum at (8.6603, 0, -5). */
  const char *tilted_shift[] = {"PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY", "CYCL DEF 7.1 X+10"};
  CHECK_STATUS(run(CNCROT_DIALECT_HEIDENHAIN, tilted_shift, 2, f), CNCROT_STATUS_OK);
  double ts_want[3] = {5 * sqrt(3.0), 0, -5}, ts_got[3] = {f[3], f[7], f[11]};
  CHECK_NEAR(ts_got, ts_want, 3, 1e-12);

  /* Syntec: translate (2, 0, 10), turn X 20, Y' 20, Z'' -30, then (0, 10, 0) in the turned
   * system. */
  const char *sy = "G158 L1 P10157 X2. Y0. Z10. A20 B20 C-30 U0 V10 W0";
  CHECK_STATUS(run(CNCROT_DIALECT_SYNTEC, &sy, 1, f), CNCROT_STATUS_OK);
  rot_of(f, r);
  intrinsic(1, 2, 3, 20, 20, -30, want);
  CHECK_NEAR(r, want, 9, 1e-14);
  double o[3] = {2 + 10 * want[1], 10 * want[4], 10 + 10 * want[7]}, got[3] = {f[3], f[7], f[11]};
  CHECK_NEAR(got, o, 3, 1e-13);
  const char *twice[] = {"G158 L3 P01159 X0 Y0 Z0 A0 B0 C10 U0 V0 W0",
                         "G158 L3 P01159 X0 Y0 Z0 A0 B0 C10 U0 V0 W0 ;Increment and then turn"};
  CHECK_STATUS(run(CNCROT_DIALECT_SYNTEC, twice, 2, f), CNCROT_STATUS_OK);
  rot_of(f, r);
  elem(3, 20, want);
  CHECK_NEAR(r, want, 9, 1e-15);
  const char *direct = "G158 L3 P10200 X0 Y0 Z10 A0 B20 C45 U0 V0 W0";
  CHECK_STATUS(run(CNCROT_DIALECT_SYNTEC, &direct, 1, f), CNCROT_STATUS_NOT_AVAILABLE);

  /* The worked numbers: PLANE SPATIAL SPA27 SPB0 SPC45, PLANE EULER 45 20 22, ROTS X30 Y20,
   * and PLANE PROJECTED with the same projections. */
  double spatial[9] = {0.707107, -0.630037, 0.321020, 0.707107, 0.630037, -0.321020, 0, 0.453990, 0.891007};
  double euler[9] = {0.406706, -0.880966, 0.241845, 0.904530, 0.351193, -0.241845, 0.128123, 0.317116, 0.939693};
  double rots[9] = {0.939693, 0.163099, 0.300627, 0, 0.878973, -0.476871, -0.342020, 0.448112, 0.825965};
  one(CNCROT_DIALECT_HEIDENHAIN, "5 PLANE SPATIAL SPA+27 SPB+0 SPC+45 TURN MB MAX FMAX SEQ-", r);
  CHECK_NEAR(r, spatial, 9, 1e-6);
  one(CNCROT_DIALECT_HEIDENHAIN, "6 PLANE EULER EULPR45 EULNU20 EULROT22 STAY ; Euler", r);
  CHECK_NEAR(r, euler, 9, 1e-6);
  one(CNCROT_DIALECT_SINUMERIK, "N10 ROTS X30 Y20", r);
  CHECK_NEAR(r, rots, 9, 1e-6);
  one(CNCROT_DIALECT_SINUMERIK, "N20 CYCLE800(1,\"TC1\",0,185,0,0,0,30,20,0,0,0,0,-1,100,1)", r);
  CHECK_NEAR(r, rots, 9, 1e-6);
  one(CNCROT_DIALECT_HEIDENHAIN, "PLANE PROJECTED PROPR+20 PROMIN+30 PROROT+0 STAY", r);
  CHECK_NEAR(r, rots, 9, 1e-6);

  /* The paper's Example 3: CYCLE600 with the probe angles (30, 45, 60 about the machine X, Y,
   * Z) gives CYCLE800 37.7923 20.7048 49.1066 (intrinsic Z, X', Y''): the same plane, and
   * the same as PLANE SPATIAL with the probe angles. */
  double a[9], b[9], c[9];
  one(CNCROT_DIALECT_SINUMERIK, "N120 CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)", a);
  one(CNCROT_DIALECT_SINUMERIK, "N130 CYCLE800(0,\"\",0,39,0,0,0,37.7923,20.7048,49.1066,0,0,0,-1)", b);
  one(CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+30 SPB+45 SPC+60 STAY", c);
  CHECK_NEAR(a, b, 9, 1e-5);
  CHECK_NEAR(a, c, 9, 1e-15);
  elem(3, 60, want);
  mul3(want, (elem(2, 45, r), r), want);
  elem(1, 30, r);
  mul3(want, r, want);
  CHECK_NEAR(c, want, 9, 1e-15);

  /* G68.2: origin, then Z, X', Z''; two G68.4 by 15 are one by 30; Haas Q123 about the
   * fixed axes. */
  one(CNCROT_DIALECT_FANUC, "N10 G68.2 X10. Y0 Z0 I30. J45. K60. (TILT)", r);
  intrinsic(3, 1, 3, 30, 45, 60, want);
  CHECK_NEAR(r, want, 9, 1e-15);
  const char *inc[] = {"G68.4 I0 J15 K0", "G68.4 I0 J15 K0"};
  CHECK_STATUS(run(CNCROT_DIALECT_FANUC, inc, 2, f), CNCROT_STATUS_OK);
  rot_of(f, r);
  elem(1, 30, want);
  CHECK_NEAR(r, want, 9, 1e-15);
  one(CNCROT_DIALECT_HAAS, "G268 X0 Y0 Z0 I10 J20 K30 Q123", r);
  intrinsic(3, 2, 1, 30, 20, 10, want);
  CHECK_NEAR(r, want, 9, 1e-15);
}

/* SINUMERIK reads back CROT(x,10,y,90,z,40) as x 0, y 90, z 30 and CROT(x,190,y,0,z,-200)
 * as x -170, y 0, z 160 (its manual); PLANE SPATIAL's rule puts the free angle in SPA. */
static void readback_and_rules(void) {
  double f[16];
  char out[CNCROT_PROGRAM_LINE_MAX + 1];
  const char *l1 = "ROT X10 Y90 Z40";
  CHECK_STATUS(run(CNCROT_DIALECT_SINUMERIK, &l1, 1, f), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_SINUMERIK, "ROT", f, 4, out, sizeof out), CNCROT_STATUS_SINGULAR);
  CHECK(strcmp(out, "ROT X=0 Y=90 Z=30") == 0, "%s", out);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", f, 4, out, sizeof out), CNCROT_STATUS_SINGULAR);
  CHECK(strcmp(out, "PLANE SPATIAL SPA-30 SPB+90 SPC+0 STAY") == 0, "%s", out);
  const char *l2 = "ROT X190 Y0 Z-200";
  CHECK_STATUS(run(CNCROT_DIALECT_SINUMERIK, &l2, 1, f), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_SINUMERIK, "rot", f, 4, out, sizeof out), CNCROT_STATUS_OK);
  CHECK(strcmp(out, "ROT X=-170 Y=0 Z=160") == 0, "%s", out);
  const char *l3 = "G68.2 X10 I0 J30 K0";
  CHECK_STATUS(run(CNCROT_DIALECT_FANUC, &l3, 1, f), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, 3, out, sizeof out), CNCROT_STATUS_OK);
  CHECK(strcmp(out, "G68.2 X10. Y0. Z0. I0. J30. K0.") == 0, "%s", out);
  /* The shortest numbers that read back: 0.1 + 0.2 is not 0.3. */
  double g[16];
  const char *l4 = "ROT Z0.30000000000000004";
  CHECK_STATUS(run(CNCROT_DIALECT_TWINCAT, &l4, 1, g), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_TWINCAT, "ROT", g, -1, out, sizeof out), CNCROT_STATUS_OK);
  const char *echo = out;
  double h[16];
  CHECK_STATUS(run(CNCROT_DIALECT_TWINCAT, &echo, 1, h), CNCROT_STATUS_OK);
  CHECK(memcmp(g, h, sizeof g) == 0, "%s does not read back bit for bit", out);
}

static const struct {
  int32_t dialect;
  const char *form;
  int origin;
} FORMS[] = {
    {CNCROT_DIALECT_SINUMERIK, "CYCLE800", 1},       {CNCROT_DIALECT_SINUMERIK, "CYCLE800 27", 1},
    {CNCROT_DIALECT_SINUMERIK, "CYCLE800 64", 1},    {CNCROT_DIALECT_SINUMERIK, "ROT", 0},
    {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 0}, {CNCROT_DIALECT_HEIDENHAIN, "PLANE EULER", 0},
    {CNCROT_DIALECT_HEIDENHAIN, "PLANE VECTOR", 0},  {CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", 0},
    {CNCROT_DIALECT_FANUC, "G68.2", 1},              {CNCROT_DIALECT_SYNTEC, "G158", 1},
    {CNCROT_DIALECT_SYNTEC, "G158 P10139", 1},       {CNCROT_DIALECT_SYNTEC, "G68.2", 1},
    {CNCROT_DIALECT_TWINCAT, "ROT", 0},              {CNCROT_DIALECT_HAAS, "G268 Q321", 1},
};
#define NFORMS ((int)(sizeof FORMS / sizeof FORMS[0]))

/* Writes frame f in form k and reads it back; returns the status. */
static int32_t through(int k, const double f[16], int decimals, double g[16]) {
  char out[CNCROT_PROGRAM_LINE_MAX + 1];
  int32_t s = cncrot_program_write(FORMS[k].dialect, FORMS[k].form, f, decimals, out, sizeof out);
  if (s < 0) return s;
  const char *line = out;
  return run(FORMS[k].dialect, &line, 1, g);
}

/* Random frames and singular ones (a new axis on an old one), through every pair of forms. */
static void every_pair_converts(void) {
  int pairs = 0;
  for (int n = 0; n < 40; n++) {
    double r[9], f[16] = {0}, rot_only[16] = {0};
    if (n < 30) {
      intrinsic(3, 2, 1, rnd(-180, 180), rnd(-90, 90), rnd(-180, 180), r);
    } else {
      double twist = (n % 3) * 55.0, mid = (n % 2) ? 90 : 180;
      intrinsic(3, 1 + n % 2, 3, twist, mid, 40 - twist, r);
    }
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) f[4 * i + j] = rot_only[4 * i + j] = r[3 * i + j];
    f[3] = rnd(-500, 500), f[7] = rnd(-500, 500), f[11] = rnd(-500, 500);
    f[15] = rot_only[15] = 1;
    for (int a = 0; a < NFORMS; a++)
      for (int b = 0; b < NFORMS; b++) {
        const double *src = FORMS[a].origin && FORMS[b].origin ? f : rot_only;
        double ga[16], gb[16];
        CHECK_STATUS(through(a, src, -1, ga), CNCROT_STATUS_OK);
        CHECK_STATUS(through(b, ga, -1, gb), CNCROT_STATUS_OK);
        CHECK_NEAR(gb, src, 16, 1e-12);
        pairs++;
      }
    /* Rounded to 4 decimals: angles within 5e-5 degrees, coordinates within 5e-5. */
    for (int a = 0; a < NFORMS; a++) {
      double g[16];
      CHECK_STATUS(through(a, FORMS[a].origin ? f : rot_only, 4, g), CNCROT_STATUS_OK);
      CHECK_NEAR(g, FORMS[a].origin ? f : rot_only, 16, 2e-4);
    }
  }
  CHECK(pairs == 40 * NFORMS * NFORMS, "%d pairs", pairs);
}

/* A program of `dialect` with a tilt active, for the cases that must leave it as it is. */
static void tilted(int32_t dialect, cncrot_program *p) {
  memset(p, 0, sizeof *p);
  const char *start = dialect == CNCROT_DIALECT_HEIDENHAIN ? "PLANE SPATIAL SPA+0 SPB+30 SPC+0"
                      : dialect == CNCROT_DIALECT_SINUMERIK ? "ROT Z30"
                      : dialect == CNCROT_DIALECT_TWINCAT   ? "ROT Z30"
                      : dialect == CNCROT_DIALECT_HAAS      ? "G268 K30 Q123"
                                                            : "G68.2 K30";
  CHECK_STATUS(cncrot_program_line(p, dialect, start, strlen(start)), CNCROT_STATUS_OK);
}

/* The working plane: G18 is kept (the frame unchanged), ROT RPL=30 then turns about Y;
 * Fanuc's G18 G68 Z X R about Y through the centre: Ry(30) about (10, 0, 0) moves the
 * origin to (10 - 5*sqrt(3), 0, 5). */
static void planes(void) {
  cncrot_program p;
  memset(&p, 0, sizeof p);
  CHECK(p.plane == CNCROT_PLANE_XY, "plane %d", (int)p.plane);
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_SINUMERIK, "N10 G18 G0 X0", 13), CNCROT_STATUS_OK);
  CHECK(p.plane == CNCROT_PLANE_ZX && p.active == 0, "plane %d, active %d", (int)p.plane, (int)p.active);
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_SINUMERIK, "ROT RPL=30", 10), CNCROT_STATUS_OK);
  double f[16], want[9];
  CHECK_STATUS(cncrot_program_frame(&p, f), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_matrix_from_angles(0, 57, (double[3]){0, 30, 0}, want), CNCROT_STATUS_OK);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) CHECK(fabs(f[4 * i + j] - want[3 * i + j]) < 1e-15, "RPL in G18: f[%d][%d] %g", i, j, f[4 * i + j]);
  memset(&p, 0, sizeof p);
  const char *g68 = "G18 G68 Z0 X10. R30.";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, g68, strlen(g68)), CNCROT_STATUS_OK);
  CHECK(p.plane == CNCROT_PLANE_ZX, "plane %d", (int)p.plane);
  CHECK(fabs(p.origin[0] - (10 - 5 * sqrt(3.0))) < 1e-13 && p.origin[1] == 0 && fabs(p.origin[2] - 5) < 1e-13,
        "origin %g %g %g", p.origin[0], p.origin[1], p.origin[2]);
  /* A plane that is not one: refused as a state the library did not write. */
  cncrot_program bad = p;
  bad.plane = 3;
  CHECK_STATUS(cncrot_program_frame(&bad, f), CNCROT_STATUS_BAD_STATE);
}

/* Every block of a program: blocks that do not concern the frame are passed over, blocks
 * that change it in ways the library does not follow say so; both leave the state
 * byte-identical and are successes. */
static void whole_programs(void) {
  static const struct {
    int32_t dialect;
    const char *line;
    int32_t status;
  } cases[] = {
      {CNCROT_DIALECT_HEIDENHAIN, "1 TOOL CALL 5 Z S8000", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_HEIDENHAIN, "2 L X+10 Y+0 FMAX M3", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_HEIDENHAIN, "3 CYCL DEF 7.0 DATUM SHIFT", CNCROT_STATUS_OK},
      {CNCROT_DIALECT_HEIDENHAIN, "3 CYCL DEF 7.1 #4", CNCROT_STATUS_NOT_FOLLOWED},
      {CNCROT_DIALECT_HEIDENHAIN, "", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_FANUC, "N10 G0 G90 X0 Y0 M3 S5000", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_FANUC, "N20 G54.1 P2", CNCROT_STATUS_NOT_FOLLOWED},
      {CNCROT_DIALECT_FANUC, "#5221=10.", CNCROT_STATUS_NOT_FOLLOWED},
      {CNCROT_DIALECT_SINUMERIK, "N10 T=\"MILL\" D1 M6", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_SINUMERIK, "N20 G55", CNCROT_STATUS_NOT_FOLLOWED},
      {CNCROT_DIALECT_SINUMERIK, "; comment", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_TWINCAT, "N10 G01 X10 F100", CNCROT_STATUS_PASSED},
      {CNCROT_DIALECT_HAAS, "G154 P3", CNCROT_STATUS_NOT_FOLLOWED},
      {CNCROT_DIALECT_SYNTEC, "G51.1 X0", CNCROT_STATUS_NOT_FOLLOWED},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    cncrot_program p, before;
    tilted(cases[k].dialect, &p);
    before = p;
    size_t column = 999;
    CHECK_STATUS(cncrot_program_line(&p, cases[k].dialect, cases[k].line, strlen(cases[k].line)), cases[k].status);
    CHECK(memcmp(&p, &before, sizeof p) == 0, "%s changed the state", cases[k].line);
    CHECK_STATUS(cncrot_program_column(&p, cases[k].dialect, cases[k].line, strlen(cases[k].line), &column),
                 cases[k].status);
    CHECK(column == 0, "%s: column %zu", cases[k].line, column);
  }
  /* What a refused block should have had: the missing word, a cycle parameter's values;
   * nothing where the reader names nothing or the block is read. */
  struct {
    int32_t dialect;
    const char *line;
    int32_t status;
    const char *what;
  } expected[] = {
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+10 SPB+0", CNCROT_STATUS_MISSING_WORD, "SPC"},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+10 SPB+0 SPC+0 TABLE", CNCROT_STATUS_MISSING_WORD, "ROT"},
      {CNCROT_DIALECT_HAAS, "G268 X0 I0 J30 K0", CNCROT_STATUS_MISSING_WORD, "Q"},
      {CNCROT_DIALECT_FANUC, "G68.2 X", CNCROT_STATUS_MISSING_WORD, "a number"},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE600(0,\"A B\",1,57,0,0,0,30,45,60,0,0,0,1,39)", CNCROT_STATUS_BAD_ARGUMENT,
       "_MIHEAD: empty, or at most 31 printable characters without spaces or quotes"},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPX+10", CNCROT_STATUS_UNKNOWN_WORD, ""},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE RESET STAY", CNCROT_STATUS_OK, ""},
  };
  for (size_t k = 0; k < sizeof expected / sizeof expected[0]; k++) {
    cncrot_program p0;
    memset(&p0, 0, sizeof p0);
    char what[CNCROT_PROGRAM_EXPECTED_SIZE];
    memset(what, 'x', sizeof what);
    CHECK_STATUS(cncrot_program_expected(&p0, expected[k].dialect, expected[k].line, strlen(expected[k].line), what,
                                         sizeof what),
                 expected[k].status);
    CHECK(strcmp(what, expected[k].what) == 0, "%s: \"%s\"", expected[k].line, what);
  }
  {
    cncrot_program p0;
    memset(&p0, 0, sizeof p0);
    char small[CNCROT_PROGRAM_EXPECTED_SIZE - 1];
    memset(small, 'x', sizeof small);
    CHECK_STATUS(cncrot_program_expected(&p0, CNCROT_DIALECT_HAAS, "G268", 4, small, sizeof small),
                 CNCROT_STATUS_NO_ROOM);
    CHECK(small[0] == 'x', "written without room");
    CHECK_STATUS(cncrot_program_expected(&p0, CNCROT_DIALECT_HAAS, "G268", 4, NULL, 96), CNCROT_STATUS_NULL_POINTER);
  }
  /* A datum shift and a tilt with its choice word: the state keeps both, the plane tilts
   * about the shifted datum, PLANE RESET keeps the shift, and the fork head's SEQ- puts
   * its master axis (B, nearest the tool) at -30, the closest choice at +30. */
  {
    static const char *prog[] = {"CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+10", "CYCL DEF 7.2 Y+20",
                                 "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN SEQ-"};
    cncrot_program q;
    memset(&q, 0, sizeof q);
    for (size_t k = 0; k < 4; k++) CHECK(cncrot_program_line(&q, CNCROT_DIALECT_HEIDENHAIN, prog[k], strlen(prog[k])) >= 0, "%s", prog[k]);
    CHECK(q.shift[0] == 10 && q.shift[1] == 20 && q.shift[2] == 0, "shift %g %g %g", q.shift[0], q.shift[1], q.shift[2]);
    CHECK(q.origin[0] == 10 && q.origin[1] == 20 && q.origin[2] == 0, "origin");
    CHECK(q.choice == CNCROT_CHOOSE_MINUS && q.reference_axis == 0, "choice %d %d", q.choice, q.reference_axis);
    cncrot_machine head;
    static const char carr[] = "$TC_CARR9[1]=1 $TC_CARR11[1]=1 $TC_CARR23[1]=\"T\"\n";
    CHECK_STATUS(cncrot_machine_from_carr(&head, carr, sizeof carr - 1, 1), CNCROT_STATUS_OK);
    double cur[3] = {0, 0, 0}, ax[3];
    CHECK(cncrot_program_axes(&q, &head, cur, ax) >= 0 && fabs(ax[1] + 30) < 1e-9, "SEQ-: B %g", ax[1]);
    CHECK_STATUS(cncrot_program_line(&q, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN", 37),
                 CNCROT_STATUS_OK);
    CHECK(q.choice == CNCROT_CHOOSE_CLOSEST, "choice kept by a plane without words");
    CHECK(cncrot_program_axes(&q, &head, cur, ax) >= 0 && fabs(ax[1] - 30) < 1e-9, "closest: B %g", ax[1]);
    CHECK_STATUS(cncrot_program_line(&q, CNCROT_DIALECT_HEIDENHAIN, "PLANE RESET STAY", 16), CNCROT_STATUS_OK);
    CHECK(q.active == 1 && q.origin[0] == 10 && q.rotation[0] == 1, "reset kept the shift");
    /* A choice the library did not write: refused. */
    cncrot_program edited = q;
    edited.choice = 7;
    CHECK_STATUS(cncrot_program_line(&edited, CNCROT_DIALECT_HEIDENHAIN, "PLANE RESET", 11), CNCROT_STATUS_BAD_STATE);
    /* G53.1 P2: the primary axis (C, which carries B) turns down only, B the shortest way.
     * The solutions are (C 0, B 30) and (C 180, B -30): from C 20, down reaches 0 after
     * 20 degrees; up (P1) reaches 180 after 160 degrees. As the machine's own choice under
     * that rule on axis 1, bit for bit. */
    cncrot_program g;
    memset(&g, 0, sizeof g);
    static const char *fanuc[] = {"G68.2 X0 Y0 Z0 I90 J30 K-90", "G53.1 P2"};
    for (size_t k = 0; k < 2; k++) CHECK(cncrot_program_line(&g, CNCROT_DIALECT_FANUC, fanuc[k], strlen(fanuc[k])) >= 0, "%s", fanuc[k]);
    CHECK(g.choice == CNCROT_CHOOSE_NEGATIVE_TURN && g.reference_axis == 0 && g.positioning == CNCROT_POSITIONING_TURN,
          "G53.1 P2: %d %d %d", g.choice, g.reference_axis, g.positioning);
    double from[3] = {20, -25, 0}, down[3], gf[16], want[3], wres[3], wrem[16];
    CHECK_STATUS(cncrot_program_axes(&g, &head, from, down), CNCROT_STATUS_OK);
    CHECK(fabs(down[0]) < 1e-9 && fabs(down[1] - 30) < 1e-9, "G53.1 P2: C %g B %g", down[0], down[1]);
    CHECK_STATUS(cncrot_program_frame(&g, gf), CNCROT_STATUS_OK);
    CHECK_STATUS(cncrot_machine_choose(&head, gf, from, CNCROT_CHOOSE_NEGATIVE_TURN, 1, want, wres, wrem), CNCROT_STATUS_OK);
    CHECK(memcmp(down, want, sizeof down) == 0, "program_axes is the machine's choice");
    {
      cncrot_program up = g;
      double ax1[3];
      CHECK_STATUS(cncrot_program_line(&up, CNCROT_DIALECT_FANUC, "G53.1 P1", 8), CNCROT_STATUS_OK);
      CHECK_STATUS(cncrot_program_axes(&up, &head, from, ax1), CNCROT_STATUS_OK);
      CHECK(fabs(ax1[0] - 180) < 1e-9 && fabs(ax1[1] + 30) < 1e-9, "G53.1 P1: C %g B %g", ax1[0], ax1[1]);
    }
    /* P3 names no way to turn: refused at the value, the state untouched. */
    cncrot_program before = g;
    CHECK_STATUS(cncrot_program_line(&g, CNCROT_DIALECT_FANUC, "G53.1 P3", 8), CNCROT_STATUS_BAD_ARGUMENT);
    CHECK(memcmp(&g, &before, sizeof g) == 0, "untouched");
    /* The retraction and feed of the turn: MB 50 along the tool axis at 2000 mm/min; in
     * CYCLE800 terms _FR 5 with _FR_I 50 (the feed has no parameter there). */
    cncrot_program h, none;
    memset(&h, 0, sizeof h);
    memset(&none, 0, sizeof none);
    static const char mb[] = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 F2000 SEQ-";
    CHECK_STATUS(cncrot_program_line(&h, CNCROT_DIALECT_HEIDENHAIN, mb, sizeof mb - 1), CNCROT_STATUS_OK);
    CHECK(h.retract == CNCROT_RETRACT_TOOL && h.retract_mm == 50 && h.feed == CNCROT_FEED_RATE && h.feed_mm_min == 2000,
          "MB50 F2000: %d %g %d %g", h.retract, h.retract_mm, h.feed, h.feed_mm_min);
    char text[CNCROT_PROGRAM_CHANGE_MAX + 1];
    CHECK_STATUS(cncrot_program_write_change(&none, &h, CNCROT_DIALECT_SINUMERIK, "CYCLE800", 4, text, sizeof text),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(text, "CYCLE800(5,\"\",0,57,0,0,0,0,30,0,0,0,0,-1,50,0)") == 0, "%s", text);
    CHECK_STATUS(cncrot_program_write_change(&none, &h, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, text, sizeof text),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(text, mb) == 0, "%s", text);
    /* A retraction by hand without a length: refused. */
    cncrot_program edited2 = h;
    edited2.retract_mm = 0;
    CHECK_STATUS(cncrot_program_line(&edited2, CNCROT_DIALECT_HEIDENHAIN, "PLANE RESET", 11), CNCROT_STATUS_BAD_STATE);
  }
  /* A passed block on a fresh state leaves it all zero: not even the dialect is recorded. */
  cncrot_program fresh, zero;
  memset(&fresh, 0, sizeof fresh);
  memset(&zero, 0, sizeof zero);
  CHECK_STATUS(cncrot_program_line(&fresh, CNCROT_DIALECT_FANUC, "G1 X10", 6), CNCROT_STATUS_PASSED);
  CHECK(memcmp(&fresh, &zero, sizeof fresh) == 0, "a passed block wrote the state");
}

/* The fork head of the machine tests: C about Z carrying B about Y (B within +-100), the
 * pivot 150 mm above the tool adapter. */
static const char FORK_HEAD[] =
    "$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1 $TC_CARR10[1]=0 $TC_CARR11[1]=1 $TC_CARR12[1]=0\n"
    "$TC_CARR6[1]=-150 $TC_CARR23[1]=\"T\" $TC_CARR31[1]=-100 $TC_CARR33[1]=100\n";

/* The positions a program's tilt moves a machine to: the fork head from swivel data.
 * Ry(30°) is C 0, B 30 or C 180, B -30; from C 730 the first, C unwound to 720. Nothing
 * active: B 0 with C free, kept where it is. The same bits as cncrot_machine_choose with
 * CNCROT_CHOOSE_CLOSEST. */
static void program_axes(void) {
  cncrot_machine m;
  memset(&m, 0, sizeof m);
  CHECK_STATUS(cncrot_machine_from_carr(&m, FORK_HEAD, strlen(FORK_HEAD), 1), CNCROT_STATUS_OK);
  cncrot_program p;
  memset(&p, 0, sizeof p);
  double cur[3] = {730, 0, 0}, ax[3], want[3];
  CHECK_STATUS(cncrot_program_axes(&p, &m, cur, ax), CNCROT_STATUS_FREE_AXIS);
  CHECK(ax[0] == 730 && ax[1] == 0 && ax[2] == 0, "nothing active: %g %g %g", ax[0], ax[1], ax[2]);
  const char *l = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_HEIDENHAIN, l, strlen(l)), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_axes(&p, &m, cur, ax), CNCROT_STATUS_OK);
  CHECK(fabs(ax[0] - 720) < 1e-9 && fabs(ax[1] - 30) < 1e-9 && ax[2] == 0, "Ry(30): %g %g %g", ax[0], ax[1], ax[2]);
  double f[16], res[3], rem[16];
  cncrot_program_frame(&p, f);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur, CNCROT_CHOOSE_CLOSEST, 0, want, res, rem), CNCROT_STATUS_OK);
  CHECK(memcmp(ax, want, sizeof ax) == 0, "not the closest choice");
  /* SEQ-: the master axis (B, the one nearest the tool) at its lower position, as
   * cncrot_machine_choose with minus on axis 2 (C 900, the half turn nearest 730, B -30),
   * but as Heidenhain's SEQ gives it: the angles themselves, C 180, not wound toward C. */
  const char *seq = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_HEIDENHAIN, seq, strlen(seq)), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_axes(&p, &m, cur, ax), CNCROT_STATUS_OK);
  CHECK(fabs(ax[0] - 180) < 1e-9 && fabs(ax[1] + 30) < 1e-9 && ax[2] == 0, "SEQ-: %g %g %g", ax[0], ax[1], ax[2]);
  CHECK_STATUS(cncrot_machine_choose(&m, f, cur, CNCROT_CHOOSE_MINUS, 2, want, res, rem), CNCROT_STATUS_OK);
  CHECK(fabs(want[0] - 900) < 1e-9 && fabs(ax[1] - want[1]) < 1e-9, "the minus choice on axis 2: %g %g", want[0], want[1]);
  /* Refusals leave the output untouched. */
  double keep[3] = {1, 2, 3}, out[3] = {1, 2, 3}, nan_cur[3] = {NAN, 0, 0};
  CHECK_STATUS(cncrot_program_axes(&p, &m, nan_cur, out), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(cncrot_program_axes(&p, NULL, cur, out), CNCROT_STATUS_NULL_POINTER);
  cncrot_program bad = p;
  bad.origin[2] = 1;
  CHECK_STATUS(cncrot_program_axes(&bad, &m, cur, out), CNCROT_STATUS_BAD_STATE);
  double far[3] = {0, 0, 5};
  CHECK_STATUS(cncrot_program_axes(&p, &m, far, out), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(memcmp(out, keep, sizeof out) == 0, "a refusal wrote the output");
}

/* Refused lines: the status, the column of the first bad character, the state untouched. */
/* Direct modes keep the rotary-axis positions; the machine gives the frame. On the fork
 * head (C about Z carrying B about Y, a head: the tool frame is Rz(C)·Ry(B)), PLANE AXIAL
 * B+30 C+45 and a CYCLE800 direct with _A = 45 (axis 1, C), _B = 30 (axis 2, B) are both
 * Rz(45)·Ry(30), written out by hand below. */
static void direct_modes(void) {
  cncrot_machine m;
  memset(&m, 0, sizeof m);
  CHECK_STATUS(cncrot_machine_from_carr(&m, FORK_HEAD, strlen(FORK_HEAD), 1), CNCROT_STATUS_OK);
  const double c = sqrt(0.5), cb = sqrt(3) / 2, sb = 0.5;
  /* Rz(45)·Ry(30), row-major. */
  const double want[9] = {c * cb, -c, c * sb, c * cb, c, c * sb, -sb, 0, cb};
  static const struct {
    int32_t dialect;
    const char *line;
    int32_t active;
    double angles[3], origin[3];
    uint32_t given;
  } cases[] = {
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE AXIAL B+30 C+45 TURN FMAX", 2, {0, 30, 45}, {0, 0, 0}, 6},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE800(0,\"TC1\",0,192,5,0,0,45,30,0,0,0,0,-1)", 3, {45, 30, 0}, {5, 0, 0}, 3},
      {CNCROT_DIALECT_SYNTEC, "G158 P10200 X0 Y0 Z10 A0 B30 C45", 2, {0, 30, 45}, {0, 0, 10}, 7},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    cncrot_program p;
    memset(&p, 0, sizeof p);
    const char *l = cases[k].line;
    CHECK_STATUS(cncrot_program_line(&p, cases[k].dialect, l, strlen(l)), CNCROT_STATUS_OK);
    CHECK(p.active == cases[k].active && p.direct_given == cases[k].given, "%s: active %d", l, p.active);
    CHECK(memcmp(p.angles, cases[k].angles, sizeof p.angles) == 0, "%s: angles", l);
    CHECK(p.positioning == CNCROT_POSITIONING_TURN, "%s: positioning", l);
    double f[16], keep[16];
    for (int i = 0; i < 16; i++) f[i] = keep[i] = -7;
    CHECK_STATUS(cncrot_program_frame(&p, f), CNCROT_STATUS_NOT_AVAILABLE);
    CHECK(memcmp(f, keep, sizeof f) == 0, "%s: a refusal wrote the frame", l);
    CHECK_STATUS(cncrot_program_frame_on(&p, &m, f), CNCROT_STATUS_OK);
    for (int i = 0; i < 3; i++) {
      CHECK_NEAR(&f[4 * i], &want[3 * i], 3, 1e-15);
      CHECK(f[4 * i + 3] == cases[k].origin[i], "%s: origin", l);
    }
    /* The modulo C's turn nearest 730; B as stated. */
    double cur[3] = {730, 0, 0}, ax[3];
    CHECK_STATUS(cncrot_program_axes(&p, &m, cur, ax), CNCROT_STATUS_OK);
    CHECK(ax[0] == 765 && ax[1] == 30 && ax[2] == 0, "%s: %g %g %g", l, ax[0], ax[1], ax[2]);
  }
  /* An A on a machine without one; B beyond its travel: refused, outputs untouched. */
  cncrot_program p;
  memset(&p, 0, sizeof p);
  const char *a = "PLANE AXIAL A+10 B+30";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_HEIDENHAIN, a, strlen(a)), CNCROT_STATUS_OK);
  double f[16] = {0}, cur[3] = {0, 0, 0}, ax[3] = {1, 2, 3};
  CHECK_STATUS(cncrot_program_frame_on(&p, &m, f), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_program_axes(&p, &m, cur, ax), CNCROT_STATUS_BAD_ARGUMENT);
  const char *far = "PLANE AXIAL B+120";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_HEIDENHAIN, far, strlen(far)), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_axes(&p, &m, cur, ax), CNCROT_STATUS_OUT_OF_TRAVEL);
  CHECK(ax[0] == 1 && ax[1] == 2 && ax[2] == 3 && f[0] == 0, "a refusal wrote");
  /* Translated into the direct mode of a dialect that names the axes by letter. */
  cncrot_program before, after;
  memset(&before, 0, sizeof before);
  memset(&after, 0, sizeof after);
  const char *l = cases[0].line;
  CHECK_STATUS(cncrot_program_line(&after, CNCROT_DIALECT_HEIDENHAIN, l, strlen(l)), CNCROT_STATUS_OK);
  char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  CHECK_STATUS(cncrot_program_write_change(&before, &after, CNCROT_DIALECT_SYNTEC, "G158", 4, out, sizeof out),
               CNCROT_STATUS_OK);
  CHECK(strcmp(out, "G158 P10200 X0. Y0. Z0. A0. B30. C45. U0. V0. W0.") == 0, "%s", out);
  CHECK_STATUS(cncrot_program_write_change(&before, &after, CNCROT_DIALECT_FANUC, "G68.2", 4, out, sizeof out),
               CNCROT_STATUS_NOT_AVAILABLE);
}

static void refusals(void) {
  static const struct {
    int32_t dialect;
    const char *line;
    int32_t status;
    size_t column;
  } cases[] = {
      {CNCROT_DIALECT_SINUMERIK, "ROT X=R1", CNCROT_STATUS_NOT_A_NUMBER, 7},
      {CNCROT_DIALECT_SINUMERIK, "N10 ROT X10 X20", CNCROT_STATUS_UNKNOWN_WORD, 13},
      {CNCROT_DIALECT_SINUMERIK, "ROT X10 B5", CNCROT_STATUS_UNKNOWN_WORD, 9},
      /* Direct mode with a _C: a swivel data set has two axes. */
      {CNCROT_DIALECT_SINUMERIK, "CYCLE800(0,\"TC1\",0,192,0,0,0,0,30,5,0,0,0,-1)", CNCROT_STATUS_NOT_AVAILABLE, 35},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE800(0,\"TC1\",0", CNCROT_STATUS_MISSING_WORD, 19},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+Q120 SPB+0 SPC+0", CNCROT_STATUS_NOT_A_NUMBER, 19},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+0 SPB+0", CNCROT_STATUS_MISSING_WORD, 26},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE AXIAL", CNCROT_STATUS_MISSING_WORD, 12},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE AXIAL B+30 B+40", CNCROT_STATUS_UNKNOWN_WORD, 18},
      {CNCROT_DIALECT_FANUC, "G68.2 X0 Y0 Z0 I0 J#100 K0", CNCROT_STATUS_NOT_A_NUMBER, 20},
      {CNCROT_DIALECT_FANUC, "G68.2 J1.2.3", CNCROT_STATUS_PARSE, 11},
      {CNCROT_DIALECT_HAAS, "G268 X0 I0 J30 K0", CNCROT_STATUS_MISSING_WORD, 18},
      {CNCROT_DIALECT_TWINCAT, "ROT Z30 G1", CNCROT_STATUS_UNKNOWN_WORD, 9},
      {CNCROT_DIALECT_SYNTEC, "G158 P10957 A30", CNCROT_STATUS_BAD_ARGUMENT, 7},
      /* A bad value at its own column, an unclosed comment as malformed text. */
      {CNCROT_DIALECT_HAAS, "G268 Q123.5", CNCROT_STATUS_BAD_ARGUMENT, 7},
      {CNCROT_DIALECT_HAAS, "G268 X1 Q0", CNCROT_STATUS_BAD_SEQUENCE, 10},
      {CNCROT_DIALECT_SYNTEC, "G158 X0 P157", CNCROT_STATUS_BAD_ARGUMENT, 10},
      {CNCROT_DIALECT_SYNTEC, "G158 P10122 X0", CNCROT_STATUS_BAD_SEQUENCE, 7},
      {CNCROT_DIALECT_FANUC, "G68.2 X1 (comment", CNCROT_STATUS_PARSE, 10},
      {CNCROT_DIALECT_FANUC, "N5 G69 (no end", CNCROT_STATUS_PARSE, 8},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE600(2,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39)", CNCROT_STATUS_BAD_FLAG, 10},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE600(0,\"UFK600\",1,58,0,0,0,30,45,60,0,0,0,1,39)", CNCROT_STATUS_BAD_SEQUENCE, 23},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1, 7)", CNCROT_STATUS_INCOMPLETE_SEQUENCE, 50},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE600(0,\"U K\",1,57,0,0,0,30,45,60,0,0,0,1,39)", CNCROT_STATUS_BAD_ARGUMENT, 12},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    cncrot_program p, before;
    tilted(cases[k].dialect, &p);
    before = p;
    size_t column = 999;
    CHECK_STATUS(cncrot_program_line(&p, cases[k].dialect, cases[k].line, strlen(cases[k].line)), cases[k].status);
    CHECK(memcmp(&p, &before, sizeof p) == 0, "%s changed the state", cases[k].line);
    CHECK_STATUS(cncrot_program_column(&p, cases[k].dialect, cases[k].line, strlen(cases[k].line), &column),
                 cases[k].status);
    CHECK(column == cases[k].column, "%s: column %zu, expected %zu", cases[k].line, column, cases[k].column);
  }
  /* Another dialect on the same program, an unknown dialect, a state not written here. */
  cncrot_program p;
  memset(&p, 0, sizeof p);
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, "G68.2 J30", 9), CNCROT_STATUS_OK);
  cncrot_program before = p;
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_HAAS, "G269", 4), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_program_line(&p, 7, "G69", 3), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, NULL, 0), CNCROT_STATUS_NULL_POINTER);
  CHECK(memcmp(&p, &before, sizeof p) == 0, "a refusal changed the state");
  p.rotation[0] = 1.5;
  before = p;
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, "G69", 3), CNCROT_STATUS_BAD_STATE);
  double f[16];
  fill_sentinel(f, 16);
  CHECK_STATUS(cncrot_program_frame(&p, f), CNCROT_STATUS_BAD_STATE);
  CHECK(is_sentinel(f, 16), "frame written on error");
  /* A line is read only up to len: the rest of the buffer may be anything. */
  memset(&p, 0, sizeof p);
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, "G69 garbage", 3), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, "G68.2 J30\r\n", 11), CNCROT_STATUS_OK);
  /* Cancels: all zero again but for the dialect and the seal. */
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, "G69 (off)", 9), CNCROT_STATUS_OK);
  cncrot_program zero;
  memset(&zero, 0, sizeof zero);
  zero.dialect = CNCROT_DIALECT_FANUC;
  zero.reserved = p.reserved;
  CHECK(memcmp(&p, &zero, sizeof p) == 0 && p.reserved != 0, "G69 left something active");
}

/* A state the library did not write is refused: every single-bit flip of a written state and
 * of the zero state (the hostile caller's case: origin[0] of G68.2 X10 I0 J30 K0 turned from 10
 * into 14 was read as another frame), and options set by hand. */
static void sealed_states(void) {
  cncrot_program states[3];
  memset(&states[0], 0, sizeof states[0]);
  memset(&states[1], 0, sizeof states[1]);
  CHECK_STATUS(cncrot_program_line(&states[1], CNCROT_DIALECT_FANUC, "G68.2 X10 I0 J30 K0", 19), CNCROT_STATUS_OK);
  CHECK(states[1].origin[0] == 10, "origin %g", states[1].origin[0]);
  CHECK_STATUS(cncrot_program_init(&states[2], CNCROT_PROGRAM_SINUMERIK_EULER), CNCROT_STATUS_OK);
  int accepted = 0;
  for (int k = 0; k < 3; k++) {
    for (size_t bit = 0; bit < 8 * sizeof(cncrot_program); bit++) {
      cncrot_program q = states[k], keep;
      ((unsigned char *)&q)[bit / 8] ^= (unsigned char)(1u << (bit % 8));
      keep = q;
      double f[16];
      fill_sentinel(f, 16);
      accepted += cncrot_program_frame(&q, f) != CNCROT_STATUS_BAD_STATE;
      accepted += cncrot_program_line(&q, CNCROT_DIALECT_FANUC, "G69", 3) != CNCROT_STATUS_BAD_STATE;
      accepted += !is_sentinel(f, 16) || memcmp(&q, &keep, sizeof q) != 0;
    }
  }
  CHECK(accepted == 0, "%d single-bit flips accepted", accepted);
  cncrot_program p;
  memset(&p, 0, sizeof p);
  p.options = CNCROT_PROGRAM_SINUMERIK_EULER;
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_SINUMERIK, "ROT Z30", 7), CNCROT_STATUS_BAD_STATE);
  cncrot_program before = states[2];
  CHECK_STATUS(cncrot_program_init(&states[2], 4), CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(memcmp(&before, &states[2], sizeof before) == 0, "init wrote on error");
  CHECK_STATUS(cncrot_program_init(NULL, 0), CNCROT_STATUS_NULL_POINTER);
  /* TABLE ROT kept in the state, cleared by the reset. */
  cncrot_program tr;
  memset(&tr, 0, sizeof tr);
  CHECK_STATUS(cncrot_program_line(&tr, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+0 SPB+0 SPC+90 TURN TABLE ROT", 47), CNCROT_STATUS_OK);
  CHECK(tr.table_rot == 1, "TABLE ROT: %u", tr.table_rot);
  CHECK_STATUS(cncrot_program_line(&tr, CNCROT_DIALECT_HEIDENHAIN, "PLANE RESET STAY", 16), CNCROT_STATUS_OK);
  CHECK(tr.table_rot == 0, "reset: %u", tr.table_rot);
  /* Cycle 19 on a machine set to axis angles: the positions of B and C, as PLANE AXIAL. */
  cncrot_program ax;
  CHECK_STATUS(cncrot_program_init(&ax, CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES), CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_line(&ax, CNCROT_DIALECT_HEIDENHAIN, "CYCL DEF 19.1 B+30 C+45", 23), CNCROT_STATUS_OK);
  CHECK(ax.active == 2 && ax.direct_given == 6 && ax.angles[1] == 30 && ax.angles[2] == 45,
        "cycle 19 axis angles: active %d given %u", ax.active, ax.direct_given);
  /* By default spatial angles: the rotation of PLANE SPATIAL SPA+0 SPB+30 SPC+0. */
  memset(&ax, 0, sizeof ax);
  CHECK_STATUS(cncrot_program_line(&ax, CNCROT_DIALECT_HEIDENHAIN, "CYCL DEF 19.1 B+30", 18), CNCROT_STATUS_OK);
  CHECK(ax.active == 1 && fabs(ax.rotation[2] - 0.5) < 1e-15, "cycle 19 spatial: %g", ax.rotation[2]);
  /* Euler mode, set by init: ROT Z30 X20 is Rz(30)·Rx(20)·Rz(0), not RPY's Rz·Ry·Rx. */
  p = states[2];
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_SINUMERIK, "ROT Z30 X20", 11), CNCROT_STATUS_OK);
  double f[16], r[9], a[9], b[9];
  CHECK_STATUS(cncrot_program_frame(&p, f), CNCROT_STATUS_OK);
  rot_of(f, r);
  elem(3, 30, a);
  elem(1, 20, b);
  double want[9];
  mul3(a, b, want);
  CHECK_NEAR(r, want, 9, 1e-15);
}

/* A line no buffer can hold is OUT_OF_RANGE, not NO_ROOM; PLANE POINTS needs no origin. */
static void long_lines_and_points(void) {
  /* Nine numbers of about 100 digits: longer than any dialect's line, whatever the buffer. */
  double a = 1e-97, f[16], r[9], x[9], y[9], z[9], xy[9];
  elem(1, a, x);
  elem(2, a, y);
  elem(3, a, z);
  mul3(x, y, xy);
  mul3(xy, z, r);
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) f[4 * i + j] = r[3 * i + j];
    f[4 * i + 3] = 1e99;
  }
  f[12] = f[13] = f[14] = 0;
  f[15] = 1;
  static char big[65536];
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_SYNTEC, "G158", f, -1, big, sizeof big), CNCROT_STATUS_OUT_OF_RANGE);
  /* PLANE POINTS needs no origin: a frame with one is refused as for every form without
   * origin words, and the rotation alone is written with P1 at the datum. */
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", f, -1, big, sizeof big),
               CNCROT_STATUS_HAS_ORIGIN);
  /* A tilt of 90° about Z: P2 one along Y', P3 one along -X. */
  double rz[16] = {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", rz, -1, big, sizeof big), CNCROT_STATUS_OK);
  CHECK(strcmp(big, "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+0 P2Y+1 P2Z+0 P3X-1 P3Y+0 P3Z+0 STAY") == 0, "%s", big);
  /* A rotation rounded where it was written (Rx(30°) printed to 3 decimals, 0.866 for
   * sqrt(3)/2) is written as its nearest rotation: in the plane of the turn the rounded block
   * is a scaled rotation by atan2(0.5, 0.866) = 30.000728°, whose polar factor is that
   * rotation. */
  double r3[16] = {1, 0, 0, 0, 0, 0.866, -0.5, 0, 0, 0.5, 0.866, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", r3, 4, big, sizeof big), CNCROT_STATUS_OK);
  CHECK(strcmp(big, "G68.2 X0. Y0. Z0. I0. J30.0007 K0.") == 0, "%s", big);
  double w6[6];
  CHECK_STATUS(cncrot_form_values(CNCROT_FORM_G68_2, 0, r3, w6, 6), CNCROT_STATUS_OK);
  CHECK(fabs(w6[4] - 30.000727780827372) < 1e-9, "%.12f", w6[4]);
  /* Nothing active is written as the cancel, in every dialect. */
  double id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", id, -1, big, sizeof big), CNCROT_STATUS_OK);
  CHECK(strcmp(big, "PLANE RESET STAY") == 0, "%s", big);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", id, 4, big, sizeof big), CNCROT_STATUS_OK);
  CHECK(strcmp(big, "G69") == 0, "%s", big);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_SINUMERIK, "CYCLE800", id, 4, big, sizeof big), CNCROT_STATUS_OK);
  CHECK(strcmp(big, "CYCLE800()") == 0, "%s", big);
}

/* Writers near their singularities: the frame Ry(90° - 1e-13°)·Rx(30°) as PLANE PROJECTED or
 * CYCLE800 mode 185 read back 3.9e-3 off with success; now words within
 * CNCROT_READ_BACK_TOLERANCE or OUT_OF_RANGE, for tilts 1e-3 .. 1e-16 from the singularity. */
static void near_singularities(void) {
  struct {
    int32_t dialect;
    const char *form;
    int32_t code, selector;
  } forms[] = {{CNCROT_DIALECT_HEIDENHAIN, "PLANE PROJECTED", CNCROT_FORM_PLANE_PROJECTED, 0},
               {CNCROT_DIALECT_SINUMERIK, "CYCLE800 185", CNCROT_FORM_CYCLE800, 185}};
  int wrong = 0, refused = 0, written = 0;
  for (int e = 3; e <= 16; e++) {
    double ry[9], rx[9], r[9], f[16];
    elem(2, 90 - pow(10, -e), ry);
    elem(1, 30, rx);
    mul3(ry, rx, r);
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) f[4 * i + j] = r[3 * i + j];
      f[4 * i + 3] = 0;
    }
    f[12] = f[13] = f[14] = 0;
    f[15] = 1;
    for (int k = 0; k < 2; k++) {
      char out[CNCROT_PROGRAM_LINE_MAX + 1];
      int32_t s = cncrot_program_write(forms[k].dialect, forms[k].form, f, -1, out, sizeof out);
      double w[9], g[16];
      size_t n = 0;
      cncrot_form_word_count(forms[k].code, &n);
      int32_t v = cncrot_form_values(forms[k].code, forms[k].selector, f, w, n);
      if (s == CNCROT_STATUS_OUT_OF_RANGE) {
        refused++;
        wrong += v != CNCROT_STATUS_OUT_OF_RANGE;
        continue;
      }
      written++;
      cncrot_program q;
      memset(&q, 0, sizeof q);
      wrong += s < 0 || v < 0 || cncrot_program_line(&q, forms[k].dialect, out, strlen(out)) != 0;
      cncrot_program_frame(&q, g);
      wrong += max_abs_diff(f, g, 16) > CNCROT_READ_BACK_TOLERANCE;
      cncrot_form_frame(forms[k].code, forms[k].selector, w, n, g);
      wrong += max_abs_diff(f, g, 16) > CNCROT_READ_BACK_TOLERANCE;
    }
  }
  CHECK(wrong == 0 && refused > 0 && written > 0, "%d wrong, %d refused, %d written", wrong, refused, written);
}

/* The writer: NUL-terminated, refused without writing when the buffer is short. */
static void writer_buffers(void) {
  double f[16] = {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  char out[64];
  memset(out, 'x', sizeof out);
  const char *want = "G68.2 X10. Y0. Z0. I0. J0. K0.";
  size_t n = strlen(want);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, -1, out, n), CNCROT_STATUS_NO_ROOM);
  CHECK(out[0] == 'x', "written on error");
  /* No tilt: J = 0 is the singular middle angle of Z, X', Z''. */
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, -1, out, n + 1), CNCROT_STATUS_SINGULAR);
  CHECK(strcmp(out, want) == 0 && out[n + 1] == 'x', "%s", out);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", f, -1, out, sizeof out),
               CNCROT_STATUS_HAS_ORIGIN);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "PLANE SPATIAL", f, -1, out, sizeof out),
               CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, 18, out, sizeof out), CNCROT_STATUS_BAD_ARGUMENT);
  f[0] = NAN;
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, -1, out, sizeof out), CNCROT_STATUS_NOT_FINITE);
  f[0] = 1;
  f[3] = 1e120;
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, -1, out, sizeof out), CNCROT_STATUS_OUT_OF_RANGE);
  CHECK_STATUS(cncrot_program_write(CNCROT_DIALECT_FANUC, NULL, f, -1, out, sizeof out), CNCROT_STATUS_NULL_POINTER);
}

/* Reads each line of a written text (one block per line) into `p`, every one accepted. */
static void read_lines(cncrot_program *p, int32_t dialect, const char *text) {
  for (const char *line = text, *end; *line; line = *end ? end + 1 : end) {
    end = strchr(line, '\n');
    if (!end) end = line + strlen(line);
    CHECK_STATUS(cncrot_program_line(p, dialect, line, (size_t)(end - line)), CNCROT_STATUS_OK);
  }
}

/* A program translated block by block with cncrot_program_write_change: the target's own
 * datum-shift blocks and cancels (expected texts hand-derived: SPB+30 is a rotation about Y,
 * Rz(90) Rx(30) Rz(-90) in G68.2's Z, X', Z''), the choice word carried as _DIR, TURN as G53.1
 * (CNCROT_POSITIONING_TURN, and a CYCLE800's swivel), each text
 * read back in the target dialect as the source frame; the refusals with `out` untouched. */
static void translated_programs(void) {
  const char *src[] = {"CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+10", "CYCL DEF 7.3 Z-5",
                       "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ+", "L Z+100 FMAX", "PLANE RESET STAY"};
  const char *fanuc[] = {"", "G52 X10. Y0. Z0.", "G52 X10. Y0. Z-5.", "G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1", "",
                         "G69"};
  /* The shift alone reset before the cycle carries the whole origin, the tilt cancelled before
   * the shift stands alone again (the same whether CYCLE800's frame is kept apart from TRANS). */
  const char *sinumerik[] = {"", "TRANS X=10 Y=0 Z=0", "TRANS X=10 Y=0 Z=-5",
                             "TRANS\nCYCLE800(0,\"\",0,57,10,0,-5,0,30,0,0,0,0,1,0,0)", "",
                             "CYCLE800()\nTRANS X=10 Y=0 Z=-5"};
  cncrot_program before, after, fan, sn;
  memset(&before, 0, sizeof before);
  memset(&fan, 0, sizeof fan);
  memset(&sn, 0, sizeof sn);
  char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  for (int k = 0; k < 6; k++) {
    after = before;
    CHECK(cncrot_program_line(&after, CNCROT_DIALECT_HEIDENHAIN, src[k], strlen(src[k])) >= 0, "%s", src[k]);
    CHECK_STATUS(
        cncrot_program_write_change(&before, &after, CNCROT_DIALECT_FANUC, "G68.2", 4, out, sizeof out),
        CNCROT_STATUS_OK);
    CHECK(strcmp(out, fanuc[k]) == 0, "%d: %s", k, out);
    read_lines(&fan, CNCROT_DIALECT_FANUC, out);
    CHECK_STATUS(cncrot_program_write_change(&before, &after, CNCROT_DIALECT_SINUMERIK, "CYCLE800", 4, out,
                                             sizeof out),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(out, sinumerik[k]) == 0, "%d: %s", k, out);
    read_lines(&sn, CNCROT_DIALECT_SINUMERIK, out);
    double want[16], a[16], b[16];
    cncrot_program_frame(&after, want);
    cncrot_program_frame(&fan, a);
    cncrot_program_frame(&sn, b);
    CHECK_NEAR(a, want, 16, 1e-12);
    CHECK_NEAR(b, want, 16, 1e-12);
    CHECK(sn.choice == after.choice, "%d: choice %d %d", k, sn.choice, after.choice);
    /* TURN is G53.1 in Fanuc and the swivel of CYCLE800. */
    CHECK(fan.positioning == after.positioning && sn.positioning == after.positioning, "%d: positioning %d %d %d", k,
          fan.positioning, sn.positioning, after.positioning);
    before = after;
  }
  /* Back from SINUMERIK: _DIR +1 is SEQ+; a G68.2's origin becomes the datum shift of a PLANE. */
  cncrot_program zero, p;
  memset(&zero, 0, sizeof zero);
  p = zero;
  const char *c800 = "CYCLE800(0,\"T\",0,57,0,0,0,30,0,0,0,0,0,1,0,0)";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_SINUMERIK, c800, strlen(c800)), CNCROT_STATUS_OK);
  CHECK_STATUS(
      cncrot_program_write_change(&zero, &p, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, out, sizeof out),
      CNCROT_STATUS_OK);
  CHECK(strcmp(out, "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX SEQ+") == 0, "%s", out);
  CHECK(p.positioning == CNCROT_POSITIONING_TURN, "a CYCLE800 swivels: %d", p.positioning);
  p = zero;
  const char *g682 = "G68.2 X10 Y20 I0 J30 K0";
  CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_FANUC, g682, strlen(g682)), CNCROT_STATUS_OK);
  CHECK_STATUS(
      cncrot_program_write_change(&zero, &p, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, out, sizeof out),
      CNCROT_STATUS_OK);
  CHECK(strcmp(out, "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\nCYCL DEF 7.2 Y+20\nCYCL DEF 7.3 Z+0\n"
                    "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY") == 0,
        "%s", out);
  /* Refusals leave `out` as it was. */
  memset(out, 'x', sizeof out);
  /* ROT has no origin words: the origin is TRANS (which replaces SINUMERIK's one frame), the
   * rotation AROT about it. */
  CHECK_STATUS(cncrot_program_write_change(&zero, &p, CNCROT_DIALECT_SINUMERIK, "ROT", 4, out, sizeof out),
               CNCROT_STATUS_OK);
  CHECK(strcmp(out, "TRANS X=10 Y=20 Z=0\nAROT X=30 Y=0 Z=0") == 0, "%s", out);
  memset(out, 'x', sizeof out);
  CHECK_STATUS(cncrot_program_write_change(&zero, &p, CNCROT_DIALECT_SINUMERIK, "ROTS", 4, out, sizeof out),
               CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_program_write_change(&zero, &p, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, out, 20),
               CNCROT_STATUS_NO_ROOM);
  CHECK_STATUS(cncrot_program_write_change(&zero, &p, CNCROT_DIALECT_FANUC, "PLANE SPATIAL", 4, out, sizeof out),
               CNCROT_STATUS_BAD_ARGUMENT);
  CHECK_STATUS(cncrot_program_write_change(&zero, NULL, CNCROT_DIALECT_FANUC, "G68.2", 4, out, sizeof out),
               CNCROT_STATUS_NULL_POINTER);
  cncrot_program edited = p;
  edited.shift[0] = 1;
  CHECK_STATUS(cncrot_program_write_change(&zero, &edited, CNCROT_DIALECT_FANUC, "G68.2", 4, out, sizeof out),
               CNCROT_STATUS_BAD_STATE);
  CHECK(out[0] == 'x' && out[sizeof out - 1] == 'x', "out touched");
}

/* What a translator writes for one block (cncrot_program_write_block): with nothing active a
 * program's safety cancel is still the target's cancel (the cancels each dialect documents) and
 * a zero datum shift the target's shift; a cycle's first line restates nothing; a block that
 * changes the state is written as cncrot_program_write_change writes it;
 * the refusals leave `out` untouched. */
static void restated_blocks(void) {
  static const struct {
    int32_t from;
    const char *block;
    int32_t to;
    const char *form;
    const char *want;
  } cases[] = {
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE RESET STAY", CNCROT_DIALECT_FANUC, "G68.2", "G69"},
      {CNCROT_DIALECT_HEIDENHAIN, "10 PLANE RESET STAY", CNCROT_DIALECT_SINUMERIK, "CYCLE800", "CYCLE800()"},
      {CNCROT_DIALECT_FANUC, "N10 G69", CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", "PLANE RESET STAY"},
      {CNCROT_DIALECT_FANUC, "G69", CNCROT_DIALECT_HAAS, "G268", "G269"},
      {CNCROT_DIALECT_SINUMERIK, "CYCLE800()", CNCROT_DIALECT_FANUC, "G68.2", "G69"},
      {CNCROT_DIALECT_FANUC, "G52 X0 Y0 Z0", CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL",
       "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+0"},
      {CNCROT_DIALECT_HEIDENHAIN, "TRANS DATUM RESET", CNCROT_DIALECT_FANUC, "G68.2", "G52 X0. Y0. Z0."},
      {CNCROT_DIALECT_HEIDENHAIN, "CYCL DEF 7.0 DATUM SHIFT", CNCROT_DIALECT_FANUC, "G68.2", ""},
      /* A turn with no tilt active: the axes to the untilted plane. */
      {CNCROT_DIALECT_FANUC, "G53.1", CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", "PLANE RESET TURN FMAX"},
      /* A zero tilt that turns: whatever was active cancelled (the block is a cancel), the zero
       * G68.2 and its turn, then the cancel again (the target untilted, as the state). */
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN FMAX", CNCROT_DIALECT_FANUC, "G68.2",
       "G69\nG68.2 X0. Y0. Z0. I0. J0. K0.\nG53.1\nG69"},
  };
  char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    cncrot_program before, after;
    memset(&before, 0, sizeof before);
    after = before;
    const char *b = cases[k].block;
    CHECK_STATUS(cncrot_program_line(&after, cases[k].from, b, strlen(b)), CNCROT_STATUS_OK);
    CHECK_STATUS(cncrot_program_write_block(&before, &after, b, strlen(b), cases[k].to, cases[k].form, 4, out,
                                            sizeof out),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(out, cases[k].want) == 0, "%s: %s", b, out);
  }
  /* A swivel to the plane the state is at already (a tool change's CYCLE800 again) turns the
   * axes again: written as that turn. A datum shift under a plane that turned moves nothing:
   * the plane again without G53.1. */
  {
    cncrot_program p;
    memset(&p, 0, sizeof p);
    const char *swivel = "CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)";
    CHECK_STATUS(cncrot_program_line(&p, CNCROT_DIALECT_SINUMERIK, swivel, strlen(swivel)), CNCROT_STATUS_OK);
    cncrot_program again = p;
    CHECK_STATUS(cncrot_program_line(&again, CNCROT_DIALECT_SINUMERIK, swivel, strlen(swivel)), CNCROT_STATUS_OK);
    CHECK_STATUS(cncrot_program_write_block(&p, &again, swivel, strlen(swivel), CNCROT_DIALECT_HEIDENHAIN,
                                            "PLANE SPATIAL", 4, out, sizeof out),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(out, "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ-") == 0, "%s", out);
    cncrot_program shifted = p;
    CHECK_STATUS(cncrot_program_line(&shifted, CNCROT_DIALECT_SINUMERIK, "ATRANS X10", 10), CNCROT_STATUS_OK);
    int32_t s = cncrot_program_write_block(&p, &shifted, "ATRANS X10", 10, CNCROT_DIALECT_FANUC, "G68.2", 4, out,
                                           sizeof out);
    CHECK(s >= 0 && strstr(out, "G68.4 X10.") != NULL && strstr(out, "G53.1") == NULL, "%d: %s", (int)s, out);
    /* Cycle 19's first line under a plane that turned changes nothing and states no turn:
     * nothing to write (it was the plane again, in G68.2 mode). */
    cncrot_program h;
    memset(&h, 0, sizeof h);
    const char *cycle[] = {"CYCL DEF 19.0 WORKING PLANE", "CYCL DEF 19.1 B+30 C+0", "L B+Q121 C+Q122 R0 FMAX"};
    for (size_t k = 0; k < 3; k++) {
      CHECK_STATUS(cncrot_program_line(&h, CNCROT_DIALECT_HEIDENHAIN, cycle[k], strlen(cycle[k])), CNCROT_STATUS_OK);
    }
    cncrot_program head = h;
    CHECK_STATUS(cncrot_program_line(&head, CNCROT_DIALECT_HEIDENHAIN, cycle[0], strlen(cycle[0])), CNCROT_STATUS_OK);
    strcpy(out, "untouched");
    CHECK_STATUS(cncrot_program_write_block(&h, &head, cycle[0], strlen(cycle[0]), CNCROT_DIALECT_FANUC, "G68.2", 4,
                                            out, sizeof out),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(out, "") == 0, "%s", out);
    /* A reset that turns the axes home beside a datum shift: the cancel the shift needs first
     * is that turn (it was CYCLE800(), the turn lost). */
    cncrot_program d;
    memset(&d, 0, sizeof d);
    const char *datum[] = {"TRANS DATUM AXIS X+50", "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX"};
    for (size_t k = 0; k < 2; k++) {
      CHECK_STATUS(cncrot_program_line(&d, CNCROT_DIALECT_HEIDENHAIN, datum[k], strlen(datum[k])),
                   CNCROT_STATUS_OK);
    }
    const char *reset = "PLANE RESET TURN MB MAX FMAX";
    cncrot_program home = d;
    CHECK_STATUS(cncrot_program_line(&home, CNCROT_DIALECT_HEIDENHAIN, reset, strlen(reset)), CNCROT_STATUS_OK);
    CHECK_STATUS(cncrot_program_write_block(&d, &home, reset, strlen(reset), CNCROT_DIALECT_SINUMERIK, "CYCLE800",
                                            4, out, sizeof out),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(out, "CYCLE800(4,\"\",0,57,0,0,0,0,0,0,0,0,0,-1,0,0)\nTRANS X=50 Y=0 Z=0") == 0, "%s", out);
  }
  /* A change: the text of cncrot_program_write_change. */
  cncrot_program before, after;
  memset(&before, 0, sizeof before);
  after = before;
  const char *tilt = "G68.2 X10 I0 J30 K0";
  CHECK_STATUS(cncrot_program_line(&after, CNCROT_DIALECT_FANUC, tilt, strlen(tilt)), CNCROT_STATUS_OK);
  char change[CNCROT_PROGRAM_CHANGE_MAX + 1];
  CHECK_STATUS(cncrot_program_write_change(&before, &after, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, change,
                                           sizeof change),
               CNCROT_STATUS_OK);
  CHECK_STATUS(cncrot_program_write_block(&before, &after, tilt, strlen(tilt), CNCROT_DIALECT_HEIDENHAIN,
                                          "PLANE SPATIAL", 4, out, sizeof out),
               CNCROT_STATUS_OK);
  CHECK(strcmp(out, change) == 0, "%s", out);
  /* Refusals leave `out` as it was. */
  memset(out, 'x', sizeof out);
  CHECK_STATUS(cncrot_program_write_block(&before, &after, NULL, 0, CNCROT_DIALECT_FANUC, "G68.2", 4, out,
                                          sizeof out),
               CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_program_write_block(&before, &after, tilt, CNCROT_PROGRAM_LINE_MAX + 3, CNCROT_DIALECT_FANUC,
                                          "G68.2", 4, out, sizeof out),
               CNCROT_STATUS_LINE_TOO_LONG);
  CHECK_STATUS(cncrot_program_write_block(&before, &after, tilt, strlen(tilt), CNCROT_DIALECT_HEIDENHAIN,
                                          "PLANE SPATIAL", 4, out, 2),
               CNCROT_STATUS_NO_ROOM);
  CHECK_STATUS(cncrot_program_write_block(&before, &after, tilt, strlen(tilt), 9, "G68.2", 4, out, sizeof out),
               CNCROT_STATUS_BAD_ARGUMENT);
  CHECK(out[0] == 'x' && out[sizeof out - 1] == 'x', "out touched");
}

/* Blocks that are one command spread over lines (cycle 7's axis lines; a tilt and its turn)
 * join; a restated cancel with nothing active and the next shift do not. */
static void joined_blocks(void) {
  static const char *lines[] = {
      "PLANE RESET STAY",         "CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+10", "CYCL DEF 7.2 Y+20",
      "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY", "L B+Q121 R0 FMAX", "CYCL DEF 7.1 X+0", "CYCL DEF 7.2 Y+20",
      "CYCL DEF 7.3 Z+0",
  };
  /* joins[k]: block k and block k + 1. */
  static const int32_t want[] = {0, 0, 1, 0, 1, 0, 1, 1};
  enum { N = sizeof lines / sizeof lines[0] };
  cncrot_program s[N + 1];
  memset(&s[0], 0, sizeof s[0]);
  for (size_t k = 0; k < N; k++) {
    s[k + 1] = s[k];
    CHECK_STATUS(cncrot_program_line(&s[k + 1], CNCROT_DIALECT_HEIDENHAIN, lines[k], strlen(lines[k])),
                 CNCROT_STATUS_OK);
  }
  for (size_t k = 0; k + 1 < N; k++) {
    int32_t join = -1;
    CHECK_STATUS(cncrot_program_joins(&s[k], &s[k + 1], &s[k + 2], &join), CNCROT_STATUS_OK);
    CHECK(join == want[k], "%s / %s: %d", lines[k], lines[k + 1], (int)join);
  }
  /* The joined text: one G52 for 7.1 and 7.2. */
  char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  CHECK_STATUS(cncrot_program_write_block(&s[2], &s[4], lines[3], strlen(lines[3]), CNCROT_DIALECT_FANUC, "G68.2", 4,
                                          out, sizeof out),
               CNCROT_STATUS_OK);
  CHECK(strcmp(out, "G52 X10. Y20. Z0.") == 0, "%s", out);
  /* Refusals leave the answer untouched. */
  int32_t join = 7;
  CHECK_STATUS(cncrot_program_joins(&s[0], NULL, &s[1], &join), CNCROT_STATUS_NULL_POINTER);
  cncrot_program bad = s[1];
  bad.shift[0] = 1;
  CHECK_STATUS(cncrot_program_joins(&s[0], &bad, &s[1], &join), CNCROT_STATUS_BAD_STATE);
  CHECK(join == 7, "join touched");
}

/* A block that adds to the tilt is kept as one and written as the target's incremental
 * form, its words exact (SPC+15 is Rz(15): G68.2's I15 J0 K0), so that a loop repeating
 * it adds as often: the text read twice gives the source block read twice. */
static void incremental_blocks(void) {
  static const char first[] = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY", step[] = "PLANE RELATIV SPC+15 STAY";
  cncrot_program p0, p1, p2, q;
  memset(&p0, 0, sizeof p0);
  CHECK_STATUS(cncrot_program_line(&p0, CNCROT_DIALECT_HEIDENHAIN, first, strlen(first)), CNCROT_STATUS_OK);
  CHECK(p0.relative == 0, "PLANE SPATIAL: %u", p0.relative);
  p1 = p0;
  CHECK_STATUS(cncrot_program_line(&p1, CNCROT_DIALECT_HEIDENHAIN, step, strlen(step)), CNCROT_STATUS_OK);
  CHECK(p1.relative == 1 && p1.spare == 0, "PLANE RELATIV: %u %u", p1.relative, p1.spare);
  char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  /* A turn about Z alone: Z, X', Z'' angles say only their sum (singular). */
  CHECK_STATUS(cncrot_program_write_block(&p0, &p1, step, strlen(step), CNCROT_DIALECT_FANUC, "G68.2", -1, out,
                                          sizeof out),
               CNCROT_STATUS_SINGULAR);
  CHECK(strcmp(out, "G68.4 X0. Y0. Z0. I15. J0. K0.") == 0, "%s", out);
  /* Twice in the target as twice in the source. */
  memset(&q, 0, sizeof q);
  CHECK_STATUS(cncrot_program_line(&q, CNCROT_DIALECT_FANUC, "G68.2 X0 Y0 Z0 I90 J30 K-90", 27), CNCROT_STATUS_OK);
  for (int k = 0; k < 2; k++)
    CHECK_STATUS(cncrot_program_line(&q, CNCROT_DIALECT_FANUC, out, strlen(out)), CNCROT_STATUS_OK);
  p2 = p1;
  CHECK_STATUS(cncrot_program_line(&p2, CNCROT_DIALECT_HEIDENHAIN, step, strlen(step)), CNCROT_STATUS_OK);
  double diff = 0;
  for (int k = 0; k < 9; k++) diff = fmax(diff, fabs(q.rotation[k] - p2.rotation[k]));
  CHECK(diff < 1e-15, "twice: %g", diff);
  /* Without the block, from the states: the same plane, up to the last bits. */
  CHECK_STATUS(cncrot_program_write_change(&p0, &p1, CNCROT_DIALECT_SINUMERIK, "CYCLE800", 4, out, sizeof out),
               CNCROT_STATUS_OK);
  CHECK(strcmp(out, "CYCLE800(0,\"\",1,57,0,0,0,0,0,15,0,0,0,0,0,0)") == 0, "%s", out);
}

/* What a translator keeps of a block: the words beside the frame command, as they stand
 * (a retract beside a cancel, the motion mode and feed beside a tilt); nothing where only
 * the block number and comments are left, or where the dialect allows no other words. */
static void kept_words(void) {
  static const struct {
    int32_t dialect;
    const char *block, *rest;
  } cases[] = {
      {CNCROT_DIALECT_FANUC, "G0 G90 G49 G69 G80 G40 G17", "G0 G90 G49 G80 G40 G17"},
      {CNCROT_DIALECT_FANUC, "G91 G28 Z0. G69", "G91 G28 Z0."},
      {CNCROT_DIALECT_FANUC, "N40 G1 G68.2 X0. Y0. Z0. I90. J-1. K-90. F300.", "N40 G1 F300."},
      {CNCROT_DIALECT_FANUC, "N50 G90 G68.2 X 10. Y[0.] Z0 I0 J30 K0 (TILT)", "N50 G90 (TILT)"},
      {CNCROT_DIALECT_FANUC, "N60 G69 (CANCEL)", ""},
      {CNCROT_DIALECT_FANUC, "N70 G53.6 H12 (ORIENT TOOL)", ""},
      /* LinuxCNC's G53.3: the turn, and a move to X Y Z in the plane (kept). */
      {CNCROT_DIALECT_FANUC, "G53.3 P1 X10 Y20 Z30", "X10 Y20 Z30"},
      {CNCROT_DIALECT_FANUC, "G1 X10. Y10.", "G1 X10. Y10."},
      {CNCROT_DIALECT_HAAS, "G0 G269 G90", "G0 G90"},
      {CNCROT_DIALECT_SYNTEC, "G1 G158 L1 P10 X0 Y0 Z0 A0 B30 C0 F100.", "G1 F100."},
      {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN F1000", ""},
      /* The turn to the plane keeps its M functions but the rotary axes' M126/M127. */
      {CNCROT_DIALECT_HEIDENHAIN, "2 L B+Q121 C+Q122 R0 FMAX M3 M126 ; SPINDLE", "M3"},
      {CNCROT_DIALECT_HEIDENHAIN, "L A+Q120 C+Q122 R0 FMAX M126", ""},
      {CNCROT_DIALECT_HEIDENHAIN, "M3 M8", "M3 M8"},
      {CNCROT_DIALECT_HEIDENHAIN, "L X+10 R0 FMAX M3", ""},
      {CNCROT_DIALECT_SINUMERIK, "N10 CYCLE800()", ""},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    char out[300];
    memset(out, 0x5A, sizeof out);
    CHECK_STATUS(cncrot_program_rest(cases[k].dialect, cases[k].block, strlen(cases[k].block), out, sizeof out),
                 CNCROT_STATUS_OK);
    CHECK(strcmp(out, cases[k].rest) == 0, "%s: '%s'", cases[k].block, out);
  }
  /* The room: the text and its NUL; too little leaves `out` untouched. */
  const char *b = cases[1].block;
  char small[12];
  memset(small, 0x5A, sizeof small);
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, b, strlen(b), small, 11), CNCROT_STATUS_NO_ROOM);
  CHECK((unsigned char)small[0] == 0x5A, "out touched");
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, b, strlen(b), small, 12), CNCROT_STATUS_OK);
  CHECK(strcmp(small, "G91 G28 Z0.") == 0, "%s", small);
  CHECK_STATUS(cncrot_program_rest(9, b, strlen(b), small, 12), CNCROT_STATUS_BAD_ARGUMENT);
  /* Longer than Fanuc reads (256 bytes and a line end). */
  static char long_block[300];
  memset(long_block, 'G', sizeof long_block);
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, long_block, sizeof long_block, small, 12),
               CNCROT_STATUS_LINE_TOO_LONG);
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, NULL, 0, small, 12), CNCROT_STATUS_NULL_POINTER);
  /* In place: the block's own buffer receives its rest. */
  char in_place[] = "G91 G28 Z0. G69";
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, in_place, strlen(in_place), in_place, sizeof in_place),
               CNCROT_STATUS_OK);
  CHECK(strcmp(in_place, "G91 G28 Z0.") == 0, "%s", in_place);
}

/* A block's length without its line end, as cncrot_program_line measures it: 257 bytes of a
 * Fanuc block (256 at most) are refused by the rest and the block writer too; 256 and a line
 * end are not. */
static void rest_and_block_lengths(void) {
  char l[300], out[600];
  memset(l, ' ', sizeof l);
  memcpy(l, "G91 G28 Z0. X1", 14);
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, l, 257, out, sizeof out), CNCROT_STATUS_LINE_TOO_LONG);
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, l, 256, out, sizeof out), CNCROT_STATUS_OK);
  l[256] = '\n';
  CHECK_STATUS(cncrot_program_rest(CNCROT_DIALECT_FANUC, l, 257, out, sizeof out), CNCROT_STATUS_OK);
  cncrot_program p, q;
  memset(&p, 0, sizeof p);
  q = p;
  const char *g = "G68.2 X0 Y0 Z0 I0 J30 K0";
  CHECK_STATUS(cncrot_program_line(&q, CNCROT_DIALECT_FANUC, g, strlen(g)), CNCROT_STATUS_OK);
  char b[300];
  memset(b, ' ', sizeof b);
  memcpy(b, g, strlen(g));
  CHECK_STATUS(cncrot_program_write_block(&p, &q, b, 257, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, out, sizeof out),
               CNCROT_STATUS_LINE_TOO_LONG);
  CHECK_STATUS(cncrot_program_write_block(&p, &q, b, 256, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL", 4, out, sizeof out),
               CNCROT_STATUS_OK);
}

int main(void) {
  kept_words();
  incremental_blocks();
  joined_blocks();
  restated_blocks();
  planes();
  vendors();
  readback_and_rules();
  every_pair_converts();
  whole_programs();
  program_axes();
  direct_modes();
  refusals();
  writer_buffers();
  sealed_states();
  long_lines_and_points();
  near_singularities();
  translated_programs();
  rest_and_block_lengths();
  return finish("test_program");
}
