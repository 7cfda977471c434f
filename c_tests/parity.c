/* Writes the parity cases for the MATLAB/Octave suite: fixed inputs and the C library's
 * outputs, every double as its 64-bit pattern in hex, so the MEX results can be compared
 * bit for bit. Cases: all 24 conventions (random, near-singular and singular rotations),
 * conversions, CYCLE600 calls, forms, program lines and translated programs, probing and
 * kinematics. Usage: parity > cases.txt */
#include <inttypes.h>
#include "cncrot.h"
#include "harness.h"

static const int32_t CODES[12] = {57, 45, 54, 30, 39, 27, 25, 29, 38, 46, 55, 59};

static void hex(double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  printf(" %016" PRIx64, u);
}
static void hexes(const double *x, int n) {
  for (int k = 0; k < n; k++) hex(x[k]);
}
/* A text as one word of hex bytes (program lines hold spaces). */
static void text_hex(const char *t) {
  printf(" ");
  for (; *t; t++) printf("%02x", (unsigned char)*t);
}

int main(void) {
  for (int kind = 0; kind < 2; kind++)
    for (int c = 0; c < 12; c++)
      for (int v = 0; v < 4; v++) {
        int proper = (CODES[c] & 3) == (CODES[c] >> 4);
        double a[3] = {rnd(-180, 180), proper ? rnd(0, 180) : rnd(-90, 90), rnd(-180, 180)};
        if (v == 1) a[1] = proper ? 1e-7 : 90 - 1e-9; /* near-singular */
        if (v == 2) a[1] = proper ? 180 : -90;        /* singular */
        if (v == 3) a[0] = 1e6 + rnd(0, 1);           /* huge angle */
        double m[9], out[3];
        cncrot_matrix_from_angles(kind, CODES[c], a, m);
        printf("M %d %d", kind, CODES[c]);
        hexes(a, 3);
        hexes(m, 9);
        printf("\n");
        int32_t s = cncrot_angles_from_matrix(kind, CODES[c], m, out);
        printf("A %d %d", kind, CODES[c]);
        hexes(m, 9);
        hexes(out, 3);
        printf(" %d\n", s);
        int32_t to = CODES[(c + 5 + v) % 12];
        s = cncrot_convert(kind, CODES[c], a, 1 - kind, to, out);
        printf("C %d %d", kind, CODES[c]);
        hexes(a, 3);
        printf(" %d %d", 1 - kind, to);
        hexes(out, 3);
        printf(" %d\n", s);
      }
  for (int k = 0; k < 24; k++) {
    int32_t inexin = k % 2, inexout = (k / 2) % 2, bin_in = CODES[k % 12], bin_out = CODES[(k * 7) % 12];
    double p[9] = {rnd(-500, 500), rnd(-500, 500), rnd(-500, 500), rnd(-180, 180), rnd(-90, 90),
                   rnd(-180, 180), rnd(-50, 50), rnd(-50, 50), rnd(-50, 50)};
    cncrot_cycle600_gud g;
    memset(&g, 0, sizeof g);
    int32_t s = cncrot_cycle600(&g, NULL, inexin, "UFK600", 1, bin_in, p[0], p[1], p[2], p[3], p[4], p[5],
                                p[6], p[7], p[8], inexout, bin_out, 0, 0, 0);
    printf("Y %d %d %d %d", inexin, bin_in, inexout, bin_out);
    hexes(p, 9);
    double r[3] = {g.cyc600_2, g.cyc600_3, g.cyc600_4};
    hexes(r, 3);
    hexes(g.frame, 16);
    printf(" %d %d %d\n", g.cyc600_5, g.cyc600_6, s);
  }
  /* The dialects' forms: words -> frame, and frame -> words. */
  static const int32_t FORMS[][3] = {{CNCROT_FORM_CYCLE800, 57, 9},   {CNCROT_FORM_CYCLE800, 64, 9},
                                     {CNCROT_FORM_CYCLE800, 185, 9},  {CNCROT_FORM_SINUMERIK_ROT, 1, 3},
                                     {CNCROT_FORM_SINUMERIK_ROTS, 2, 2}, {CNCROT_FORM_PLANE_SPATIAL, 0, 3},
                                     {CNCROT_FORM_PLANE_EULER, 0, 3}, {CNCROT_FORM_PLANE_VECTOR, 0, 6},
                                     {CNCROT_FORM_PLANE_POINTS, 0, 9}, {CNCROT_FORM_G68_2, 0, 6},
                                     {CNCROT_FORM_G158, 10157, 9},    {CNCROT_FORM_TWINCAT_ROT, 0, 3},
                                     {CNCROT_FORM_G268, 321, 6},      {CNCROT_FORM_G68_3, 0, 7}};
  for (int k = 0; k < (int)(sizeof FORMS / sizeof FORMS[0]); k++)
    for (int v = 0; v < 3; v++) {
      int32_t form = FORMS[k][0], sel = FORMS[k][1];
      size_t n = (size_t)FORMS[k][2];
      double w[9], f[16], w2[9];
      for (size_t j = 0; j < n; j++) w[j] = rnd(-170, 170);
      if (cncrot_form_frame(form, sel, w, n, f) < 0) continue;
      printf("F %d %d %d", form, sel, (int)n);
      hexes(w, (int)n);
      hexes(f, 16);
      printf("\n");
      if (form == CNCROT_FORM_SINUMERIK_ROTS) continue;
      if (form == CNCROT_FORM_SINUMERIK_ROT || form == CNCROT_FORM_PLANE_SPATIAL || form == CNCROT_FORM_PLANE_EULER ||
          form == CNCROT_FORM_PLANE_VECTOR || form == CNCROT_FORM_TWINCAT_ROT)
        f[3] = f[7] = f[11] = 0;
      int32_t s = cncrot_form_values(form, sel, f, w2, n);
      if (s < 0) continue;
      printf("V %d %d %d", form, sel, (int)n);
      hexes(f, 16);
      hexes(w2, (int)n);
      printf(" %d\n", s);
    }
  /* Program lines: a line read into a fresh program (its bytes in hex) and the frame; a
   * frame written in a form (the form's and the line's bytes in hex). */
  static const struct {
    int32_t dialect;
    const char *form;
  } WRITERS[] = {{CNCROT_DIALECT_SINUMERIK, "CYCLE800"},   {CNCROT_DIALECT_SINUMERIK, "ROT"},
                 {CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL"}, {CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS"},
                 {CNCROT_DIALECT_FANUC, "G68.2"},          {CNCROT_DIALECT_SYNTEC, "G158 P10139"},
                 {CNCROT_DIALECT_TWINCAT, "ROT"},          {CNCROT_DIALECT_HAAS, "G268 Q321"}};
  for (int k = 0; k < (int)(sizeof WRITERS / sizeof WRITERS[0]); k++)
    for (int v = 0; v < 3; v++) {
      double a[3] = {rnd(-170, 170), rnd(-80, 80), rnd(-170, 170)}, o[3] = {rnd(-99, 99), rnd(-99, 99), rnd(-99, 99)};
      double f[16], none[3] = {0, 0, 0};
      int origin = strcmp(WRITERS[k].form, "ROT") != 0 && strcmp(WRITERS[k].form, "PLANE SPATIAL") != 0;
      cncrot_frame_from_angles(1, 27, a, origin ? o : none, none, f);
      char line[CNCROT_PROGRAM_LINE_MAX + 1];
      int decimals = v == 2 ? 3 : -1;
      int32_t s = cncrot_program_write(WRITERS[k].dialect, WRITERS[k].form, f, decimals, line, sizeof line);
      if (s < 0) continue;
      printf("W %d %d", WRITERS[k].dialect, decimals);
      text_hex(WRITERS[k].form);
      hexes(f, 16);
      text_hex(line);
      printf(" %d\n", s);
      cncrot_program p;
      memset(&p, 0, sizeof p);
      double g[16];
      if (cncrot_program_line(&p, WRITERS[k].dialect, line, strlen(line)) < 0 || cncrot_program_frame(&p, g) < 0)
        continue;
      printf("L %d", WRITERS[k].dialect);
      text_hex(line);
      hexes(g, 16);
      printf("\n");
    }
  /* Whole programs translated block by block as cncrot_program_translate does it
   * (cncrot_program_write_block into another dialect, blocks that join written at the last
   * of them: cncrot_program_joins; cncrot_program_write_change within one): a datum shift, a
   * tilt with its origin, a way of moving to it, its cancel; the program's lines and each
   * line's text in the target ("-" for none) in hex. */
  static const struct {
    int32_t dialect;
    const char *form;
  } TARGETS[] = {{CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL"},
                 {CNCROT_DIALECT_FANUC, "G68.2"},
                 {CNCROT_DIALECT_SINUMERIK, "CYCLE800"},
                 {CNCROT_DIALECT_HAAS, "G268"}};
  for (int v = 0; v < 4; v++) {
    char l[4][200];
    snprintf(l[0], sizeof l[0], "G52 X%.6f Y%.6f", rnd(-100, 100), rnd(-100, 100));
    snprintf(l[1], sizeof l[1], "G68.2 X%.6f Y0 Z%.6f I%.6f J%.6f K%.6f", rnd(-50, 50), rnd(-50, 50),
             rnd(-170, 170), rnd(1, 89), rnd(-170, 170));
    if (v == 2) {
      /* A tilt and a cancel among other words: kept beside the translation. */
      char t[150];
      memcpy(t, l[1], sizeof t - 1);
      t[sizeof t - 1] = '\0';
      snprintf(l[1], sizeof l[1], "N40 G1 %s F300.", t);
    }
    snprintf(l[2], sizeof l[2], "%s", v % 2 ? "G53.6" : "G53.1");
    snprintf(l[3], sizeof l[3], "%s", v == 2 ? "G91 G28 Z0. G69" : "G69");
    cncrot_program s[5];
    memset(&s[0], 0, sizeof s[0]);
    for (int j = 0; j < 4; j++) {
      s[j + 1] = s[j];
      if (cncrot_program_line(&s[j + 1], CNCROT_DIALECT_FANUC, l[j], strlen(l[j])) < 0) return 1;
    }
    for (int k = 0; k < (int)(sizeof TARGETS / sizeof TARGETS[0]); k++) {
      int decimals = v == 3 ? 4 : -1;
      int32_t to = TARGETS[k].dialect;
      printf("T %d %d %d", CNCROT_DIALECT_FANUC, to, decimals);
      text_hex(TARGETS[k].form);
      printf(" 4");
      for (int j = 0; j < 4; j++) text_hex(l[j]);
      int run = -1;
      for (int j = 0; j < 4; j++) {
        static char text[CNCROT_PROGRAM_CHANGE_MAX + 1];
        /* The block's other words first, on a line of their own (cncrot_program_rest). */
        char keep[CNCROT_PROGRAM_LINE_MAX + 3] = "";
        if (to != CNCROT_DIALECT_FANUC &&
            cncrot_program_rest(CNCROT_DIALECT_FANUC, l[j], strlen(l[j]), keep, sizeof keep) < 0)
          return 1;
        int32_t join = 0;
        if (to != CNCROT_DIALECT_FANUC && j + 1 < 4 && cncrot_program_joins(&s[j], &s[j + 1], &s[j + 2], &join) < 0)
          return 1;
        if (join) {
          if (run < 0) run = j;
          if (keep[0])
            text_hex(keep);
          else
            printf(" -");
          continue;
        }
        const cncrot_program *from = &s[run < 0 ? j : run];
        run = -1;
        int32_t w = to == CNCROT_DIALECT_FANUC
                        ? cncrot_program_write_change(&s[j], &s[j + 1], to, TARGETS[k].form, decimals, text, sizeof text)
                        : cncrot_program_write_block(from, &s[j + 1], l[j], strlen(l[j]), to, TARGETS[k].form,
                                                     decimals, text, sizeof text);
        if (w < 0) return 1;
        if (keep[0]) {
          static char both[CNCROT_PROGRAM_LINE_MAX + CNCROT_PROGRAM_CHANGE_MAX + 8];
          snprintf(both, sizeof both, "%s%s%s", keep, text[0] ? "\n" : "", text);
          text_hex(both);
        } else if (text[0]) {
          text_hex(text);
        } else {
          printf(" -");
        }
      }
      printf("\n");
    }
  }
  /* Probing: flanges, planes of five points, edges. */
  for (int k = 0; k < 12; k++) {
    double a1[3] = {rnd(-100, 100), rnd(-100, 100), rnd(-10, 10)}, a2[3], b1[3], b2[3], ang[3], f[16];
    a2[0] = a1[0] + rnd(50, 150), a2[1] = a1[1], a2[2] = a1[2] + rnd(-30, 30);
    b1[0] = a1[0], b1[1] = a1[1], b1[2] = a1[2];
    b2[0] = a1[0], b2[1] = a1[1] + rnd(50, 150), b2[2] = a1[2] + rnd(-30, 30);
    if (cncrot_probe_flange(a1, a2, b1, b2, ang, f) >= 0) {
      printf("PF");
      hexes(a1, 3), hexes(a2, 3), hexes(b1, 3), hexes(b2, 3), hexes(ang, 3), hexes(f, 16);
      printf("\n");
    }
    double pts[15], g[16], res[2];
    for (int j = 0; j < 15; j++) pts[j] = j % 3 == 2 ? 5 + rnd(-0.1, 0.1) + 0.2 * pts[j - 2] : rnd(-100, 100);
    if (cncrot_probe_plane(pts, 5, g, res) >= 0) {
      printf("PP");
      hexes(pts, 15), hexes(g, 16), hexes(res, 2);
      printf("\n");
    }
    double e1[3] = {rnd(-50, 50), rnd(-50, 50), rnd(-5, 5)}, e2[3] = {rnd(-50, 50), rnd(-50, 50), rnd(-5, 5)}, angle, t[16];
    if (cncrot_probe_edge(f, e1, e2, &angle, t) >= 0) {
      printf("PE");
      hexes(f, 16), hexes(e1, 3), hexes(e2, 3), hexes(&angle, 1), hexes(t, 16);
      printf("\n");
    }
  }
  /* Kinematics: the fork head and the three-axis machine of matlab/tests (rows
   * [work_side v p min max offset hirth_offset hirth_step]); forward, inverse, choice. */
  static const double MACH[2][3][12] = {
      {{0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0, 150, -100, 100, 0, 0, 0}},
      {{1, 0, 0, 1, 500, 300, 0, 0, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0, 540, -120, 120, 0, 0, 0},
       {0, 1, 0, 0, 0, 0, 250, 0, 0, 0, 0, 0}}};
  for (int k = 0; k < 2; k++) {
    cncrot_machine m;
    memset(&m, 0, sizeof m);
    for (int r = 0; r < 2 + k; r++)
      cncrot_machine_add_axis(&m, (int32_t)MACH[k][r][0], MACH[k][r] + 1, MACH[k][r] + 4, MACH[k][r][7], MACH[k][r][8]);
    /* A direct mode's frame on the machine (PLANE AXIAL: C and B by letter on the head, the
     * table's A, C and B; CYCLE800 direct: axes 1 and 2). */
    for (int j = 0; j < 4; j++) {
      char line[96];
      int32_t dialect = j % 2 ? CNCROT_DIALECT_SINUMERIK : CNCROT_DIALECT_HEIDENHAIN;
      double a = rnd(-90, 90), b = rnd(-90, 90);
      if (dialect == CNCROT_DIALECT_HEIDENHAIN)
        snprintf(line, sizeof line, "PLANE AXIAL %s%.6f C%+.6f TURN", k ? "A" : "B", a, b);
      else
        snprintf(line, sizeof line, "CYCLE800(0,\"TC1\",0,192,1,2,3,%.6f,%.6f,0,0,0,0,-1)", a, b);
      cncrot_program p;
      memset(&p, 0, sizeof p);
      double f[16];
      if (cncrot_program_line(&p, dialect, line, strlen(line)) < 0 || cncrot_program_frame_on(&p, &m, f) < 0) continue;
      printf("KP %d %d", k, dialect), text_hex(line), hexes(f, 16), printf("\n");
    }
    for (int j = 0; j < 12; j++) {
      double ax[3] = {rnd(-180, 180), rnd(-100, 100), k ? rnd(-180, 180) : 0}, f[16], sol[6] = {0}, cur[3] = {rnd(-720, 720), 0, 0};
      double out[3], res[3], rem[16];
      size_t n = 0;
      if (cncrot_machine_forward(&m, ax, f) < 0) continue;
      printf("KF %d", k), hexes(ax, 3), hexes(f, 16), printf("\n");
      int32_t s = cncrot_machine_inverse(&m, f, sol, 2, &n);
      printf("KI %d", k), hexes(f, 16), printf(" %d", (int)n), hexes(sol, 6), printf(" %d\n", s);
      /* The five-axis transformation: a pose from random axes, back from positions near. */
      double six[6] = {rnd(-300, 300), rnd(-300, 300), rnd(-300, 300), ax[0], ax[1], ax[2]}, len = rnd(0, 200);
      double pose[16], prev6[6] = {0, 0, 0, ax[0] + rnd(-5, 5), ax[1] + rnd(-5, 5), k ? ax[2] + rnd(-5, 5) : 0}, back[6];
      if (cncrot_machine_tcp_forward(&m, six, len, pose) == 0) {
        int32_t t = cncrot_machine_tcp_inverse(&m, pose, len, prev6, back);
        if (t >= 0) {
          printf("KT %d", k), hexes(six, 6), hexes(&len, 1), hexes(pose, 16), hexes(prev6, 6), hexes(back, 6);
          printf(" %d\n", t);
        }
        /* The same point as a CL row (its direction scaled): the library's pose of it, and
         * the axes for it, as MATLAB's CL rows take them. */
        double sc = rnd(0.5, 3), tip[3] = {pose[3], pose[7], pose[11]};
        double dir[3] = {pose[2] * sc, pose[6] * sc, pose[10] * sc}, cl[16], cl_back[6];
        /* Three rotary axes: carried from where the machine stands, as the gateway does. */
        double before[16];
        int32_t c = m.count == 3 && cncrot_machine_forward(&m, prev6 + 3, before) == 0 ? cncrot_cl_pose_toward(tip, dir, before, cl)
                                                                                       : cncrot_cl_pose(tip, dir, cl);
        if (c == 0) {
          int32_t u = cncrot_machine_tcp_inverse(&m, cl, len, prev6, cl_back);
          if (u >= 0) {
            printf("KL %d", k), hexes(tip, 3), hexes(dir, 3), hexes(&len, 1), hexes(cl, 16), hexes(prev6, 6);
            hexes(cl_back, 6), printf(" %d\n", u);
          }
        }
      }
      int32_t rule = j % 4, ref = rule == 1 || rule == 2 ? 2 : 0;
      s = cncrot_machine_choose(&m, f, cur, rule, ref, out, res, rem);
      if (s >= 0) {
        printf("KC %d %d %d", k, rule, ref), hexes(f, 16), hexes(cur, 3), hexes(out, 3), hexes(res, 3), hexes(rem, 16);
        printf(" %d\n", s);
      }
    }
  }
  return 0;
}
