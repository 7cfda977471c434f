/* angles_out = cncrot_convert(intrinsic_in, sequence_in, angles_in, intrinsic_out,
 * sequence_out): see cncrot_convert.m. One call of cncrot_convert_many for all rows. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 5, 5, nlhs, 2);
  int32_t ki = integer_arg(prhs[0], "intrinsic_in");
  int32_t si = integer_arg(prhs[1], "sequence_in");
  size_t n = rows3_arg(prhs[2], "angles_in");
  int32_t ko = integer_arg(prhs[3], "intrinsic_out");
  int32_t so = integer_arg(prhs[4], "sequence_out");
  const double *in = real_data(prhs[2], "angles_in");
  size_t k, rows = n ? n : 1;
  /* Rows contiguous for the library (MATLAB keeps columns contiguous). */
  double *a = (double *)mxCalloc(3 * rows, sizeof(double));
  double *b = (double *)mxCalloc(3 * rows, sizeof(double));
  int32_t *st = batch_statuses(n);
  rows_from_columns(in, n, a);
  raise_batch(cncrot_convert_many(ki, si, a, n, ko, so, b, st), st, n);
  mxArray *out = mxCreateDoubleMatrix(n, 3, mxREAL);
  mxArray *sts = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *o = mxGetDoubles(out), *s = mxGetDoubles(sts);
  columns_from_rows(b, n, o);
  for (k = 0; k < n; k++) s[k] = st[k];
  mxFree(a);
  mxFree(b);
  mxFree(st);
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = sts; else mxDestroyArray(sts);
}
