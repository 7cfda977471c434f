/* Worst-case stack use of every exported function, measured on a painted stack.
 *
 * Each function runs (through makecontext/swapcontext) on a stack of its own that was
 * filled with a pattern; afterwards the deepest byte that no longer holds the pattern gives
 * the stack the call used. The calls cover the success, remark and error paths; the inputs
 * and outputs are globals, so the wrapper's own frame is a few words, and the empty
 * wrapper's use is subtracted. Usage: stack LIMIT_HOT LIMIT_SETUP; prints a table and exits
 * 1 if a hot-path function needs more than LIMIT_HOT bytes or a setup function (HEAD_DEF
 * parsing, program lines, the machine kinematics: block preparation, not the interpolation
 * cycle) more than LIMIT_SETUP. Not built with sanitizers (they change frames). */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ucontext.h>
#include "cncrot.h"

#define STACK_BYTES (256 * 1024)
#define PAINT 0xA5

static unsigned char stack_mem[STACK_BYTES] __attribute__((aligned(64)));
static ucontext_t caller, callee;
static void (*current)(void);
static volatile int sink;

static void trampoline(void) { current(); }

static size_t used_by(void (*f)(void)) {
  memset(stack_mem, PAINT, sizeof stack_mem);
  if (getcontext(&callee) != 0) abort();
  callee.uc_stack.ss_sp = stack_mem;
  callee.uc_stack.ss_size = sizeof stack_mem;
  callee.uc_link = &caller;
  current = f;
  makecontext(&callee, trampoline, 0);
  if (swapcontext(&caller, &callee) != 0) abort();
  size_t k = 0;
  while (k < sizeof stack_mem && stack_mem[k] == PAINT) k++;
  return sizeof stack_mem - k;
}

static const double A[3] = {30, 90, 60}, B[3] = {10, 20, 30}, HUGE_A[3] = {1e300, -1e15, 7e20};
static const double NAN_A[3] = {0, 0, 0}; /* set to NaN in main */
static double nan_a[3];
static const double ID[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
static const double MEASURED[9] = {1, 0.001, 0, -0.001, 1, 0, 0, 0, 1.0002};
static const double ILL[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1e-6};
static const double IDF[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static double m[9], out3[3], f[16], f2[16];
static cncrot_head_table table;
static cncrot_cycle600_gud gud;
static int32_t line;
static const char HEADS[] =
    "N830 TZ7:\nN840 _HEAD_NAME=\"IFVW207S\"\nN850 _HEAD_ALLOWED=1\n"
    "N860 _DELTA_L1=540.735 _DELTA_L2=250.049\nN870 _DELTA_H1=200.007\n"
    "N880 _OFFS_L1_X=0.024 _OFFS_L1_Y=0.032\nN890 _OFFS_L2_X=0.011 _OFFS_L2_Y=-0.041\n"
    "N900 _OFFS_H1_X=0.335 _OFFS_H1_Z=0.247 ; tool side\nN910 GOTOF END\n"
    "_HEAD_NAME=\"H1\"\n_HEAD_NAME=\"H2\"\n_HEAD_NAME=\"H3\"\n_HEAD_NAME=\"H4\"\n"
    "_HEAD_NAME=\"H5\"\n_HEAD_NAME=\"H6\"\n_HEAD_NAME=\"H7\"\n_HEAD_NAME=\"H8\"\n"
    "_HEAD_NAME=\"H9\"\n_HEAD_NAME=\"H10\"\n_HEAD_NAME=\"H11\"\n_HEAD_NAME=\"H12\"\n"
    "_HEAD_NAME=\"H13\"\n_HEAD_NAME=\"H14\"\n_HEAD_NAME=\"UFK600\"\nEND:\nM17\n";

static void none(void) {}
/* The canary: a frame of 4 KiB, which the measurement must see. */
static void big_frame(void) {
  volatile unsigned char buf[4096];
  for (size_t k = 0; k < sizeof buf; k++) buf[k] = (unsigned char)k;
  sink += buf[100];
}
static void status_str(void) { sink += cncrot_status_str(-15)[0] + cncrot_status_str(42)[0]; }
static void matrix_from_angles(void) {
  sink += cncrot_matrix_from_angles(1, 57, A, m) + cncrot_matrix_from_angles(0, 27, HUGE_A, m) +
          cncrot_matrix_from_angles(1, 57, nan_a, m) + cncrot_matrix_from_angles(1, 64, A, m);
}
static void angles_from_matrix(void) {
  sink += cncrot_angles_from_matrix(1, 57, ID, out3) + cncrot_angles_from_matrix(0, 25, MEASURED, out3) +
          cncrot_angles_from_matrix(1, 57, ILL, out3);
}
static void convert(void) {
  sink += cncrot_convert(0, 57, A, 1, 39, out3) + cncrot_convert(0, 57, HUGE_A, 1, 55, out3) +
          cncrot_convert(0, 57, nan_a, 1, 39, out3);
}
/* Batches: three rows (good, singular or huge, NaN), with statuses. */
static double rows3[9] = {30, 45, 60, 30, 90, 60, 1e300, -1e15, 7e20}, mats[27], outs[9];
static int32_t sts[3];
static void matrices_from_angles(void) {
  sink += cncrot_matrices_from_angles(0, 57, rows3, 3, mats, sts) +
          cncrot_matrices_from_angles(0, 64, rows3, 3, mats, NULL);
}
static void angles_from_matrices(void) {
  sink += cncrot_angles_from_matrices(1, 39, mats, 3, outs, sts) +
          cncrot_angles_from_matrices(1, 39, ILL, 1, outs, NULL);
}
static void convert_many(void) {
  sink += cncrot_convert_many(0, 57, rows3, 3, 1, 39, outs, sts) +
          cncrot_convert_many(0, 57, nan_a, 1, 1, 39, outs, sts);
}
static void second_solution(void) {
  sink += cncrot_second_solution(57, HUGE_A, out3) + cncrot_second_solution(55, B, out3);
}
static void closest_angles(void) {
  sink += cncrot_closest_angles(1, 55, ID, B, out3) + cncrot_closest_angles(1, 57, MEASURED, HUGE_A, out3);
}
static void check_rotation(void) { sink += cncrot_check_rotation(ID) + cncrot_check_rotation(ILL); }
static void nearest_rotation(void) {
  sink += cncrot_nearest_rotation(MEASURED, m) + cncrot_nearest_rotation(ILL, m);
}
static void add_rotation(void) {
  sink += cncrot_add_rotation(1, 57, A, MEASURED, m) + cncrot_add_rotation(0, 57, HUGE_A, ID, m);
}
static void rotate_vector(void) { sink += cncrot_rotate_vector(MEASURED, A, out3) + cncrot_rotate_vector(ILL, A, out3); }
static void rotate_vector_inverse(void) { sink += cncrot_rotate_vector_inverse(MEASURED, A, out3); }
static void frame_from_angles(void) { sink += cncrot_frame_from_angles(1, 57, A, B, HUGE_A, f); }
static void frame_about_point(void) { sink += cncrot_frame_about_point(1, 57, A, B, f); }
static void frame_compose(void) {
  cncrot_frame_from_angles(1, 57, A, B, B, f2);
  sink += cncrot_frame_compose(f2, f2, f) + cncrot_frame_compose(IDF, f2, f);
}
static void frame_inverse(void) { sink += cncrot_frame_inverse(f2, f); }
static void frame_transform_point(void) { sink += cncrot_frame_transform_point(f2, A, out3); }
static void cycle600_gud_size(void) { sink += (int)cncrot_cycle600_gud_size(); }
static void head_table_parse(void) {
  static const char bad[] = "_HEAD_NAME=\"A\"\nDELTA_L2=1\n";
  sink += cncrot_head_table_parse(&table, HEADS, sizeof HEADS - 1, &line) +
          cncrot_head_table_parse(&table, bad, sizeof bad - 1, &line);
}
static void form_word_count(void) {
  static size_t n;
  sink += cncrot_form_word_count(CNCROT_FORM_G158, &n) + cncrot_form_word_count(0, &n);
}
static void form_frame(void) {
  static const double g68[6] = {10, 0, 0, 30, 45, 60}, c800[9] = {1, 2, 3, 30, 20, 10, 4, 5, 6};
  static const double pts[9] = {0, 0, 0, 1, 1, 0, -1, 1, 0};
  sink += cncrot_form_frame(CNCROT_FORM_G68_2, 0, g68, 6, f) + cncrot_form_frame(CNCROT_FORM_CYCLE800, 128 + 57, c800, 9, f) +
          cncrot_form_frame(CNCROT_FORM_PLANE_POINTS, 0, pts, 9, f) + cncrot_form_frame(CNCROT_FORM_G158, 10157, c800, 9, f) +
          cncrot_form_frame(CNCROT_FORM_G268, 321, g68, 6, f) + cncrot_form_frame(CNCROT_FORM_PLANE_VECTOR, 0, g68, 6, f);
}
static void form_values(void) {
  static double w[9];
  cncrot_frame_from_angles(1, 57, A, B, B, f2);
  sink += cncrot_form_values(CNCROT_FORM_CYCLE800, 128 + 57, f2, w, 9) + cncrot_form_values(CNCROT_FORM_G158, 10157, f2, w, 9) +
          cncrot_form_values(CNCROT_FORM_PLANE_POINTS, 0, f2, w, 9) + cncrot_form_values(CNCROT_FORM_G268, 123, f2, w, 6) +
          cncrot_form_values(CNCROT_FORM_SINUMERIK_ROT, 1, IDF, w, 3);
}
static void probe_flange(void) {
  static const double o[3] = {0, 0, 0}, x[3] = {100, 0, 10}, y[3] = {0, 100, -5};
  sink += cncrot_probe_flange(o, x, o, y, out3, f) + cncrot_probe_flange(o, o, o, y, out3, f);
}
static void probe_plane(void) {
  static const double pts[24] = {0, 0, 5, 100, 0, 5, 0, 100, 5, 100, 100, 5.02, 50, 50, 5, 20, 70, 5.01, 90, 10, 4.99, 60, 60, 5};
  static double res[2];
  sink += cncrot_probe_plane(pts, 8, f, res) + cncrot_probe_plane(pts, 2, f, res);
}
static void probe_plane_toward(void) {
  static const double pts[12] = {0, 0, 0, 0, 50, 0, 100, 50, -10, 100, 0, -10}, none[3] = {0, 0, 0};
  static double res[2];
  sink += cncrot_probe_plane_toward(pts, 4, none, f, res) + cncrot_probe_plane_toward(pts, 2, none, f, res);
}
static void probe_edge(void) {
  static const double e1[3] = {0, 0, 0}, e2[3] = {100, 100, 0};
  static double a;
  sink += cncrot_probe_edge(IDF, e1, e2, &a, f) + cncrot_probe_edge(IDF, e1, e1, &a, f);
}
static cncrot_program prog, axial;
static const char AXIAL[] = "PLANE AXIAL B+30 C+45 TURN FMAX";
static const char C800[] = "N10 CYCLE800(1,\"TC1\",0,57,10,0,0,30,45,60,0,0,0,-1,100,1)";
static const char C600[] = "N20 CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39,1,0,0) ; paper";
static const char C19[] = "7 CYCL DEF 19.1 A+10 B+30 C+45 F1000 DIST50 MB MAX";
static const char PLANE[] = "5 PLANE POINTS P1X+10 P1Y+0 P1Z+0 P2X+10.123456789012345 P2Y+5 P2Z+0 P3X+0 P3Y+0 P3Z+0 STAY";
static void program_line(void) {
  memset(&prog, 0, sizeof prog);
  sink += cncrot_program_line(&prog, CNCROT_DIALECT_SINUMERIK, C800, sizeof C800 - 1) +
          cncrot_program_line(&prog, CNCROT_DIALECT_SINUMERIK, C600, sizeof C600 - 1);
  memset(&prog, 0, sizeof prog);
  sink += cncrot_program_line(&prog, CNCROT_DIALECT_HEIDENHAIN, PLANE, sizeof PLANE - 1) +
          cncrot_program_line(&prog, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+Q1", 20);
  memset(&axial, 0, sizeof axial);
  sink += cncrot_program_line(&axial, CNCROT_DIALECT_HEIDENHAIN, AXIAL, sizeof AXIAL - 1);
  /* Cycle 19, spatial and (on a machine set so) axis angles. */
  sink += cncrot_program_line(&prog, CNCROT_DIALECT_HEIDENHAIN, C19, sizeof C19 - 1) +
          cncrot_program_line(&prog, CNCROT_DIALECT_HEIDENHAIN, "L A+Q120 C+Q122 FMAX M126", 26);
  static cncrot_program c19;
  sink += cncrot_program_init(&c19, CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES) +
          cncrot_program_line(&c19, CNCROT_DIALECT_HEIDENHAIN, C19, sizeof C19 - 1);
}
static void program_column(void) {
  static size_t col;
  sink += cncrot_program_column(&prog, CNCROT_DIALECT_HEIDENHAIN, PLANE, sizeof PLANE - 1, &col) +
          cncrot_program_column(&prog, CNCROT_DIALECT_HEIDENHAIN, "PLANE RELATIV SPA+1.5e", 22, &col);
}
static void program_expected(void) {
  static char what[CNCROT_PROGRAM_EXPECTED_SIZE];
  static const char spaced[] = "CYCLE600(0,\"A B\",1,57,0,0,0,30,45,60,0,0,0,1,39)";
  sink += cncrot_program_expected(&prog, CNCROT_DIALECT_HEIDENHAIN, PLANE, sizeof PLANE - 1, what, sizeof what) +
          cncrot_program_expected(&prog, CNCROT_DIALECT_SINUMERIK, spaced, sizeof spaced - 1, what, sizeof what);
}
static void program_frame(void) { sink += cncrot_program_frame(&prog, f); }
static void program_init(void) { sink += cncrot_program_init(&prog, CNCROT_PROGRAM_SINUMERIK_EULER); }
static void program_write(void) {
  static char out[CNCROT_PROGRAM_LINE_MAX + 1];
  /* Shortest digits of numbers near 1e-90 and 1e99 take the longest exact arithmetic. */
  static const double g[16] = {0.36, -0.48, 0.8, 1e-90, 0.8, 0.6, 0, 9.87654321e98, -0.48, 0.64, 0.6, -3.1e-7, 0, 0, 0, 1};
  sink += cncrot_program_write(CNCROT_DIALECT_SINUMERIK, "CYCLE800 185", g, -1, out, sizeof out) +
          cncrot_program_write(CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", g, -1, out, sizeof out) +
          cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", g, 17, out, sizeof out);
}
static cncrot_program change_from, change_to, added_to, added_far;
static const char added[] = "G68.4 I1.234567890123 J45.678901234 K-12.3456789";
static const char added_origin[] = "G68.4 X0.5 Y-0.25 Z0.000000001 I1.234567890123 J45.678901234 K-12.3456789";
static void program_write_change(void) {
  static char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  /* A tilt with an origin into PLANE POINTS: a cancel, cycle 7 and the plane, the numbers
     in their shortest exact digits. */
  sink += cncrot_program_write_change(&change_from, &change_to, CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", -1,
                                      out, sizeof out) +
          cncrot_program_write_change(&change_to, &change_from, CNCROT_DIALECT_SINUMERIK, "CYCLE800 185", -1, out,
                                      sizeof out) +
          cncrot_program_write_change(&change_from, &change_to, CNCROT_DIALECT_FANUC, "G68.2", 17, out, sizeof out);
  /* Increments: three PLANE RELATIV, an additive CYCLE800 with an origin. */
  sink += cncrot_program_write_change(&change_to, &added_to, CNCROT_DIALECT_HEIDENHAIN, "PLANE POINTS", -1, out,
                                      sizeof out) +
          cncrot_program_write_change(&change_to, &added_far, CNCROT_DIALECT_SINUMERIK, "CYCLE800 185", -1, out,
                                      sizeof out);
}
static cncrot_program cancelled;
static void program_write_block(void) {
  static char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  static const char b[] = "G68.2 X1.000000000001 Y2 Z3 I12.345678901 J33.3333333 K-77.7777777";
  static const char cancel[] = "G69";
  /* A tilt (the block read twice more on the probes) and a cancel restated with nothing active. */
  sink += cncrot_program_write_block(&change_from, &change_to, b, sizeof b - 1, CNCROT_DIALECT_HEIDENHAIN,
                                     "PLANE POINTS", -1, out, sizeof out) +
          cncrot_program_write_block(&cancelled, &cancelled, cancel, sizeof cancel - 1, CNCROT_DIALECT_SINUMERIK,
                                     "CYCLE800 185", -1, out, sizeof out);
  /* Increments, their own words read on a third probe. */
  sink += cncrot_program_write_block(&change_to, &added_to, added, sizeof added - 1, CNCROT_DIALECT_HEIDENHAIN,
                                     "PLANE POINTS", -1, out, sizeof out) +
          cncrot_program_write_block(&change_to, &added_far, added_origin, sizeof added_origin - 1,
                                     CNCROT_DIALECT_SINUMERIK, "CYCLE800 185", -1, out, sizeof out);
}
static void program_rest(void) {
  static char out[CNCROT_PROGRAM_LINE_MAX + 3];
  static const char b[] = "N40 G1 G68.2 X 10. Y[0.] Z0 I0 J30 K0 F300. (TILT) G91 G28 Z0. G69 ; end";
  sink += cncrot_program_rest(CNCROT_DIALECT_SYNTEC, b, sizeof b - 1, out, sizeof out) + out[0];
}
static void program_joins(void) {
  int32_t join = 0;
  sink += cncrot_program_joins(&change_from, &change_to, &cancelled, &join) + join;
}
static void cycle600(void) {
  memset(&gud, 0, sizeof gud);
  sink += cncrot_cycle600(&gud, &table, 0, "UFK600", 1, 57, 1, 2, 3, 30, 45, 60, 4, 5, 6, 1, 39, 0, 0, 0);
  sink += cncrot_cycle600(&gud, &table, 1, "UFK600", 1, 57, 1, 2, 3, 30, 90, 60, 4, 5, 6, 0, 55, 1, 1, 1);
  sink += cncrot_cycle600(&gud, NULL, 1, "IFVW207S", 0, 57, 1, 2, 3, 30, 90, 60, 4, 5, 6, 0, 55, 1, 1, 1);
  sink += cncrot_cycle600(&gud, &table, 1, "NOPE", 1, 57, 1, 2, 3, 30, 90, 60, 4, 5, 6, 0, 55, 1, 1, 1);
}
static cncrot_machine mach, head3;
/* Built with the fork head (build_fork). */
static cncrot_machine tabled;
static cncrot_program table_rot;
static const char CARR[] =
    "N10 $TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1 $TC_CARR10[1]=0 $TC_CARR11[1]=1.5EX0 $TC_CARR12[1]=1\n"
    "N20 $TC_CARR4[1]=0.011 $TC_CARR5[1]=-0.041 $TC_CARR6[1]=-250.049 $TC_CARR23[1]=\"m\"\n"
    "N30 $TC_CARR15[1]=10 $TC_CARR28[1]=2.5 $TC_CARR30[1]=-360 $TC_CARR32[1]=360\n"
    "N40 $TC_CARR34[1]=\"TABLE_AND_HEAD_0123456789\" ; name\n$TC_DP1[1,1]=120\nM17\n";
static const double TILT[16] = {0.36, -0.48, 0.8, 0, 0.8, 0.6, 0, 0, -0.48, 0.64, 0.6, 0, 0, 0, 0, 1};
static void machine_from_carr(void) {
  sink += cncrot_machine_from_carr(&mach, CARR, sizeof CARR - 1, 1) +
          cncrot_machine_from_carr(&mach, CARR, sizeof CARR - 1, 2);
}
static void machine_carr_error_line(void) {
  sink += cncrot_machine_carr_error_line(CARR, sizeof CARR - 1, 1, &line);
}
static void machine_from_head(void) {
  static const double z[3] = {0, 0, 1}, x[3] = {1, 0, 0};
  sink += cncrot_machine_from_head(&mach, &table, "IFVW207S", z, x);
}
static void machine_add_axis(void) {
  static const double z[3] = {0, 0, 1}, y[3] = {0, 1, 0}, x[3] = {1, 0, 0}, o[3] = {10, 20, 30};
  memset(&head3, 0, sizeof head3);
  sink += cncrot_machine_add_axis(&head3, 1, z, o, 0, 0) + cncrot_machine_add_axis(&head3, 0, y, o, -100, 100) +
          cncrot_machine_add_axis(&head3, 0, x, o, 0, 0) + cncrot_machine_add_axis(&head3, 0, x, o, 0, 0);
}
static void machine_forward(void) {
  static const double ax[3] = {10, 20, 30};
  sink += cncrot_machine_forward(&head3, ax, f);
}
static void machine_inverse(void) {
  static double sol[6];
  static size_t n;
  sink += cncrot_machine_inverse(&head3, TILT, sol, 2, &n) + cncrot_machine_inverse(&mach, TILT, sol, 2, &n);
}
static void machine_choose(void) {
  static const double cur[3] = {750, 10, -20};
  static double ax[3], res[3], rem[16];
  sink += cncrot_machine_choose(&head3, TILT, cur, CNCROT_CHOOSE_CLOSEST, 0, ax, res, rem) +
          cncrot_machine_choose(&mach, TILT, cur, CNCROT_CHOOSE_MINUS, 2, ax, res, rem);
}
static void program_axes(void) {
  static const double cur[3] = {750, 10, -20};
  static double ax[3];
  sink += cncrot_program_axes(&prog, &head3, cur, ax) + cncrot_program_axes(&prog, &mach, cur, ax) +
          cncrot_program_axes(&axial, &head3, cur, ax) + cncrot_program_axes(&table_rot, &tabled, cur, ax);
}
static void program_frame_on(void) {
  sink += cncrot_program_frame_on(&axial, &head3, f) + cncrot_program_frame_on(&prog, &mach, f);
}
static void machine_follow(void) {
  static const double from[3] = {0, 0, 0}, to[3] = {30, 40, 50}, lin[3] = {1, 2, 3};
  sink += cncrot_machine_follow(&head3, from, to, lin, 100, out3);
}
static void machine_tcp_forward(void) {
  static const double ax[6] = {10, 20, 30, 40, 50, 60};
  static double pose[16];
  sink += cncrot_machine_tcp_forward(&head3, ax, 100, pose) + cncrot_machine_tcp_forward(&mach, ax, 100, pose);
}
/* The identity pose: the tool along the first axis of both machines, a pole (the general way). */
static const double POLE[16] = {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1};
/* A rotation rounded to 6 decimals (sqrt(3)/2 as 0.866025): solved for its nearest rotation. */
static const double ROUNDED[16] = {0, 0.866025, 0.5, 10, -1, 0, 0, 0, 0, -0.5, 0.866025, 0, 0, 0, 0, 1};
/* Its two ways apart: the common case (a tilt away from the poles, no Hirth grid: a fork
 * head and head3) and the general way (the poles of both, the fork with a Hirth grid). */
static cncrot_machine fork, fork_hirth;
/* head3's chain is C (table), B, X (head): X along the table's Z is its pole. */
static const double POLE3[16] = {0, 0, -1, 5, 0, 1, 0, 6, 1, 0, 0, 7, 0, 0, 0, 1};
static void build_fork(void) {
  static const double z[3] = {0, 0, 1}, x[3] = {1, 0, 0}, p[3] = {0, 0, 150};
  memset(&fork, 0, sizeof fork);
  sink += cncrot_machine_add_axis(&fork, 0, z, p, 0, 0) + cncrot_machine_add_axis(&fork, 0, x, p, -120, 120);
  fork_hirth = fork;
  fork_hirth.axes[0].hirth_step_deg = 2.5;
  sink += cncrot_machine_seal(&fork_hirth);
  /* A table C with a head B, and a tilt that turns the free table (TABLE ROT). */
  static const double y[3] = {0, 1, 0}, o[3] = {0, 0, 0};
  static const char TR[] = "PLANE SPATIAL SPA+0 SPB+0 SPC+90 TURN TABLE ROT";
  memset(&tabled, 0, sizeof tabled);
  memset(&table_rot, 0, sizeof table_rot);
  sink += cncrot_machine_add_axis(&tabled, 1, z, o, 0, 0) + cncrot_machine_add_axis(&tabled, 0, y, p, -100, 100) +
          cncrot_program_line(&table_rot, CNCROT_DIALECT_HEIDENHAIN, TR, sizeof TR - 1);
}
static void machine_tcp_inverse_common(void) {
  static const double prev[6] = {0, 0, 0, 750, 10, -20}, prev2[6] = {0, 0, 0, 750, 10, 0};
  static double ax[6];
  sink += cncrot_machine_tcp_inverse(&head3, TILT, 100, prev, ax) + cncrot_machine_tcp_inverse(&fork, TILT, 100, prev2, ax);
}
static void machine_tcp_inverse_general(void) {
  static const double prev[6] = {0, 0, 0, 750, 10, -20}, prev2[6] = {0, 0, 0, 750, 10, 0};
  static double ax[6];
  sink += cncrot_machine_tcp_inverse(&head3, POLE3, 100, prev, ax) + cncrot_machine_tcp_inverse(&fork, POLE, 100, prev2, ax) +
          cncrot_machine_tcp_inverse(&fork_hirth, TILT, 100, prev2, ax) +
          cncrot_machine_tcp_inverse(&fork_hirth, POLE, 100, prev2, ax) +
          cncrot_machine_tcp_inverse(&head3, ROUNDED, 100, prev, ax) +
          cncrot_machine_tcp_inverse(&fork, ROUNDED, 100, prev2, ax);
}
/* The export's worst case: both ways, and the machines before (called here, not through the
 * two functions above, whose frames would be counted too). */
static void machine_tcp_inverse(void) {
  static const double prev[6] = {0, 0, 0, 750, 10, -20}, prev2[6] = {0, 0, 0, 750, 10, 0};
  static double ax[6];
  sink += cncrot_machine_tcp_inverse(&head3, TILT, 100, prev, ax) + cncrot_machine_tcp_inverse(&mach, TILT, 100, prev, ax) +
          cncrot_machine_tcp_inverse(&head3, POLE, 100, prev, ax) + cncrot_machine_tcp_inverse(&mach, POLE, 100, prev, ax) +
          cncrot_machine_tcp_inverse(&fork, TILT, 100, prev2, ax) + cncrot_machine_tcp_inverse(&head3, POLE3, 100, prev, ax) +
          cncrot_machine_tcp_inverse(&fork, POLE, 100, prev2, ax) + cncrot_machine_tcp_inverse(&fork_hirth, TILT, 100, prev2, ax) +
          cncrot_machine_tcp_inverse(&fork_hirth, POLE, 100, prev2, ax);
}
/* Unsealed copies (a field edited by hand): every field checked on each call. */
static cncrot_machine edited(const cncrot_machine *m) {
  cncrot_machine e = *m;
  e.axes[0].offset_deg += 1e-3;
  return e;
}
static void machine_tcp_inverse_unsealed(void) {
  static const double prev[6] = {0, 0, 0, 750, 10, -20};
  static double ax[6];
  static cncrot_machine a, b;
  a = edited(&head3);
  b = edited(&mach);
  sink += cncrot_machine_tcp_inverse(&a, TILT, 100, prev, ax) + cncrot_machine_tcp_inverse(&b, TILT, 100, prev, ax) +
          cncrot_machine_tcp_inverse(&a, POLE, 100, prev, ax) + cncrot_machine_tcp_inverse(&b, POLE, 100, prev, ax);
}
static void machine_tcp_forward_unsealed(void) {
  static const double ax[6] = {10, 20, 30, 40, 50, 60};
  static double pose[16];
  static cncrot_machine a, b;
  a = edited(&head3);
  b = edited(&mach);
  sink += cncrot_machine_tcp_forward(&a, ax, 100, pose) + cncrot_machine_tcp_forward(&b, ax, 100, pose);
}
static void tool_path_line(void) {
  static const char *lines[] = {"TRAORI", "N30 G1 X10 Y0 Z5 A3=0 B3=-1 C3=1", "N40 ORIRPY", "N50 A2=10 B2=20 C2=30",
                                "N60 G2 X1 Y1 CR=5"};
  static cncrot_tool_path t;
  memset(&t, 0, sizeof t);
  for (size_t k = 0; k < sizeof lines / sizeof lines[0]; k++)
    sink += cncrot_tool_path_line(&t, CNCROT_DIALECT_SINUMERIK, lines[k], strlen(lines[k]));
  static const char h[] = "3 LN X+1 Y+2 Z+3 NX+0 NY+0 NZ+1 TX+0 TY+0.6 TZ+0.8 R0 F1000 M128";
  sink += cncrot_tool_path_line(&t, CNCROT_DIALECT_HEIDENHAIN, h, sizeof h - 1);
}
static void tool_path_axes(void) {
  static const double prev[6] = {0, 0, 0, 750, 10, -20};
  static double ax[6];
  static cncrot_tool_path t;
  memset(&t, 0, sizeof t);
  static const char a[] = "G43.5 H1 G1 X1 Y2 Z3 I0.5 J0 K0.8";
  sink += cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, a, sizeof a - 1);
  sink += cncrot_tool_path_axes(&t, &head3, 100, prev, CNCROT_CHOOSE_CLOSEST, 0, ax) +
          cncrot_tool_path_axes(&t, &mach, 100, prev, CNCROT_CHOOSE_MINUS, 2, ax);
  static const char b[] = "X2 A10 B20 C30";
  sink += cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, b, sizeof b - 1);
  sink += cncrot_tool_path_axes(&t, &head3, 100, prev, CNCROT_CHOOSE_CLOSEST, 0, ax);
}
static void cl_pose(void) {
  static const double tip[3] = {1, 2, 3}, dir[3] = {0.3, -0.4, 0.8}, along_x[3] = {-1, 0, 0.1};
  static double pose[16];
  sink += cncrot_cl_pose(tip, dir, pose) + cncrot_cl_pose(tip, along_x, pose);
}
static void cl_pose_toward(void) {
  static const double tip[3] = {1, 2, 3}, dir[3] = {0.3, -0.4, 0.8}, back[3] = {-0.3, 0.4, -0.7};
  static double pose[16];
  sink += cncrot_cl_pose(tip, dir, pose);
  sink += cncrot_cl_pose_toward(tip, dir, pose, pose) + cncrot_cl_pose_toward(tip, back, pose, pose);
}
static void machine_seal(void) {
  static cncrot_machine a;
  a = edited(&head3);
  sink += cncrot_machine_seal(&a);
}
static void machine_tcp_inverse_rule(void) {
  static const double prev[6] = {0, 0, 0, 750, 10, -20};
  static double ax[6];
  sink += cncrot_machine_tcp_inverse_rule(&head3, TILT, 100, prev, CNCROT_CHOOSE_MINUS, 2, ax) +
          cncrot_machine_tcp_inverse_rule(&mach, TILT, 100, prev, CNCROT_CHOOSE_CLOSEST, 0, ax);
}
static void cycle600_position(void) {
  static const double cur[3] = {0, 0, 0};
  static double ax[3], res[3], rem[16];
  sink += cncrot_cycle600_position(&gud, &head3, cur, ax, res, rem);
}

struct entry {
  const char *name;
  void (*f)(void);
  int setup; /* 1: setup-time (not on a real-time cycle's hot path) */
};
#define E(n, s) {"cncrot_" #n, n, s}
static const struct entry ENTRIES[] = {
    E(status_str, 0),        E(matrix_from_angles, 0), E(angles_from_matrix, 0),
    E(convert, 0),           E(second_solution, 0),    E(closest_angles, 0),
    E(check_rotation, 0),    E(nearest_rotation, 0),   E(add_rotation, 0),
    E(rotate_vector, 0),     E(rotate_vector_inverse, 0), E(frame_from_angles, 0),
    E(frame_about_point, 0), E(frame_compose, 0),      E(frame_inverse, 0),
    E(frame_transform_point, 0), E(cycle600_gud_size, 0), E(head_table_parse, 1),
    E(cycle600, 0),          E(form_frame, 0),         E(form_values, 0),
    E(form_word_count, 0),   E(probe_flange, 0),       E(probe_plane, 0),
    E(probe_plane_toward, 0),
    E(probe_edge, 0),        E(program_line, 1),       E(program_column, 1),
    E(program_expected, 1),  E(program_frame, 0),     E(program_write, 1),      E(program_init, 0),
    E(program_write_change, 1),
    E(program_write_block, 1),
    E(program_joins, 0),      E(program_rest, 0),
    E(machine_from_carr, 1), E(machine_carr_error_line, 1), E(machine_from_head, 1),
    E(machine_add_axis, 1),  E(machine_forward, 1),    E(machine_inverse, 1),
    E(machine_choose, 1),    E(machine_follow, 1),     E(cycle600_position, 1),
    E(program_axes, 1),      E(program_frame_on, 1),   E(machine_tcp_forward, 0), E(machine_tcp_inverse, 0),
    E(machine_tcp_inverse_rule, 1), E(machine_seal, 1), E(cl_pose, 0), E(cl_pose_toward, 0), E(tool_path_line, 1), E(tool_path_axes, 1),
    E(matrices_from_angles, 0), E(angles_from_matrices, 0), E(convert_many, 0),
};

/* Other paths of measured functions (not names the header declares: stack.sh matches those
 * against ENTRIES). */
static const struct entry PATHS[] = {
    {"cncrot_machine_tcp_forward, unsealed", machine_tcp_forward_unsealed, 1},
    {"cncrot_machine_tcp_inverse, unsealed", machine_tcp_inverse_unsealed, 1},
    {"cncrot_machine_tcp_inverse, common case", machine_tcp_inverse_common, 0},
    {"cncrot_machine_tcp_inverse, general way", machine_tcp_inverse_general, 0},
};

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: stack LIMIT_HOT LIMIT_SETUP\n");
    return 2;
  }
  long limit_hot = atol(argv[1]), limit_setup = atol(argv[2]);
  (void)NAN_A;
  nan_a[0] = strtod("nan", NULL);
  {
    static const char a[] = "G52 X0.1234567890123 Y98765.4321 Z-0.000001";
    static const char b[] = "G68.2 X1.000000000001 Y2 Z3 I12.345678901 J33.3333333 K-77.7777777";
    if (cncrot_program_line(&change_from, CNCROT_DIALECT_FANUC, a, sizeof a - 1) != 0) abort();
    change_to = change_from;
    if (cncrot_program_line(&change_to, CNCROT_DIALECT_FANUC, b, sizeof b - 1) != 0) abort();
    if (cncrot_program_line(&cancelled, CNCROT_DIALECT_FANUC, "G69", 3) != 0) abort();
    added_to = added_far = change_to;
    if (cncrot_program_line(&added_to, CNCROT_DIALECT_FANUC, added, sizeof added - 1) != 0) abort();
    if (cncrot_program_line(&added_far, CNCROT_DIALECT_FANUC, added_origin, sizeof added_origin - 1) != 0) abort();
    if (!added_to.relative || !added_far.relative) abort();
  }
  build_fork();
  size_t base = used_by(none);
  int failed = 0;
  size_t n = sizeof ENTRIES / sizeof ENTRIES[0];
  printf("stack bytes beyond an empty call (%zu bytes), limits %ld hot path / %ld setup:\n", base,
         limit_hot, limit_setup);
  for (size_t k = 0; k < n; k++) {
    size_t used = used_by(ENTRIES[k].f) - base;
    long limit = ENTRIES[k].setup ? limit_setup : limit_hot;
    int over = (long)used > limit;
    failed |= over;
    printf("%s %-32s %6zu%s\n", over ? "OVER" : "    ", ENTRIES[k].name, used,
           ENTRIES[k].setup ? "  (setup)" : "");
  }
  for (size_t k = 0; k < sizeof PATHS / sizeof PATHS[0]; k++) {
    size_t used = used_by(PATHS[k].f) - base;
    long limit = PATHS[k].setup ? limit_setup : limit_hot;
    int over = (long)used > limit;
    failed |= over;
    printf("%s %-40s %6zu%s\n", over ? "OVER" : "    ", PATHS[k].name, used, PATHS[k].setup ? "  (setup)" : "");
  }
  /* The measurement must be able to fail: a function with a 4 KiB frame is seen. */
  size_t canary = used_by(big_frame) - base;
  if (canary < 4096) {
    printf("stack: the canary's 4096-byte frame measured %zu: the measurement is broken\n", canary);
    failed = 1;
  }
  printf("stack: %s\n", failed ? "FAILED" : "ok");
  return failed;
}
