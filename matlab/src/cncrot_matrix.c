/* R = cncrot_matrix(intrinsic, sequence, angles): see cncrot_matrix.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 1);
  int32_t intrinsic = integer_arg(prhs[0], "intrinsic");
  int32_t sequence = integer_arg(prhs[1], "sequence");
  size_t n = rows3_arg(prhs[2], "angles");
  const double *a = mxGetDoubles(prhs[2]);
  mwSize dims[3] = {3, 3, (mwSize)n};
  mxArray *out = mxCreateNumericArray(n == 1 ? 2 : 3, dims, mxDOUBLE_CLASS, mxREAL);
  double *r = mxGetDoubles(out);
  int32_t status = 0;
  size_t k;
  for (k = 0; k < n; k++) {
    double angles[3] = {a[k], a[k + n], a[k + 2 * n]}, m[9];
    status = cncrot_matrix_from_angles(intrinsic, sequence, angles, m);
    if (status < 0) break;
    to_col_major(m, r + 9 * k);
  }
  if (status < 0) {
    mxDestroyArray(out);
    raise_status(status, k);
  }
  plhs[0] = out;
}
