/* [S, free] = cncrot_machine_inverse(machine, F): see cncrot_machine_inverse.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 2, nlhs, 2);
  cncrot_machine m;
  machine_arg(prhs[0], 1, &m);
  double f[16], sol[6];
  frame_arg(prhs[1], 2, "F", f);
  size_t n = 0;
  int32_t s = cncrot_machine_inverse(&m, f, sol, 2, &n);
  if (s < 0) raise_at(s, label(2, "F"), NULL, -1, 0);
  mxArray *out = mxCreateDoubleMatrix(n, 3, mxREAL);
  double *o = mxGetDoubles(out);
  for (size_t r = 0; r < n; r++)
    for (int c = 0; c < 3; c++) o[r + n * c] = sol[3 * r + c];
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = mxCreateLogicalScalar(s == CNCROT_STATUS_FREE_AXIS);
}
