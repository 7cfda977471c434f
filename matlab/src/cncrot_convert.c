/* angles_out = cncrot_convert(intrinsic_in, sequence_in, angles_in, intrinsic_out,
 * sequence_out): see cncrot_convert.m. One call of cncrot_convert_many for all rows. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 5, 5, nlhs, 2);
  int32_t ki = convention_arg(prhs[0], 1, "intrinsic_in");
  int32_t si = sequence_arg(prhs[1], 2, "sequence_in", 0);
  size_t n = rows3_arg(prhs[2], 3, "angles_in");
  int32_t ko = convention_arg(prhs[3], 4, "intrinsic_out");
  int32_t so = sequence_arg(prhs[4], 5, "sequence_out", 1);
  const double *in = real_data(prhs[2], 3, "angles_in");
  size_t k, rows = n ? n : 1;
  /* Rows contiguous for the library (MATLAB keeps columns contiguous). */
  double *a = (double *)mxCalloc(3 * rows, sizeof(double));
  double *b = (double *)mxCalloc(3 * rows, sizeof(double));
  int32_t *st = batch_statuses(n);
  rows_from_columns(in, n, a);
  raise_batch(cncrot_convert_many(ki, si, a, n, ko, so, b, st), st, n, label(3, "angles_in"), "row");
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
