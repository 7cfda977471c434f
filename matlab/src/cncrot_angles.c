/* [angles, status] = cncrot_angles(intrinsic, sequence, R): see cncrot_angles.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 2);
  int32_t intrinsic = integer_arg(prhs[0], "intrinsic");
  int32_t sequence = integer_arg(prhs[1], "sequence");
  size_t n = matrices_arg(prhs[2], "R");
  const double *r = real_data(prhs[2], "R");
  int32_t status;
  if (n == 0) {
    double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, angles[3];
    status = cncrot_angles_from_matrix(intrinsic, sequence, id, angles);
    if (status < 0) raise_status(status, -1, 0);
  }
  mxArray *out = mxCreateDoubleMatrix(n, 3, mxREAL);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *a = mxGetDoubles(out), *s = mxGetDoubles(st);
  size_t k;
  for (k = 0; k < n; k++) {
    double m[9], angles[3];
    to_row_major(r + 9 * k, m);
    status = cncrot_angles_from_matrix(intrinsic, sequence, m, angles);
    if (status < 0) {
      mxDestroyArray(out);
      mxDestroyArray(st);
      raise_status(status, (long)k, n);
    }
    a[k] = angles[0];
    a[k + n] = angles[1];
    a[k + 2 * n] = angles[2];
    s[k] = status;
  }
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = st; else mxDestroyArray(st);
}
