/* CYCLE600 and HEAD_DEF through the C ABI: the paper's Example 3, additive calls,
 * translations, every invalid parameter (state untouched), save/restore of the state. */
#include <stdlib.h>
#include "cncrot.h"
#include "harness.h"

#define CALL(g, h, inexin, name, swrec, binin, px, py, pz, a1, a2, a3, rx, ry, rz, inexout, binout, rotad) \
  cncrot_cycle600((g), (h), (inexin), (name), (swrec), (binin), (px), (py), (pz), (a1), (a2), (a3), \
                  (rx), (ry), (rz), (inexout), (binout), (rotad), 0, 0)

static const char HEAD_DEF[] =
    "N830 TZ7:\n"
    "N840 _HEAD_NAME=\"IFVW207S\"\n"
    "N850 _HEAD_ALLOWED=1\n"
    "N860 _DELTA_L1=540.735 _DELTA_L2=250.049\n"
    "N870 _DELTA_H1=200.007\n"
    "N880 _OFFS_L1_X=0.024 _OFFS_L1_Y=0.032\n"
    "N890 _OFFS_L2_X=0.011 _OFFS_L2_Y=-0.041\n"
    "N900 _OFFS_H1_X=0.335 _OFFS_H1_Z=0.247\n"
    "N905 _HEAD_NAME=\"UFK600\"\n"
    "N906 _HEAD_ALLOWED=1\n"
    "N910 GOTOF END\n";

static void example3(void) {
  cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  CHECK(cncrot_cycle600_gud_size() == sizeof gud, "layout agrees");
  /* N120 CYCLE600(0, "UFK600", 1, 57, 0,0,0, 30,45,60, 0,0,0, 1, 39, 0,0,0) */
  CHECK_STATUS(cncrot_cycle600(&gud, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0), 0);
  const double i39[3] = {37.7923, 20.7048, 49.1066};
  double got[3] = {gud.cyc600_2, gud.cyc600_3, gud.cyc600_4};
  CHECK(strcmp(gud.cyc600_1, "UFK600") == 0, "name %s", gud.cyc600_1);
  CHECK_NEAR(got, i39, 3, 1e-4);
  CHECK(gud.cyc600_5 == 1 && gud.cyc600_6 == 39, "%d %d", gud.cyc600_5, gud.cyc600_6);
  /* Second call: _INEXOUT = 0; _CYC600_5 is 0 (the paper's 1 is a misprint). */
  CHECK_STATUS(cncrot_cycle600(&gud, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 39, 0, 0, 0), 0);
  const double e39[3] = {39.6392, -16.2799, 50.3607};
  double got2[3] = {gud.cyc600_2, gud.cyc600_3, gud.cyc600_4};
  CHECK_NEAR(got2, e39, 3, 1e-4);
  CHECK(gud.cyc600_5 == 0 && gud.cyc600_6 == 39, "%d %d", gud.cyc600_5, gud.cyc600_6);
}

static void additive_and_translations(void) {
  for (int kind = 0; kind < 2; kind++) {
    cncrot_cycle600_gud one, steps;
    memset(&one, 0, sizeof one);
    memset(&steps, 0, sizeof steps);
    CALL(&one, NULL, kind, "H", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0);
    CHECK_STATUS(CALL(&steps, NULL, kind, "H", 1, 1, 0, 0, 0, 30, 0, 0, 0, 0, 0, 1, 39, 0), 0);
    CHECK_STATUS(CALL(&steps, NULL, kind, "H", 1, 2, 0, 0, 0, 45, 0, 0, 0, 0, 0, 1, 39, 1), 0);
    CHECK_STATUS(CALL(&steps, NULL, kind, "H", 1, 3, 0, 0, 0, 60, 0, 0, 0, 0, 0, 1, 39, 1), 0);
    double a[3] = {one.cyc600_2, one.cyc600_3, one.cyc600_4};
    double b[3] = {steps.cyc600_2, steps.cyc600_3, steps.cyc600_4};
    CHECK_NEAR(a, b, 3, 1e-12);
    CHECK_NEAR(one.frame, steps.frame, 16, 1e-15);
  }
  /* Translations: Trans(10,0,0)·Rz(90)·Trans(5,0,0) puts the origin at (10, 5, 0). */
  cncrot_cycle600_gud g;
  memset(&g, 0, sizeof g);
  CHECK_STATUS(CALL(&g, NULL, 1, "H", 1, 3, 10, 0, 0, 90, 0, 0, 5, 0, 0, 1, 27, 0), 0);
  const double expect[16] = {0, -1, 0, 10, 1, 0, 0, 5, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK_NEAR(g.frame, expect, 16, 0);
  /* Additive intrinsic Z90 with a translation after: composes as frames,
   * t = (10,5,0) + Rz(90)·Rz(90)·(1,0,0) = (10,5,0) + (-1,0,0). */
  CHECK_STATUS(CALL(&g, NULL, 1, "H", 1, 3, 0, 0, 0, 90, 0, 0, 1, 0, 0, 1, 27, 1), 0);
  const double expect2[16] = {-1, 0, 0, 9, 0, -1, 0, 5, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK_NEAR(g.frame, expect2, 16, 1e-15);
  CHECK(fabs(g.cyc600_2 - 180) < 1e-12 && g.cyc600_3 == 0 && g.cyc600_4 == 0, "%g", g.cyc600_2);
  /* A singular output is a positive status. */
  CHECK_STATUS(CALL(&g, NULL, 1, "H", 1, 27, 0, 0, 0, 40, 90, 10, 0, 0, 0, 1, 27, 0), CNCROT_STATUS_SINGULAR);
  CHECK(fabs(g.cyc600_2 - 30) < 1e-12 && g.cyc600_3 == 90 && g.cyc600_4 == 0, "singular rule");
}

static void heads_and_invalid(void) {
  cncrot_head_table heads;
  int32_t line = -1;
  CHECK_STATUS(cncrot_head_table_parse(&heads, HEAD_DEF, strlen(HEAD_DEF), &line), 0);
  CHECK(line == 0 && heads.count == 2, "count %d", heads.count);
  CHECK(strcmp(heads.heads[0].name, "IFVW207S") == 0 && heads.heads[0].delta[0] == 540.735 &&
            heads.heads[0].offsets[5] == 0.247 && heads.heads[0].allowed == 1, "head 0");
  /* Unknown lines are reported with their number, the table untouched. */
  cncrot_head_table before = heads;
  const char *bad = "N840 _HEAD_NAME=\"A\"\nN850 DELTA_L2=250.049\n";
  CHECK_STATUS(cncrot_head_table_parse(&heads, bad, strlen(bad), &line), CNCROT_STATUS_PARSE);
  CHECK(line == 2 && memcmp(&before, &heads, sizeof heads) == 0, "line %d", line);
  /* Not NUL-terminated: only len bytes are read. */
  char raw[5] = {'R', 'E', 'T', '\n', 'X'};
  CHECK_STATUS(cncrot_head_table_parse(&heads, raw, 4, NULL), 0);
  CHECK(heads.count == 0, "empty");
  heads = before;
  CHECK_STATUS(cncrot_head_table_parse(NULL, HEAD_DEF, 1, &line), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(cncrot_head_table_parse(&heads, NULL, 1, &line), CNCROT_STATUS_NULL_POINTER);

  cncrot_cycle600_gud gud, saved;
  memset(&gud, 0, sizeof gud);
  CHECK_STATUS(CALL(&gud, &heads, 0, "IFVW207S", 1, 57, 1, 2, 3, 30, 45, 60, 4, 5, 6, 1, 39, 0), 0);
  saved = gud;
  const double nan = NAN, inf = INFINITY;
  /* Every invalid parameter: negative status, state bit for bit unchanged. */
  CHECK_STATUS(CALL(&gud, &heads, 0, "NOPE", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_UNKNOWN_HEAD);
  CHECK_STATUS(CALL(&gud, &heads, 2, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 2, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 64, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_BAD_SEQUENCE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 22, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_BAD_SEQUENCE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, -1, 39, 0), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 3, 0), CNCROT_STATUS_INCOMPLETE_SEQUENCE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 99, 0), CNCROT_STATUS_BAD_SEQUENCE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 5), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(cncrot_cycle600(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0, 2, 0), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(cncrot_cycle600(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0, 0, -7), CNCROT_STATUS_BAD_FLAG);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, nan, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, inf, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, -inf, 1, 39, 0), CNCROT_STATUS_NOT_FINITE);
  CHECK_STATUS(CALL(&gud, &heads, 0, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_NAME_TOO_LONG);
  CHECK_STATUS(CALL(&gud, &heads, 0, NULL, 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_NULL_POINTER);
  CHECK_STATUS(CALL(NULL, &heads, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_NULL_POINTER);
  /* Finite positions whose frame overflows (1e308 + 1e308): refused, not stored. */
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 1, 57, 1e308, 0, 0, 0, 0, 0, 1e308, 0, 0, 1, 39, 0), CNCROT_STATUS_OUT_OF_RANGE);
  CHECK(memcmp(&gud, &saved, sizeof gud) == 0, "state untouched by every invalid call");
  /* _SW_REC = 0 recalculates like 1 (positioning: cncrot_cycle600_position). */
  CHECK_STATUS(CALL(&gud, &heads, 0, "UFK600", 0, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0), CNCROT_STATUS_OK);
  /* A corrupt state is refused and left alone: an edited field fails the checksum. */
  cncrot_cycle600_gud corrupt = saved;
  corrupt.frame[0] = 2.0;
  cncrot_cycle600_gud corrupt_copy = corrupt;
  CHECK_STATUS(CALL(&corrupt, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 1), CNCROT_STATUS_BAD_STATE);
  CHECK(memcmp(&corrupt, &corrupt_copy, sizeof corrupt) == 0, "corrupt state untouched");
  corrupt = saved;
  corrupt.active = 0; /* "inactive" no longer hides a stored rotation */
  CHECK_STATUS(CALL(&corrupt, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 1), CNCROT_STATUS_BAD_STATE);
  CHECK(saved.format == CNCROT_CYCLE600_GUD_FORMAT && saved.checksum != 0, "format %u", saved.format);
  CHECK(strncmp(cncrot_status_str(-15), "CNCROT_STATUS_BAD_STATE", 23) == 0, "name");
  /* Every single-bit flip of a valid state, and of the zeroed initial state, is refused. */
  cncrot_cycle600_gud zero;
  memset(&zero, 0, sizeof zero);
  const cncrot_cycle600_gud *bases[2] = {&saved, &zero};
  int accepted = 0;
  for (int b = 0; b < 2; b++) {
    for (size_t bit = 0; bit < 8 * sizeof saved; bit++) {
      cncrot_cycle600_gud flipped = *bases[b];
      ((unsigned char *)&flipped)[bit / 8] ^= (unsigned char)(1u << (bit % 8));
      if (CALL(&flipped, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 1) != CNCROT_STATUS_BAD_STATE) accepted++;
    }
  }
  CHECK(accepted == 0, "%d single-bit flips accepted", accepted);
}

static void save_and_restore(void) {
  /* Store the state as bytes, "restart", restore, and continue additively: the same result
   * as without the restart. */
  cncrot_cycle600_gud live, restored;
  memset(&live, 0, sizeof live);
  CALL(&live, NULL, 1, "IFVW207S", 1, 39, 1, 2, 3, 10, 20, 30, 4, 5, 6, 1, 57, 0);
  unsigned char bytes[sizeof live];
  memcpy(bytes, &live, sizeof live);
  memset(&restored, 0xAB, sizeof restored);
  memcpy(&restored, bytes, sizeof restored);
  CALL(&live, NULL, 1, "IFVW207S", 1, 3, 0, 0, 0, 15, 0, 0, 0, 0, 0, 1, 57, 1);
  CHECK_STATUS(CALL(&restored, NULL, 1, "IFVW207S", 1, 3, 0, 0, 0, 15, 0, 0, 0, 0, 0, 1, 57, 1), 0);
  CHECK(memcmp(&live, &restored, sizeof live) == 0, "restored state continues identically");
}

int main(void) {
  example3();
  additive_and_translations();
  heads_and_invalid();
  save_and_restore();
  return finish("test_cycle600");
}
