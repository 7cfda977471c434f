/* [axes, remaining, residual, status] = cncrot_machine_choose(machine, F, current, rule, ref):
 * see cncrot_machine_choose.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 5, nlhs, 4);
  cncrot_machine m;
  machine_arg(prhs[0], 1, &m);
  double f[16], cur[3], ax[3], res[3], rem[16];
  frame_arg(prhs[1], 2, "F", f);
  point_arg(prhs[2], 3, "current", cur);
  int32_t rule = nrhs > 3 ? rule_arg(prhs[3], 4, "rule") : CNCROT_CHOOSE_CLOSEST;
  int32_t ref = nrhs > 4 ? integer_arg(prhs[4], 5, "ref") : 0;
  int32_t s = cncrot_machine_choose(&m, f, cur, rule, ref, ax, res, rem);
  if (s == CNCROT_STATUS_BAD_ARGUMENT) {
    /* Of the library's reasons, the one that holds (header: rule, reference axis, an
     * unused current position not 0). */
    rule_ref_check(rule, ref, m.count, 5);
    for (int k = m.count; k < 3; k++)
      if (cur[k] != 0)
        fail("cncrot:badArgument", "%s: the position of axis %d, which the machine does not have, must be 0; got %s",
             label(3, "current"), k + 1, number_text(cur[k]));
  }
  if (s < 0) {
    const char *where = NULL;
    if (s == CNCROT_STATUS_UNREACHABLE || s == CNCROT_STATUS_OUT_OF_TRAVEL || s == CNCROT_STATUS_NOT_A_ROTATION) where = label(2, "F");
    raise_at(s, where, NULL, -1, 0);
  }
  mxArray *a = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(a), ax, sizeof ax);
  plhs[0] = a;
  if (nlhs > 1) {
    plhs[1] = mxCreateDoubleMatrix(4, 4, mxREAL);
    frame_to_col_major(rem, mxGetDoubles(plhs[1]));
  }
  if (nlhs > 2) {
    plhs[2] = mxCreateDoubleMatrix(1, 3, mxREAL);
    memcpy(mxGetDoubles(plhs[2]), res, sizeof res);
  }
  if (nlhs > 3) plhs[3] = mxCreateDoubleScalar(s);
}
