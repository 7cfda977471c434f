/* R = cncrot_matrix(intrinsic, sequence, angles): see cncrot_matrix.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 1);
  int32_t intrinsic = integer_arg(prhs[0], "intrinsic");
  int32_t sequence = integer_arg(prhs[1], "sequence");
  size_t n = rows3_arg(prhs[2], "angles");
  const double *a = real_data(prhs[2], "angles");
  int32_t status;
  if (n == 0) {
    /* No rows: the flag and code are still the library's to accept. */
    double zero[3] = {0, 0, 0}, m[9];
    status = cncrot_matrix_from_angles(intrinsic, sequence, zero, m);
    if (status < 0) raise_status(status, -1, 0);
  }
  mwSize dims[3] = {3, 3, (mwSize)n};
  mxArray *out = mxCreateNumericArray(n == 1 ? 2 : 3, dims, mxDOUBLE_CLASS, mxREAL);
  double *r = mxGetDoubles(out);
  size_t k;
  for (k = 0; k < n; k++) {
    double angles[3] = {a[k], a[k + n], a[k + 2 * n]}, m[9];
    status = cncrot_matrix_from_angles(intrinsic, sequence, angles, m);
    if (status < 0) {
      mxDestroyArray(out);
      raise_status(status, (long)k, n);
    }
    to_col_major(m, r + 9 * k);
  }
  plhs[0] = out;
}
