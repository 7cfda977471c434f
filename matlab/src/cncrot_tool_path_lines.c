/* [P, kinds] = cncrot_tool_path_lines(dialect, lines)
 * [axes, kinds] = cncrot_tool_path_lines(dialect, lines, machine, L, previous, rule, ref):
 * see cncrot_tool_path_lines.m. */
#include <math.h>
#include "program_state.h"

/* Rotary positions by letter name the machine's axes: a letter a block leaves out is where
   that axis stands (from `previous` on, then each point's), each axis' letter the one its
   direction is nearest; under Heidenhain's AXIS SPAT (flags bit 2) the letters are spatial
   angles, left as the program states them. */
static void stand(cncrot_tool_path *t, const cncrot_machine *m, const double at[6]) {
  if (t->flags & 4) return;
  /* The library's letters (axis_letters): each axis the one its direction is nearest;
     where two are nearest one letter, the axis more nearly along it keeps it (the first of
     equals), the other takes its next nearest free letter. */
  int n = m->count < 3 ? m->count : 3, order[3] = {0, 1, 2}, taken[3] = {0, 0, 0};
  double c[3][3], strength[3];
  for (int j = 0; j < n; j++) {
    const double *v = m->axes[j].direction;
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    strength[j] = 0;
    for (int i = 0; i < 3; i++) {
      c[j][i] = fabs(v[i]) / len;
      if (c[j][i] > strength[j]) strength[j] = c[j][i];
    }
  }
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && strength[order[j]] > strength[order[j - 1]]; j--) {
      int x = order[j];
      order[j] = order[j - 1], order[j - 1] = x;
    }
  for (int q = 0; q < n; q++) {
    int j = order[q], rank[3] = {0, 1, 2};
    for (int i = 1; i < 3; i++)
      for (int r = i; r > 0 && c[j][rank[r]] > c[j][rank[r - 1]]; r--) {
        int x = rank[r];
        rank[r] = rank[r - 1], rank[r - 1] = x;
      }
    for (int i = 0; i < 3; i++)
      if (!taken[rank[i]]) {
        taken[rank[i]] = 1;
        t->axes[rank[i]] = at[3 + j];
        break;
      }
  }
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 7, nlhs, 2);
  if (nrhs == 3) fail("cncrot:nargin", "a machine needs the tool length L as well (see help %s)", mexFunctionName());
  int32_t dialect = dialect_arg(prhs[0], 1, "dialect");
  cncrot_machine m;
  int on_machine = nrhs >= 4;
  double len = 0, prev[6] = {0, 0, 0, 0, 0, 0};
  int32_t rule = CNCROT_CHOOSE_CLOSEST, ref = 0;
  if (on_machine) {
    machine_arg(prhs[2], 3, &m);
    len = finite_arg(scalar_arg(prhs[3], 4, "L"), 4, "L");
    if (nrhs > 4) previous_arg(prhs[4], 5, prev);
    if (nrhs > 5) rule = rule_arg(prhs[5], 6, "rule");
    if (nrhs > 6) ref = integer_arg(prhs[6], 7, "ref");
    rule_ref_check(rule, ref, m.count, 7);
  }
  const mxArray *lines = lines_arg(prhs[1], 2);
  int cell = mxIsCell(lines);
  size_t n = cell ? mxGetNumberOfElements(lines) : 1;
  /* Off the machine: x y z, i j k (a direction), a b c (positions by letter); on it: the axes. */
  mxArray *out = mxCreateDoubleMatrix(n, on_machine ? 6 : 9, mxREAL);
  mxArray *kinds = mxCreateCellMatrix(n, 1);
  double *o = mxGetDoubles(out);
  size_t cols = on_machine ? 6 : 9;
  for (size_t k = 0; k < n * cols; k++) o[k] = mxGetNaN();
  cncrot_tool_path t;
  memset(&t, 0, sizeof t);
  if (on_machine) stand(&t, &m, prev);
  for (size_t k = 0; k < n; k++) {
    const mxArray *a = cell ? mxGetCell(lines, k) : lines;
    if (!a) a = mxCreateString("");
    char buf[CNCROT_PROGRAM_LINE_MAX + 3];
    size_t bytes = line_bytes(a, 2, buf, sizeof buf);
    int32_t s = cncrot_tool_path_line(&t, dialect, buf, bytes);
    if (s == CNCROT_STATUS_NOT_AVAILABLE) {
      mxDestroyArray(out);
      mxDestroyArray(kinds);
      fail("cncrot:notAvailable", "%s: the five-axis programs of this dialect are not read (TwinCAT's)", label(1, "dialect"));
    }
    if (s < 0) {
      mxDestroyArray(out);
      mxDestroyArray(kinds);
      raise_at(s, label(2, "lines"), "line", (long)k, n > 1 ? n : 2);
    }
    const char *kind = s == CNCROT_STATUS_PASSED         ? "passed"
                       : s == CNCROT_STATUS_NOT_FOLLOWED ? "not followed"
                       : t.point                         ? "point"
                                                         : "applied";
    mxSetCell(kinds, k, mxCreateString(kind));
    if (s != 0 || !t.point) continue;
    if (on_machine) {
      double ax[6];
      s = cncrot_tool_path_axes(&t, &m, len, prev, rule, ref, ax);
      if (s == CNCROT_STATUS_BAD_ARGUMENT && t.orientation == CNCROT_ORIENTATION_AXES) {
        mxDestroyArray(out);
        mxDestroyArray(kinds);
        fail("cncrot:badArgument",
             "%s, line %d: the block gives a position to a rotary axis the machine (argument 3) does not have "
             "(A, B, C go to the machine's axis whose direction is nearest X, Y, Z)",
             label(2, "lines"), (int)k + 1);
      }
      if (s < 0) {
        mxDestroyArray(out);
        mxDestroyArray(kinds);
        raise_at(s, label(2, "lines"), "line", (long)k, n > 1 ? n : 2);
      }
      for (int j = 0; j < 6; j++) o[k + n * j] = ax[j];
      memcpy(prev, ax, sizeof prev);
      /* The letters a later block leaves out are where the machine's axes now stand (as
         cncrot path takes them). */
      stand(&t, &m, ax);
      /* The rule picks the first point's solution; the points after it continue from it. */
      rule = CNCROT_CHOOSE_CLOSEST, ref = 0;
    } else {
      for (int j = 0; j < 3; j++) o[k + n * j] = t.tip[j];
      if (t.orientation == CNCROT_ORIENTATION_DIRECTION)
        for (int j = 0; j < 3; j++) o[k + n * (3 + j)] = t.direction[j];
      if (t.orientation == CNCROT_ORIENTATION_AXES)
        for (int j = 0; j < 3; j++) o[k + n * (6 + j)] = t.axes[j];
    }
  }
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = kinds; else mxDestroyArray(kinds);
}
