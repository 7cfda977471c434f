/* [axes, remaining, residual, status] = cncrot_machine_choose(machine, F, current, rule, ref):
 * see cncrot_machine_choose.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 5, nlhs, 4);
  cncrot_machine m;
  machine_arg(prhs[0], &m);
  if (squares_arg(prhs[1], "F", 4) != 1) mexErrMsgIdAndTxt("cncrot:badSize", "F must be 4-by-4");
  if (mxGetNumberOfElements(prhs[2]) != 3) mexErrMsgIdAndTxt("cncrot:badSize", "current must have 3 elements");
  double f[16], cur[3], ax[3], res[3], rem[16];
  frame_to_row_major(real_data(prhs[1], "F"), f);
  memcpy(cur, real_data(prhs[2], "current"), sizeof cur);
  int32_t rule = nrhs > 3 ? integer_arg(prhs[3], "rule") : CNCROT_CHOOSE_CLOSEST;
  int32_t ref = nrhs > 4 ? integer_arg(prhs[4], "reference axis") : 0;
  int32_t s = cncrot_machine_choose(&m, f, cur, rule, ref, ax, res, rem);
  if (s < 0) raise_status(s, -1, 0);
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
