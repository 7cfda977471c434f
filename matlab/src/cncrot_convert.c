/* angles_out = cncrot_convert(intrinsic_in, sequence_in, angles_in, intrinsic_out,
 * sequence_out): see cncrot_convert.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 5, 5, nlhs, 2);
  int32_t ki = integer_arg(prhs[0], "intrinsic_in");
  int32_t si = integer_arg(prhs[1], "sequence_in");
  size_t n = rows3_arg(prhs[2], "angles_in");
  int32_t ko = integer_arg(prhs[3], "intrinsic_out");
  int32_t so = integer_arg(prhs[4], "sequence_out");
  const double *in = real_data(prhs[2], "angles_in");
  int32_t status;
  if (n == 0) {
    double zero[3] = {0, 0, 0}, b[3];
    status = cncrot_convert(ki, si, zero, ko, so, b);
    if (status < 0) raise_status(status, -1, 0);
  }
  mxArray *out = mxCreateDoubleMatrix(n, 3, mxREAL);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *o = mxGetDoubles(out), *s = mxGetDoubles(st);
  size_t k;
  for (k = 0; k < n; k++) {
    double a[3] = {in[k], in[k + n], in[k + 2 * n]}, b[3];
    status = cncrot_convert(ki, si, a, ko, so, b);
    if (status < 0) {
      mxDestroyArray(out);
      mxDestroyArray(st);
      raise_status(status, (long)k, n);
    }
    o[k] = b[0];
    o[k + n] = b[1];
    o[k + 2 * n] = b[2];
    s[k] = status;
  }
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = st; else mxDestroyArray(st);
}
